//! The fused step against the general path's passes, bit for bit, on random states that
//! include values at the ends of the range (so that blocks saturate and fall back), pinned
//! and dead slots, group restrictions, drag coefficients from 0.5 kg/s up and steps from
//! 0.5 s up, 1 s included (which take the general path through the dispatch).

use proptest::prelude::*;

#[cfg(vector_kernels)]
mod kernel;

use crate::math::saturation::count_saturations;
use crate::math::{Fraction, Fx, FxI48F16, Real, Vec3};
use crate::particles::SpringDesc;
use crate::particles::forces::{AccelerationField, ForceField, ForceGenerator, ForceSet};
use crate::particles::integrators::{self, Integrator, Scratch, StepContext};
use crate::particles::storage::{Attributes, Kinematics};
use crate::particles::user_force::UserForceRegistry;
use crate::types::Handle;

/// A random raw value: physical (|x| < 2⁸ in I32F32), or, when `wild`, also large, near
/// the range limits, or anything.
fn bits(wild: bool) -> BoxedStrategy<i64> {
    let physical = -(1i64 << 40)..(1i64 << 40);
    if !wild {
        return physical.boxed();
    }
    prop_oneof![
        3 => physical,
        2 => -(1i64 << 52)..(1i64 << 52),
        1 => (i64::MAX - (1 << 40))..=i64::MAX,
        1 => i64::MIN..(i64::MIN + (1 << 40)),
        1 => any::<i64>(),
    ]
    .boxed()
}

/// Inverse masses: pinned or dead (0), ordinary, and, when `wild`, tiny masses (large 1/m)
/// or any bits.
fn inv_mass_bits(wild: bool) -> BoxedStrategy<i64> {
    if !wild {
        return prop_oneof![1 => Just(0i64), 4 => 0..(1i64 << 36)].boxed();
    }
    prop_oneof![
        2 => Just(0i64),
        4 => 0..(1i64 << 36),
        1 => 0..(1i64 << 50),
        1 => any::<i64>(),
    ]
    .boxed()
}

/// Coefficients and step lengths: fractions (0 ≤ c < 1/2) and, when `wild`, also 1/2,
/// up to 1, exactly 1, above, or any bits.
fn factor_bits(wild: bool) -> BoxedStrategy<i64> {
    if !wild {
        return (0..(1i64 << 31)).boxed();
    }
    prop_oneof![
        6 => 0..(1i64 << 31),
        1 => Just(1i64 << 31),
        1 => (1i64 << 31)..(1i64 << 32),
        1 => Just(1i64 << 32),
        1 => (1i64 << 32)..(1i64 << 40),
        1 => any::<i64>(),
    ]
    .boxed()
}

fn vector(wild: bool) -> impl Strategy<Value = [i64; 3]> {
    [bits(wild), bits(wild), bits(wild)]
}

#[derive(Clone, Debug)]
struct Slot {
    position: [i64; 3],
    velocity: [i64; 3],
    external_force: [i64; 3],
    inv_mass: i64,
    group: u16,
}

fn slot(wild: bool) -> impl Strategy<Value = Slot> {
    (
        vector(wild),
        vector(wild),
        vector(wild),
        inv_mass_bits(wild),
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
        )
}

#[derive(Clone, Debug)]
struct Case {
    slots: Vec<Slot>,
    /// (coefficient bits, group restriction) per linear drag.
    drags: Vec<(i64, Option<u16>)>,
    /// (scale bits, group restriction) per gravity field.
    gravity_fields: Vec<(i64, Option<u16>)>,
    gravity: [i64; 3],
    dt: i64,
}

/// A case of physical values only, or (`wild`) one with values anywhere in the range.
fn case_of(wild: bool) -> impl Strategy<Value = Case> {
    let restriction = prop_oneof![3 => Just(None), 1 => (0u16..3).prop_map(Some)];
    let gravity_restriction = if wild {
        prop_oneof![6 => Just(None), 1 => (0u16..3).prop_map(Some)].boxed()
    } else {
        Just(None).boxed()
    };
    (
        prop::collection::vec(slot(wild), 1..200),
        prop::collection::vec((factor_bits(wild), restriction), 0..6),
        prop::collection::vec((bits(wild), gravity_restriction), 0..3),
        vector(wild),
        factor_bits(wild),
    )
        .prop_map(|(slots, drags, gravity_fields, gravity, dt)| Case {
            slots,
            drags,
            gravity_fields,
            gravity,
            dt,
        })
}

fn case() -> impl Strategy<Value = Case> {
    prop_oneof![case_of(false), case_of(true)]
}

fn vec3<R: Real>(raw: [i64; 3], from_bits: fn(i64) -> R) -> Vec3<R> {
    Vec3::new(from_bits(raw[0]), from_bits(raw[1]), from_bits(raw[2]))
}

