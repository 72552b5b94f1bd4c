//! The block passes against their lane-by-lane forms: whichever path a block takes (the
//! solve and warm-start kernels with each backend the processor has, AVX-512 and AVX2, or
//! the fallback when a value leaves the kernels' bound), the bits and the saturation count
//! are those of the lanes solved one after another.

#[cfg(vector_kernels)]
use super::kernel::{Kernel, KernelFacts, Kernels, solve_on, warm_start_on};
use super::{ContactArms, ContactBlock, SolvePass};
use crate::math::cpu::{each_backend, kernels_present};
use crate::math::saturation::count_saturations;
#[cfg(vector_kernels)]
use crate::math::wide::{Backend, backends, on_backend, with_backend};
use crate::math::{Fx, Mat3, Pcg32, Real, Vec3};
use crate::rigid::contact::{Contact, ContactKey, ContactPoint};
use crate::rigid::manifold::MAX_MANIFOLD_POINTS;
use crate::rigid::solver::body::SolverBody;
use crate::rigid::solver::lanes::LANES;
use crate::rigid::solver::softness::Softness;

/// A value in [−scale, scale).
fn value(rng: &mut Pcg32, scale: f64) -> Fx // ok-det: test input
{
    rng.range(Fx::from_f64(-scale), Fx::from_f64(scale))
}

fn vector(rng: &mut Pcg32, scale: f64) -> Vec3<Fx> // ok-det: test input
{
    Vec3::new(value(rng, scale), value(rng, scale), value(rng, scale))
}

/// The masses of the moving bodies of a test.
#[derive(Clone, Copy)]
enum Masses {
    /// From 0.01 to 100 kg.
    Spread,
    /// One mass from 0.01 to 100 kg for all.
    Equal,
    /// From 200 to 2000 kg: every velocity change per unit impulse within the narrow
    /// kernels' bound.
    Heavy,
}

/// `count` moving bodies after the static body, with velocities and motions up to
/// `scale`, masses as given and inertias to match; every fifth one kinematic (zero inverse
/// mass and inertia).
fn bodies(rng: &mut Pcg32, count: usize, scale: f64, masses: Masses) -> Vec<SolverBody<Fx>> // ok-det: test input
{
    let mut bodies = vec![SolverBody::default()];
    let common = rng.range(Fx::from_f64(0.01), Fx::from_int(100));
    for i in 0..count {
        let kinematic = i % 5 == 4;
        let inv_mass = match masses {
            _ if kinematic => Fx::ZERO,
            Masses::Spread => rng.range(Fx::from_f64(0.01), Fx::from_int(100)),
            Masses::Equal => common,
            Masses::Heavy => rng.range(Fx::from_f64(0.0005), Fx::from_f64(0.005)),
        };
        let inv_inertia = Mat3::from_symmetric(
            Vec3::new(
                inv_mass * Fx::from_int(3),
                inv_mass * Fx::from_int(2),
                inv_mass * Fx::from_int(4),
            ),
            inv_mass * Fx::from_f64(0.1),
            Fx::ZERO,
            inv_mass * Fx::from_f64(-0.2),
        );
        bodies.push(SolverBody {
            v: vector(rng, scale),
            w: vector(rng, scale),
            dp: vector(rng, scale / 100.0),
            dtheta: vector(rng, scale / 100.0),
            inv_mass,
            inv_inertia,
        });
    }
    bodies
}

/// A block of `lanes` contacts with no moving body twice (independent) or with bodies
/// drawn at random (not independent), with impulses up to `impulse` and separations up to
/// `separation`, prepared.
fn block(
    rng: &mut Pcg32,
    bodies: &[SolverBody<Fx>],
    lanes: usize,
    independent: bool,
    (impulse, separation): (f64, f64), // ok-det: test input
) -> ContactBlock<Fx> {
    let (mut block, arms) = lanes_of(rng, bodies, lanes, independent, (impulse, separation), 1.0);
    block.prepare_products(&arms, bodies);
    block.soften(&pass(true));
    block
}

