//! The row sums' dispatch against the scalar form, with every backend of the kernels this
//! processor runs and with none, bit for bit and saturation for saturation, on random rows
//! at everyday magnitudes, near the kernel's bound and at the ends of the range.

use super::{
    GradientBits, density_rates, density_rates_scalar, gradient_sums, gradient_sums_scalar,
    pressure_pushes, pressure_pushes_scalar, smoothing_sums, smoothing_sums_scalar,
};
use crate::fluid::neighbours::NeighbourLists;
use crate::math::cpu::{each_backend, kernels_present};
use crate::math::saturation::count_saturations;
use crate::math::{Fx, Pcg32, Real, Vec3};

/// A random value of at most `bits` bits of magnitude (as raw I32F32 bits), either sign;
/// one in eight is ±2^bits exactly, and with `extremes` one in sixteen is `i64::MIN` or
/// `i64::MAX`.
fn value(rng: &mut Pcg32, bits: u32, extremes: bool) -> Fx {
    let pick = rng.below(16);
    if extremes && pick == 0 {
        return Fx::from_bits(if rng.below(2) == 0 {
            i64::MIN
        } else {
            i64::MAX
        });
    }
    let magnitude = if pick < 2 {
        1i64 << bits.min(62)
    } else {
        (rng.next_u64() >> (64 - bits.min(63))) as i64
    };
    Fx::from_bits(if rng.below(2) == 0 {
        magnitude
    } else {
        -magnitude
    })
}

fn vector(rng: &mut Pcg32, bits: u32, extremes: bool) -> Vec3<Fx> {
    Vec3::new(
        value(rng, bits, extremes),
        value(rng, bits, extremes),
        value(rng, bits, extremes),
    )
}

/// `n` rows of 0 to `longest` entries (every length mod 8 occurs), random neighbours below
/// `n`, kernel values and gradients of `gradient_bits` bits.
fn lists(
    rng: &mut Pcg32,
    n: usize,
    longest: u32,
    gradient_bits: u32,
    extremes: bool,
) -> NeighbourLists<Fx> {
    let mut lists = NeighbourLists::default();
    lists.start.push(0);
    for _ in 0..n {
        for _ in 0..rng.below(longest + 1) {
            lists.index.push(rng.below(n as u32));
            lists.value.push(value(rng, gradient_bits, extremes));
            let g = vector(rng, gradient_bits, extremes);
            for (list, c) in lists.gradients.iter_mut().zip([g.x, g.y, g.z]) {
                list.push(c);
            }
        }
        lists.start.push(lists.index.len() as u32);
    }
    lists
}

/// Compares the four sums on one random case (inverse densities of the stiffnesses' bits)
/// with every backend; returns whether the dispatched results came from the kernels (where
/// they exist) rather than from the scalar fallback, which must be the same answer for
/// every backend.
fn compare(seed: u64, n: usize, longest: u32, bits: [u32; 2], extremes: bool) -> bool {
    let mut taken = None;
    each_backend(|| {
        let now = compare_once(seed, n, longest, bits, extremes);
        if kernels_present() {
            assert!(
                taken.is_none_or(|t| t == now),
                "seed {seed}: backends disagree"
            );
            taken = Some(now);
        }
    });
    taken.unwrap_or(false)
}

