//! The scene: everything needed to build a world, in a human-readable form (RON files) that
//! also travels inside replay files.

use serde::{Deserialize, Serialize};

use super::mass_ratios::mass_ratio_warnings;
use super::simulation::input_at;
use crate::character::{CharacterDesc, CharacterSystem};
use crate::fluid::{FluidDesc, FluidSystem};
use crate::math::{Fx, Real, Vec3};
use crate::particles::{ParticleSystem, ParticlesDesc};
use crate::rigid::{JointsDesc, RigidDesc, RigidSystem};
use crate::soft::{SoftDesc, SoftSystem};
use crate::types::{SceneError, check_rates};
use crate::water::{WaterDesc, WaterSystem};
use crate::world::soft_coupling::SceneBodies;
use crate::world::{Settings, TickInput, World};

/// A scene: world settings, subsystem descriptions and an optional input script.
///
/// In RON every field but `name` may be left out; see `scenes/` for examples.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct Scene<R: Real = Fx> {
    /// Short name, as listed by `fixstep scenes`.
    pub name: String,
    /// One line saying what the scene shows.
    #[serde(default)]
    pub description: String,
    /// Gravitational acceleration, m/s². Default (0, −9.81, 0): y is up.
    #[serde(default = "default_gravity")]
    pub gravity: Vec3<R>,
    /// Ticks per simulated second. Default 60.
    #[serde(default = "default_tick_rate")]
    pub tick_rate: u32,
    /// Substeps per tick. Default 1.
    #[serde(default = "default_substeps")]
    pub substeps: u32,
    /// Seed of the world's random generator.
    #[serde(default)]
    pub seed: u64,
    /// How many ticks `fixstep run` simulates when not told otherwise. Default 600.
    #[serde(default = "default_ticks")]
    pub ticks: u64,
    /// Particles, emitters and their forces.
    #[serde(default)]
    pub particles: Option<ParticlesDesc<R>>,
    /// Rigid bodies and the contact solver's settings.
    #[serde(default)]
    pub rigid: Option<RigidDesc<R>>,
    /// A fluid in a tank. Left out of a written scene when absent, so scenes without one
    /// read as they did before fluids.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fluid: Option<FluidDesc<R>>,
    /// Soft bodies (cloth, rope, jelly), their colliders and the XPBD settings. Left out of
    /// a written scene when absent.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub soft: Option<SoftDesc<R>>,
    /// Joints between the rigid bodies (which the scene must have). Left out of a written
    /// scene when absent.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub joints: Option<JointsDesc<R>>,
    /// Kinematic characters ([`crate::character`]), driven by
    /// [`Command::MoveCharacter`](crate::types::Command::MoveCharacter) with the handle
    /// (index, 0). Left out of a written scene when empty.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub characters: Vec<CharacterDesc<R>>,
    /// A height-field water surface, and what floats on it. Left out of a written scene
    /// when absent.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub water_surface: Option<WaterDesc<R>>,
    /// Scripted inputs, fed to the world at their ticks by [`Simulation`](super::Simulation)
    /// (and so by `fixstep run`).
    #[serde(default)]
    pub script: Vec<TickInput<R>>,
}

fn default_gravity<R: Real>() -> Vec3<R> {
    Vec3::new(R::ZERO, -R::from_ratio(981, 100), R::ZERO)
}

fn default_tick_rate() -> u32 {
    60
}

fn default_substeps() -> u32 {
    1
}

fn default_ticks() -> u64 {
    600
}

impl<R: Real> Scene<R> {
    /// An empty scene with default settings.
    pub fn empty(name: &str) -> Self {
        Self {
            name: name.to_owned(),
            description: String::new(),
            gravity: default_gravity(),
            tick_rate: default_tick_rate(),
            substeps: default_substeps(),
            seed: 0,
            ticks: default_ticks(),
            particles: None,
            rigid: None,
            fluid: None,
            soft: None,
            joints: None,
            characters: Vec::new(),
            water_surface: None,
            script: Vec::new(),
        }
    }

    /// Checks every field and builds the world at tick 0. Pairs of rigid bodies whose mass
    /// ratio the solver cannot hold become warnings ([`World::warnings`],
    /// [`mass_ratios`](super::mass_ratios)).
    pub fn build(&self) -> Result<World<R>, SceneError> {
        check_rates(self.tick_rate, self.substeps)?;
        for (i, input) in self.script.iter().enumerate() {
            if i > 0 && input.tick <= self.script[i - 1].tick {
                return Err(SceneError::new(
                    format!("script[{i}].tick"),
                    format!(
                        "ticks must increase (got {} after {})",
                        input.tick,
                        self.script[i - 1].tick
                    ),
                ));
            }
        }
        self.check_spawns()?;
        let settings = Settings {
            gravity: self.gravity,
            tick_rate: self.tick_rate,
            substeps: self.substeps,
        };
        let mut world = World::new(settings, self.seed);
        if let Some(desc) = &self.particles {
            world
                .set_particles(ParticleSystem::from_desc(desc).map_err(|e| e.within("particles"))?);
        }
        if let Some(desc) = &self.rigid {
            let mut rigid = RigidSystem::from_desc(desc).map_err(|e| e.within("rigid"))?;
            if let Some(joints) = &self.joints {
                rigid.add_joints(joints).map_err(|e| e.within("joints"))?;
            }
            for warning in mass_ratio_warnings(&rigid) {
                world.add_build_warning(warning);
            }
            world.set_rigid(rigid);
        } else if self.joints.is_some() {
            return Err(SceneError::new(
                "joints",
                "joints join rigid bodies, and the scene has no `rigid` section",
            ));
        }
        if let Some(desc) = &self.fluid {
            let dt = R::from_ratio(1, i64::from(self.tick_rate) * i64::from(self.substeps));
            world.set_fluid(FluidSystem::from_desc(desc, dt).map_err(|e| e.within("fluid"))?);
        }
        if let Some(desc) = &self.soft {
            let dt = R::from_ratio(1, i64::from(self.tick_rate) * i64::from(self.substeps));
            let bodies = SceneBodies(world.rigid());
            let soft = SoftSystem::from_desc_with_bodies(desc, dt, &bodies)
                .map_err(|e| e.within("soft"))?;
            if soft.couples() && self.fluid.as_ref().is_some_and(|f| f.bodies.is_some()) {
                return Err(SceneError::new(
                    "soft",
                    "soft bodies coupled to rigid bodies and a fluid that meets them cannot \
                     share a scene yet: each steps the rigid bodies at its own rate",
                ));
            }
            world.set_soft(soft);
        }
        if !self.characters.is_empty() {
            world.set_characters(CharacterSystem::from_desc(&self.characters)?);
        }
        if let Some(desc) = &self.water_surface {
            let dt = R::from_ratio(1, i64::from(self.tick_rate) * i64::from(self.substeps));
            world.set_water(
                WaterSystem::from_desc(desc, dt, self.gravity)
                    .map_err(|e| e.within("water_surface"))?,
            );
        }
        Ok(world)
    }

    /// The scripted inputs for `tick`, if any. [`Simulation`](super::Simulation) feeds them
    /// to a world tick by tick.
    pub fn script_at(&self, tick: u64) -> Option<&TickInput<R>> {
        input_at(&self.script, tick)
    }
}
