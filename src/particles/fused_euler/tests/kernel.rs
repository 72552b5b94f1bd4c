//! The vector kernel, with every backend the processor has (AVX2, AVX-512), against the checked scalar
//! operators, the portable guarded step and the general path, bit for bit: their lane
//! products on any operands (rounding ties and negative values included), single blocks
//! whose magnitudes sit anywhere from zero to the range limits (so that the bound check
//! accepts some and refuses others), and whole steps. A backend the processor lacks is
//! not checked; with neither, these tests check nothing.

use core::cell::Cell;

use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};

use super::super::kernel::products::{mul_fraction_on, mul_mass_biased_on};
use super::super::kernel::{Constants, step_block_on, step_with};
use super::super::{Block, step_portable};
use super::{Case, Slot, build};
use crate::math::saturation::count_saturations;
use crate::math::wide::{Backend, backends};
use crate::math::{Fraction, Fx, Vec3};
use crate::particles::forces::{ForceField, LinearField};
use crate::particles::storage::{Attributes, Kinematics};
use crate::particles::user_force::UserForceRegistry;

/// A value of at most `bits` significant bits (|value| < 2^bits, or −2^bits), either sign,
/// now and then the largest such magnitudes; 64 bits is any `i64`.
fn sized(bits: u32) -> BoxedStrategy<i64> {
    if bits >= 64 {
        return prop_oneof![
            3 => any::<i64>(),
            1 => (0i64..16).prop_map(|small| i64::MAX - small),
            1 => (0i64..16).prop_map(|small| i64::MIN + small),
        ]
        .boxed();
    }
    let largest = i64::MAX >> (63 - bits);
    prop_oneof![
        3 => (0..=bits, any::<u64>(), any::<bool>()).prop_map(|(bits, random, negative)| {
            let magnitude = random.checked_shr(64 - bits).unwrap_or(0) as i64;
            if negative { -magnitude } else { magnitude }
        }),
        1 => (0..16i64, any::<bool>()).prop_map(move |(small, negative)| {
            let magnitude = (largest - small).max(0);
            if negative { -magnitude - 1 } else { magnitude }
        }),
    ]
    .boxed()
}

/// `value` with its low `zeros` bits cleared: products by it tie often.
fn sparse(value: i64, zeros: u32) -> i64 {
    value & !((1i64 << zeros) - 1)
}

/// A fraction's bits, in [0, 2³¹): uniform, with sparse low bits, ½·2⁻ⁿ or 0.
fn fraction_bits() -> BoxedStrategy<i64> {
    prop_oneof![
        3 => 0..(1i64 << 31),
        3 => (0..(1i64 << 31), 0u32..31).prop_map(|(c, zeros)| sparse(c, zeros)),
        1 => (1u32..31).prop_map(|n| (1i64 << 31) >> n),
        1 => Just(0i64),
    ]
    .boxed()
}

/// An inverse mass of at most `bits` bits: 0 (pinned or dead) or non-negative with sparse
/// low bits or not; when `negative`, now and then negative.
fn inv_mass_bits(bits: u32, negative: bool) -> BoxedStrategy<i64> {
    let magnitude = move || sized(bits).prop_map(|m| m.unsigned_abs().min(i64::MAX as u64) as i64);
    prop_oneof![
        1 => Just(0i64),
        4 => magnitude(),
        4 => (magnitude(), 0u32..40).prop_map(|(m, zeros)| sparse(m, zeros)),
        u32::from(negative) => magnitude().prop_map(|m| -m),
    ]
    .boxed()
}

/// 1 to `max` slots, often a multiple of eight (which every kernel can take whole).
fn slots(
    slot: impl Strategy<Value = Slot> + Clone,
    max: usize,
) -> impl Strategy<Value = Vec<Slot>> {
    prop_oneof![
        prop::collection::vec(slot.clone(), 1..=max),
        (1..=max / 8).prop_flat_map(move |n| prop::collection::vec(slot.clone(), 8 * n)),
    ]
}

/// A drag's group restriction: mostly none.
fn restriction() -> impl Strategy<Value = Option<u16>> {
    prop_oneof![3 => Just(None), 1 => (0u16..3).prop_map(Some)]
}

/// The backends the processor has.
fn kernels() -> Vec<Backend> {
    backends()
}

/// Eight operands as the kernel's lanes take them.
fn words(values: &[i64]) -> [i64; 8] {
    let mut words = [0; 8];
    words.copy_from_slice(values);
    words
}

/// Eight operands: a vector of each kernel.
fn lanes(strategy: BoxedStrategy<i64>) -> impl Strategy<Value = Vec<i64>> {
    prop::collection::vec(strategy, 8)
}

fn vector(bits: u32) -> impl Strategy<Value = [i64; 3]> + Clone {
    [sized(bits), sized(bits), sized(bits)]
}

