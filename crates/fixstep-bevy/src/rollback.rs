//! bevy_ggrs registration: the world is saved as a snapshot every frame, restored on a
//! rollback, and its checksum is what GGRS compares between peers and in a sync test.

use bevy::prelude::App;
use bevy_ggrs::{ResourceSnapshotPlugin, RollbackApp, Strategy};
use fixstep::math::Fx;
use fixstep::world::WorldState;

use super::components::{BodyLink, Character, CharacterLink, Joint, JointLink, RigidBody};
use super::world::FixstepWorld;

/// bevy_ggrs's snapshot strategy for [`FixstepWorld`]: stores `World::snapshot()`,
/// restores it exactly with `World::restore` (and forgets the inputs of later ticks).
pub struct WorldSnapshotStrategy;

impl Strategy for WorldSnapshotStrategy {
    type Target = FixstepWorld;
    type Stored = WorldState<Fx>;

    fn store(target: &FixstepWorld) -> WorldState<Fx> {
        target.world.snapshot()
    }

    /// Never used: the world exists from `PostStartup` on, before the first frame is saved,
    /// so a rollback always updates it in place.
    fn load(_stored: &WorldState<Fx>) -> FixstepWorld {
        unreachable!("fixstep-bevy: the world is restored in place, never rebuilt")
    }

    fn update(target: &mut FixstepWorld, stored: &WorldState<Fx>) {
        target.restore(stored);
    }
}

/// Registers the world and the links for rollback, the world's checksum for desync
/// detection, and `Rollback` as a required component of the plugin's components. [`FixstepPlugin::ggrs`](super::FixstepPlugin::ggrs) calls it.
pub fn register_rollback(app: &mut App) {
    app.add_plugins(ResourceSnapshotPlugin::<WorldSnapshotStrategy>::default())
        .checksum_resource::<FixstepWorld>(FixstepWorld::checksum)
        .rollback_component_with_copy::<BodyLink>()
        .rollback_component_with_copy::<JointLink>()
        .rollback_component_with_copy::<CharacterLink>()
        // Every entity of a body, joint or character is a rollback entity: one spawned
        // after a frame is despawned when that frame is loaded, and spawned again (with the
        // same body) when the frames are simulated again.
        .require_rollback::<RigidBody>()
        .require_rollback::<Joint>()
        .require_rollback::<Character>();
}