/// [`compare`] with the backend in force.
fn compare_once(seed: u64, n: usize, longest: u32, bits: [u32; 2], extremes: bool) -> bool {
    let mut rng = Pcg32::new(seed, 7);
    let lists = lists(&mut rng, n, longest, bits[0], extremes);
    let velocities: Vec<_> = (0..n)
        .map(|_| vector(&mut rng, bits[1], extremes))
        .collect();
    let stiffness: Vec<_> = (0..n).map(|_| value(&mut rng, bits[1], extremes)).collect();

    // The gradient sums first: they measure the gradients for the two sums after them.
    let (mut fast, mut slow) = ((Vec::new(), Vec::new()), (Vec::new(), Vec::new()));
    let (gradients, fast_count) =
        count_saturations(|| gradient_sums(&lists, &mut fast.0, &mut fast.1));
    let ((), slow_count) =
        count_saturations(|| gradient_sums_scalar(&lists, &mut slow.0, &mut slow.1));
    assert_eq!(fast, slow, "gradient sums, seed {seed}");
    assert_eq!(
        fast_count, slow_count,
        "gradient sum saturations, seed {seed}"
    );
    assert_eq!(gradients == GradientBits(None), !kernels_present());

    let (mut fast, mut slow) = (Vec::new(), Vec::new());
    let ((), fast_count) =
        count_saturations(|| density_rates(&lists, gradients, &velocities, &mut fast));
    let ((), slow_count) =
        count_saturations(|| density_rates_scalar(&lists, &velocities, &mut slow));
    assert_eq!(fast, slow, "density rates, seed {seed}");
    assert_eq!(
        fast_count, slow_count,
        "density rate saturations, seed {seed}"
    );

    let (mut fast, mut slow) = (Vec::new(), Vec::new());
    let ((), fast_count) =
        count_saturations(|| pressure_pushes(&lists, gradients, &stiffness, &mut fast));
    let ((), slow_count) =
        count_saturations(|| pressure_pushes_scalar(&lists, &stiffness, &mut slow));
    assert_eq!(fast, slow, "pressure pushes, seed {seed}");
    assert_eq!(
        fast_count, slow_count,
        "pressure push saturations, seed {seed}"
    );

    let inv_density = &stiffness;
    let (mut fast, mut slow) = (Vec::new(), Vec::new());
    let ((), fast_count) =
        count_saturations(|| smoothing_sums(&lists, &velocities, inv_density, &mut fast));
    let ((), slow_count) = count_saturations(|| {
        smoothing_sums_scalar(&lists, &velocities, inv_density, &mut slow);
    });
    assert_eq!(fast, slow, "smoothing sums, seed {seed}");
    assert_eq!(
        fast_count, slow_count,
        "smoothing sum saturations, seed {seed}"
    );
    kernel_takes(&lists, &velocities, &stiffness)
}

/// Whether the four kernels of the backend in force take the case (not falling back to the
/// scalar form).
#[cfg(vector_kernels)]
fn kernel_takes(lists: &NeighbourLists<Fx>, velocities: &[Vec3<Fx>], stiffness: &[Fx]) -> bool {
    use super::kernel;
    let Some(backend) = crate::math::wide::backend() else {
        return false;
    };
    let (gradients_stand, Some(bits)) =
        kernel::gradient_sums(backend, lists, &mut Vec::new(), &mut Vec::new())
    else {
        return false;
    };
    let takes = [
        kernel::density_rates(backend, lists, bits, velocities, &mut Vec::new()),
        kernel::pressure_pushes(backend, lists, bits, stiffness, &mut Vec::new()),
        kernel::smoothing_sums(backend, lists, velocities, stiffness, &mut Vec::new()),
        gradients_stand,
    ];
    takes.iter().all(|&t| t)
}

#[cfg(not(vector_kernels))]
fn kernel_takes(_: &NeighbourLists<Fx>, _: &[Vec3<Fx>], _: &[Fx]) -> bool {
    false
}

#[test]
fn everyday_magnitudes_take_the_kernel_and_match() {
    // Gradients up to 2⁴¹ (about 500 1/m), velocities and stiffnesses up to 2³⁶ (16).
    for seed in 0..40 {
        let taken = compare(seed, 300, 40, [41, 36], false);
        assert_eq!(taken, kernels_present(), "seed {seed}");
    }
}

#[test]
fn magnitudes_near_the_bound_match() {
    // Around the bound: some cases pass the check, some fall back; all must match.
    let mut taken = 0;
    for seed in 0..200 {
        let a = 40 + (seed % 20) as u32;
        let b = 30 + (seed % 23) as u32;
        taken += u32::from(compare(seed, 64, 70, [a, b], false));
    }
    if kernels_present() {
        assert!(taken > 0 && taken < 200, "{taken} of 200 taken");
    }
}

