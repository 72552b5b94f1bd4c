//! The batched separating-axis test against the one-pair test: whichever lanes the
//! AVX-512 kernel takes, every pair gets the bits of [`separating_axes`] and the manifold
//! of [`box_box`], with the same saturation count.

use super::{Axes, BoxPair, Choice, box_box, contact, separating_axes, separating_axes_batch};
use crate::math::cpu::kernels_present;
use crate::math::saturation::count_saturations;
use crate::math::{Fx, Mat3, Pcg32, Quat, Real, Vec3};
use crate::rigid::solver::LANES;
use crate::rigid::transform::Transform;

/// A value in [−scale, scale).
fn value(rng: &mut Pcg32, scale: f64) -> Fx // ok-det: test input
{
    rng.range(Fx::from_f64(-scale), Fx::from_f64(scale))
}

/// Half extents between 0.05 and `scale` m.
fn half_extents(rng: &mut Pcg32, scale: f64) -> Vec3<Fx> // ok-det: test input
{
    let lo = Fx::from_f64(0.05);
    let hi = Fx::from_f64(scale.max(0.06));
    Vec3::new(rng.range(lo, hi), rng.range(lo, hi), rng.range(lo, hi))
}

/// A rotation by up to `angle` rad about a random axis.
fn rotation(rng: &mut Pcg32, angle: f64) -> Quat<Fx> // ok-det: test input
{
    if angle == 0.0 {
        return Quat::IDENTITY;
    }
    Quat::from_axis_angle(rng.unit_vector(), value(rng, angle))
}

/// A pose of B against A of one of the kinds the narrowphase meets: 0 random in a cube
/// around A (overlapping, touching and separated), 1 resting on a face of A (tilted by up
/// to 0.05 rad, within about 2 cm of touching), 2 stacked exactly (axis-aligned, equal
/// sizes, separations on a 2⁻¹² m lattice: ties between the faces), 3 turned so that
/// edges meet edges, 4 far apart, 5 beyond the kernel's bound (half extents or offsets
/// past 2¹⁴ m, and the threshold's square past it), 6 on a coarse lattice (see
/// [`lattice_pair`]: exact ties between axes), 7 with B's deepest face axis deeper than A's
/// by the bias ± one raw bit (see [`bias_pair`]).
pub(super) fn pair(
    rng: &mut Pcg32,
    kind: u32,
) -> (Vec3<Fx>, Transform<Fx>, Vec3<Fx>, Transform<Fx>) {
    let centre_a = Vec3::new(value(rng, 50.0), value(rng, 50.0), value(rng, 50.0));
    let xf = |position: Vec3<Fx>, q: Quat<Fx>| Transform::from_pose(position, q);
    match kind {
        0 => {
            let (ha, hb) = (half_extents(rng, 2.0), half_extents(rng, 2.0));
            let reach = (ha.length() + hb.length()).to_f64();
            let offset = Vec3::new(value(rng, reach), value(rng, reach), value(rng, reach));
            let (qa, qb) = (rotation(rng, 3.2), rotation(rng, 3.2));
            (ha, xf(centre_a, qa), hb, xf(centre_a + offset, qb))
        }
        1 => {
            let (ha, hb) = (half_extents(rng, 1.0), half_extents(rng, 1.0));
            let qa = rotation(rng, 3.2);
            let axis = rng.below(3) as usize;
            let up = if rng.below(2) == 0 { Fx::ONE } else { -Fx::ONE };
            let gap = value(rng, 0.03);
            let mut local = Vec3::new(value(rng, 0.5), value(rng, 0.5), value(rng, 0.5));
            let height = ha.to_array()[axis] + hb.to_array()[axis] + gap;
            match axis {
                0 => local.x = height * up,
                1 => local.y = height * up,
                _ => local.z = height * up,
            }
            let xa = xf(centre_a, qa);
            let qb = qa * rotation(rng, 0.05);
            (ha, xa, hb, xf(xa.point(local), qb))
        }
        2 => {
            let h = Fx::from_ratio(1 + rng.below(8) as i64, 4);
            let half = Vec3::new(h, h, h);
            let lattice = |rng: &mut Pcg32, around: i64| {
                Fx::from_ratio(around * 4096 + rng.below(161) as i64 - 80, 4096)
            };
            let step = 2 * (1 + rng.below(8) as i64) * 4096 / 4;
            let (i, j) = (rng.below(3) as i64 - 1, rng.below(3) as i64 - 1);
            let offset = Vec3::new(
                lattice(rng, 0) + Fx::from_ratio(i * step, 4096),
                lattice(rng, 0) + Fx::from_ratio(j * step, 4096),
                lattice(rng, 0) + h * Fx::from_ratio(2, 1),
            );
            let corner = Vec3::new(Fx::from_ratio(3, 1), Fx::ZERO, Fx::from_ratio(-7, 2));
            (
                half,
                xf(corner, Quat::IDENTITY),
                half,
                xf(corner + offset, Quat::IDENTITY),
            )
        }
        3 => {
            let (ha, hb) = (half_extents(rng, 1.0), half_extents(rng, 1.0));
            let qa = rotation(rng, 3.2);
            let qb =
                qa * Quat::from_axis_angle(
                    Vec3::new(Fx::ONE, Fx::ZERO, Fx::ZERO),
                    Fx::from_f64(0.785),
                ) * Quat::from_axis_angle(
                    Vec3::new(Fx::ZERO, Fx::ONE, Fx::ZERO),
                    Fx::from_f64(0.785),
                ) * rotation(rng, 0.1);
            let xa = xf(centre_a, qa);
            // B's centre beyond A's edge along x, B's edge towards it.
            let reach = (ha.y + ha.z).to_f64() * 0.7 + hb.length().to_f64() * 0.8;
            let local = Vec3::new(
                value(rng, 0.3),
                Fx::from_f64(reach) + value(rng, 0.05),
                Fx::from_f64(reach) + value(rng, 0.05),
            );
            (ha, xa, hb, xf(xa.point(local), qb))
        }
        4 => {
            let (ha, hb) = (half_extents(rng, 2.0), half_extents(rng, 2.0));
            let offset = rng.unit_vector::<Fx>() * Fx::from_f64(10.0);
            let (qa, qb) = (rotation(rng, 3.2), rotation(rng, 3.2));
            (ha, xf(centre_a, qa), hb, xf(centre_a + offset, qb))
        }
        6 => lattice_pair(rng),
        7 => bias_pair(rng),
        _ => {
            let big = [200.0, 20_000.0, 3.0e5][rng.below(3) as usize];
            let (ha, hb) = (half_extents(rng, big), half_extents(rng, 2.0));
            let offset = Vec3::new(value(rng, big), value(rng, big), value(rng, big));
            let (qa, qb) = (rotation(rng, 3.2), rotation(rng, 3.2));
            (ha, xf(centre_a, qa), hb, xf(centre_a + offset, qb))
        }
    }
}

