//! The solve and warm-start passes of an independent block of I32F32 constraints as
//! kernels: the eight lanes side by side, one `i64` lane per constraint, with the bits of
//! [`ContactBlock::solve_lanes`] and [`ContactBlock::warm_start_lanes`]. They are written
//! once against [`Wide`](crate::math::wide::Wide) and run with its AVX-512 backend where the processor has AVX-512F
//! and DQ, else with its AVX2 backend where it has AVX2; elsewhere the blocks go lane by
//! lane. (A portable backend, eight `i64` in an array, was measured slower than the lanes'
//! scalar code, so there is none.)
//!
//! # Why side by side gives the same bits
//!
//! The lanes of an independent block share no moving body, so solving them one after
//! another or together reads and writes the same values; bodies that do not move (the
//! static body, kinematic bodies) have zero inverse mass and inertia, so every lane writes
//! back exactly the value it read, and two lanes writing one such body write the same
//! value.
//!
//! # Exactness
//!
//! The kernel computes every operation of [`ContactBlock::solve_lanes`], in the same
//! order, modulo 2⁶⁴. Every value it loads (body velocities and motions, constraint
//! coefficients, impulses, kept separations) and every value that enters a product is
//! checked to lie in [−2⁴⁶, 2⁴⁶) as raw bits (|x| ≤ 16384 in I32F32): the coefficients,
//! which do not change during a step, once per step ([`KernelFacts`]), the rest in the
//! kernels. Then:
//!
//! * a product a·b of checked values is at most 2⁹² before rounding, 2⁶⁰ after;
//! * a dot product of three is at most 3·2⁹² before rounding, below 2⁶² after;
//! * every sum and difference of the pass has at most four terms, each a checked value or
//!   a product or dot product: below 2⁶³.
//!
//! So no operation leaves the `i64` range: the checked operators saturate nowhere and
//! their results are the exact rounded values, which the kernel's exact residues equal.
//!
//! The linear velocities enter no product themselves, only their difference v_b − v_a,
//! which is checked where it is used; in the warm start kernel no velocity enters a
//! product. Such velocities are checked when loaded, not after each impulse: a pass adds
//! to each at most seven changes (four points' λ n/m or λ I⁻¹(r × n), and two tangent
//! changes and a twist change), each a product of checked values below 2⁶⁰, so they stay
//! below 2⁴⁶ + 7·2⁶⁰ < 2⁶³ and every sum is exact. A velocity left past the bound by a
//! pass fails the next pass's load check.
//! When a check fails in a lane in use, the kernel stops before writing anything and the
//! block takes [`ContactBlock::solve_lanes`], which saturates and counts as usual.
//!
//! # Products
//!
//! The checked `*` and the fused dot product of checked values, exact in `i64` lanes, are
//! those of [`Wide`](crate::math::wide::Wide): [`Wide::mul`](crate::math::wide::Wide::mul), [`Wide::times`](crate::math::wide::Wide::times) and [`Wide::dot`](crate::math::wide::Wide::dot).
//!
//! # Narrow products
//!
//! When one factor a lies in [−2³¹, 2³¹) (|a| < ½), it is its own low half (a_h = 0) and
//! the product needs two multiplies of 32-bit halves, both exact in 64 bits:
//! ⌊(a·b + 2³¹)/2³²⌋ = a·b_h + ⌊(a·b_l + 2³¹)/2³²⌋ ([`Wide::times`](crate::math::wide::Wide::times)), about half the work of the
//! wide form. In a contact row one factor of most products is small in SI units: a
//! velocity (the dot products v·n, ω·(r × n), and the motions of the relax pass), or a
//! velocity change per unit impulse (n/m, I⁻¹(r × n) and the like, below ½ for bodies
//! above 2 kg) multiplying an impulse. Each kernel therefore comes twice: a narrow one,
//! tried first when a block's velocity changes per unit impulse are all below ½
//! ([`KernelFacts`]), which checks its velocities against 2³¹ (and the rest against 2⁴⁶)
//! and keeps the wide form for the few products of two large factors (effective mass
//! times biased velocity, friction coefficient times total impulse, squared impulses); and
//! the wide one above, which a block takes when a narrow check fails (it has written
//! nothing then), for the rest of the step. Both compute the same exact values, so the
//! bits are those of the lanes either way. The bounds of the sums above hold a fortiori.
//!
//! # Shared products
//!
//! A product λ n/m_a and λ n/m_b (likewise λ t/m) is the same bits on both sides when
//! the two bodies have the same inverse mass, and zero on a side whose inverse mass is
//! zero; when that holds in every lane of a block ([`KernelFacts`]), the kernels compute
//! it once and apply it to the sides that move.
//!
//! The friction rows are one set per lane (two tangents at the friction centre and a twist
//! about the normal), after the lane's normal rows. The clamp of the tangent impulse to its
//! disc, which needs 1/√x, runs per lane in scalar code with the checked operators, in the
//! few lanes where it applies; the twist clamp is a min and a max.

use super::{ContactArms, ContactBlock, ContactBlockOf, SolvePass, SolvePassOf};
#[cfg(target_arch = "aarch64")]
use crate::math::wide::neon::Neon;
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
use crate::math::wide::simd128::Simd128;
#[cfg(target_arch = "x86_64")]
use crate::math::wide::{avx2::Avx2, avx512::Avx512};
use crate::math::wide::{backend, on_backend};
use crate::math::{Fx, Real};
use crate::rigid::solver::body::{SolverBodiesOf, SolverBody};
use crate::rigid::solver::lanes::{LANES, Lanes, Lanes3};
use crate::rigid::solver::wide_bodies::WideBodies;

/// The kernel that took a block: with narrow products, or wide ones ([`Wide::times`](crate::math::wide::Wide::times)).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kernel {
    Narrow,
    Wide,
}

