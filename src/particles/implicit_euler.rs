//! The implicit Euler step of the particles: the springs and linear drags of the force
//! list become the system of [`implicit_springs`](crate::math::implicit_springs), every
//! other force acts explicitly through a(x₀, v₀).

use super::forces::{ForceField, ForceGenerator};
use super::groups::applies_to;
use super::storage::{Attributes, Kinematics};
use crate::math::implicit_springs::ImplicitSprings;
use crate::math::{Real, Vec3};

/// (M + h C + h² K) Δv = h M a(x₀, v₀) − h² K v₀, then v ← v₀ + Δv and x ← x₀ + h v for
/// every movable particle, with `acceleration` a working array of the slot count and
/// `solver` the system's working arrays.
pub(crate) fn step<R: Real>(
    h: R,
    kinematics: &mut Kinematics<R>,
    attributes: &Attributes<R>,
    field: &ForceField<'_, R>,
    acceleration: &mut [Vec3<R>],
    solver: &mut ImplicitSprings<R>,
) {
    field.accelerations(&kinematics.positions, &kinematics.velocities, acceleration);
    let x = &kinematics.positions;
    let movable = |i: usize| attributes.is_movable(i);
    solver.begin(x.len());
    let generators = &field.force_set().generators;
    for generator in generators {
        match *generator {
            ForceGenerator::AnchoredSpring {
                particle,
                anchor,
                ref spring,
            } => {
                if let Some(i) = attributes.resolve(particle) {
                    solver.add_spring(i, None, spring, x[i] - anchor, h, movable);
                }
            }
            ForceGenerator::Spring {
                first,
                second,
                ref spring,
            } => {
                if let (Some(i), Some(j)) = (attributes.resolve(first), attributes.resolve(second))
                {
                    solver.add_spring(i, Some(j), spring, x[i] - x[j], h, movable);
                }
            }
            _ => {}
        }
    }
    let drag = |i: usize| {
        generators
            .iter()
            .fold(R::ZERO, |sum, generator| match *generator {
                ForceGenerator::LinearDrag { coefficient, group }
                    if applies_to(group, attributes.groups[i]) =>
                {
                    sum + coefficient
                }
                _ => sum,
            })
    };
    let (delta_v, _) = solver.solve(
        h,
        &attributes.masses,
        drag,
        acceleration,
        &kinematics.velocities,
    );
    for (i, &dv) in delta_v.iter().enumerate() {
        if attributes.is_movable(i) {
            let v = kinematics.velocities[i] + dv;
            kinematics.velocities[i] = v;
            kinematics.positions[i] = kinematics.positions[i].add_scaled(v, h);
        }
    }
}
