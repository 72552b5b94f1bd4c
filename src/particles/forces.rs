//! Force generators in compiled form, and the evaluation of the acceleration a(x, v) of
//! every particle.
//!
//! Evaluation is a pure function of the positions and velocities it is given (plus masses,
//! groups, the tick's external forces and gravity), so RK4 can evaluate it at its stages.
//! It runs in three passes over the slots, each in ascending slot order:
//!
//! 1. `F_i ← external force of the tick`;
//! 2. every force generator in scene order adds to `F_i` (drag, springs, user forces);
//! 3. `a_i ← F_i / m_i + Σ acceleration fields` (gravity, point gravity), fields in scene
//!    order; pinned and dead slots get `a_i = 0`.

use serde::{Deserialize, Serialize};

use super::damping::Damping;
use super::groups::applies_to;
use super::storage::Attributes;
use super::user_force::{ParticleView, UserForceRegistry};
use crate::math::spring::{SpringDesc, spring_force};
use crate::math::{Fraction, Real, Vec3};
use crate::types::Handle;

/// The compiled force list of a system, split by how each entry acts.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct ForceSet<R: Real> {
    /// Mass-independent accelerations, in scene order.
    pub fields: Vec<AccelerationField<R>>,
    /// Forces, in scene order.
    pub generators: Vec<ForceGenerator<R>>,
    /// Velocity damping, applied after each step, in scene order.
    pub dampings: Vec<Damping<R>>,
}

/// An acceleration that does not depend on the particle's mass.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) enum AccelerationField<R: Real> {
    /// a = scale · g, m/s².
    Gravity { scale: R, group: Option<u16> },
    /// a = −GM r (|r|² + ε²)^{−3/2}, m/s², r = x − centre.
    PointGravity {
        centre: Vec3<R>,
        gm: R,
        softening_squared: R,
        group: Option<u16>,
    },
}

/// A generator of forces (N).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) enum ForceGenerator<R: Real> {
    /// F = −k v.
    LinearDrag { coefficient: R, group: Option<u16> },
    /// F = −k |v| v.
    QuadraticDrag { coefficient: R, group: Option<u16> },
    /// A damped spring from a fixed anchor to a particle.
    AnchoredSpring {
        particle: Handle,
        anchor: Vec3<R>,
        spring: SpringDesc<R>,
    },
    /// A damped spring between two particles.
    Spring {
        first: Handle,
        second: Handle,
        spring: SpringDesc<R>,
    },
    /// A registered [`ParticleForce`](super::ParticleForce); `scene_index` is its position in
    /// the scene's force list, for error messages.
    User { name: String, scene_index: u32 },
}

/// Softened point-gravity acceleration, m/s²: a = −GM r (|r|² + ε²)^{−3/2}, with `offset`
/// r = x − centre (m), `gm` in m³/s² and `softening_squared` ε² in m². One `rsqrt`, no
/// division.
#[inline]
pub(crate) fn point_gravity_acceleration<R: Real>(
    offset: Vec3<R>,
    gm: R,
    softening_squared: R,
) -> Vec3<R> {
    let inv_distance = (offset.length_squared() + softening_squared).rsqrt();
    offset * -(gm * inv_distance * inv_distance * inv_distance)
}

/// Adds the linear drag F = −k v (N) of `coefficient` k (kg/s), restricted to `group`, to
/// the `forces` of the movable particles with velocities `velocities` (m/s). All slices
/// cover the same slots.
#[inline]
pub(crate) fn add_linear_drag<R: Real>(
    coefficient: R,
    group: Option<u16>,
    velocities: &[Vec3<R>],
    inv_masses: &[R],
    groups: &[u16],
    forces: &mut [Vec3<R>],
) {
    let particles = forces
        .iter_mut()
        .zip(velocities)
        .zip(inv_masses.iter().zip(groups));
    for ((force, &velocity), (&inv_mass, &particle_group)) in particles {
        if inv_mass != R::ZERO && applies_to(group, particle_group) {
            *force -= velocity * coefficient;
        }
    }
}

