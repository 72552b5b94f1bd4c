//! [`to_world`] against [`Transform::point`] one point at a time: the same bits and the
//! same saturation count on random rotations and matrices, raw words of every size up to
//! the kernel's bound and past it, and every count of points; the kernel takes exactly the
//! inputs within its bound. Other formats (I48F16, f64) go one by one, with the same bits.

use super::to_world;
use crate::math::cpu::{each_backend, kernels_present};
use crate::math::saturation::count_saturations;
use crate::math::{Fx, FxI48F16, Mat3, Pcg32, Quat, Vec3};
use crate::rigid::manifold::MAX_MANIFOLD_POINTS;
use crate::rigid::transform::Transform;

/// The kernel's bound on raw words: operands lie in [−2⁴⁶, 2⁴⁶).
const BOUND: i64 = 1 << 46;

/// A raw word of up to `bits` significant bits, either sign; a quarter of them sit on the
/// edge of that range (±(2^bits − 1), −2^bits) and a quarter have low halves of 0 or 2³¹
/// (products rounding at a tie).
fn word(rng: &mut Pcg32, bits: u32) -> i64 {
    let limit = 1i64 << bits;
    let raw = ((u64::from(rng.next_u32()) << 32 | u64::from(rng.next_u32())) as i64) >> (63 - bits);
    match rng.next_u32() % 8 {
        0 => limit - 1,
        1 => -limit,
        2 => raw & !0xffff_ffff,
        3 => (raw & !0xffff_ffff) | 1 << 31,
        _ => raw,
    }
}

/// A vector of three such words (see [`word`]), m.
fn vector(rng: &mut Pcg32, bits: u32) -> Vec3<Fx> {
    let mut v = || Fx::from_bits(word(rng, bits));
    Vec3::new(v(), v(), v())
}

/// A rotation from a random unit quaternion.
fn rotation(rng: &mut Pcg32) -> Mat3<Fx> {
    let mut c = || Fx::from_bits(i64::from(rng.next_u32() as i32));
    Quat::new(c(), c(), c(), c()).normalize().to_mat3()
}

/// `to_world` and the scalar form on the same input: equal points (the first `count`) and
/// saturation counts. Returns whether the kernel took the input.
fn check(xf: &Transform<Fx>, local: &[Vec3<Fx>; MAX_MANIFOLD_POINTS], count: usize) -> bool {
    let (expected, expected_saturations) = count_saturations(|| {
        local[..count]
            .iter()
            .map(|&p| xf.point(p))
            .collect::<Vec<_>>()
    });
    let (world, saturations) = count_saturations(|| to_world(xf, local, count));
    assert_eq!(world[..count], expected[..], "{xf:?} {local:?}");
    assert_eq!(saturations, expected_saturations, "{xf:?} {local:?}");
    kernel_takes(xf, local)
}

/// Whether the kernel takes the input (and then gives the scalar form's four points).
fn kernel_takes(xf: &Transform<Fx>, local: &[Vec3<Fx>; MAX_MANIFOLD_POINTS]) -> bool {
    #[cfg(vector_kernels)]
    {
        let mut world = [Vec3::ZERO; MAX_MANIFOLD_POINTS];
        let taken = super::kernel::to_world(xf, local, &mut world);
        if taken {
            assert_eq!(world, local.map(|p| xf.point(p)), "{xf:?} {local:?}");
        }
        taken
    }
    #[cfg(not(vector_kernels))]
    {
        let _ = (xf, local);
        false
    }
}

/// Whether every operand's raw word is within the kernel's bound.
fn within_bound(xf: &Transform<Fx>, local: &[Vec3<Fx>; MAX_MANIFOLD_POINTS]) -> bool {
    let words = xf
        .rotation
        .cols
        .iter()
        .chain([&xf.translation])
        .chain(local);
    words
        .flat_map(|v| v.to_array())
        .all(|x| (-BOUND..BOUND).contains(&x.to_bits()))
}

#[test]
fn rotations_and_points_of_every_size_match_the_scalar_form() {
    each_backend(|| {
        let mut rng = Pcg32::new(0x000f_0ce5, 7);
        let mut taken = 0;
        for trial in 0..40_000 {
            let bits = [20, 34, 40, 45, 46][trial % 5];
            let xf = Transform {
                rotation: rotation(&mut rng),
                translation: vector(&mut rng, bits),
            };
            let local = core::array::from_fn(|_| vector(&mut rng, bits));
            let count = trial % (MAX_MANIFOLD_POINTS + 1);
            let kernel = check(&xf, &local, count);
            assert_eq!(kernel, kernels_present() && within_bound(&xf, &local));
            taken += usize::from(kernel);
        }
        if kernels_present() {
            assert!(taken > 30_000, "{taken}");
        }
    });
}

