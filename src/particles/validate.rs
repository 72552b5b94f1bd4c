//! The invariants of a particle system's state, checked when a state comes from outside
//! (a snapshot file) rather than from [`ParticleSystem::from_desc`] and the step.
//!
//! A system built and stepped by the engine always satisfies them; a decoded one might not,
//! and the step relies on them: every per-slot array has one entry per slot (indexing), dead
//! slots carry no mass, lifetime or force (the integrators skip slots by `inv_mass == 0`, and
//! ageing kills only live slots), the slot allocator's counters agree with the alive flags
//! (recycling order), and emitters stay within the rates a scene may ask for (the emission
//! loop runs once per owed particle).

use super::collisions::check_collision;
use super::desc::{MAX_CAPACITY, MAX_EMISSION_RATE};
use super::storage::ParticleStorage;
use super::system::ParticleSystem;
use crate::math::{Real, Vec3};
use crate::types::SceneError;

impl<R: Real> ParticleSystem<R> {
    /// Checks the invariants the step relies on; the error names the offending field, as a
    /// path from `particles`.
    pub fn validate(&self) -> Result<(), SceneError> {
        validate_storage(&self.storage).map_err(|e| e.within("storage"))?;
        for (i, template) in self.templates.iter().enumerate() {
            check_mass(template.mass, template.inv_mass)
                .map_err(|e| e.within(&format!("templates[{i}]")))?;
        }
        for (i, collision) in self.collisions.iter().enumerate() {
            let at = format!("collisions[{i}]");
            if i > 0 && self.collisions[i - 1].group >= collision.group {
                return Err(SceneError::new("group", "groups must ascend, each once").within(&at));
            }
            check_collision(collision).map_err(|e| e.within(&at))?;
        }
        if let Some(contacts) = &self.contacts {
            contacts.validate().map_err(|e| e.within("contacts"))?;
        }
        let max_rate = R::from_int(MAX_EMISSION_RATE);
        for (i, emitter) in self.emitters.iter().enumerate() {
            let at = format!("emitters[{i}]");
            if emitter.rate < R::ZERO || emitter.rate > max_rate {
                return Err(SceneError::new(
                    "rate",
                    format!("must be 0 to {MAX_EMISSION_RATE} particles per second"),
                )
                .within(&at));
            }
            if emitter.accumulator < R::ZERO || emitter.accumulator >= R::ONE {
                return Err(SceneError::new("accumulator", "must be in [0, 1)").within(&at));
            }
            check_mass(emitter.mass, emitter.inv_mass).map_err(|e| e.within(&at))?;
        }
        Ok(())
    }
}

/// A mass and its inverse: both zero (pinned) or both positive.
fn check_mass<R: Real>(mass: R, inv_mass: R) -> Result<(), SceneError> {
    let pinned = mass == R::ZERO && inv_mass == R::ZERO;
    if pinned || (mass > R::ZERO && inv_mass > R::ZERO) {
        Ok(())
    } else {
        Err(SceneError::new(
            "mass",
            "mass and inverse mass must both be 0 (pinned) or both be positive",
        ))
    }
}

