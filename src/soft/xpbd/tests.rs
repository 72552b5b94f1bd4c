//! The prediction and the velocity update against their scalar forms, vertex by vertex:
//! whichever path a block of vertices takes (the kernels, with every backend the processor
//! has, the scalar step for the blocks that fail a check and the tail), the bits and the
//! saturation count are the scalar step's.

use super::{Motion, Vertices, predict_vertex, update_velocity};
use crate::math::saturation::count_saturations;
use crate::math::{Fx, Pcg32, Real, Vec3};

/// A value in [−scale, scale).
fn value(rng: &mut Pcg32, scale: f64) -> Fx // ok-det: test input
{
    rng.range(Fx::from_f64(-scale), Fx::from_f64(scale))
}

/// A vector up to `scale`, one component in twenty at an end of the format.
fn vector(rng: &mut Pcg32, scale: f64) -> Vec3<Fx> // ok-det: test input
{
    let mut component = || match rng.below(20) {
        0 => [Fx::MAX, Fx::MIN][rng.below(2) as usize],
        _ => value(rng, scale),
    };
    Vec3::new(component(), component(), component())
}

/// `count` vertices up to `scale`, every sixth one pinned.
fn arrays(rng: &mut Pcg32, count: usize, scale: f64) -> [Vec<Vec3<Fx>>; 3] // ok-det: test input
{
    let mut vectors = || (0..count).map(|_| vector(rng, scale)).collect();
    [vectors(), vectors(), vectors()]
}

fn masses(rng: &mut Pcg32, count: usize) -> Vec<Fx> {
    (0..count)
        .map(|i| {
            if i % 6 == 5 {
                Fx::ZERO
            } else {
                rng.range(Fx::from_f64(0.01), Fx::from_int(100))
            }
        })
        .collect()
}

#[test]
fn prediction_matches_the_scalar_step() {
    let mut rng = Pcg32::new(11, 13);
    for trial in 0..300 {
        let count = 40 + trial % 9;
        let scale = [1.0, 100.0, 10000.0, 30000.0][trial % 4];
        let [x, v, previous] = arrays(&mut rng, count, scale);
        let w = masses(&mut rng, count);
        let h = Fx::from_ratio(1, [60, 600, 2][trial % 3]);
        let damping = [Fx::ZERO, Fx::HALF, Fx::from_int(3)][trial % 3];
        let motion = Motion {
            h,
            gravity: vector(&mut rng, [10.0, 1e6][trial % 2]),
            retain: (Fx::ONE + h * damping).recip(),
            damped: damping != Fx::ZERO,
            wind: vector(&mut rng, 5.0),
            drag: [Fx::ZERO, Fx::from_ratio(1, 10)][usize::from(trial % 5 == 0)],
        };
        let range = trial % 3..count - trial % 5;
        let run = |kernel: bool| {
            let (mut x, mut v, mut previous) = (x.clone(), v.clone(), previous.clone());
            let mut vertices = Vertices {
                x: &mut x,
                v: &mut v,
                previous: &mut previous,
                w: &w,
            };
            let ((), saturations) = count_saturations(|| {
                if !(kernel && super::kernel::predict(range.clone(), &mut vertices, &motion)) {
                    for i in range.clone() {
                        predict_vertex(i, &mut vertices, &motion);
                    }
                }
            });
            (x, v, previous, saturations)
        };
        crate::math::cpu::each_backend(|| assert_eq!(run(true), run(false), "trial {trial}"));
    }
}

#[test]
fn velocity_update_matches_the_scalar_step() {
    let mut rng = Pcg32::new(17, 19);
    for trial in 0..300 {
        let count = 40 + trial % 9;
        let scale = [1.0, 100.0, 10000.0, 30000.0][trial % 4];
        let [x, v, previous] = arrays(&mut rng, count, scale);
        let w = masses(&mut rng, count);
        let inv_h = Fx::from_int([60, 600, 2, 20000][trial % 4]);
        let range = trial % 3..count - trial % 5;
        let run = |kernel: bool| {
            let mut v = v.clone();
            let ((), saturations) = count_saturations(|| {
                if !(kernel
                    && super::kernel::update_velocities(
                        range.clone(),
                        &x,
                        &previous,
                        &w,
                        &mut v,
                        inv_h,
                    ))
                {
                    for i in range.clone() {
                        update_velocity(i, &x, &previous, &w, &mut v, inv_h);
                    }
                }
            });
            (v, saturations)
        };
        crate::math::cpu::each_backend(|| assert_eq!(run(true), run(false), "trial {trial}"));
    }
}