/// Solves `block` with a kernel when `R` is I32F32 and the block's coefficients lie within
/// the checked bound ([`KernelFacts`]) and the processor has AVX-512 (F and DQ) or AVX2,
/// with the wider, and tells which kernel took it ([`solve_on`]).
pub(super) fn solve<R: Real>(
    block: &mut ContactBlock<R>,
    bodies: &mut [SolverBody<R>],
    pass: &SolvePass<R>,
) -> Option<Kernel> {
    let block = R::as_fixed_mut::<ContactBlockOf>(block)?;
    let bodies = R::as_fixed_mut::<SolverBodiesOf>(bodies)?;
    let pass = R::as_fixed::<SolvePassOf>(pass)?;
    on_backend!(backend()?, wide => solve_on(wide, block, bodies, pass))
}

/// Solves an independent `block` with the backend `wide`: none (having written nothing)
/// when its coefficients leave the checked bound ([`KernelFacts`]); else the narrow kernel
/// when the block's facts allow it and every value stays within its bound, else the wide
/// one; none (having written nothing) when a value leaves the wide bound too.
pub(super) fn solve_on<W: Kernels>(
    wide: W,
    block: &mut ContactBlock<Fx>,
    bodies: &mut [SolverBody<Fx>],
    pass: &SolvePass<Fx>,
) -> Option<Kernel> {
    if !block.kernel.in_bound {
        return None;
    }
    let narrow = block.kernel.narrow
        && if pass.use_bias {
            wide.solve_block::<false, true>(block, bodies, pass)
        } else {
            wide.solve_block::<true, true>(block, bodies, pass)
        };
    if narrow {
        return Some(Kernel::Narrow);
    }
    // A block that left the narrow bound (moving fast, pushing hard) is likely to leave it
    // again: the rest of the step goes straight to the wide kernel.
    block.kernel.narrow = false;
    let taken = if pass.use_bias {
        wide.solve_block::<false, false>(block, bodies, pass)
    } else {
        wide.solve_block::<true, false>(block, bodies, pass)
    };
    taken.then_some(Kernel::Wide)
}

/// Warm starts `block` with a kernel, under the same conditions as [`solve`], and tells
/// which kernel took it (none: nothing was written).
pub(super) fn warm_start<R: Real>(
    block: &mut ContactBlock<R>,
    bodies: &mut [SolverBody<R>],
) -> Option<Kernel> {
    let block = R::as_fixed_mut::<ContactBlockOf>(block)?;
    let bodies = R::as_fixed_mut::<SolverBodiesOf>(bodies)?;
    on_backend!(backend()?, wide => warm_start_on(wide, block, bodies))
}

/// Warm starts an independent `block` with the backend `wide`, under the conditions of
/// [`solve_on`], narrow first.
pub(super) fn warm_start_on<W: Kernels>(
    wide: W,
    block: &mut ContactBlock<Fx>,
    bodies: &mut [SolverBody<Fx>],
) -> Option<Kernel> {
    if !block.kernel.in_bound {
        return None;
    }
    if block.kernel.narrow && wide.warm_start_block::<true>(block, bodies) {
        return Some(Kernel::Narrow);
    }
    // As in `solve_on`: the rest of the step goes to the wide kernel.
    block.kernel.narrow = false;
    wide.warm_start_block::<false>(block, bodies)
        .then_some(Kernel::Wide)
}

/// The kernels of this module compiled for a backend: each one function, with the
/// backend's instructions enabled (the generic forms are always inlined into it).
pub(super) trait Kernels: WideBodies {
    /// [`solve_block`] with this backend.
    fn solve_block<const RELAX: bool, const NARROW: bool>(
        self,
        block: &mut ContactBlock<Fx>,
        bodies: &mut [SolverBody<Fx>],
        pass: &SolvePass<Fx>,
    ) -> bool;

    /// [`warm_start_block`] with this backend.
    fn warm_start_block<const NARROW: bool>(
        self,
        block: &ContactBlock<Fx>,
        bodies: &mut [SolverBody<Fx>],
    ) -> bool;

    /// [`facts`] with this backend.
    fn facts(self, block: &ContactBlock<Fx>) -> KernelFacts;

    /// [`prepare_block`](super::prepare_kernel::prepare_block) with this backend.
    fn prepare_block(
        self,
        block: &mut ContactBlock<Fx>,
        arms: &ContactArms<Fx>,
        bodies: &[SolverBody<Fx>],
    ) -> bool;
}