/// The block of [`block`] before its products, with its anchors: points within 2·`reach`
/// and centres within `reach` of the origin (m).
fn lanes_of(
    rng: &mut Pcg32,
    bodies: &[SolverBody<Fx>],
    lanes: usize,
    independent: bool,
    (impulse, separation): (f64, f64), // ok-det: test input
    reach: f64,                        // ok-det: test input
) -> (ContactBlock<Fx>, ContactArms<Fx>) {
    let mut arms = ContactArms::ZERO;
    let moving = bodies.len() as u32 - 1;
    let mut order: Vec<u32> = (1..=moving).collect();
    for i in (1..order.len()).rev() {
        order.swap(i, rng.below(i as u32 + 1) as usize);
    }
    let mut block = ContactBlock::empty();
    block.clear(independent);
    for l in 0..lanes {
        let (a, b) = if independent {
            // One lane in three against the static body.
            let a = if l % 3 == 2 { 0 } else { order[2 * l] };
            (a, order[2 * l + 1])
        } else {
            (rng.below(moving) + 1, rng.below(moving) + 1)
        };
        let b = if a == b { 0 } else { b };
        let count = 1 + rng.below(MAX_MANIFOLD_POINTS as u32) as usize;
        let mut points = [ContactPoint::default(); MAX_MANIFOLD_POINTS];
        for p in &mut points[..count] {
            // One point in three is new: no impulse to warm start with.
            let fresh = rng.below(3) == 0;
            let carried = if fresh { 0.0 } else { impulse };
            *p = ContactPoint {
                point: vector(rng, 2.0 * reach),
                separation: value(rng, separation),
                id: 0,
                normal_impulse: rng.range(Fx::ZERO, Fx::from_f64(carried)),
            };
        }
        // One contact in three is new: no friction impulse to warm start with.
        let carried = if rng.below(3) == 0 { 0.0 } else { impulse };
        let contact = Contact {
            key: ContactKey {
                body_a: a,
                body_b: b,
                part_a: 0,
                part_b: 0,
            },
            normal: rng.unit_vector(),
            count: count as u8,
            points,
            friction_impulse: [value(rng, carried / 2.0), value(rng, carried / 2.0)],
            twist_impulse: value(rng, carried / 4.0),
            frame: crate::rigid::contact::NO_FRAME,
        };
        block.prepare_lane(
            &contact,
            l as u32,
            (a, vector(rng, reach)),
            (b, vector(rng, reach)),
            bodies,
            rng.range(Fx::ZERO, Fx::ONE),
            rng.range(Fx::ZERO, Fx::ONE),
            &mut arms,
        );
    }
    (block, arms)
}

fn pass(use_bias: bool) -> SolvePass<Fx> {
    let h = Fx::from_ratio(1, 240);
    SolvePass {
        soft: Softness::new(Fx::from_int(45), Fx::from_int(10), h),
        soft_static: Softness::new(Fx::from_int(60), Fx::from_int(10), h),
        inv_h: Fx::from_int(240),
        max_push: Fx::from_int(3),
        use_bias,
    }
}

/// Bits of everything a pass writes: the bodies' velocities and the block's impulses and
/// kept separations.
fn state(bodies: &[SolverBody<Fx>], block: &ContactBlock<Fx>) -> Vec<i64> {
    let mut bits = Vec::new();
    for b in bodies {
        for v in [b.v, b.w] {
            bits.extend([v.x, v.y, v.z].map(Fx::to_bits));
        }
    }
    for p in &block.points {
        for l in 0..LANES {
            bits.extend(
                [
                    p.normal_impulse[l],
                    p.max_normal_impulse[l],
                    p.separation[l],
                ]
                .map(Fx::to_bits),
            );
        }
    }
    let f = &block.friction_rows;
    for l in 0..LANES {
        bits.extend(
            [
                f.tangent_impulse[0][l],
                f.tangent_impulse[1][l],
                f.twist_impulse[l],
            ]
            .map(Fx::to_bits),
        );
    }
    bits
}

