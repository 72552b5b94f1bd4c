//! The link between entities and fixstep objects: component hooks queue the entities that
//! gain a body, joint or character and the bodies whose entity goes, in the order the
//! commands that did it were applied, which is the order of the systems that gave them.

use bevy::ecs::lifecycle::HookContext;
use bevy::ecs::world::DeferredWorld;
use bevy::prelude::{Entity, Resource};
use fixstep::world::Handle;

use super::components::BodyLink;

/// What happened to the plugin's components since the last step, in order.
#[derive(Resource, Default, Debug)]
pub(crate) struct LinkQueue {
    /// Entities whose `RigidBody` was added.
    pub bodies: Vec<Entity>,
    /// Entities whose `Joint` was added (only those present at startup become joints).
    pub joints: Vec<Entity>,
    /// Entities whose `Character` was added (only those present at startup become
    /// characters).
    pub characters: Vec<Entity>,
    /// Bodies whose entity lost its `BodyLink` (despawned, or its `RigidBody` removed).
    pub removals: Vec<Handle>,
}

impl LinkQueue {
    /// Forgets everything queued (after a rollback: the queued changes belong to frames
    /// that are being simulated again).
    pub fn clear(&mut self) {
        self.bodies.clear();
        self.joints.clear();
        self.characters.clear();
        self.removals.clear();
    }
}

fn queue<'a>(world: &'a mut DeferredWorld) -> Option<bevy::prelude::Mut<'a, LinkQueue>> {
    world.get_resource_mut::<LinkQueue>()
}

pub(crate) fn on_body_added(mut world: DeferredWorld, ctx: HookContext) {
    if let Some(mut q) = queue(&mut world) {
        q.bodies.push(ctx.entity);
    }
}

pub(crate) fn on_joint_added(mut world: DeferredWorld, ctx: HookContext) {
    if let Some(mut q) = queue(&mut world) {
        q.joints.push(ctx.entity);
    }
}

pub(crate) fn on_character_added(mut world: DeferredWorld, ctx: HookContext) {
    if let Some(mut q) = queue(&mut world) {
        q.characters.push(ctx.entity);
    }
}

/// A `RigidBody` removed from a linked entity unlinks it (the body goes at the next step).
pub(crate) fn on_body_removed(mut world: DeferredWorld, ctx: HookContext) {
    if world.get::<BodyLink>(ctx.entity).is_some() {
        world.commands().entity(ctx.entity).try_remove::<BodyLink>();
    }
}

pub(crate) fn on_link_removed(mut world: DeferredWorld, ctx: HookContext) {
    let Some(&BodyLink(handle)) = world.get::<BodyLink>(ctx.entity) else {
        return;
    };
    if let Some(mut q) = queue(&mut world) {
        q.removals.push(handle);
    }
}
