//! fixstep in Bevy: a plugin that steps a deterministic fixstep [`World`](fixstep::world::World)
//! from Bevy's `FixedUpdate` (or bevy_ggrs's `GgrsSchedule`), with components for bodies,
//! colliders, joints and characters, poses copied to `Transform` with render interpolation,
//! the world's events as Bevy messages, scene queries as a system parameter, and, with
//! bevy_ggrs, the world's snapshot and checksum registered for rollback.
//!
//! The fixstep world is the simulation state: Bevy entities are linked to its bodies by
//! [`BodyLink`] handles, bodies spawned at run time become `SpawnBody` commands of the
//! world's input and despawned ones `Remove` commands, so every change is in the tick's
//! input, rolled back with the world and recorded in its replay. See `docs/bevy.md`.

pub mod box_game;
mod components;
mod events;
mod interpolate;
mod link;
mod plugin;
mod query;
mod rollback;
mod scene_build;
mod step;
mod world;

pub use components::{
    BodyLink, Character, CharacterLink, Collider, FixedTransform, FixedVelocity, Joint, JointLink,
    RenderPose, RigidBody,
};
pub use events::PhysicsEvent;
pub use plugin::{FixstepPlugin, FixstepSystems, Stepping};
pub use query::PhysicsQuery;
pub use rollback::{WorldSnapshotStrategy, register_rollback};
pub use world::{FixstepWorld, PLUGIN_PLAYER};

/// The plugin's types in one import.
pub mod prelude {
    pub use super::{
        BodyLink, Character, CharacterLink, Collider, FixedTransform, FixedVelocity, FixstepPlugin,
        FixstepSystems, FixstepWorld, Joint, JointLink, PhysicsEvent, PhysicsQuery, RenderPose,
        RigidBody, Stepping,
    };
}