/// No kernel exists off x86_64.
#[cfg(not(vector_kernels))]
enum Kernel {}

/// No backend exists off x86_64.
#[cfg(not(vector_kernels))]
#[derive(Clone, Copy, Debug)]
enum Backend {}

/// The backends this processor runs (none off x86_64).
#[cfg(not(vector_kernels))]
fn backends() -> Vec<Backend> {
    Vec::new()
}

#[cfg(vector_kernels)]
impl Backend {
    /// The facts of `block` as this backend finds them.
    fn facts(self, block: &ContactBlock<Fx>) -> KernelFacts {
        on_backend!(self, wide => wide.facts(block))
    }

    /// The solve pass of `block` with this backend's kernels, as [`ContactBlock::solve`]
    /// takes it: a kernel for an independent block within the bound, else the lanes.
    fn solve(
        self,
        block: &mut ContactBlock<Fx>,
        bodies: &mut [SolverBody<Fx>],
        pass: &SolvePass<Fx>,
    ) -> Option<Kernel> {
        let taken = if block.independent {
            on_backend!(self, wide => solve_on(wide, block, bodies, pass))
        } else {
            None
        };
        if taken.is_none() {
            block.solve_lanes(bodies, pass);
        }
        taken
    }

    /// The warm start of `block` with this backend's kernels, likewise.
    fn warm_start(self, block: &mut ContactBlock<Fx>, bodies: &mut [SolverBody<Fx>]) {
        let taken = block.independent
            && on_backend!(self, wide => warm_start_on(wide, block, bodies)).is_some();
        if !taken {
            block.warm_start_lanes(bodies);
        }
    }
}

#[cfg(not(vector_kernels))]
impl Backend {
    fn solve(
        self,
        _: &mut ContactBlock<Fx>,
        _: &mut [SolverBody<Fx>],
        _: &SolvePass<Fx>,
    ) -> Option<Kernel> {
        match self {}
    }

    fn warm_start(self, _: &mut ContactBlock<Fx>, _: &mut [SolverBody<Fx>]) {
        match self {}
    }
}

/// A substep and a half, as the solver runs them: warm start, the biased pass, the relax
/// pass (which keeps the separations), warm start and the biased pass again (which reads
/// them); with the kernels of `backend`, or lane by lane. The bodies' motions stay as
/// drawn, as if the positions had moved before the relax pass.
fn run_passes(
    block: &mut ContactBlock<Fx>,
    bodies: &mut [SolverBody<Fx>],
    backend: Option<Backend>,
) {
    for use_bias in [true, false, true] {
        match backend {
            Some(backend) => {
                if use_bias {
                    backend.warm_start(block, bodies);
                }
                backend.solve(block, bodies, &pass(use_bias));
            }
            None => {
                if use_bias {
                    block.warm_start_lanes(bodies);
                }
                block.solve_lanes(bodies, &pass(use_bias));
            }
        }
    }
}

/// What the kernels did in a comparison: the passes each solve kernel took (the first
/// pass of each independent block, with and without bias), and the blocks that shared the
/// products λ n/m and λ t/m between their two sides.
#[derive(Debug, Default, PartialEq)]
struct Runs {
    narrow: usize,
    wide: usize,
    shared: usize,
}

impl Runs {
    /// One more pass taken by `kernel`.
    fn count(&mut self, kernel: Kernel) {
        #[cfg(vector_kernels)]
        match kernel {
            Kernel::Narrow => self.narrow += 1,
            Kernel::Wide => self.wide += 1,
        }
        #[cfg(not(vector_kernels))]
        match kernel {}
    }
}

/// The magnitudes of a comparison: the largest velocity (m/s, and a hundredth of it for
/// the motions), impulse (N·s) and separation (m), and the masses.
struct Scales {
    velocity: f64,   // ok-det: test input
    impulse: f64,    // ok-det: test input
    separation: f64, // ok-det: test input
    masses: Masses,
}

/// Everyday magnitudes with bodies of `masses`.
const fn everyday(masses: Masses) -> Scales {
    Scales {
        velocity: 5.0,
        impulse: 5.0,
        separation: 0.05,
        masses,
    }
}