/// The state and forces of `case` in the format whose values are `from_bits`.
fn build<R: Real>(
    case: &Case,
    from_bits: fn(i64) -> R,
) -> (Kinematics<R>, Attributes<R>, ForceSet<R>) {
    let mut kinematics = Kinematics::default();
    let mut attributes = Attributes::default();
    for slot in &case.slots {
        kinematics.positions.push(vec3(slot.position, from_bits));
        kinematics.velocities.push(vec3(slot.velocity, from_bits));
        kinematics.previous_positions.push(Vec3::ZERO);
        kinematics.has_previous_position.push(false);
        kinematics.accelerations.push(Vec3::ZERO);
        let inv_mass = from_bits(slot.inv_mass);
        attributes.inv_masses.push(inv_mass);
        attributes.masses.push(R::ZERO);
        attributes
            .external_forces
            .push(vec3(slot.external_force, from_bits));
        attributes.lifetimes.push(R::ZERO);
        attributes.groups.push(slot.group);
        attributes.alive.push(inv_mass != R::ZERO);
        attributes.generations.push(0);
    }
    let forces = ForceSet {
        fields: case
            .gravity_fields
            .iter()
            .map(|&(scale, group)| AccelerationField::Gravity {
                scale: from_bits(scale),
                group,
            })
            .collect(),
        generators: case
            .drags
            .iter()
            .map(|&(coefficient, group)| ForceGenerator::LinearDrag {
                coefficient: from_bits(coefficient),
                group,
            })
            .collect(),
        dampings: Vec::new(),
    };
    (kinematics, attributes, forces)
}

/// Runs `advance(SemiImplicitEuler)` on a copy of `kinematics`; returns the new state and
/// the saturations counted.
fn advance<R: Real>(
    field: &ForceField<'_, R>,
    dt: R,
    kinematics: &Kinematics<R>,
    attributes: &Attributes<R>,
) -> (Kinematics<R>, u64) {
    let mut kinematics = kinematics.clone();
    let mut scratch = Scratch::default();
    let mut accelerations_current = false;
    let ((), saturations) = count_saturations(|| {
        integrators::advance(
            Integrator::SemiImplicitEuler,
            dt,
            StepContext {
                kinematics: &mut kinematics,
                attributes,
                field,
                scratch: &mut scratch,
                accelerations_current: &mut accelerations_current,
            },
        )
    });
    (kinematics, saturations)
}

/// Steps `case` with the engine (fused where it applies) and with the general path, which
/// the same forces plus a spring on a particle that does not exist (no force at all) force
/// the step onto; checks that bits and saturation counts agree and returns whether the
/// fused step applied.
fn check<R: Real>(
    case: &Case,
    from_bits: fn(i64) -> R,
    to_bits: fn(R) -> i64,
) -> Result<bool, TestCaseError> {
    let (kinematics, attributes, forces) = build(case, from_bits);
    let mut general_forces = forces.clone();
    general_forces
        .generators
        .push(ForceGenerator::AnchoredSpring {
            particle: Handle::new(u32::MAX, 0),
            anchor: Vec3::ZERO,
            spring: SpringDesc {
                stiffness: R::ONE,
                damping: R::ONE,
                rest_length: R::ZERO,
            },
        });
    let user_forces = UserForceRegistry::default();
    let gravity = vec3(case.gravity, from_bits);
    let field = ForceField::new(&forces, &user_forces, &attributes, gravity);
    let general_field = ForceField::new(&general_forces, &user_forces, &attributes, gravity);
    prop_assert!(general_field.linear().is_none());
    let dt = from_bits(case.dt);

    let (engine, engine_saturations) = advance(&field, dt, &kinematics, &attributes);
    let (general, general_saturations) = advance(&general_field, dt, &kinematics, &attributes);
    let raw = |values: &[Vec3<R>]| -> Vec<[i64; 3]> {
        values
            .iter()
            .map(|v| [to_bits(v.x), to_bits(v.y), to_bits(v.z)])
            .collect()
    };
    prop_assert_eq!(raw(&engine.positions), raw(&general.positions));
    prop_assert_eq!(raw(&engine.velocities), raw(&general.velocities));
    prop_assert_eq!(engine_saturations, general_saturations);
    Ok(field.linear().is_some() && Fraction::new(dt).is_some())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3_000))]

    #[test]
    fn fused_step_matches_general_path_i32f32(case in case()) {
        check(&case, Fx::from_bits, Fx::to_bits)?;
    }

    #[test]
    fn fused_step_matches_general_path_i48f16(case in case()) {
        check(&case, FxI48F16::from_bits, FxI48F16::to_bits)?;
    }

    #[test]
    fn fused_step_matches_general_path_f64(case in case()) {
        // Rust leaves NaN payloads unspecified, so every NaN compares as one value.
        let canonical = |value: f64| if value.is_nan() { -1 } else { value.to_bits() as i64 }; // ok-det: test of the f64 format
        check(&case, |bits| f64::from_bits(bits as u64), canonical)?; // ok-det: test of the f64 format
    }
}

/// The fused step applies to the benchmark's kind of system, on blocks that saturate and on
/// blocks that do not.
#[test]
fn fused_step_is_taken_with_and_without_saturation() {
    let slot = |position: i64, velocity: i64| Slot {
        position: [position; 3],
        velocity: [velocity; 3],
        external_force: [1 << 32; 3],
        inv_mass: 1 << 32,
        group: 0,
    };
    for position in [1i64 << 40, i64::MAX - 1] {
        let case = Case {
            slots: (0..130).map(|i| slot(position - i, 5 << 32)).collect(),
            drags: vec![(429_496_730, None)],
            gravity_fields: vec![(1 << 32, None)],
            gravity: [0, -(42_125_000_000), 0],
            dt: 71_582_788,
        };
        assert!(check(&case, Fx::from_bits, Fx::to_bits).expect("same bits"));
    }
}