/// [`Kernels`] for a backend whose instructions are `$features`: each kernel an entry point
/// with them enabled, into which the generic form is inlined.
macro_rules! kernels_for {
    ($backend:ident, $features:literal) => {
        impl Kernels for $backend {
            #[inline]
            fn solve_block<const RELAX: bool, const NARROW: bool>(
                self,
                block: &mut ContactBlock<Fx>,
                bodies: &mut [SolverBody<Fx>],
                pass: &SolvePass<Fx>,
            ) -> bool {
                /// # Safety
                /// The processor must have the backend's instructions.
                #[target_feature(enable = $features)]
                unsafe fn entry<const RELAX: bool, const NARROW: bool>(
                    wide: $backend,
                    block: &mut ContactBlock<Fx>,
                    bodies: &mut [SolverBody<Fx>],
                    pass: &SolvePass<Fx>,
                ) -> bool {
                    solve_block::<$backend, RELAX, NARROW>(wide, block, bodies, pass)
                }
                // SAFETY: a value of the backend exists only where the processor has its
                // instructions.
                unsafe { entry::<RELAX, NARROW>(self, block, bodies, pass) }
            }

            #[inline]
            fn warm_start_block<const NARROW: bool>(
                self,
                block: &ContactBlock<Fx>,
                bodies: &mut [SolverBody<Fx>],
            ) -> bool {
                /// # Safety
                /// The processor must have the backend's instructions.
                #[target_feature(enable = $features)]
                unsafe fn entry<const NARROW: bool>(
                    wide: $backend,
                    block: &ContactBlock<Fx>,
                    bodies: &mut [SolverBody<Fx>],
                ) -> bool {
                    warm_start_block::<$backend, NARROW>(wide, block, bodies)
                }
                // SAFETY: as in `solve_block`.
                unsafe { entry::<NARROW>(self, block, bodies) }
            }

            #[inline]
            fn facts(self, block: &ContactBlock<Fx>) -> KernelFacts {
                /// # Safety
                /// The processor must have the backend's instructions.
                #[target_feature(enable = $features)]
                unsafe fn entry(wide: $backend, block: &ContactBlock<Fx>) -> KernelFacts {
                    facts(wide, block)
                }
                // SAFETY: as in `solve_block`.
                unsafe { entry(self, block) }
            }

            #[inline]
            fn prepare_block(
                self,
                block: &mut ContactBlock<Fx>,
                arms: &ContactArms<Fx>,
                bodies: &[SolverBody<Fx>],
            ) -> bool {
                /// # Safety
                /// The processor must have the backend's instructions.
                #[target_feature(enable = $features)]
                unsafe fn entry(
                    wide: $backend,
                    block: &mut ContactBlock<Fx>,
                    arms: &ContactArms<Fx>,
                    bodies: &[SolverBody<Fx>],
                ) -> bool {
                    super::prepare_kernel::prepare_block(wide, block, arms, bodies)
                }
                // SAFETY: as in `solve_block`.
                unsafe { entry(self, block, arms, bodies) }
            }
        }
    };
}

#[cfg(target_arch = "x86_64")]
kernels_for!(Avx512, "avx512f,avx512cd,avx512dq");
#[cfg(target_arch = "x86_64")]
kernels_for!(Avx2, "avx2");
#[cfg(target_arch = "aarch64")]
kernels_for!(Neon, "neon");
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
kernels_for!(Simd128, "simd128");

/// What the kernels need to know of a block's coefficients, which do not change during a
/// step: found once per step ([`KernelFacts::of`]).
#[derive(Clone, Copy, Debug)]
#[cfg_attr(test, derive(PartialEq))]
pub(super) struct KernelFacts {
    /// Whether every coefficient the passes read lies within the checked bound in the
    /// lanes and points in use (see the module documentation): the normal, tangents and
    /// their per-mass forms, the arms and their inertia products, the effective masses
    /// (rigid and soft), the separations at the start of the step, the twist arms and the
    /// friction coefficients. The kernels take only such blocks, and check only what
    /// changes: velocities, motions, impulses and what they compute.
    in_bound: bool,
    /// Whether, in every lane in use, n/m_a and t/m_a equal n/m_b and t/m_b or one side's
    /// are all zero (bodies of equal mass, or a body that does not move): then one product
    /// λ n/m (and λ t/m) serves both sides, A's where B's are zero.
    pub(super) linear_shared: bool,
    /// The lanes whose side A (B) has a nonzero n/m or t/m: the lanes where a shared
    /// product changes that side's velocity.
    moving_a: u8,
    moving_b: u8,
    /// Whether every velocity change per unit impulse (n/m, t/m, I⁻¹(r × n), I⁻¹(r × t),
    /// I⁻¹n) lies within the narrow bound [−2³¹, 2³¹) in the lanes and points in use
    /// (bodies heavier than 2 kg, with inertias to match): then the kernels try narrow
    /// products ([`Wide::times`](crate::math::wide::Wide::times)) first. Cleared for the rest of the step when they fail.
    narrow: bool,
}

impl KernelFacts {
    /// Facts of a block the kernels do not take.
    pub(super) const NONE: Self = Self {
        in_bound: false,
        linear_shared: false,
        moving_a: 0,
        moving_b: 0,
        narrow: false,
    };

    /// The facts of `block`, complete for the step; [`NONE`](Self::NONE) when `R` is not
    /// I32F32 or the processor has neither AVX-512 nor AVX2.
    pub(super) fn of<R: Real>(block: &ContactBlock<R>) -> Self {
        let Some(block) = R::as_fixed::<ContactBlockOf>(block) else {
            return Self::NONE;
        };
        match backend() {
            Some(backend) => on_backend!(backend, wide => wide.facts(block)),
            None => Self::NONE,
        }
    }
}