/// Runs `trials` random blocks at the given magnitudes through the passes lane by lane and
/// with each backend's kernels, asserting the same bits and saturation counts, and returns
/// what the kernels did: the same with every backend (asserted), none without one.
fn compare(seed: u64, trials: usize, scales: &Scales) -> Runs {
    let backends = backends();
    let mut rng = Pcg32::new(seed, 7);
    let mut runs: Vec<Runs> = backends.iter().map(|_| Runs::default()).collect();
    for trial in 0..trials {
        let lanes = 1 + trial % LANES;
        let independent = trial % 7 != 6;
        let bodies = bodies(&mut rng, 2 * LANES + 2, scales.velocity, scales.masses);
        let magnitudes = (scales.impulse, scales.separation);
        let block = block(&mut rng, &bodies, lanes, independent, magnitudes);
        let (mut slow_bodies, mut slow_block) = (bodies.clone(), block.clone());
        let ((), slow_saturations) =
            count_saturations(|| run_passes(&mut slow_block, &mut slow_bodies, None));
        for (&backend, runs) in backends.iter().zip(&mut runs) {
            #[cfg(vector_kernels)]
            assert_eq!(
                backend.facts(&block),
                block.kernel,
                "trial {trial}, {backend:?}"
            );
            let (mut fast_bodies, mut fast_block) = (bodies.clone(), block.clone());
            let ((), fast_saturations) = count_saturations(|| {
                run_passes(&mut fast_block, &mut fast_bodies, Some(backend));
            });
            assert_eq!(
                state(&fast_bodies, &fast_block),
                state(&slow_bodies, &slow_block),
                "trial {trial}, {backend:?}"
            );
            assert_eq!(
                fast_saturations, slow_saturations,
                "trial {trial}, {backend:?}"
            );
            if independent {
                for use_bias in [true, false] {
                    let (mut bodies, mut block) = (bodies.clone(), block.clone());
                    if let Some(kernel) = backend.solve(&mut block, &mut bodies, &pass(use_bias)) {
                        runs.count(kernel);
                    }
                }
            }
            runs.shared += usize::from(shares_linear_products(&block));
        }
    }
    for other in runs.iter().skip(1) {
        assert_eq!(other, &runs[0], "the backends took different kernels");
    }
    runs.into_iter().next().unwrap_or_default()
}

/// Whether the kernels share the products λ n/m and λ t/m between the sides of `block`.
#[cfg(vector_kernels)]
fn shares_linear_products(block: &ContactBlock<Fx>) -> bool {
    block.kernel.linear_shared
}

#[cfg(not(vector_kernels))]
fn shares_linear_products(_: &ContactBlock<Fx>) -> bool {
    false
}

/// Independent blocks among `trials`, each compared with and without bias.
const fn independent_passes(trials: usize) -> usize {
    2 * (trials - trials / 7)
}

#[test]
fn blocks_at_everyday_magnitudes_match_the_lanes() {
    let runs = compare(1, 400, &everyday(Masses::Spread));
    if !backends().is_empty() {
        // Everyday values stay inside the wide bound: a kernel takes every independent
        // block.
        assert_eq!(runs.narrow + runs.wide, independent_passes(400));
    }
}

#[test]
fn blocks_of_equal_masses_match_the_lanes() {
    let runs = compare(7, 400, &everyday(Masses::Equal));
    if !backends().is_empty() {
        assert_eq!(runs.narrow + runs.wide, independent_passes(400));
        // Lanes of two moving bodies, with the static body or with a kinematic one: every
        // block can share.
        assert_eq!(runs.shared, 400);
    }
}