/// A case whose positions, velocities, external forces and inverse masses have at most
/// some number of bits each (drawn per case, from 0 to 64), up to four drags, gravity from
/// unrestricted fields and a fractional step: linear fields, for the AVX2 path, near and
/// across the bounds it checks.
fn bounded_case(max_slots: usize) -> impl Strategy<Value = Case> {
    // Bit counts weighted towards those the kernel accepts, and across its bounds.
    let x_bits = prop_oneof![2 => 0u32..=58, 1 => 56u32..=64];
    let v_bits = || prop_oneof![2 => 0u32..=50, 1 => 45u32..=64];
    let m_bits = prop_oneof![2 => 0u32..=40, 1 => 30u32..=64];
    let g_bits = prop_oneof![3 => 0u32..=40, 1 => 0u32..=64];
    let negative = prop_oneof![9 => Just(false), 1 => Just(true)];
    (x_bits, v_bits(), v_bits(), m_bits, g_bits, negative).prop_flat_map(
        move |(x_bits, v_bits, f_bits, m_bits, g_bits, negative)| {
            let slot = (
                vector(x_bits),
                vector(v_bits),
                vector(f_bits),
                inv_mass_bits(m_bits, negative),
                0u16..3,
            )
                .prop_map(
                    |(position, velocity, external_force, inv_mass, group)| Slot {
                        position,
                        velocity,
                        external_force,
                        inv_mass,
                        group,
                    },
                );
            let gravity_fields = prop_oneof![
                Just(vec![]),
                Just(vec![(1i64 << 32, None)]),
                prop::collection::vec((sized(34), Just(None)), 1..3),
            ];
            (
                slots(slot, max_slots),
                prop::collection::vec((fraction_bits(), restriction()), 0..=4),
                gravity_fields,
                vector(g_bits),
                fraction_bits(),
            )
                .prop_map(|(slots, drags, gravity_fields, gravity, dt)| Case {
                    slots,
                    drags,
                    gravity_fields,
                    gravity,
                    dt,
                })
        },
    )
}

/// The state of `case`, its linear field and its step, when the field is linear and the
/// step a fraction.
struct Linear {
    kinematics: Kinematics<Fx>,
    attributes: Attributes<Fx>,
    field: LinearField<Fx>,
    h: Fraction<Fx>,
}

fn linear(case: &Case) -> Option<Linear> {
    let (kinematics, attributes, forces) = build(case, Fx::from_bits);
    let user_forces = UserForceRegistry::default();
    let gravity = Vec3::new(
        Fx::from_bits(case.gravity[0]),
        Fx::from_bits(case.gravity[1]),
        Fx::from_bits(case.gravity[2]),
    );
    let field = ForceField::new(&forces, &user_forces, &attributes, gravity).linear()?;
    let h = Fraction::new(Fx::from_bits(case.dt))?;
    Some(Linear {
        kinematics,
        attributes,
        field,
        h,
    })
}

fn raw(values: &[Vec3<Fx>]) -> Vec<[i64; 3]> {
    values
        .iter()
        .map(|v| [v.x.to_bits(), v.y.to_bits(), v.z.to_bits()])
        .collect()
}

/// The whole state as one block.
fn block<'a>(kinematics: &'a mut Kinematics<Fx>, attributes: &'a Attributes<Fx>) -> Block<'a, Fx> {
    Block {
        positions: &mut kinematics.positions,
        velocities: &mut kinematics.velocities,
        external_forces: &attributes.external_forces,
        inv_masses: &attributes.inv_masses,
        groups: &attributes.groups,
    }
}

/// Steps one block of `case` with `kernel` and with the general path; the kernel must either
/// refuse it and leave it untouched, or give the general path's bits when the general path
/// saturates nowhere. Returns whether the kernel took the block.
fn check_block(kernel: Backend, case: &Case) -> Result<bool, TestCaseError> {
    let Some(Linear {
        kinematics,
        attributes,
        field,
        h,
    }) = linear(case)
    else {
        return Ok(false);
    };
    let constants = Constants::new(&field, h);
    let mut fast = kinematics.clone();
    let taken = step_block_on(kernel, &mut block(&mut fast, &attributes), &constants);
    let mut general = kinematics.clone();
    let ((), saturations) = count_saturations(|| {
        block(&mut general, &attributes).step_checked(&field, h.get());
    });
    if taken {
        prop_assert_eq!(saturations, 0);
        prop_assert_eq!(raw(&fast.positions), raw(&general.positions));
        prop_assert_eq!(raw(&fast.velocities), raw(&general.velocities));
    } else {
        prop_assert_eq!(raw(&fast.positions), raw(&kinematics.positions));
        prop_assert_eq!(raw(&fast.velocities), raw(&kinematics.velocities));
    }
    Ok(taken)
}