/// [`KernelFacts::of`] for I32F32, with the backend `wide`.
#[inline(always)]
fn facts<W: WideBodies>(w: W, block: &ContactBlock<Fx>) -> KernelFacts {
    let active = ((1u16 << block.len) - 1) as u8;
    let f = &block.friction_rows;
    let mut bad = (vectors_out_of_bound(
        w,
        &[
            &block.normal,
            &block.normal_a,
            &block.normal_b,
            &block.tangents[0],
            &block.tangents[1],
            &block.tangents_a[0],
            &block.tangents_a[1],
            &block.tangents_b[0],
            &block.tangents_b[1],
            &f.rt_a[0],
            &f.rt_a[1],
            &f.rt_b[0],
            &f.rt_b[1],
            &f.it_a[0],
            &f.it_a[1],
            &f.it_b[0],
            &f.it_b[1],
            &f.twist_a,
            &f.twist_b,
        ],
    ) | scalars_out_of_bound(
        w,
        &[
            &block.friction,
            &f.tangent_mass[0],
            &f.tangent_mass[1],
            &f.twist_mass,
        ],
    )) & active;
    let counts = counts_of(w, block);
    for (k, cp) in block.points.iter().enumerate() {
        bad |= (vectors_out_of_bound(w, &[&cp.rn_a, &cp.rn_b, &cp.in_a, &cp.in_b])
            | scalars_out_of_bound(
                w,
                &[
                    &cp.normal_mass,
                    &cp.soft_normal_mass,
                    &cp.base_separation,
                    &cp.twist_arm,
                ],
            ))
            & points_in_use(w, counts, active, k);
    }
    // The lanes where every component of the side's n/m and t/m is zero, and where the
    // two sides' are equal.
    let side_a = [
        w.load3(&block.normal_a),
        w.load3(&block.tangents_a[0]),
        w.load3(&block.tangents_a[1]),
    ];
    let side_b = [
        w.load3(&block.normal_b),
        w.load3(&block.tangents_b[0]),
        w.load3(&block.tangents_b[1]),
    ];
    let zero = w.zero();
    let mut still_a = active;
    let mut still_b = active;
    let mut equal = active;
    for i in 0..3 {
        for j in 0..3 {
            let (a, b) = (side_a[i][j], side_b[i][j]);
            still_a &= w.equal(a, zero);
            still_b &= w.equal(b, zero);
            equal &= w.equal(a, b);
        }
    }
    // The velocity changes per unit impulse, against the narrow bound.
    let mut wide = vectors_beyond_narrow(
        w,
        &[
            &block.normal_a,
            &block.normal_b,
            &block.tangents_a[0],
            &block.tangents_a[1],
            &block.tangents_b[0],
            &block.tangents_b[1],
            &f.it_a[0],
            &f.it_a[1],
            &f.it_b[0],
            &f.it_b[1],
            &f.twist_a,
            &f.twist_b,
        ],
    ) & active;
    for (k, cp) in block.points.iter().enumerate() {
        wide |=
            vectors_beyond_narrow(w, &[&cp.in_a, &cp.in_b]) & points_in_use(w, counts, active, k);
    }
    KernelFacts {
        in_bound: bad == 0,
        linear_shared: (still_a | still_b | equal) & active == active,
        moving_a: active & !still_a,
        moving_b: active & !still_b,
        narrow: wide == 0,
    }
}

/// Velocity changes per unit impulse of a block's lanes on each side, n/m (K = 1) or t₁/m
/// and t₂/m (K = 2), and how a product with them reaches the two sides. Each set is loaded
/// where its rows begin, so that it holds no registers before.
struct Linear<W: WideBodies, const K: usize> {
    /// Per side (A, B), the K coefficient vectors, or the shared ones on both sides.
    sides: [[[W::V; 3]; K]; 2],
    /// The lanes each side moves in when the coefficients are shared
    /// ([`KernelFacts::linear_shared`]).
    shared: Option<(u8, u8)>,
}

impl<W: WideBodies> Linear<W, 1> {
    /// n/m_a and n/m_b of `block` ([`Linear::of`]).
    #[inline(always)]
    fn normal(w: W, block: &ContactBlock<Fx>) -> Self {
        Self::of(w, &block.kernel, [&block.normal_a], [&block.normal_b])
    }
}

impl<W: WideBodies> Linear<W, 2> {
    /// t₁/m_a, t₂/m_a and t₁/m_b, t₂/m_b of `block` ([`Linear::of`]).
    #[inline(always)]
    fn tangents(w: W, block: &ContactBlock<Fx>) -> Self {
        let [a1, a2] = &block.tangents_a;
        let [b1, b2] = &block.tangents_b;
        Self::of(w, &block.kernel, [a1, a2], [b1, b2])
    }
}

impl<W: WideBodies, const K: usize> Linear<W, K> {
    /// The coefficients `a` and `b` of the two sides: when they are shared (`facts`), B's
    /// where B moves and A's elsewhere (where B's are zero), for both sides.
    #[inline(always)]
    fn of(w: W, facts: &KernelFacts, a: [&Lanes3<Fx>; K], b: [&Lanes3<Fx>; K]) -> Self {
        let mut side_a = [[w.zero(); 3]; K];
        let mut side_b = [[w.zero(); 3]; K];
        for j in 0..K {
            side_a[j] = w.load3(a[j]);
            side_b[j] = w.load3(b[j]);
        }
        if !facts.linear_shared {
            return Self {
                sides: [side_a, side_b],
                shared: None,
            };
        }
        let mut shared = [[w.zero(); 3]; K];
        for j in 0..K {
            shared[j] = w.select3(facts.moving_b, side_b[j], side_a[j]);
        }
        Self {
            sides: [shared; 2],
            shared: Some((facts.moving_a, facts.moving_b)),
        }
    }

    /// (Δv_a, Δv_b) = (Σⱼ λⱼ cⱼ,a, Σⱼ λⱼ cⱼ,b), each product rounded as `Vec3 * R`.
    #[inline(always)]
    fn changes<const NARROW: bool>(&self, w: W, impulses: [W::V; K]) -> ([W::V; 3], [W::V; 3]) {
        match self.shared {
            Some((moving_a, moving_b)) => {
                let change = combine::<W, NARROW, K>(w, self.sides[0], impulses);
                (w.keep3(moving_a, change), w.keep3(moving_b, change))
            }
            None => (
                combine::<W, NARROW, K>(w, self.sides[0], impulses),
                combine::<W, NARROW, K>(w, self.sides[1], impulses),
            ),
        }
    }
}

