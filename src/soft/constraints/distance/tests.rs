//! The pass over every row against the rows solved one by one with the scalar row:
//! whichever path a block takes (the AVX-512 kernel where the processor has it, the scalar
//! row for the lanes it leaves, the blocks that share a vertex and the tail), the bits and
//! the saturation count are the scalar row's.

use super::{DistanceFactors, Distances};
use crate::math::saturation::count_saturations;
use crate::math::{Fx, Pcg32, Real, Vec3};

/// A value in [−scale, scale) m.
fn value(rng: &mut Pcg32, scale: f64) -> Fx // ok-det: test input
{
    rng.range(Fx::from_f64(-scale), Fx::from_f64(scale))
}

fn vector(rng: &mut Pcg32, scale: f64) -> Vec3<Fx> // ok-det: test input
{
    Vec3::new(value(rng, scale), value(rng, scale), value(rng, scale))
}

/// Raw bits anywhere in the format, a third of them at its ends.
fn extreme(rng: &mut Pcg32) -> Fx {
    match rng.below(6) {
        0 => Fx::MAX,
        1 => Fx::MIN,
        _ => Fx::from_bits(rng.next_u64() as i64),
    }
}

/// `rows` rows over `vertices` vertices: mostly runs of rows that share no vertex (a
/// shuffled vertex list cut into pairs), some ends drawn at random.
fn rows(rng: &mut Pcg32, vertices: u32, rows: usize) -> Distances<Fx> {
    let mut d = Distances::default();
    let mut order: Vec<u32> = (0..vertices).collect();
    let mut next = order.len();
    while d.a.len() < rows {
        if next + 2 > order.len() {
            for i in (1..order.len()).rev() {
                order.swap(i, rng.below(i as u32 + 1) as usize);
            }
            next = 0;
        }
        let (mut a, b) = (order[next], order[next + 1]);
        next += 2;
        if rng.below(20) == 0 {
            a = rng.below(vertices);
        }
        d.push(a, b, Fx::from_f64(0.02), Fx::ZERO);
    }
    d
}

/// Factors with shares in [0, 1] and relaxations in [0, 1), as `factors` gives, for rows
/// over at most 128 vertices.
fn factors(rng: &mut Pcg32, d: &Distances<Fx>) -> DistanceFactors<Fx> {
    let mut f = d.factors(&[Fx::ONE; 128], Fx::ONE);
    let count = d.a.len();
    f.share_a = (0..count).map(|_| rng.range(Fx::ZERO, Fx::ONE)).collect();
    f.share_b = (0..count).map(|_| rng.range(Fx::ZERO, Fx::ONE)).collect();
    f.relax = (0..count).map(|_| rng.range(Fx::ZERO, Fx::ONE)).collect();
    f
}

/// One pass by [`Distances::solve`] and one row by row, with every backend of the kernel;
/// asserts the same bits and the same saturation count.
fn assert_same(d: &Distances<Fx>, f: &DistanceFactors<Fx>, positions: &[Vec3<Fx>], case: &str) {
    crate::math::cpu::each_backend(|| assert_same_once(d, f, positions, case));
}

/// [`assert_same`] with the backend in force.
fn assert_same_once(
    d: &Distances<Fx>,
    f: &DistanceFactors<Fx>,
    positions: &[Vec3<Fx>],
    case: &str,
) {
    let (mut fast, mut slow) = (d.clone(), d.clone());
    let (mut fast_x, mut slow_x) = (positions.to_vec(), positions.to_vec());
    let ((), fast_saturations) = count_saturations(|| fast.solve(&mut fast_x, f));
    let ((), slow_saturations) = count_saturations(|| {
        let n = slow.a.len();
        let mut run = slow.run(f, 0..n);
        for c in 0..n {
            run.solve_row(&mut slow_x, c);
        }
    });
    let bits = |x: &[Vec3<Fx>]| -> Vec<[i64; 3]> {
        x.iter()
            .map(|p| [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()])
            .collect()
    };
    assert_eq!(bits(&fast_x), bits(&slow_x), "{case}: positions");
    assert_eq!(fast, slow, "{case}: λ and 1/|d|");
    assert_eq!(fast_saturations, slow_saturations, "{case}: saturations");
}

/// Edges near their last length, as in a cloth: the series path, with every so often a
/// stretched, crushed or collapsed edge (the square root or no axis); edges shorter and
/// longer than half a metre.
#[test]
fn cloth_like_rows_match_the_scalar_row() {
    let mut rng = Pcg32::new(3, 5);
    for trial in 0..200 {
        let vertices = 96;
        let mut d = rows(&mut rng, vertices, 8 * 9 + (trial % 8));
        // Half the trials in a box small enough for the short products (|d| < 0.5 m).
        let scale = [2.0, 0.2][trial % 2];
        let positions: Vec<Vec3<Fx>> = (0..vertices).map(|_| vector(&mut rng, scale)).collect();
        for c in 0..d.a.len() {
            let (a, b) = (d.a[c] as usize, d.b[c] as usize);
            let length = (positions[a] - positions[b]).length();
            let stretch = match rng.below(10) {
                0 => rng.range(Fx::from_f64(0.3), Fx::from_int(3)),
                _ => rng.range(Fx::from_f64(0.97), Fx::from_f64(1.03)),
            };
            d.inv_length[c] = (length * stretch).recip();
            d.rest[c] = length * rng.range(Fx::from_f64(0.9), Fx::from_f64(1.1));
            d.lambda[c] = value(&mut rng, 0.01);
        }
        if trial % 7 == 0 {
            let c = rng.below(d.a.len() as u32) as usize;
            d.b[c] = d.a[c];
        }
        let f = factors(&mut rng, &d);
        assert_same(&d, &f, &positions, &format!("cloth trial {trial}"));
    }
}

/// Values from small to the ends of the format: the kernel's bound checks, the lanes it
/// leaves and the saturating rows.
#[test]
fn wide_and_extreme_rows_match_the_scalar_row() {
    let mut rng = Pcg32::new(7, 9);
    for trial in 0..400 {
        let vertices = 64;
        let mut d = rows(&mut rng, vertices, 8 * 6 + (trial % 8));
        let scale = [1.0, 100.0, 8000.0, 20000.0, 1e9][trial % 5];
        let mut positions: Vec<Vec3<Fx>> = (0..vertices).map(|_| vector(&mut rng, scale)).collect();
        for c in 0..d.a.len() {
            let (a, b) = (d.a[c] as usize, d.b[c] as usize);
            let length = (positions[a] - positions[b]).length();
            d.inv_length[c] = length.recip() * rng.range(Fx::from_f64(0.9), Fx::from_f64(1.1));
            d.rest[c] = value(&mut rng, scale);
            d.lambda[c] = value(&mut rng, scale / 10.0);
        }
        let mut f = factors(&mut rng, &d);
        if trial % 3 == 0 {
            for _ in 0..4 {
                let c = rng.below(d.a.len() as u32) as usize;
                match rng.below(6) {
                    0 => d.inv_length[c] = extreme(&mut rng),
                    1 => d.rest[c] = extreme(&mut rng),
                    2 => d.lambda[c] = extreme(&mut rng),
                    3 => f.share_a[c] = extreme(&mut rng),
                    4 => f.relax[c] = extreme(&mut rng),
                    _ => positions[d.a[c] as usize].y = extreme(&mut rng),
                }
            }
        }
        assert_same(&d, &f, &positions, &format!("wide trial {trial}"));
    }
}