#[test]
fn any_matrix_up_to_and_past_the_bound_matches_the_scalar_form() {
    each_backend(|| {
        let mut rng = Pcg32::new(0xb0_07d, 3);
        let (mut taken, mut declined, mut saturated) = (0, 0, 0);
        for trial in 0..40_000 {
            // 46 bits: every word within the bound, its edges included; 47 and 62: some past
            // it (the kernel declines), some saturating in the scalar form.
            let bits = [46, 46, 47, 62][trial % 4];
            let xf = Transform {
                rotation: Mat3::from_cols(
                    vector(&mut rng, bits),
                    vector(&mut rng, bits),
                    vector(&mut rng, bits),
                ),
                translation: vector(&mut rng, bits),
            };
            let local = core::array::from_fn(|_| vector(&mut rng, bits));
            let (_, saturations) = count_saturations(|| local.map(|p| xf.point(p)));
            let kernel = check(&xf, &local, MAX_MANIFOLD_POINTS);
            assert_eq!(kernel, kernels_present() && within_bound(&xf, &local));
            assert!(!kernel || saturations == 0);
            taken += usize::from(kernel);
            declined += usize::from(!kernel);
            saturated += usize::from(saturations > 0);
        }
        if kernels_present() {
            assert!(
                taken > 10_000 && declined > 15_000 && saturated > 5_000,
                "{taken} {declined} {saturated}"
            );
        }
    });
}

#[test]
fn one_word_past_the_bound_is_left_to_the_scalar_form() {
    each_backend(|| {
        let mut rng = Pcg32::new(0xed6e, 5);
        for trial in 0..2_000 {
            let mut xf = Transform {
                rotation: rotation(&mut rng),
                translation: vector(&mut rng, 40),
            };
            let mut local: [Vec3<Fx>; MAX_MANIFOLD_POINTS] =
                core::array::from_fn(|_| vector(&mut rng, 40));
            // One word (of 24) on the edge of the bound, inside it or just past it.
            let edge = [BOUND - 1, -BOUND, BOUND, -BOUND - 1][trial % 4];
            let slot = (trial / 4) % 24;
            let value = Fx::from_bits(edge);
            let mut vectors: Vec<&mut Vec3<Fx>> = xf.rotation.cols.iter_mut().collect();
            vectors.push(&mut xf.translation);
            vectors.extend(local.iter_mut());
            let v = &mut vectors[slot / 3];
            match slot % 3 {
                0 => v.x = value,
                1 => v.y = value,
                _ => v.z = value,
            }
            let kernel = check(&xf, &local, MAX_MANIFOLD_POINTS);
            assert_eq!(kernel, kernels_present() && trial % 4 < 2, "trial {trial}");
        }
    });
}

/// `v`'s raw words shifted right by `shift` bits, as I48F16 words.
fn coarse(v: Vec3<Fx>, shift: u32) -> Vec3<FxI48F16> {
    let word = |x: Fx| FxI48F16::from_bits(x.to_bits() >> shift);
    Vec3::new(word(v.x), word(v.y), word(v.z))
}

/// `v` in f64.
fn float(v: Vec3<FxI48F16>) -> Vec3<f64> // ok-det: test input
{
    let [x, y, z] = v.to_f64();
    Vec3::new(x, y, z)
}

#[test]
fn other_formats_transform_one_by_one() {
    let mut rng = Pcg32::new(0x0f64, 9);
    for trial in 0..2_000 {
        let count = trial % (MAX_MANIFOLD_POINTS + 1);
        // A rotation in I48F16 (its I32F32 words less 16 bits), offsets of every size.
        let [c0, c1, c2] = rotation(&mut rng).cols.map(|c| coarse(c, 16));
        let xf = Transform {
            rotation: Mat3::from_cols(c0, c1, c2),
            translation: coarse(vector(&mut rng, 45), 0),
        };
        let bits = [30, 45, 62][trial % 3];
        let local = core::array::from_fn(|_| coarse(vector(&mut rng, bits), 0));
        let (expected, expected_saturations) = count_saturations(|| {
            local[..count]
                .iter()
                .map(|&p| xf.point(p))
                .collect::<Vec<_>>()
        });
        let (world, saturations) = count_saturations(|| to_world(&xf, &local, count));
        assert_eq!(world[..count], expected[..], "trial {trial}");
        assert_eq!(saturations, expected_saturations, "trial {trial}");
        let [f0, f1, f2] = xf.rotation.cols.map(float);
        let xf = Transform {
            rotation: Mat3::from_cols(f0, f1, f2),
            translation: float(xf.translation),
        };
        let local = local.map(float);
        let world = to_world(&xf, &local, count);
        for (w, &p) in world.iter().zip(&local).take(count) {
            assert_eq!(
                w.to_f64().map(f64::to_bits),
                xf.point(p).to_f64().map(f64::to_bits)
            );
        }
    }
}