/// Turns the forces F (N) in `forces` into accelerations a = g + F/m (m/s²) in place, with
/// `uniform_gravity` g (m/s²) and 1/m from `inv_masses` (1/kg); pinned and dead slots get
/// a = 0. Both slices cover the same slots.
#[inline]
pub(crate) fn forces_to_accelerations<R: Real>(
    uniform_gravity: Vec3<R>,
    inv_masses: &[R],
    forces: &mut [Vec3<R>],
) {
    for (acceleration, &inv_mass) in forces.iter_mut().zip(inv_masses) {
        *acceleration = if inv_mass == R::ZERO {
            Vec3::ZERO
        } else {
            uniform_gravity.add_scaled(*acceleration, inv_mass)
        };
    }
}

/// The most linear drags a [`LinearField`] holds.
const MAX_LINEAR_DRAGS: usize = 4;

/// A force field in which each particle's acceleration depends only on its own velocity,
/// linearly: a = g + (F_ext − Σⱼ kⱼ v)/m, with g uniform gravity (m/s²) and up to
/// [`MAX_LINEAR_DRAGS`] linear drags of coefficients 0 ≤ kⱼ < 0.5 kg/s (each a
/// [`Fraction`]). The fused
/// semi-implicit Euler step handles exactly these fields.
pub(crate) struct LinearField<R: Real> {
    /// g, m/s².
    pub uniform_gravity: Vec3<R>,
    drags: [(Fraction<R>, Option<u16>); MAX_LINEAR_DRAGS],
    drag_count: usize,
}

impl<R: Real> LinearField<R> {
    /// (kⱼ, group restriction) of each linear drag, in scene order.
    pub fn drags(&self) -> &[(Fraction<R>, Option<u16>)] {
        &self.drags[..self.drag_count]
    }
}

/// Everything force evaluation needs besides the positions and velocities, fixed for one
/// step.
pub(crate) struct ForceField<'a, R: Real> {
    forces: &'a ForceSet<R>,
    user_forces: &'a UserForceRegistry<R>,
    attributes: &'a Attributes<R>,
    /// World gravity g, m/s².
    gravity: Vec3<R>,
    /// Σ scale · g over the gravity fields without a group restriction, m/s².
    uniform_gravity: Vec3<R>,
    /// Whether any field depends on the particle (a group restriction or point gravity);
    /// when none does, the per-particle loop over fields is skipped.
    per_particle_fields: bool,
}

impl<'a, R: Real> ForceField<'a, R> {
    /// The field of `forces` acting on the particles described by `attributes`, under the
    /// world gravity `gravity` (m/s²).
    pub fn new(
        forces: &'a ForceSet<R>,
        user_forces: &'a UserForceRegistry<R>,
        attributes: &'a Attributes<R>,
        gravity: Vec3<R>,
    ) -> Self {
        let uniform_gravity = forces
            .fields
            .iter()
            .fold(Vec3::ZERO, |sum, field| match *field {
                AccelerationField::Gravity { scale, group: None } => sum + gravity * scale,
                _ => sum,
            });
        let per_particle_fields = forces
            .fields
            .iter()
            .any(|field| !matches!(field, AccelerationField::Gravity { group: None, .. }));
        Self {
            forces,
            user_forces,
            attributes,
            gravity,
            uniform_gravity,
            per_particle_fields,
        }
    }

