//! The world's events as Bevy messages, with the entities of the handles.

use bevy::prelude::{Entity, Message, Query};
use fixstep::rigid::{Event, EventKind};
use fixstep::world::Handle;

use super::components::{BodyLink, CharacterLink, JointLink};

/// One event of a tick (contact begin and end, sensor enter and exit, joint break,
/// character land and hit), sent as a Bevy message after the tick. Under rollback a
/// re-simulated tick sends its events again: game logic that must roll back reads
/// [`FixstepWorld::world`](super::FixstepWorld::world)`.events()` in the step schedule;
/// messages suit presentation (sounds, particles).
#[derive(Message, Clone, Copy, Debug, PartialEq, Eq)]
pub struct PhysicsEvent {
    /// The tick during which it happened.
    pub tick: u64,
    /// What happened.
    pub kind: EventKind,
    /// The first object: the body of lower slot, the joint, or the character.
    pub a: Handle,
    /// The second body, if any.
    pub b: Option<Handle>,
    /// The entity linked to `a`, if any.
    pub entity_a: Option<Entity>,
    /// The entity linked to `b`, if any.
    pub entity_b: Option<Entity>,
}

/// Handle → entity, for the bodies, characters and joints, sorted by handle.
pub(crate) struct EntityTable {
    bodies: Vec<(Handle, Entity)>,
    characters: Vec<(Handle, Entity)>,
    joints: Vec<(Handle, Entity)>,
}

pub(crate) fn entity_table(
    bodies: &Query<(Entity, &BodyLink)>,
    characters: &Query<(Entity, &CharacterLink)>,
    joints: &Query<(Entity, &JointLink)>,
) -> EntityTable {
    let mut table = EntityTable {
        bodies: bodies.iter().map(|(e, l)| (l.0, e)).collect(),
        characters: characters.iter().map(|(e, l)| (l.0, e)).collect(),
        joints: joints.iter().map(|(e, l)| (l.0, e)).collect(),
    };
    table.bodies.sort_unstable();
    table.characters.sort_unstable();
    table.joints.sort_unstable();
    table
}

fn find(list: &[(Handle, Entity)], handle: Handle) -> Option<Entity> {
    list.binary_search_by_key(&handle, |(h, _)| *h)
        .ok()
        .map(|i| list[i].1)
}

impl EntityTable {
    /// The message of `event`.
    pub fn event(&self, event: &Event) -> PhysicsEvent {
        let a_list = match event.kind {
            EventKind::JointBreak => &self.joints,
            EventKind::CharacterLand | EventKind::CharacterHit => &self.characters,
            _ => &self.bodies,
        };
        PhysicsEvent {
            tick: event.tick,
            kind: event.kind,
            a: event.a,
            b: event.b,
            entity_a: find(a_list, event.a),
            entity_b: event.b.and_then(|b| find(&self.bodies, b)),
        }
    }
}
