//! The pass over every tether against the rows solved one by one with the scalar row:
//! whichever path a row takes (the AVX-512 kernel where the processor has it, the scalar
//! row for the lanes it leaves, the blocks that are not independent and the tail), the bits
//! and the saturation count are the scalar row's.

use super::Tethers;
use crate::math::saturation::count_saturations;
use crate::math::{Fx, Pcg32, Real, Vec3};

/// A value in [−scale, scale) m.
fn value(rng: &mut Pcg32, scale: f64) -> Fx // ok-det: test input
{
    rng.range(Fx::from_f64(-scale), Fx::from_f64(scale))
}

/// A position up to `scale`, one component in thirty at an end of the format.
fn vector(rng: &mut Pcg32, scale: f64) -> Vec3<Fx> // ok-det: test input
{
    let mut component = || match rng.below(30) {
        0 => [Fx::MAX, Fx::MIN][rng.below(2) as usize],
        _ => value(rng, scale),
    };
    Vec3::new(component(), component(), component())
}

/// Tethers of `free` vertices to each of the `anchors` vertices before them, in rounds (as
/// the builder orders them), some anchors swapped for a tethered vertex; rest lengths near
/// the starting distances.
fn tethers(rng: &mut Pcg32, anchors: u32, free: u32, positions: &[Vec3<Fx>]) -> Tethers<Fx> {
    let mut t = Tethers::default();
    for a in 0..anchors {
        for v in anchors..anchors + free {
            let anchor = if rng.below(40) == 0 {
                anchors + rng.below(free)
            } else {
                a
            };
            let distance = positions[v as usize].distance(positions[anchor as usize]);
            t.vertex.push(v);
            t.anchor.push(anchor);
            t.rest
                .push(distance * rng.range(Fx::from_f64(0.8), Fx::from_f64(1.25)));
        }
    }
    t
}

#[test]
fn tethers_match_the_scalar_row() {
    let mut rng = Pcg32::new(23, 29);
    for trial in 0..300 {
        let (anchors, free) = (1 + trial % 3, 30 + trial % 11);
        let scale = [1.0, 100.0, 10000.0, 30000.0][trial as usize % 4];
        let positions: Vec<Vec3<Fx>> = (0..anchors + free)
            .map(|_| vector(&mut rng, scale))
            .collect();
        let mut t = tethers(&mut rng, anchors, free, &positions);
        if trial % 5 == 0 {
            let r = rng.below(t.rest.len() as u32) as usize;
            t.rest[r] = [Fx::MAX, Fx::MIN, Fx::ZERO][rng.below(3) as usize];
        }
        let independent = t.independent_blocks();
        crate::math::cpu::each_backend(|| {
            let (mut fast, mut slow) = (positions.clone(), positions.clone());
            let ((), fast_saturations) = count_saturations(|| t.solve(&mut fast, &independent));
            let ((), slow_saturations) = count_saturations(|| {
                for r in 0..t.vertex.len() {
                    t.solve_row(&mut slow, r);
                }
            });
            assert_eq!(fast, slow, "trial {trial}");
            assert_eq!(fast_saturations, slow_saturations, "trial {trial}");
        });
    }
}