    /// The compiled force list the field evaluates.
    pub fn force_set(&self) -> &'a ForceSet<R> {
        self.forces
    }

    /// The field as a [`LinearField`], when it is one: no field depends on the particle and
    /// the generators are at most [`MAX_LINEAR_DRAGS`] linear drags with 0 ≤ k < 0.5 kg/s.
    pub fn linear(&self) -> Option<LinearField<R>> {
        if self.per_particle_fields || self.forces.generators.len() > MAX_LINEAR_DRAGS {
            return None;
        }
        let mut field = LinearField {
            uniform_gravity: self.uniform_gravity,
            drags: [(Fraction::ZERO, None); MAX_LINEAR_DRAGS],
            drag_count: 0,
        };
        for generator in &self.forces.generators {
            let ForceGenerator::LinearDrag { coefficient, group } = *generator else {
                return None;
            };
            field.drags[field.drag_count] = (Fraction::new(coefficient)?, group);
            field.drag_count += 1;
        }
        Some(field)
    }

    /// Writes a_i(x, v) (m/s²) for every slot into `out`, given positions `x` (m) and
    /// velocities `v` (m/s) of every slot. All three slices have the slot count as length.
    pub fn accelerations(&self, x: &[Vec3<R>], v: &[Vec3<R>], out: &mut [Vec3<R>]) {
        let attributes = self.attributes;
        out.copy_from_slice(&attributes.external_forces);
        for generator in &self.forces.generators {
            self.add_forces(generator, x, v, out);
        }
        if !self.per_particle_fields {
            forces_to_accelerations(self.uniform_gravity, &attributes.inv_masses, out);
            return;
        }
        for (i, acceleration) in out.iter_mut().enumerate() {
            let inv_mass = attributes.inv_masses[i];
            if inv_mass == R::ZERO {
                *acceleration = Vec3::ZERO;
                continue;
            }
            let mut total = self.uniform_gravity.add_scaled(*acceleration, inv_mass);
            let group = attributes.groups[i];
            for field in &self.forces.fields {
                match *field {
                    AccelerationField::Gravity {
                        scale,
                        group: Some(only),
                    } if only == group => total += self.gravity * scale,
                    AccelerationField::PointGravity {
                        centre,
                        gm,
                        softening_squared,
                        group: restriction,
                    } if applies_to(restriction, group) => {
                        total += point_gravity_acceleration(x[i] - centre, gm, softening_squared);
                    }
                    _ => {}
                }
            }
            *acceleration = total;
        }
    }

    /// Adds the forces (N) of one generator to `forces`.
    fn add_forces(
        &self,
        generator: &ForceGenerator<R>,
        x: &[Vec3<R>],
        v: &[Vec3<R>],
        forces: &mut [Vec3<R>],
    ) {
        let attributes = self.attributes;
        match *generator {
            ForceGenerator::LinearDrag { coefficient, group } => add_linear_drag(
                coefficient,
                group,
                v,
                &attributes.inv_masses,
                &attributes.groups,
                forces,
            ),
            ForceGenerator::QuadraticDrag { coefficient, group } => {
                for (i, force) in forces.iter_mut().enumerate() {
                    if attributes.is_movable(i) && applies_to(group, attributes.groups[i]) {
                        *force -= v[i] * (coefficient * v[i].length());
                    }
                }
            }
            ForceGenerator::AnchoredSpring {
                particle,
                anchor,
                ref spring,
            } => {
                if let Some(i) = attributes.resolve(particle) {
                    forces[i] += spring_force(spring, x[i] - anchor, v[i]);
                }
            }
            ForceGenerator::Spring {
                first,
                second,
                ref spring,
            } => {
                if let (Some(i), Some(j)) = (attributes.resolve(first), attributes.resolve(second))
                {
                    let force = spring_force(spring, x[i] - x[j], v[i] - v[j]);
                    forces[i] += force;
                    forces[j] -= force;
                }
            }
            ForceGenerator::User { ref name, .. } => {
                if let Some(user_force) = self.user_forces.get(name) {
                    let view = ParticleView {
                        positions: x,
                        velocities: v,
                        inv_masses: &attributes.inv_masses,
                        groups: &attributes.groups,
                        alive: &attributes.alive,
                    };
                    user_force.accumulate(&view, forces);
                }
            }
        }
    }
}
