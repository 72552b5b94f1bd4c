//! From scene description to particle system: every field is checked, then compiled
//! (inverse masses, unit directions, cone constants, handles for springs).
//!
//! Errors name the field relative to the particle description (`emitters[2].rate`); the
//! scene prefixes `particles.`.

use super::collisions::check_collision;
use super::contacts::ParticleContacts;
use super::damping::Damping;
use super::desc::{
    EmitterDesc, ForceDesc, Interval, MAX_CAPACITY, MAX_EMISSION_RATE, ParticlesDesc, Spread,
    SpringDesc,
};
use super::emitter::{EmissionShape, Emitter};
use super::forces::{AccelerationField, ForceGenerator, ForceSet};
use super::integrators::Scratch;
use super::storage::{NewParticle, ParticleStorage};
use super::system::ParticleSystem;
use super::template::SpawnTemplate;
use super::user_force::UserForceRegistry;
use crate::math::{Real, Vec3};
use crate::types::Handle;
use crate::types::SceneError;

/// `Ok` when `ok`, otherwise the error about `field`.
fn ensure(
    ok: bool,
    field: impl FnOnce() -> String,
    message: impl FnOnce() -> String,
) -> Result<(), SceneError> {
    if ok {
        Ok(())
    } else {
        Err(SceneError::new(field(), message()))
    }
}

/// Checks that `value` ≥ 0.
fn non_negative<R: Real>(value: R, field: impl FnOnce() -> String) -> Result<(), SceneError> {
    ensure(value >= R::ZERO, field, || {
        format!("must be ≥ 0 (got {value})")
    })
}

/// (mass, 1/mass) for a mass in kg; (0, 0) pins. Fails for negative masses and for masses
/// whose inverse the number format cannot hold.
fn compile_mass<R: Real>(mass: R, field: impl Fn() -> String) -> Result<(R, R), SceneError> {
    non_negative(mass, &field)?;
    if mass == R::ZERO {
        return Ok((R::ZERO, R::ZERO));
    }
    let inv_mass = mass.recip();
    ensure(inv_mass != R::ZERO && inv_mass < R::MAX, field, || {
        format!(
            "{mass} kg is out of the range the {} format can invert",
            R::NAME
        )
    })?;
    Ok((mass, inv_mass))
}

/// The unit vector along `v`, or an error when it is zero.
fn unit<R: Real>(v: Vec3<R>, field: impl FnOnce() -> String) -> Result<Vec3<R>, SceneError> {
    match v.try_normalize() {
        Some((unit, _)) => Ok(unit),
        None => Err(SceneError::new(field(), "must not be the zero vector")),
    }
}