/// The warm start kernel: per point, v_a −= λ_n n/m_a, ω_a −= λ_n I_a⁻¹(r_a × n), and the
/// opposite on B; then per lane the friction impulses, v_a −= λ₁ t₁/m_a + λ₂ t₂/m_a,
/// ω_a −= λ₁ I_a⁻¹(r_a × t₁) + λ₂ I_a⁻¹(r_a × t₂) + λ_twist I_a⁻¹n, and the opposite on B,
/// as in [`ContactBlock::warm_start`] (zero impulses add zero, the same as skipping them).
/// Narrow or wide products ([`Wide::times`](crate::math::wide::Wide::times)); the velocities, which enter no product here,
/// are checked against the wide bound when loaded, either way, and not after each impulse
/// (see the module documentation). Returns false, having written nothing, when a value
/// leaves its checked bound in a lane in use.
#[inline(always)]
fn warm_start_block<W: WideBodies, const NARROW: bool>(
    w: W,
    block: &ContactBlock<Fx>,
    bodies: &mut [SolverBody<Fx>],
) -> bool {
    let Some(lanes) = BodyLanes::new(block, bodies) else {
        return false;
    };
    let active = lanes.active;
    let (mut side_a, mut side_b) = lanes.load(w, bodies, false);
    // Warm starting only adds to the velocities: they need the wide bound, whatever the
    // products.
    let mut bad = side_a.beyond::<false>(w) | side_b.beyond::<false>(w);
    let zero = w.zero();
    let normal_linear = Linear::normal(w, block);
    let counts = counts_of(w, block);
    for (k, cp) in block.points.iter().enumerate() {
        let in_use = w.greater(counts, w.splat(k as i64)) & active;
        if in_use == 0 {
            continue;
        }
        let n = w.select(in_use, w.load(&cp.normal_impulse), zero);
        let (in_a, in_b) = (w.load3(&cp.in_a), w.load3(&cp.in_b));
        bad |= w.out_of_bound(n) & in_use;
        let (dv_a, dv_b) = normal_linear.changes::<NARROW>(w, [n]);
        Side::exchange(
            w,
            (&mut side_a, &mut side_b),
            [
                dv_a,
                w.times3::<NARROW>(in_a, n),
                dv_b,
                w.times3::<NARROW>(in_b, n),
            ],
        );
        if bad != 0 {
            return false;
        }
    }
    let f = &block.friction_rows;
    let it_a = [w.load3(&f.it_a[0]), w.load3(&f.it_a[1])];
    let it_b = [w.load3(&f.it_b[0]), w.load3(&f.it_b[1])];
    let (twist_a, twist_b) = (w.load3(&f.twist_a), w.load3(&f.twist_b));
    let t = [
        w.select(active, w.load(&f.tangent_impulse[0]), zero),
        w.select(active, w.load(&f.tangent_impulse[1]), zero),
    ];
    let twist = w.select(active, w.load(&f.twist_impulse), zero);
    bad |= (w.out_of_bound(t[0]) | w.out_of_bound(t[1]) | w.out_of_bound(twist)) & active;
    let (dv_a, dv_b) = Linear::tangents(w, block).changes::<NARROW>(w, t);
    Side::exchange(
        w,
        (&mut side_a, &mut side_b),
        [
            dv_a,
            w.add3(
                combine::<W, NARROW, 2>(w, it_a, t),
                w.times3::<NARROW>(twist_a, twist),
            ),
            dv_b,
            w.add3(
                combine::<W, NARROW, 2>(w, it_b, t),
                w.times3::<NARROW>(twist_b, twist),
            ),
        ],
    );
    if bad != 0 {
        return false;
    }
    lanes.store(w, bodies, &side_a, &side_b);
    true
}

/// The velocities and motions of the lanes' bodies on one side.
struct Side<W: WideBodies> {
    v: [W::V; 3],
    w: [W::V; 3],
    dp: [W::V; 3],
    dtheta: [W::V; 3],
}

impl<W: WideBodies> Side<W> {
    /// Applies an impulse's velocity changes, A losing and B gaining:
    /// v_a −= Δv_a, ω_a −= Δω_a, v_b += Δv_b, ω_b += Δω_b. The new velocities are not
    /// checked: a velocity that enters products later is checked there ([`Side::spin_beyond`]
    /// and the relative velocity), and the sums are exact (see the module documentation).
    #[inline(always)]
    fn exchange(w: W, (a, b): (&mut Self, &mut Self), [dv_a, dw_a, dv_b, dw_b]: [[W::V; 3]; 4]) {
        a.v = w.sub3(a.v, dv_a);
        a.w = w.sub3(a.w, dw_a);
        b.v = w.add3(b.v, dv_b);
        b.w = w.add3(b.w, dw_b);
    }

    /// The lanes where an angular velocity of either side, a factor of the next row's
    /// products ω·(r × n) and ω·(r × t), lies outside the bound of changing values
    /// ([`Wide::beyond`](crate::math::wide::Wide::beyond)).
    #[inline(always)]
    fn spin_beyond<const NARROW: bool>(w: W, a: &Self, b: &Self) -> u8 {
        w.beyond3::<NARROW>(a.w) | w.beyond3::<NARROW>(b.w)
    }

    /// The lanes where a value lies outside the bound of changing values
    /// ([`Wide::beyond`](crate::math::wide::Wide::beyond)).
    #[inline(always)]
    fn beyond<const NARROW: bool>(&self, w: W) -> u8 {
        w.beyond3::<NARROW>(self.v)
            | w.beyond3::<NARROW>(self.w)
            | w.beyond3::<NARROW>(self.dp)
            | w.beyond3::<NARROW>(self.dtheta)
    }
}

/// Where the bodies of a block's lanes are.
struct BodyLanes {
    /// The lanes in use: the first `len` of the block.
    active: u8,
    /// The indices of each lane's body A and body B (checked in the lanes in use).
    a: [u32; LANES],
    b: [u32; LANES],
}

impl BodyLanes {
    /// The bodies of `block`'s lanes in `bodies`, or `None` if the index of a lane in use
    /// is out of bounds.
    #[inline(always)]
    fn new(block: &ContactBlock<Fx>, bodies: &[SolverBody<Fx>]) -> Option<Self> {
        let inside = |indices: &[u32; LANES]| {
            indices[..block.len]
                .iter()
                .all(|&i| (i as usize) < bodies.len())
        };
        (inside(&block.a) && inside(&block.b)).then_some(Self {
            active: ((1u16 << block.len) - 1) as u8,
            a: block.a,
            b: block.b,
        })
    }