/// A pair whose products are all exact, so that separations tie between face axes and
/// between edge axes: axes from {−1, −½, 0, ½, 1} (a signed permutation, a proper rotation,
/// half of the time; otherwise any such matrix, which the test does not need to be a
/// rotation), half extents in quarters of a metre and offsets in eighths.
fn lattice_pair(rng: &mut Pcg32) -> (Vec3<Fx>, Transform<Fx>, Vec3<Fx>, Transform<Fx>) {
    let axes = |rng: &mut Pcg32| {
        let mut cols = [[Fx::ZERO; 3]; 3];
        if rng.below(2) == 0 {
            let shift = rng.below(3) as usize;
            for (j, col) in cols.iter_mut().enumerate() {
                col[(j + shift) % 3] = if rng.below(2) == 0 { Fx::ONE } else { -Fx::ONE };
            }
        } else {
            for x in cols.iter_mut().flatten() {
                *x = Fx::from_ratio(rng.below(5) as i64 - 2, 2);
            }
        }
        let col = |c: [Fx; 3]| Vec3::new(c[0], c[1], c[2]);
        Mat3::from_cols(col(cols[0]), col(cols[1]), col(cols[2]))
    };
    let half = |rng: &mut Pcg32| Fx::from_ratio(1 + rng.below(6) as i64, 4);
    let ha = Vec3::new(half(rng), half(rng), half(rng));
    let hb = Vec3::new(half(rng), half(rng), half(rng));
    let offset = |rng: &mut Pcg32| Fx::from_ratio(rng.below(33) as i64 - 16, 8);
    let d = Vec3::new(offset(rng), offset(rng), offset(rng));
    let centre = Vec3::new(Fx::from_ratio(5, 4), Fx::from_ratio(-3, 1), Fx::ZERO);
    let (ra, rb) = (axes(rng), axes(rng));
    (
        ha,
        Transform {
            rotation: ra,
            translation: centre,
        },
        hb,
        Transform {
            rotation: rb,
            translation: centre + d,
        },
    )
}