impl<R: Real> ParticleSystem<R> {
    /// Checks `desc` and builds the system at tick 0: particle `i` of the description in
    /// slot `i` with generation 0, emitters on or off as described, accumulators at 0.
    pub fn from_desc(desc: &ParticlesDesc<R>) -> Result<Self, SceneError> {
        let capacity = desc.capacity;
        ensure(
            (1..=MAX_CAPACITY).contains(&capacity),
            || "capacity".into(),
            || format!("must be 1 to {MAX_CAPACITY} (got {capacity})"),
        )?;
        ensure(
            desc.particles.len() <= capacity as usize,
            || "particles".into(),
            || {
                format!(
                    "{} particles do not fit in capacity {capacity}",
                    desc.particles.len()
                )
            },
        )?;

        let mut storage = ParticleStorage::new(capacity);
        for (i, particle) in desc.particles.iter().enumerate() {
            let (mass, inv_mass) = compile_mass(particle.mass, || format!("particles[{i}].mass"))?;
            non_negative(particle.lifetime, || format!("particles[{i}].lifetime"))?;
            ensure(
                inv_mass != R::ZERO || particle.velocity == Vec3::ZERO,
                || format!("particles[{i}].velocity"),
                || "a pinned particle (mass 0) starts at rest".into(),
            )?;
            storage.allocate(NewParticle {
                position: particle.position,
                velocity: particle.velocity,
                mass,
                inv_mass,
                group: particle.group,
                lifetime: particle.lifetime,
            });
        }

        let templates = desc
            .templates
            .iter()
            .enumerate()
            .map(|(i, template)| {
                let (mass, inv_mass) =
                    compile_mass(template.mass, || format!("templates[{i}].mass"))?;
                non_negative(template.lifetime, || format!("templates[{i}].lifetime"))?;
                Ok(SpawnTemplate {
                    mass,
                    inv_mass,
                    group: template.group,
                    lifetime: template.lifetime,
                })
            })
            .collect::<Result<Vec<_>, SceneError>>()?;

        let emitters = desc
            .emitters
            .iter()
            .enumerate()
            .map(|(i, emitter)| {
                compile_emitter(emitter).map_err(|e| e.within(&format!("emitters[{i}]")))
            })
            .collect::<Result<Vec<_>, SceneError>>()?;

        let mut forces = ForceSet::default();
        for (i, force) in desc.forces.iter().enumerate() {
            compile_force(force, i as u32, desc.particles.len(), &mut forces)
                .map_err(|e| e.within(&format!("forces[{i}]")))?;
        }

        for (i, collision) in desc.collisions.iter().enumerate() {
            check_collision(collision).map_err(|e| e.within(&format!("collisions[{i}]")))?;
            ensure(
                !desc.collisions[..i]
                    .iter()
                    .any(|c| c.group == collision.group),
                || format!("collisions[{i}].group"),
                || format!("group {} already has an entry", collision.group),
            )?;
        }
        let mut collisions = desc.collisions.clone();
        collisions.sort_by_key(|c| c.group);
        let contacts = desc
            .contacts
            .as_ref()
            .map(|contacts| {
                ParticleContacts::from_desc(contacts, desc.particles.len())
                    .map_err(|e| e.within("contacts"))
            })
            .transpose()?;

        Ok(Self {
            integrator: desc.integrator,
            storage,
            templates,
            emitters,
            forces,
            collisions,
            contacts,
            accelerations_current: false,
            last_gravity: Vec3::ZERO,
            external_forces_pending: false,
            user_forces: UserForceRegistry::default(),
            scratch: Scratch::default(),
        })
    }
}

/// Checks an interval `[min, max]` with 0 ≤ min ≤ max.
fn check_interval<R: Real>(interval: Interval<R>, field: &str) -> Result<(), SceneError> {
    non_negative(interval.min, || format!("{field}.min"))?;
    ensure(
        interval.min <= interval.max,
        || format!("{field}.max"),
        || format!("must be ≥ min (got {} < {})", interval.max, interval.min),
    )
}

/// Checks and compiles one emitter; field paths are relative to the emitter.
fn compile_emitter<R: Real>(desc: &EmitterDesc<R>) -> Result<Emitter<R>, SceneError> {
    non_negative(desc.rate, || "rate".into())?;
    ensure(
        desc.rate <= R::from_int(MAX_EMISSION_RATE),
        || "rate".into(),
        || {
            format!(
                "must be at most {MAX_EMISSION_RATE} per second (got {})",
                desc.rate
            )
        },
    )?;
    check_interval(desc.speed, "speed")?;
    check_interval(desc.lifetime, "lifetime")?;
    let immortal = desc.lifetime.min == R::ZERO && desc.lifetime.max == R::ZERO;
    ensure(
        immortal || desc.lifetime.min > R::ZERO,
        || "lifetime.min".into(),
        || "must be > 0 unless max is 0 too (a drawn 0 would mean immortal)".into(),
    )?;
    let (mass, inv_mass) = compile_mass(desc.mass, || "mass".into())?;
    let shape = match desc.spread {
        Spread::Cone { axis, half_angle } => {
            let axis = unit(axis, || "spread.axis".into())?;
            ensure(
                half_angle >= R::ZERO && half_angle <= R::PI,
                || "spread.half_angle".into(),
                || format!("must be in [0, π] radians (got {half_angle})"),
            )?;
            let tangent = axis.any_orthonormal();
            EmissionShape::Cone {
                axis,
                tangent,
                bitangent: axis.cross(tangent),
                one_minus_cos_half_angle: R::ONE - half_angle.cos(),
            }
        }
        Spread::Box {
            half_extents,
            direction,
        } => {
            for (axis, extent) in ["x", "y", "z"].into_iter().zip(half_extents.to_array()) {
                non_negative(extent, || format!("spread.half_extents.{axis}"))?;
            }
            EmissionShape::Box {
                half_extents,
                direction: unit(direction, || "spread.direction".into())?,
            }
        }
    };
    Ok(Emitter {
        position: desc.position,
        rate: desc.rate,
        shape,
        speed: desc.speed,
        lifetime: desc.lifetime,
        mass,
        inv_mass,
        group: desc.group,
        on: desc.on,
        accumulator: R::ZERO,
    })
}