    /// The two sides' bodies, with their motions when `with_motion`.
    #[inline(always)]
    fn load<W: WideBodies>(
        &self,
        w: W,
        bodies: &[SolverBody<Fx>],
        with_motion: bool,
    ) -> (Side<W>, Side<W>) {
        // SAFETY: `new` checked the index of every lane in use against these bodies (the
        // kernels keep the same slice throughout).
        let [[a_v, a_w, a_dp, a_dtheta], [b_v, b_w, b_dp, b_dtheta]] = unsafe {
            [
                w.load_bodies(bodies, &self.a, self.active, with_motion),
                w.load_bodies(bodies, &self.b, self.active, with_motion),
            ]
        };
        (
            Side {
                v: a_v,
                w: a_w,
                dp: a_dp,
                dtheta: a_dtheta,
            },
            Side {
                v: b_v,
                w: b_w,
                dp: b_dp,
                dtheta: b_dtheta,
            },
        )
    }

    /// Writes both sides' velocities back. Lanes that share a body share it only when it
    /// does not move, and then write the values they read.
    #[inline(always)]
    fn store<W: WideBodies>(&self, w: W, bodies: &mut [SolverBody<Fx>], a: &Side<W>, b: &Side<W>) {
        // SAFETY: as in `load`.
        unsafe {
            w.store_velocities(bodies, &self.a, self.active, [a.v, a.w]);
            w.store_velocities(bodies, &self.b, self.active, [b.v, b.w]);
        }
    }
}

