//! The plugin: where the world steps, and the systems around the step.

use bevy::prelude::*;
use fixstep::math::Fx;
use fixstep::scene::Scene;

use super::events::PhysicsEvent;
use super::interpolate::interpolate;
use super::link::LinkQueue;
use super::rollback::register_rollback;
use super::scene_build::build_world;
use super::step::{Spawning, after_load, queue_commands, step_world, sync_poses};

/// Where the world steps.
#[derive(Resource, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stepping {
    /// Bevy's `FixedUpdate`, whose rate the plugin sets to the scene's tick rate.
    FixedUpdate,
    /// bevy_ggrs's `GgrsSchedule` (add `GgrsPlugin` too), with the world's snapshot and
    /// checksum registered for rollback; the plugin sets `RollbackFrameRate` to the scene's
    /// tick rate.
    Ggrs,
}

/// The plugin's systems in the step schedule, in order: game systems that give commands
/// ([`FixstepWorld::push`](super::FixstepWorld::push)) or spawn and despawn bodies run
/// `.before(FixstepSystems::Step)`; those that read the new state `.after(..)`.
#[derive(SystemSet, Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FixstepSystems {
    /// Queue the component changes as commands, step, link, copy the poses.
    Step,
}

/// The scene the world is built from at `PostStartup` (taken then).
#[derive(Resource)]
pub(crate) struct BaseScene(pub Scene<Fx>);

/// Steps a fixstep world built from `scene` (plus the startup entities' bodies, joints and
/// characters) once per tick in the chosen schedule.
pub struct FixstepPlugin {
    scene: Scene<Fx>,
    stepping: Stepping,
}

impl FixstepPlugin {
    /// Steps in `FixedUpdate`.
    pub fn new(scene: Scene<Fx>) -> Self {
        Self {
            scene,
            stepping: Stepping::FixedUpdate,
        }
    }

    /// Steps in bevy_ggrs's `GgrsSchedule`, with rollback and checksums registered.
    pub fn ggrs(scene: Scene<Fx>) -> Self {
        Self {
            scene,
            stepping: Stepping::Ggrs,
        }
    }
}

impl Plugin for FixstepPlugin {
    fn build(&self, app: &mut App) {
        let tick_rate = self.scene.tick_rate.max(1);
        app.insert_resource(BaseScene(self.scene.clone()))
            .insert_resource(self.stepping)
            .init_resource::<LinkQueue>()
            .init_resource::<Spawning>()
            .add_message::<PhysicsEvent>()
            .add_systems(PostStartup, build_world)
            .add_systems(Update, interpolate);
        let systems = (queue_commands, step_world, sync_poses)
            .chain()
            .in_set(FixstepSystems::Step);
        match self.stepping {
            Stepping::FixedUpdate => {
                app.insert_resource(Time::<Fixed>::from_hz(f64::from(tick_rate)))
                    .add_systems(FixedUpdate, systems);
            }
            Stepping::Ggrs => {
                register_rollback(app);
                app.insert_resource(bevy_ggrs::RollbackFrameRate(tick_rate as usize))
                    .add_systems(bevy_ggrs::GgrsSchedule, systems)
                    .add_systems(
                        bevy_ggrs::LoadWorld,
                        after_load.in_set(bevy_ggrs::LoadWorldSystems::Mapping),
                    );
            }
        }
    }
}