/// Checks a spring's parameters; field paths are relative to the force.
fn check_spring<R: Real>(spring: &SpringDesc<R>) -> Result<(), SceneError> {
    non_negative(spring.stiffness, || "spring.stiffness".into())?;
    non_negative(spring.damping, || "spring.damping".into())?;
    non_negative(spring.rest_length, || "spring.rest_length".into())
}

/// The handle of scene particle `index` (slot `index`, generation 0), or an error naming
/// `field` when there is no such particle.
fn scene_particle(index: u32, particle_count: usize, field: &str) -> Result<Handle, SceneError> {
    ensure(
        (index as usize) < particle_count,
        || field.to_owned(),
        || format!("no particle {index}: the scene has {particle_count}"),
    )?;
    Ok(Handle::new(index, 0))
}

/// Checks one force description and adds its compiled form to `forces`; field paths are
/// relative to the force.
fn compile_force<R: Real>(
    desc: &ForceDesc<R>,
    scene_index: u32,
    particle_count: usize,
    forces: &mut ForceSet<R>,
) -> Result<(), SceneError> {
    match *desc {
        ForceDesc::Gravity { scale, group } => {
            forces
                .fields
                .push(AccelerationField::Gravity { scale, group });
        }
        ForceDesc::LinearDrag { coefficient, group } => {
            non_negative(coefficient, || "coefficient".into())?;
            forces
                .generators
                .push(ForceGenerator::LinearDrag { coefficient, group });
        }
        ForceDesc::QuadraticDrag { coefficient, group } => {
            non_negative(coefficient, || "coefficient".into())?;
            forces
                .generators
                .push(ForceGenerator::QuadraticDrag { coefficient, group });
        }
        ForceDesc::Damping {
            kept_per_second,
            group,
        } => {
            ensure(
                kept_per_second > R::ZERO && kept_per_second <= R::ONE,
                || "kept_per_second".into(),
                || format!("must be in (0, 1] (got {kept_per_second})"),
            )?;
            forces.dampings.push(Damping::new(kept_per_second, group));
        }
        ForceDesc::AnchoredSpring {
            particle,
            anchor,
            spring,
        } => {
            let particle = scene_particle(particle, particle_count, "particle")?;
            check_spring(&spring)?;
            forces.generators.push(ForceGenerator::AnchoredSpring {
                particle,
                anchor,
                spring,
            });
        }
        ForceDesc::Spring {
            first,
            second,
            spring,
        } => {
            let first_handle = scene_particle(first, particle_count, "first")?;
            let second_handle = scene_particle(second, particle_count, "second")?;
            ensure(
                first != second,
                || "second".into(),
                || format!("a spring needs two different particles (both are {first})"),
            )?;
            check_spring(&spring)?;
            forces.generators.push(ForceGenerator::Spring {
                first: first_handle,
                second: second_handle,
                spring,
            });
        }
        ForceDesc::PointGravity {
            centre,
            gm,
            softening,
            group,
        } => {
            non_negative(softening, || "softening".into())?;
            forces.fields.push(AccelerationField::PointGravity {
                centre,
                gm,
                softening_squared: softening * softening,
                group,
            });
        }
        ForceDesc::User { ref name } => {
            ensure(
                !name.is_empty(),
                || "name".into(),
                || "must not be empty".into(),
            )?;
            forces.generators.push(ForceGenerator::User {
                name: name.clone(),
                scene_index,
            });
        }
    }
    Ok(())
}