/// The kernel, for the biased pass or (`RELAX`) the relax pass, with narrow or wide
/// products ([`Wide::times`](crate::math::wide::Wide::times)). Returns false, having written nothing, when a value leaves
/// its checked bound in a lane in use.
///
/// The biased pass reads the separations the block keeps; the relax pass computes them
/// from the bodies' motions and keeps them (as [`ContactBlock::solve_lanes`] does).
#[inline(always)]
fn solve_block<W: WideBodies, const RELAX: bool, const NARROW: bool>(
    w: W,
    block: &mut ContactBlock<Fx>,
    bodies: &mut [SolverBody<Fx>],
    pass: &SolvePass<Fx>,
) -> bool {
    let Some(lanes) = BodyLanes::new(block, bodies) else {
        return false;
    };
    let active = lanes.active;
    let (mut side_a, mut side_b) = lanes.load(w, bodies, RELAX);
    let mut bad = side_a.beyond::<NARROW>(w) | side_b.beyond::<NARROW>(w);
    if bad != 0 {
        return false;
    }

    let zero = w.zero();
    let rigid_partner = block
        .rigid_partner
        .iter()
        .enumerate()
        .fold(0u8, |mask, (l, &rigid)| mask | (u8::from(rigid) << l));
    let bias_rate = w.select(
        rigid_partner,
        w.splat(pass.soft_static.bias_rate.to_bits()),
        w.splat(pass.soft.bias_rate.to_bits()),
    );
    let impulse_scale = w.select(
        rigid_partner,
        w.splat(pass.soft_static.impulse_scale.to_bits()),
        w.splat(pass.soft.impulse_scale.to_bits()),
    );
    let inv_h = w.splat(pass.inv_h.to_bits());
    let lowest_bias = w.splat((-pass.max_push).to_bits());
    bad |= (w.out_of_bound(bias_rate)
        | w.beyond::<NARROW>(impulse_scale)
        | w.out_of_bound(inv_h)
        | w.out_of_bound(lowest_bias))
        & active;

    let normal = w.load3(&block.normal);
    let normal_linear = Linear::normal(w, block);
    let counts = counts_of(w, block);

    // Normal impulses. In the relax pass the separations first, from the motions, which it
    // then no longer needs; the biased pass reads the block's with each row.
    let mut separations = [zero; 4];
    if RELAX {
        let moved = w.sub3(side_b.dp, side_a.dp);
        bad |= w.beyond3::<NARROW>(moved) & active;
        let moved_apart = w.dot::<NARROW>(moved, normal);
        for (k, cp) in block.points.iter().enumerate() {
            let in_use = points_in_use(w, counts, active, k);
            if in_use == 0 {
                continue;
            }
            let (rn_a, rn_b) = (w.load3(&cp.rn_a), w.load3(&cp.rn_b));
            let base_separation = w.load(&cp.base_separation);
            let s = w.sub(
                w.add(
                    w.add(base_separation, moved_apart),
                    w.dot::<NARROW>(side_b.dtheta, rn_b),
                ),
                w.dot::<NARROW>(side_a.dtheta, rn_a),
            );
            bad |= w.beyond::<NARROW>(s) & in_use;
            separations[k] = s;
        }
    }
    let mut normal_impulses = [zero; 4];
    let mut max_normal_impulses = [zero; 4];
    for (k, cp) in block.points.iter().enumerate() {
        let in_use = points_in_use(w, counts, active, k);
        if in_use == 0 {
            // No lane has this point (nor the next ones): nothing to solve or store.
            continue;
        }
        let (rn_a, rn_b) = (w.load3(&cp.rn_a), w.load3(&cp.rn_b));
        let normal_mass = w.load(&cp.normal_mass);
        let old = w.load(&cp.normal_impulse);
        let old_max = w.load(&cp.max_normal_impulse);
        bad |= (w.out_of_bound(old) | w.out_of_bound(old_max)) & in_use;
        // The biased pass reads each point's kept separation with its row.
        let s = if RELAX {
            separations[k]
        } else {
            let s = w.load(&cp.separation);
            bad |= w.beyond::<NARROW>(s) & in_use;
            s
        };
        let apart = w.greater(s, zero);
        // s/h for the points still apart (s·inv_h is only computed when there are some).
        let speculative_bias = if apart & in_use != 0 {
            w.times::<NARROW>(s, inv_h)
        } else {
            zero
        };
        let dv = w.sub3(side_b.v, side_a.v);
        bad |= w.beyond3::<NARROW>(dv) & in_use;
        let vn = w.sub(
            w.add(w.dot::<NARROW>(dv, normal), w.dot::<NARROW>(side_b.w, rn_b)),
            w.dot::<NARROW>(side_a.w, rn_a),
        );
        let impulse = if RELAX {
            let biased = w.add(vn, w.select(apart, speculative_bias, zero));
            bad |= w.out_of_bound(biased) & in_use;
            w.sub(zero, w.mul(normal_mass, biased))
        } else {
            let soft_mass = w.load(&cp.soft_normal_mass);
            let soft_bias = w.max(w.times::<NARROW>(s, bias_rate), lowest_bias);
            let biased = w.add(vn, w.select(apart, speculative_bias, soft_bias));
            let mass = w.select(apart, normal_mass, soft_mass);
            let scale_impulse = w.select(apart, zero, impulse_scale);
            bad |= w.out_of_bound(biased) & in_use;
            w.sub(
                w.sub(zero, w.mul(mass, biased)),
                w.times::<NARROW>(scale_impulse, old),
            )
        };
        let new = w.max(w.add(old, impulse), zero);
        let applied = w.select(in_use, w.sub(new, old), zero);
        bad |= w.out_of_bound(applied) & in_use;
        let (dv_a, dv_b) = normal_linear.changes::<NARROW>(w, [applied]);
        Side::exchange(
            w,
            (&mut side_a, &mut side_b),
            [
                dv_a,
                w.times3::<NARROW>(w.load3(&cp.in_a), applied),
                dv_b,
                w.times3::<NARROW>(w.load3(&cp.in_b), applied),
            ],
        );
        bad |= Side::spin_beyond::<NARROW>(w, &side_a, &side_b) & active;
        normal_impulses[k] = w.select(in_use, new, old);
        max_normal_impulses[k] = w.select(in_use, w.max(old_max, applied), old_max);
        if bad != 0 {
            return false;
        }
    }

    // Friction: the lane's total normal impulse Λ = Σ λ_n,k and Σ λ_n,k d_k, then the two
    // tangent rows and the twist row.
    let f = &block.friction_rows;
    // Lanes of one point have no twist row.
    let twisting = points_in_use(w, counts, active, 1);
    let mut normal_sum = zero;
    let mut twist_sum = zero;
    for (k, cp) in block.points.iter().enumerate() {
        let in_use = points_in_use(w, counts, active, k);
        if in_use == 0 {
            continue;
        }
        let impulse = w.select(in_use, normal_impulses[k], zero);
        bad |= w.out_of_bound(impulse) & in_use;
        normal_sum = w.add(normal_sum, impulse);
        if twisting != 0 {
            let arm = w.select(in_use, w.load(&cp.twist_arm), zero);
            twist_sum = w.add(twist_sum, w.mul(impulse, arm));
        }
    }
    let friction = w.load(&block.friction);
    let old = [w.load(&f.tangent_impulse[0]), w.load(&f.tangent_impulse[1])];
    let old_twist = w.load(&f.twist_impulse);
    let resting = w.equal(normal_sum, zero)
        & w.equal(old[0], zero)
        & w.equal(old[1], zero)
        & w.equal(old_twist, zero);
    let in_use = active & !resting;
    let mut tangent_impulses = old;
    let mut twist_impulses = old_twist;
    if in_use != 0 {
        bad |= (w.out_of_bound(normal_sum)
            | w.out_of_bound(twist_sum)
            | w.out_of_bound(old[0])
            | w.out_of_bound(old[1])
            | w.out_of_bound(old_twist))
            & in_use;
        let dv = w.sub3(side_b.v, side_a.v);
        bad |= w.beyond3::<NARROW>(dv) & in_use;
        let mut new = [zero; 2];
        // Each row's coefficients are loaded where they are used, to spare registers.
        for j in 0..2 {
            let vt = w.sub(
                w.add(
                    w.dot::<NARROW>(dv, w.load3(&block.tangents[j])),
                    w.dot::<NARROW>(side_b.w, w.load3(&f.rt_b[j])),
                ),
                w.dot::<NARROW>(side_a.w, w.load3(&f.rt_a[j])),
            );
            bad |= w.out_of_bound(vt) & in_use;
            new[j] = w.sub(old[j], w.mul(w.load(&f.tangent_mass[j]), vt));
        }
        let limit = w.mul(friction, normal_sum);
        bad |= (w.out_of_bound(new[0]) | w.out_of_bound(new[1]) | w.out_of_bound(limit)) & in_use;
        if bad != 0 {
            return false;
        }
        let length_squared = w.add(w.mul(new[0], new[0]), w.mul(new[1], new[1]));
        let outside = w.greater(length_squared, w.mul(limit, limit)) & in_use;
        if outside != 0 {
            let [mut first, mut second, mut limits, mut lengths] = [[Fx::ZERO; LANES]; 4];
            w.store(&mut first, new[0]);
            w.store(&mut second, new[1]);
            w.store(&mut limits, limit);
            w.store(&mut lengths, length_squared);
            clamp_to_cone(outside, [&mut first, &mut second], &limits, &lengths);
            new = [w.load(&first), w.load(&second)];
        }
        let applied = [
            w.select(in_use, w.sub(new[0], old[0]), zero),
            w.select(in_use, w.sub(new[1], old[1]), zero),
        ];
        bad |= (w.out_of_bound(applied[0]) | w.out_of_bound(applied[1])) & in_use;
        let (dv_a, dv_b) = Linear::tangents(w, block).changes::<NARROW>(w, applied);
        Side::exchange(
            w,
            (&mut side_a, &mut side_b),
            [
                dv_a,
                combine::<W, NARROW, 2>(w, [w.load3(&f.it_a[0]), w.load3(&f.it_a[1])], applied),
                dv_b,
                combine::<W, NARROW, 2>(w, [w.load3(&f.it_b[0]), w.load3(&f.it_b[1])], applied),
            ],
        );
        // The twist row reads the angular velocities only through ω_b − ω_a, checked there.
        tangent_impulses = [
            w.select(in_use, new[0], old[0]),
            w.select(in_use, new[1], old[1]),
        ];

        let in_use = in_use & twisting;
        if in_use != 0 {
            let twist_limit = w.mul(friction, twist_sum);
            let spin_rate = w.sub3(side_b.w, side_a.w);
            bad |= (w.out_of_bound(twist_limit) | w.beyond3::<NARROW>(spin_rate)) & in_use;
            let spin = w.dot::<NARROW>(spin_rate, normal);
            bad |= w.out_of_bound(spin) & in_use;
            let unclamped = w.sub(old_twist, w.mul(w.load(&f.twist_mass), spin));
            let new_twist = w.min(w.max(unclamped, w.sub(zero, twist_limit)), twist_limit);
            let applied = w.select(in_use, w.sub(new_twist, old_twist), zero);
            bad |= w.out_of_bound(applied) & in_use;
            // The last row: its velocities enter no product in this pass.
            Side::exchange(
                w,
                (&mut side_a, &mut side_b),
                [
                    [zero; 3],
                    w.times3::<NARROW>(w.load3(&f.twist_a), applied),
                    [zero; 3],
                    w.times3::<NARROW>(w.load3(&f.twist_b), applied),
                ],
            );
            if bad != 0 {
                return false;
            }
            twist_impulses = w.select(in_use, new_twist, old_twist);
        }
    }
    if bad != 0 {
        return false;
    }

    for (k, cp) in block.points.iter_mut().enumerate() {
        let in_use = points_in_use(w, counts, active, k);
        if in_use == 0 {
            continue;
        }
        w.store(&mut cp.normal_impulse, normal_impulses[k]);
        w.store(&mut cp.max_normal_impulse, max_normal_impulses[k]);
        if RELAX {
            w.store_lanes(&mut cp.separation, in_use, separations[k]);
        }
    }
    let f = &mut block.friction_rows;
    w.store(&mut f.tangent_impulse[0], tangent_impulses[0]);
    w.store(&mut f.tangent_impulse[1], tangent_impulses[1]);
    w.store(&mut f.twist_impulse, twist_impulses);
    lanes.store(w, bodies, &side_a, &side_b);
    true
}