#[test]
fn blocks_of_heavy_slow_bodies_take_the_narrow_kernel() {
    // Velocities up to 0.2 m/s, impulses up to 10 N·s and separations up to 0.2 mm (a
    // push-out below 0.05 m/s) on bodies of 200 to 2000 kg.
    let scales = Scales {
        velocity: 0.2,
        impulse: 10.0,
        separation: 0.0002,
        masses: Masses::Heavy,
    };
    let runs = compare(8, 400, &scales);
    if !backends().is_empty() {
        // All but the few blocks whose pass pushes a velocity past 0.5 m/s.
        assert_eq!(runs.narrow + runs.wide, independent_passes(400));
        assert!(runs.narrow > 9 * independent_passes(400) / 10, "{runs:?}");
    }
}

#[test]
fn blocks_near_the_narrow_bound_match_the_lanes() {
    // Velocities up to 0.3 m/s, relative velocities up to 0.6 m/s: past the narrow bound
    // (0.5 m/s) in some blocks and not in others, or pushed past it by an impulse; the wide
    // kernel takes those.
    let scales = Scales {
        velocity: 0.3,
        impulse: 10.0,
        separation: 0.0002,
        masses: Masses::Heavy,
    };
    let runs = compare(9, 400, &scales);
    if !backends().is_empty() {
        assert!(runs.narrow > 0 && runs.wide > 0, "{runs:?}");
        assert_eq!(runs.narrow + runs.wide, independent_passes(400));
    }
}

#[test]
fn blocks_near_the_kernel_bound_match_the_lanes() {
    // Velocities and impulses near 2¹⁴: some blocks pass the check, some do not.
    let scales = Scales {
        velocity: 4_000.0,
        impulse: 4_000.0,
        ..everyday(Masses::Spread)
    };
    let runs = compare(2, 400, &scales);
    if !backends().is_empty() {
        let taken = runs.narrow + runs.wide;
        assert!(
            taken > 0 && taken < independent_passes(400),
            "the kernels ran {taken} times"
        );
    }
}

#[test]
fn blocks_pushed_past_the_kernel_bound_match_the_lanes() {
    // Velocities within 2¹⁴ when loaded and impulses large enough to push them past it
    // during a pass: the kernels do not check the velocities after each impulse (only where
    // they enter products), so they finish such a pass with exact sums and the next pass
    // refuses the block.
    let scales = Scales {
        velocity: 12_000.0,
        impulse: 12_000.0,
        ..everyday(Masses::Spread)
    };
    let runs = compare(4, 400, &scales);
    if !backends().is_empty() {
        let taken = runs.narrow + runs.wide;
        assert!(
            taken > 0 && taken < independent_passes(400),
            "the kernels ran {taken} times"
        );
    }
}

#[test]
fn blocks_that_saturate_match_the_lanes() {
    // Values near the ends of the range: the kernels refuse, the lanes saturate and count.
    let scales = Scales {
        velocity: 1.0e9,
        impulse: 1.0e9,
        ..everyday(Masses::Spread)
    };
    let runs = compare(3, 100, &scales);
    assert_eq!(runs.narrow + runs.wide, 0);
}

/// Runs `trials` random blocks, velocities up to `scale` and anchors within `reach`, through
/// both forms of the preparation products, with each backend the processor has, and
/// returns how many blocks the kernel took: the same with every backend (asserted), none
/// without one.
fn compare_preparation(seed: u64, trials: usize, scale: f64, reach: f64) -> usize // ok-det: test input
{
    #[cfg(vector_kernels)]
    {
        let runs: Vec<usize> = backends()
            .into_iter()
            .map(|backend| {
                with_backend(Some(backend), || {
                    compare_preparation_once(seed, trials, scale, reach)
                })
            })
            .collect();
        if let Some(&first) = runs.first() {
            assert!(runs.iter().all(|&r| r == first), "{runs:?}");
            return first;
        }
    }
    compare_preparation_once(seed, trials, scale, reach)
}