#[test]
fn extreme_values_saturate_as_the_scalar_form() {
    for seed in 0..100 {
        let taken = compare(seed, 40, 20, [62, 62], true);
        assert!(!taken, "seed {seed}: extremes must fall back");
    }
}

#[test]
fn empty_and_short_rows_match() {
    for seed in 0..20 {
        compare(seed, 1, 3, [41, 36], false);
        compare(seed, 17, 0, [41, 36], false);
    }
}

#[test]
fn small_velocities_and_stiffnesses_take_the_narrow_products_and_match() {
    // Magnitudes up to 2²⁹ and 2³⁰ (0.125 and 0.25): differences and sums of 32-bit signed
    // numbers (the two-multiply product) and just beyond.
    for seed in 0..40 {
        let bits = 29 + (seed % 2) as u32;
        let taken = compare(seed, 300, 40, [41, bits], false);
        assert_eq!(taken, kernels_present(), "seed {seed}");
    }
}

/// One row of eight entries whose density rate and pressure push leave the range: each
/// gradient component 2⁵⁰ (raw bits), each velocity difference 2⁴¹ and stiffness sum 2⁴²,
/// so that the 24 terms of the rate (2⁵⁹ each) and the 8 of each push component (2⁶⁰),
/// all of one sign, pass 2⁶³. The scalar form
/// saturates; the kernels, told the gradients' true bit length, must fall back to it, and
/// with a bound measured on other lists (gradients of one bit) they would wrap instead.
#[test]
fn sums_beyond_the_range_fall_back_on_the_measured_gradients() {
    let big = Fx::from_bits(1 << 50);
    let mut lists = NeighbourLists::default();
    lists.start.extend([0, 8]);
    for j in 1..=8 {
        lists.index.push(j);
        lists.value.push(big);
        for g in &mut lists.gradients {
            g.push(big);
        }
    }
    lists.start.extend(std::iter::repeat_n(8, 8));
    let fast = Fx::from_bits(1 << 41);
    let mut velocities = vec![Vec3::ZERO; 9];
    velocities[0] = Vec3::new(fast, fast, fast);
    let mut stiffness = vec![Fx::ZERO; 9];
    stiffness[0] = Fx::from_bits(1 << 42);

    each_backend(|| beyond_the_range(&lists, &velocities, &stiffness));
}

fn beyond_the_range(lists: &NeighbourLists<Fx>, velocities: &[Vec3<Fx>], stiffness: &[Fx]) {
    let gradients = gradient_sums(lists, &mut Vec::new(), &mut Vec::new());
    let mut rates = [Vec::new(), Vec::new()];
    let (_, saturations) =
        count_saturations(|| density_rates(lists, gradients, velocities, &mut rates[0]));
    density_rates_scalar(lists, velocities, &mut rates[1]);
    assert_eq!(rates[0], rates[1]);
    assert_eq!(rates[0][0], Fx::MAX);
    assert!(saturations > 0);
    let mut pushes = [Vec::new(), Vec::new()];
    pressure_pushes(lists, gradients, stiffness, &mut pushes[0]);
    pressure_pushes_scalar(lists, stiffness, &mut pushes[1]);
    assert_eq!(pushes[0], pushes[1]);
    assert_eq!(pushes[0][0], Vec3::new(Fx::MAX, Fx::MAX, Fx::MAX));

    // The test can fail: with a stale bound the kernels take the row and wrap.
    #[cfg(vector_kernels)]
    if kernels_present() {
        let mut wrapped = Vec::new();
        let backend = crate::math::wide::backend().expect("present");
        assert!(super::kernel::density_rates(
            backend,
            lists,
            1,
            velocities,
            &mut wrapped
        ));
        assert_ne!(wrapped[0], Fx::MAX);
    }
}