fn validate_storage<R: Real>(storage: &ParticleStorage<R>) -> Result<(), SceneError> {
    let slots = storage.slot_count();
    let k = &storage.kinematics;
    let a = &storage.attributes;
    let lengths = [
        ("kinematics.positions", k.positions.len()),
        ("kinematics.velocities", k.velocities.len()),
        ("kinematics.previous_positions", k.previous_positions.len()),
        (
            "kinematics.has_previous_position",
            k.has_previous_position.len(),
        ),
        ("kinematics.accelerations", k.accelerations.len()),
        ("attributes.inv_masses", a.inv_masses.len()),
        ("attributes.masses", a.masses.len()),
        ("attributes.external_forces", a.external_forces.len()),
        ("attributes.lifetimes", a.lifetimes.len()),
        ("attributes.groups", a.groups.len()),
        ("attributes.generations", a.generations.len()),
    ];
    for (field, len) in lengths {
        if len != slots {
            return Err(SceneError::new(
                field,
                format!("has {len} entries for {slots} slots (attributes.alive)"),
            ));
        }
    }
    let capacity = storage.capacity();
    if capacity == 0 || capacity > MAX_CAPACITY {
        return Err(SceneError::new(
            "capacity",
            format!("must be 1 to {MAX_CAPACITY} (got {capacity})"),
        ));
    }
    if slots > capacity as usize {
        return Err(SceneError::new(
            "attributes.alive",
            format!("{slots} slots exceed the capacity {capacity}"),
        ));
    }
    let live = a.alive.iter().filter(|&&alive| alive).count();
    if storage.live_count() as usize != live {
        return Err(SceneError::new(
            "live_count",
            format!("is {} but {live} slots are alive", storage.live_count()),
        ));
    }
    let first_dead = a.alive.iter().position(|&alive| !alive).unwrap_or(slots);
    if storage.lowest_free() as usize != first_dead {
        return Err(SceneError::new(
            "lowest_free",
            format!(
                "is {} but the lowest dead slot is {first_dead}",
                storage.lowest_free()
            ),
        ));
    }
    for i in 0..slots {
        if a.alive[i] {
            check_mass(a.masses[i], a.inv_masses[i])
                .map_err(|e| e.within(&format!("attributes[{i}]")))?;
            if a.lifetimes[i] < R::ZERO {
                return Err(SceneError::new(
                    format!("attributes.lifetimes[{i}]"),
                    "must not be negative",
                ));
            }
        } else if a.masses[i] != R::ZERO
            || a.inv_masses[i] != R::ZERO
            || a.lifetimes[i] != R::ZERO
            || a.external_forces[i] != Vec3::ZERO
        {
            return Err(SceneError::new(
                format!("attributes[{i}]"),
                "a dead slot must have zero mass, inverse mass, lifetime and external force",
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use crate::fixstep_scenes::particles::fountain;
    use crate::math::{Fx, Real};
    use crate::particles::{ParticleSystem, ParticlesDesc};

    /// The fountain's particle system after 400 steps, so that slots are alive and dead.
    fn system() -> ParticleSystem<Fx> {
        let desc: ParticlesDesc<Fx> = fountain();
        let mut system = ParticleSystem::from_desc(&desc).expect("valid");
        let mut rng = crate::math::rng::Pcg32::new(1, 2);
        for _ in 0..400 {
            system.step(Fx::from_ratio(1, 60), crate::math::Vec3::ZERO, &mut rng);
            system.end_tick();
        }
        system
    }

    fn field_of(system: &ParticleSystem<Fx>) -> String {
        system.validate().expect_err("invalid").field
    }

    #[test]
    fn a_stepped_system_is_valid() {
        system().validate().expect("valid");
    }

    #[test]
    fn a_short_array_is_named() {
        let mut s = system();
        s.storage.kinematics.velocities.pop();
        assert_eq!(field_of(&s), "storage.kinematics.velocities");
    }

    #[test]
    fn a_wrong_live_count_is_named() {
        let mut s = system();
        s.storage.attributes.alive[0] = !s.storage.attributes.alive[0];
        let field = field_of(&s);
        assert!(field == "storage.live_count", "{field}");
    }

    #[test]
    fn a_dead_slot_with_mass_is_named() {
        let mut s = system();
        let dead = s.storage.attributes.alive.iter().position(|a| !a);
        let i = dead.expect("the fountain recycles slots");
        s.storage.attributes.masses[i] = Fx::ONE;
        assert_eq!(field_of(&s), format!("storage.attributes[{i}]"));
    }

    #[test]
    fn a_negative_mass_is_named() {
        let mut s = system();
        let i = s
            .storage
            .attributes
            .alive
            .iter()
            .position(|&a| a)
            .expect("alive");
        s.storage.attributes.masses[i] = -Fx::ONE;
        assert_eq!(field_of(&s), format!("storage.attributes[{i}].mass"));
    }

    #[test]
    fn an_emitter_owing_too_much_is_named() {
        let mut s = system();
        s.emitters[0].accumulator = Fx::from_int(1 << 30);
        assert_eq!(field_of(&s), "emitters[0].accumulator");
    }
}