/// [`compare_preparation`] with the backend the thread has.
fn compare_preparation_once(seed: u64, trials: usize, scale: f64, reach: f64) -> usize // ok-det: test input
{
    let mut rng = Pcg32::new(seed, 11);
    let mut kernel_runs = 0;
    for trial in 0..trials {
        let lanes = 1 + trial % LANES;
        let bodies = bodies(&mut rng, 2 * LANES + 2, scale, Masses::Spread);
        let magnitudes = (1.0, 0.05);
        let (block, arms) = lanes_of(&mut rng, &bodies, lanes, trial % 7 != 6, magnitudes, reach);
        let (mut fast, mut slow) = (block.clone(), block.clone());
        let (took, fast_saturations) =
            count_saturations(|| prepare_kernel(&mut fast, &arms, &bodies));
        if took {
            kernel_runs += 1;
            assert_eq!(fast_saturations, 0, "trial {trial}");
        } else {
            fast = block.clone();
        }
        let ((), slow_saturations) =
            count_saturations(|| slow.prepare_products_lanes(&arms, &bodies));
        if !took {
            fast.prepare_products_lanes(&arms, &bodies);
        }
        assert_eq!(fast, slow, "trial {trial}");
        if took {
            assert_eq!(
                slow_saturations, 0,
                "trial {trial}: the kernel took a block that saturates"
            );
        }
        // The full stage, whichever path it takes, gives the lanes' twist arms and
        // effective masses.
        let (mut whole, mut by_lanes) = (block.clone(), block.clone());
        whole.prepare_products(&arms, &bodies);
        by_lanes.tangents_lanes();
        by_lanes.twist_arms_lanes(&arms);
        by_lanes.prepare_products_lanes(&arms, &bodies);
        by_lanes.invert_effective_masses();
        assert_eq!(whole, by_lanes, "trial {trial}");
    }
    kernel_runs
}

/// The preparation kernel on `block`; whether it took it.
#[cfg(vector_kernels)]
fn prepare_kernel(
    block: &mut ContactBlock<Fx>,
    arms: &ContactArms<Fx>,
    bodies: &[SolverBody<Fx>],
) -> bool {
    super::prepare_kernel::prepare(block, arms, bodies)
}

#[cfg(not(vector_kernels))]
fn prepare_kernel(_: &mut ContactBlock<Fx>, _: &ContactArms<Fx>, _: &[SolverBody<Fx>]) -> bool {
    false
}

#[test]
fn preparation_at_everyday_magnitudes_matches_the_lanes() {
    let runs = compare_preparation(4, 400, 5.0, 2.0);
    if !backends().is_empty() {
        assert_eq!(runs, 400);
    }
}

#[test]
fn preparation_near_the_kernel_bound_matches_the_lanes() {
    // Inverse inertias up to 400 and anchors up to 100 m: I⁻¹(r × n) reaches past 2¹⁴ in
    // some blocks and not in others.
    let runs = compare_preparation(5, 400, 100.0, 40.0);
    if !backends().is_empty() {
        assert!(runs > 0 && runs < 400, "the kernel ran {runs} times");
    }
}

#[test]
fn preparation_that_saturates_matches_the_lanes() {
    let runs = compare_preparation(6, 100, 1.0e9, 1.0e8);
    assert_eq!(runs, 0);
}

/// Runs `trials` random blocks whose normals are unit vectors times a length drawn from
/// `lengths` (one per lane) through both forms of the tangents, and returns how many blocks
/// the kernel took and how many saturations the lanes counted. The bits and saturation
/// counts must match whichever path runs.
fn compare_tangents(seed: u64, trials: usize, lengths: &[f64]) -> (usize, u64) // ok-det: test input
{
    let mut rng = Pcg32::new(seed, 13);
    let (mut kernel_runs, mut saturations) = (0, 0);
    for trial in 0..trials {
        let lanes = 1 + trial % LANES;
        let bodies = bodies(&mut rng, 2 * LANES + 2, 1.0, Masses::Spread);
        let (mut block, _) = lanes_of(&mut rng, &bodies, lanes, true, (1.0, 0.05), 1.0);
        for l in 0..lanes {
            let length = lengths[rng.below(lengths.len() as u32) as usize];
            let n = rng.unit_vector::<Fx>() * Fx::from_f64(length);
            block.normal.set(l, n);
            block.tangents[0].set(l, n.any_orthogonal());
        }
        let (mut fast, mut slow) = (block.clone(), block.clone());
        let (took, fast_saturations) = count_saturations(|| tangents_kernel(&mut fast));
        if took {
            kernel_runs += 1;
        } else {
            assert_eq!(fast, block, "trial {trial}: the kernel wrote and gave up");
            fast.tangents_lanes();
        }
        let ((), slow_saturations) = count_saturations(|| slow.tangents_lanes());
        saturations += slow_saturations;
        assert_eq!(fast, slow, "trial {trial}");
        if took {
            assert_eq!(
                (fast_saturations, slow_saturations),
                (0, 0),
                "trial {trial}"
            );
        }
        // The whole stage, whichever path it takes, gives the lanes' tangents.
        let mut whole = block.clone();
        let ((), whole_saturations) = count_saturations(|| whole.tangents());
        assert_eq!(whole, slow, "trial {trial}");
        assert_eq!(whole_saturations, slow_saturations, "trial {trial}");
    }
    (kernel_runs, saturations)
}