/// A pair whose deepest face axis of B is deeper than A's deepest by exactly 2⁻¹¹ m (the
/// bias below which A's face is kept) plus k raw bits, k ∈ {−1, 0, 1}, all products exact.
/// A is the unit cube's double at the origin of its frame, B's matrix the identity but
/// for ½ on the diagonal at axis m (not a rotation; the test does not need one), B's half
/// extent along m ¼ and the offset along m t = ±(¾ − 2(2⁻¹¹ + k·2⁻³²)). Along m:
/// s_A = |t| − (1 + ¼·½), s_B = |t|/2 − (¼ + 1·½), so s_B − s_A = (¾ − |t|)/2 =
/// 2⁻¹¹ + k·2⁻³², and every other axis is at least ⅛ m shallower. A kernel whose bias is
/// off by one raw bit chooses the other face for k = 0 or k = 1.
fn bias_pair(rng: &mut Pcg32) -> (Vec3<Fx>, Transform<Fx>, Vec3<Fx>, Transform<Fx>) {
    let m = rng.below(3) as usize;
    let k = i64::from(rng.below(3)) - 1;
    let mut t = Fx::from_ratio(3, 4) - Fx::from_bits(2 * ((1 << 21) + k));
    if rng.below(2) == 0 {
        t = -t;
    }
    let mut ha = [Fx::ONE; 3];
    let mut hb = [Fx::ONE; 3];
    let mut d = [Fx::ZERO; 3];
    let mut cols = [Vec3::<Fx>::ZERO; 3];
    for i in 0..3 {
        let mut col = [Fx::ZERO; 3];
        if i == m {
            col[i] = Fx::HALF;
            hb[i] = Fx::from_ratio(1, 4);
            d[i] = t;
        } else {
            col[i] = Fx::ONE;
            ha[i] = Fx::from_ratio(2 + rng.below(3) as i64, 4);
            hb[i] = Fx::from_ratio(1 + rng.below(3) as i64, 4);
            d[i] = Fx::from_ratio(rng.below(5) as i64 - 2, 8);
        }
        cols[i] = Vec3::new(col[0], col[1], col[2]);
    }
    let vec = |v: [Fx; 3]| Vec3::new(v[0], v[1], v[2]);
    let centre = Vec3::new(
        Fx::from_ratio(-7, 4),
        Fx::from_ratio(1, 2),
        Fx::from_ratio(9, 8),
    );
    (
        vec(ha),
        Transform {
            rotation: Mat3::IDENTITY,
            translation: centre,
        },
        vec(hb),
        Transform {
            rotation: Mat3::from_cols(cols[0], cols[1], cols[2]),
            translation: centre + vec(d),
        },
    )
}

/// How many pairs of each outcome a run saw, and how many lanes the kernel took.
#[derive(Default, Debug)]
struct Tally {
    separated: usize,
    face_a: usize,
    face_b: usize,
    edge: usize,
    taken: usize,
}

/// Runs `trials` batches of 1 to [`LANES`] pairs of the kinds `kinds`, each through the
/// batch and one by one; asserts the same axes, the same manifolds and the same saturation
/// counts, pair by pair.
fn compare_once(seed: u64, trials: usize, kinds: &[u32], margin: Fx) -> Tally {
    let mut rng = Pcg32::new(seed, 29);
    let mut tally = Tally::default();
    for trial in 0..trials {
        let count = 1 + trial % LANES;
        let poses: Vec<_> = (0..count)
            .map(|l| pair(&mut rng, kinds[(trial + l) % kinds.len()]))
            .collect();
        let pairs: Vec<BoxPair<'_, Fx>> = poses
            .iter()
            .map(|(half_a, xf_a, half_b, xf_b)| BoxPair {
                half_a: *half_a,
                xf_a,
                half_b: *half_b,
                xf_b,
            })
            .collect();
        let (expected, slow_saturations) = count_saturations(|| {
            pairs
                .iter()
                .map(|p| separating_axes(p.half_a, p.xf_a, p.half_b, p.xf_b, margin))
                .collect::<Vec<_>>()
        });
        let (batch, fast_saturations) = count_saturations(|| separating_axes_batch(&pairs, margin));
        assert_eq!(fast_saturations, slow_saturations, "trial {trial}");
        assert!(batch[count..].iter().all(Option::is_none), "trial {trial}");
        for (l, (p, expected)) in pairs.iter().zip(&expected).enumerate() {
            assert_eq!(batch[l], *expected, "trial {trial}, lane {l}");
            let manifold = batch[l].map_or(crate::rigid::manifold::Manifold::EMPTY, |axes| {
                contact(p, &axes, margin)
            });
            let scalar = box_box(p.half_a, p.xf_a, p.half_b, p.xf_b, margin);
            assert_eq!(manifold, scalar, "trial {trial}, lane {l}");
            match expected {
                None => tally.separated += 1,
                Some(Axes { choice, .. }) => match choice {
                    Choice::Face { of_b: false, .. } => tally.face_a += 1,
                    Choice::Face { of_b: true, .. } => tally.face_b += 1,
                    Choice::Edge { .. } => tally.edge += 1,
                },
            }
        }
        tally.taken += kernel_lanes(&pairs, margin).count_ones() as usize;
    }
    tally
}

