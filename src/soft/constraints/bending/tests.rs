//! The pass over every hinge against the hinges solved one by one with the scalar row:
//! whichever path a block takes (the AVX-512 kernel where the processor has it, the scalar
//! row for the blocks it leaves, those that share a vertex and the tail), the bits and the
//! saturation count are the scalar row's.

use super::Hinges;
use crate::math::saturation::count_saturations;
use crate::math::{Fx, Pcg32, Real, Vec3};

/// A value in [−scale, scale), one in forty at an end of the format.
fn value(rng: &mut Pcg32, scale: f64) -> Fx // ok-det: test input
{
    match rng.below(40) {
        0 => [Fx::MAX, Fx::MIN][rng.below(2) as usize],
        _ => rng.range(Fx::from_f64(-scale), Fx::from_f64(scale)),
    }
}

fn vector(rng: &mut Pcg32, scale: f64) -> Vec3<Fx> // ok-det: test input
{
    Vec3::new(value(rng, scale), value(rng, scale), value(rng, scale))
}

/// `count` hinges over `vertices` vertices: runs that share no vertex (a shuffled vertex
/// list cut into fours), a corner drawn at random every so often.
fn hinges(rng: &mut Pcg32, vertices: u32, count: usize, scale: f64) -> Hinges<Fx> // ok-det: test input
{
    let mut h = Hinges::default();
    let mut order: Vec<u32> = (0..vertices).collect();
    let mut next = order.len();
    while h.vertices.len() < count {
        if next + 4 > order.len() {
            for i in (1..order.len()).rev() {
                order.swap(i, rng.below(i as u32 + 1) as usize);
            }
            next = 0;
        }
        let mut corners = [
            order[next],
            order[next + 1],
            order[next + 2],
            order[next + 3],
        ];
        next += 4;
        if rng.below(30) == 0 {
            corners[rng.below(4) as usize] = rng.below(vertices);
        }
        h.vertices.push(corners);
        h.coefficients
            .push([0; 4].map(|_| value(rng, 200.0 * scale.min(1.0))));
        h.compliance.push(Fx::ONE);
        h.lambda.push(vector(rng, scale / 100.0));
    }
    h
}

#[test]
fn hinges_match_the_scalar_row() {
    let mut rng = Pcg32::new(31, 37);
    for trial in 0..300 {
        let vertices = 160;
        let scale = [1.0, 100.0, 10000.0, 30000.0][trial % 4];
        let rows = hinges(&mut rng, vertices, 8 * 4 + trial % 8, scale);
        let positions: Vec<Vec3<Fx>> = (0..vertices).map(|_| vector(&mut rng, scale)).collect();
        let shares: Vec<[Fx; 4]> = (0..rows.vertices.len())
            .map(|_| [0; 4].map(|_| value(&mut rng, 0.01)))
            .collect();
        let relax: Vec<Fx> = (0..rows.vertices.len())
            .map(|_| rng.range(Fx::ZERO, Fx::ONE))
            .collect();
        let independent = rows.independent_blocks();
        crate::math::cpu::each_backend(|| {
            let (mut fast, mut slow) = (rows.clone(), rows.clone());
            let (mut fast_x, mut slow_x) = (positions.clone(), positions.clone());
            let ((), fast_saturations) =
                count_saturations(|| fast.solve(&mut fast_x, &shares, &relax, &independent));
            let ((), slow_saturations) = count_saturations(|| {
                let mut run = super::HingeRun {
                    vertices: &slow.vertices,
                    coefficients: &slow.coefficients,
                    lambda: &mut slow.lambda,
                    shares: &shares,
                    relax: &relax,
                    independent: &[],
                };
                for h in 0..run.vertices.len() {
                    run.solve_row(&mut slow_x, h);
                }
            });
            assert_eq!(fast_x, slow_x, "trial {trial}: positions");
            assert_eq!(fast, slow, "trial {trial}: μ");
            assert_eq!(
                fast_saturations, slow_saturations,
                "trial {trial}: saturations"
            );
        });
    }
}