/// The tangents kernel on `block`; whether it took it.
#[cfg(vector_kernels)]
fn tangents_kernel(block: &mut ContactBlock<Fx>) -> bool {
    super::roots_kernel::tangents(block)
}

#[cfg(not(vector_kernels))]
fn tangents_kernel(_: &mut ContactBlock<Fx>) -> bool {
    false
}

#[test]
fn tangents_of_unit_normals_match_the_lanes() {
    each_backend(|| {
        let (runs, saturations) = compare_tangents(7, 2000, &[1.0]);
        assert_eq!(saturations, 0);
        if kernels_present() {
            assert_eq!(runs, 2000);
        }
    });
}

#[test]
fn tangents_near_the_kernel_bounds_match_the_lanes() {
    each_backend(|| {
        // |o| ≥ 0.577 |n|: lengths of n about the shortest |o| the kernel takes (2⁻¹³) and
        // about the bound of o and n (2¹⁴), on either side, and zero.
        let shortest = 2f64.powi(-13);
        let lengths = [
            0.0,
            shortest,
            shortest * 1.5,
            shortest * 1.8,
            shortest * 2.0,
            1.0,
            16_000.0,
            16_400.0,
            20_000.0,
        ];
        let (runs, _) = compare_tangents(8, 2000, &lengths);
        if kernels_present() {
            assert!(runs > 0 && runs < 2000, "the kernel ran {runs} times");
        }
    });
}

#[test]
fn tangents_that_saturate_match_the_lanes() {
    each_backend(|| {
        // |o|² leaves the range (2³¹ m²) beyond |o| ≈ 46 341 m; past the kernel's bound.
        let (runs, saturations) = compare_tangents(9, 400, &[1.0, 50_000.0, 1.0e6, 2.0e9]);
        assert!(saturations > 0);
        if kernels_present() {
            // Only blocks whose normals are all unit vectors.
            assert!(runs > 0 && runs < 400, "the kernel ran {runs} times");
        }
    });
}

/// Built-in scenes whose contacts the kernels take: each gives the same checksum after
/// `ticks` ticks lane by lane and with each backend the processor has.
#[test]
fn scenes_match_the_lanes_with_every_backend() {
    use crate::fixstep_scenes::builtin_scene;
    use crate::world::TickInput;
    for (name, ticks) in [
        ("pyramid", 40),
        ("stack", 60),
        ("cradle", 60),
        ("incline", 60),
    ] {
        let run = |_backend: Option<Backend>| {
            let steps = || {
                let mut world = builtin_scene::<Fx>(name)
                    .and_then(|scene| scene.build().ok())
                    .expect("a built-in scene");
                for _ in 0..ticks {
                    world.step(&TickInput::default());
                }
                world.checksum()
            };
            #[cfg(vector_kernels)]
            return with_backend(_backend, steps);
            #[cfg(not(vector_kernels))]
            steps()
        };
        let lanes = run(None);
        for backend in backends() {
            assert_eq!(run(Some(backend)), lanes, "{name}, {backend:?}");
        }
    }
}