/// Steps `case` with `kernel` and with the portable path; bits and saturation counts must
/// agree.
fn check_step(kernel: Backend, case: &Case) -> Result<(), TestCaseError> {
    let Some(Linear {
        kinematics,
        attributes,
        field,
        h,
    }) = linear(case)
    else {
        return Ok(());
    };
    let mut fast = kinematics.clone();
    let (taken, fast_saturations) =
        count_saturations(|| step_with(kernel, &field, h, &mut fast, &attributes));
    let mut portable = kinematics;
    let ((), portable_saturations) =
        count_saturations(|| step_portable(&field, h, &mut portable, &attributes));
    prop_assert!(taken);
    prop_assert_eq!(raw(&fast.positions), raw(&portable.positions));
    prop_assert_eq!(raw(&fast.velocities), raw(&portable.velocities));
    prop_assert_eq!(fast_saturations, portable_saturations);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(5_000))]

    /// `mul_fraction` is the checked `*` for any a and every fraction.
    #[test]
    fn mul_fraction_lanes_are_the_checked_product(
        a in lanes(sized(64)),
        c in lanes(fraction_bits()),
    ) {
        for kernel in kernels() {
            let lanes = mul_fraction_on(kernel, words(&a), words(&c));
            for i in 0..a.len() {
                let (product, saturations) =
                    count_saturations(|| Fx::from_bits(a[i]) * Fx::from_bits(c[i]));
                prop_assert_eq!(saturations, 0);
                prop_assert_eq!(lanes[i], product.to_bits(), "{:?}", kernel);
            }
        }
    }

    /// `mul_mass_biased` is the checked `*` plus 2³⁰ for |a| ≤ 2⁶², 0 ≤ m < 2⁶² whenever
    /// the product is in range.
    #[test]
    fn mul_mass_lanes_are_the_checked_product(
        a in lanes(sized(63).prop_map(|a| a.clamp(-(1 << 62), 1 << 62)).boxed()),
        m in lanes(inv_mass_bits(62, false)),
    ) {
        for kernel in kernels() {
            let lanes = mul_mass_biased_on(kernel, words(&a), words(&m));
            for i in 0..a.len() {
                let (product, saturations) =
                    count_saturations(|| Fx::from_bits(a[i]) * Fx::from_bits(m[i]));
                if saturations == 0 {
                    prop_assert_eq!(
                        lanes[i],
                        product.to_bits().wrapping_add(1 << 30),
                        "{:?}",
                        kernel
                    );
                }
            }
        }
    }

    /// Whole steps, physical and wild (`super::case`) and bounded, take the same bits
    /// through each kernel as through the portable path.
    #[test]
    fn kernel_steps_match_portable_step(case in prop_oneof![super::case(), bounded_case(200)]) {
        for kernel in kernels() {
            check_step(kernel, &case)?;
        }
    }
}

/// Single blocks with magnitudes anywhere up to the range limits: every block a kernel
/// takes gives the general path's bits, every block it refuses is untouched, and it takes
/// and refuses many.
#[test]
fn kernel_blocks_match_general_path() {
    for kernel in kernels() {
        let (taken, refused) = (Cell::new(0u32), Cell::new(0u32));
        let mut runner = TestRunner::new(Config::with_cases(20_000));
        runner
            .run(&bounded_case(64), |case| {
                let counter = if check_block(kernel, &case)? {
                    &taken
                } else {
                    &refused
                };
                counter.set(counter.get() + 1);
                Ok(())
            })
            .expect("the kernel's block gives the general path's bits");
        let (taken, refused) = (taken.get(), refused.get());
        assert!(
            taken > 2_000 && refused > 2_000,
            "{kernel:?}: taken {taken}, refused {refused}"
        );
    }
}

/// The kernels take blocks up to the bounds they document (here e_x = 62: positions just
/// under 2⁶¹, velocities and forces of 2⁵³, 1/m = 1.25 kg⁻¹), with ties in the products.
#[test]
fn kernel_block_at_its_bounds() {
    let slot = |i: i64| Slot {
        position: [(1 << 61) - 1 - i, -(1 << 61) + i, (1 << 60) + 2 * i],
        velocity: [(1 << 53) + 2, -(1 << 53) - 6, 2 + i],
        external_force: [-(1 << 53) + 2 * i, (1 << 53), -2],
        inv_mass: if i % 7 == 0 { 0 } else { (1 << 32) + (1 << 30) },
        group: 0,
    };
    let case = Case {
        slots: (0..64).map(slot).collect(),
        drags: vec![(1 << 30, None), ((1 << 30) + (1 << 29), None)],
        gravity_fields: vec![(1 << 32, None)],
        gravity: [1 << 30, -(42_125_000_000), -(1 << 33)],
        dt: 1 << 30,
    };
    for kernel in kernels() {
        assert!(check_block(kernel, &case).expect("same bits"), "{kernel:?}");
    }
}
