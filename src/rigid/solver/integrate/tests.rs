//! The orientation kernel against [`Quat::integrate`]: with each backend the processor has,
//! whichever lanes it takes, the bits are those of the scalar update, body by body.

use crate::math::cpu::kernels_present;
use crate::math::saturation::count_saturations;
use crate::math::{Fx, Pcg32, Quat, Real, Vec3};
use crate::rigid::solver::body::SolverBody;
use crate::rigid::solver::lanes::LANES;

/// A value in [−scale, scale).
fn value(rng: &mut Pcg32, scale: f64) -> Fx // ok-det: test input
{
    rng.range(Fx::from_f64(-scale), Fx::from_f64(scale))
}

/// A rotation, its components moved by up to `drift` each (so that some are not quite
/// unit length).
fn orientation(rng: &mut Pcg32, drift: f64) -> Quat<Fx> // ok-det: test input
{
    let angle = value(rng, 3.0);
    let q = Quat::from_axis_angle(rng.unit_vector(), angle);
    Quat::new(
        q.w + value(rng, drift),
        q.x + value(rng, drift),
        q.y + value(rng, drift),
        q.z + value(rng, drift),
    )
}

/// Runs `trials` chunks of up to [`LANES`] bodies, with angular velocities up to `spin`
/// (rad/s; one body in five at rest) and orientations off unit length by up to `drift`,
/// through the kernel, the lanes it leaves through [`Quat::integrate`], and all of them
/// through [`Quat::integrate`]; asserts the same bits and no saturation difference, and
/// returns how many lanes the kernel integrated.
fn compare(seed: u64, trials: usize, spin: f64, drift: f64) -> usize // ok-det: test input
{
    let mut rng = Pcg32::new(seed, 13);
    let h = Fx::from_ratio(1, 300);
    let mut taken = 0;
    for trial in 0..trials {
        let count = 1 + trial % LANES;
        let mut bodies = Vec::new();
        let mut orientations = Vec::new();
        for l in 0..count {
            let w = if l % 5 == 4 {
                Vec3::ZERO
            } else {
                Vec3::new(
                    value(&mut rng, spin),
                    value(&mut rng, spin),
                    value(&mut rng, spin),
                )
            };
            bodies.push(SolverBody {
                w,
                ..SolverBody::default()
            });
            orientations.push(orientation(&mut rng, drift));
        }
        // Slots in reverse, to check the mapping from lanes to slots.
        let slots: Vec<u32> = (0..count as u32).rev().collect();
        let mut expected = orientations.clone();
        let ((), slow_saturations) = count_saturations(|| {
            for (body, &slot) in bodies.iter().zip(&slots) {
                let q = &mut expected[slot as usize];
                if body.w != Vec3::ZERO {
                    *q = q.integrate(body.w, h);
                }
            }
        });
        let mut fast = orientations.clone();
        let (done, fast_saturations) = count_saturations(|| {
            let done = kernel(&bodies, &slots, &mut fast, h);
            for (l, (body, &slot)) in bodies.iter().zip(&slots).enumerate() {
                let q = &mut fast[slot as usize];
                if done & (1 << l) == 0 && body.w != Vec3::ZERO {
                    *q = q.integrate(body.w, h);
                }
            }
            done
        });
        assert_eq!(fast, expected, "trial {trial}");
        assert_eq!(fast_saturations, slow_saturations, "trial {trial}");
        let spinning = bodies.iter().enumerate().filter(|(_, b)| b.w != Vec3::ZERO);
        taken += spinning.filter(|&(l, _)| done & (1 << l) != 0).count();
    }
    taken
}

/// The kernel on a chunk: the lanes it is done with.
#[cfg(vector_kernels)]
fn kernel(bodies: &[SolverBody<Fx>], slots: &[u32], orientations: &mut [Quat<Fx>], h: Fx) -> u8 {
    super::kernel::integrate_orientations(bodies, slots, orientations, h)
}

#[cfg(not(vector_kernels))]
fn kernel(_: &[SolverBody<Fx>], _: &[u32], _: &mut [Quat<Fx>], _: Fx) -> u8 {
    0
}

/// [`compare`] with each backend the processor has (once, with none, off x86_64): the
/// fewest lanes a backend took.
fn compare_backends(seed: u64, trials: usize, spin: f64, drift: f64) -> usize // ok-det: test input
{
    #[cfg(vector_kernels)]
    {
        use crate::math::wide::{backends, with_backend};
        let mut fewest = usize::MAX;
        for backend in backends() {
            let taken = with_backend(Some(backend), || compare(seed, trials, spin, drift));
            fewest = fewest.min(taken);
        }
        if fewest != usize::MAX {
            return fewest;
        }
    }
    compare(seed, trials, spin, drift)
}

#[test]
fn rotations_near_unit_length_match_quat_integrate() {
    // Up to 5 rad/s in each axis: turns of up to 0.03 rad per substep, well inside the
    // near-unit path.
    let taken = compare_backends(1, 400, 5.0, 1.0e-6);
    if kernels_present() {
        // About 1,440 spinning bodies, all within the kernel's reach.
        assert!(taken > 1400, "the kernel took {taken} lanes");
    }
}

#[test]
fn rotations_off_unit_length_match_quat_integrate() {
    // Spins up to 20 rad/s and components off by up to 10⁻³: some past the near-unit test,
    // which the kernel leaves.
    let taken = compare_backends(2, 400, 20.0, 1.0e-3);
    if kernels_present() {
        assert!(taken > 0, "the kernel took no lane");
    }
}

#[test]
fn fast_spins_and_huge_values_match_quat_integrate() {
    // Up to 10⁶ rad/s: ω past the kernel's bound in some lanes, and turns of many radians
    // per substep, far from unit length.
    compare_backends(3, 200, 1.0e6, 1.0e-6);
}