/// The tangent impulses `new` of the `outside` lanes scaled back onto the cone's edge,
/// λ ← λ · (limit / |λ|), with the checked operators as in the lane-by-lane solve.
#[inline(never)]
fn clamp_to_cone(
    outside: u8,
    new: [&mut Lanes<Fx>; 2],
    limits: &Lanes<Fx>,
    lengths_squared: &Lanes<Fx>,
) {
    let [first, second] = new;
    for l in 0..LANES {
        if outside & (1 << l) != 0 {
            let scale = limits[l] * lengths_squared[l].rsqrt();
            first[l] *= scale;
            second[l] *= scale;
        }
    }
}

/// The points in use of each lane, as lanes.
#[inline(always)]
pub(super) fn counts_of<W: WideBodies>(w: W, block: &ContactBlock<Fx>) -> W::V {
    let mut counts = [0; LANES];
    for (count, &points) in counts.iter_mut().zip(&block.count) {
        *count = i64::from(points);
    }
    w.load_words(counts)
}

/// The lanes where lane `k` has a point: k < its count, among `active`.
#[inline(always)]
pub(super) fn points_in_use<W: WideBodies>(w: W, counts: W::V, active: u8, k: usize) -> u8 {
    w.greater(counts, w.splat(k as i64)) & active
}

/// a₁λ₁ + … + a_Kλ_K for K vectors of coefficients and K impulses ([`Wide::times`](crate::math::wide::Wide::times)),
/// summed in that order.
#[inline(always)]
fn combine<W: WideBodies, const NARROW: bool, const K: usize>(
    w: W,
    a: [[W::V; 3]; K],
    impulses: [W::V; K],
) -> [W::V; 3] {
    let mut sum = w.times3::<NARROW>(a[0], impulses[0]);
    for j in 1..K {
        sum = w.add3(sum, w.times3::<NARROW>(a[j], impulses[j]));
    }
    sum
}

/// The lanes where a component of one of `vectors` lies outside [−2⁴⁶, 2⁴⁶).
#[inline(always)]
fn vectors_out_of_bound<W: WideBodies>(w: W, vectors: &[&Lanes3<Fx>]) -> u8 {
    let mut bad = 0;
    for v in vectors {
        bad |= w.out_of_bound3(w.load3(v));
    }
    bad
}

/// The lanes where one of `scalars` lies outside [−2⁴⁶, 2⁴⁶).
#[inline(always)]
fn scalars_out_of_bound<W: WideBodies>(w: W, scalars: &[&Lanes<Fx>]) -> u8 {
    let mut bad = 0;
    for x in scalars {
        bad |= w.out_of_bound(w.load(x));
    }
    bad
}

/// The lanes where a component of one of `vectors` lies outside [−2³¹, 2³¹).
#[inline(always)]
fn vectors_beyond_narrow<W: WideBodies>(w: W, vectors: &[&Lanes3<Fx>]) -> u8 {
    let mut wide = 0;
    for v in vectors {
        wide |= w.beyond3::<true>(w.load3(v));
    }
    wide
}