/// The lanes the kernel takes (none without it).
fn kernel_lanes(pairs: &[BoxPair<'_, Fx>], margin: Fx) -> u8 {
    #[cfg(vector_kernels)]
    {
        let mut out = [None; LANES];
        super::kernel::separating_axes_lanes(pairs, margin, &mut out)
    }
    #[cfg(not(vector_kernels))]
    {
        let _ = (pairs, margin);
        0
    }
}

/// [`compare_once`] with each backend the processor has (once, with none, off x86_64):
/// the same outcomes each time; the tally of the backend that took the fewest lanes.
fn compare(seed: u64, trials: usize, kinds: &[u32], margin: Fx) -> Tally {
    #[cfg(vector_kernels)]
    {
        use crate::math::wide::{backends, with_backend};
        let mut fewest: Option<Tally> = None;
        for backend in backends() {
            let tally = with_backend(Some(backend), || compare_once(seed, trials, kinds, margin));
            if let Some(other) = &fewest {
                let outcomes = |t: &Tally| (t.separated, t.face_a, t.face_b, t.edge);
                assert_eq!(outcomes(&tally), outcomes(other), "{backend:?}");
            }
            if fewest.as_ref().is_none_or(|f| tally.taken < f.taken) {
                fewest = Some(tally);
            }
        }
        if let Some(tally) = fewest {
            return tally;
        }
    }
    compare_once(seed, trials, kinds, margin)
}

#[test]
fn random_poses_match_the_scalar_test() {
    let margin = Fx::from_ratio(2, 100);
    let tally = compare(1, 3000, &[0, 1, 2, 3, 4, 6], margin);
    // Every outcome occurs often, so that every branch of the kernel is compared.
    assert!(tally.separated > 500, "{tally:?}");
    assert!(tally.face_a > 500, "{tally:?}");
    assert!(tally.face_b > 500, "{tally:?}");
    assert!(tally.edge > 300, "{tally:?}");
    if kernels_present() {
        assert!(tally.taken * 10 > 13_500 * 9, "{tally:?}");
    }
}

#[test]
fn exact_ties_match_the_scalar_test() {
    // Lattice poses: face axes as deep as one another, edge axes as deep as one another
    // or as the face, the first in the scalar's order winning.
    for (seed, margin) in [
        (7, Fx::from_ratio(2, 100)),
        (8, Fx::ZERO),
        (9, Fx::from_ratio(1, 8)),
    ] {
        let tally = compare(seed, 3000, &[6], margin);
        assert!(
            tally.face_a > 300 && tally.face_b > 100 && tally.edge > 100,
            "{tally:?}"
        );
    }
}

#[test]
fn resting_stacked_and_edge_poses_match_with_other_margins() {
    for (seed, margin) in [
        (2, Fx::ZERO),
        (3, Fx::from_ratio(1, 10)),
        (4, Fx::from_ratio(1, 4096)),
    ] {
        let tally = compare(seed, 1000, &[1, 2, 3], margin);
        assert!(
            tally.face_a > 100 && tally.face_b > 100 && tally.edge > 50,
            "{tally:?}"
        );
    }
}

#[test]
fn values_past_the_bound_match_the_scalar_test() {
    let margin = Fx::from_ratio(2, 100);
    let tally = compare(5, 1000, &[5, 0, 5, 1], margin);
    if kernels_present() {
        // Half of the pairs are past the bound: the kernel leaves those lanes.
        assert!(tally.taken > 1000 && tally.taken < 4000, "{tally:?}");
    }
    // A margin whose square is past the bound: no lane is the kernel's.
    let huge = Fx::from_ratio(1 << 10, 1);
    let tally = compare(6, 200, &[0, 1, 4], huge);
    assert_eq!(tally.taken, 0, "{tally:?}");
}

#[test]
fn face_b_deeper_by_the_bias_give_the_scalar_choice() {
    // B's face deeper than A's by the bias less a bit, the bias, the bias and a bit: A, A,
    // B, in batches mixed with random and resting poses.
    let margin = Fx::from_ratio(2, 100);
    let tally = compare(10, 2000, &[7, 0, 7, 1], margin);
    assert!(tally.face_a > 600 && tally.face_b > 600, "{tally:?}");
    if kernels_present() {
        assert!(tally.taken * 10 > 9_000 * 9, "{tally:?}");
    }
}
