//! Building the world at `PostStartup`: the plugin's scene plus the bodies, joints and
//! characters of the entities spawned at startup, in the order their components were
//! added. Body `k` of those entities gets slot `n + k` (after the scene's `n` bodies,
//! lattice copies counted), joint `k` and character `k` likewise after the scene's own.

use bevy::prelude::{Entity, World as BevyWorld};
use fixstep::math::Fx;
use fixstep::rigid::{BodyDesc, JointsDesc, RigidDesc};
use fixstep::scene::Scene;
use fixstep::world::Handle;

use super::components::{
    BodyLink, Character, CharacterLink, Collider, FixedTransform, FixedVelocity, Joint, JointLink,
    RigidBody,
};
use super::link::LinkQueue;
use super::plugin::BaseScene;
use super::world::FixstepWorld;

/// Builds [`FixstepWorld`] from [`BaseScene`] and the queued startup entities, and links
/// them. A scene that does not build is a programming error of the game: it panics with
/// the scene's message.
pub(crate) fn build_world(world: &mut BevyWorld) {
    let Some(BaseScene(mut scene)) = world.remove_resource::<BaseScene>() else {
        return;
    };
    let (bodies, joints, characters) = {
        let mut queue = world.resource_mut::<LinkQueue>();
        let taken = (
            core::mem::take(&mut queue.bodies),
            core::mem::take(&mut queue.joints),
            core::mem::take(&mut queue.characters),
        );
        queue.clear();
        taken
    };
    let body_links = add_bodies(world, &mut scene, &bodies);
    let joint_links = add_joints(world, &mut scene, &joints, &body_links);
    let character_links = add_characters(world, &mut scene, &characters);
    let fixstep = match FixstepWorld::new(scene) {
        Ok(w) => w,
        Err(e) => panic!("fixstep-bevy: the scene does not build: {e}"),
    };
    for (entity, handle) in body_links {
        world.entity_mut(entity).insert(BodyLink(handle));
    }
    // Joint handles as the built world numbers them (the scene's own joints, lattices
    // counted, come first).
    let joint_handles: Vec<Handle> = fixstep
        .world()
        .rigid()
        .map(|r| r.joint_handles().collect())
        .unwrap_or_default();
    let first = joint_handles.len().saturating_sub(joint_links.len());
    for ((entity, _), &handle) in joint_links.iter().zip(&joint_handles[first..]) {
        world.entity_mut(*entity).insert(JointLink(handle));
    }
    for (entity, handle) in character_links {
        world.entity_mut(entity).insert(CharacterLink(handle));
    }
    world.insert_resource(fixstep);
}

fn add_bodies(
    world: &BevyWorld,
    scene: &mut Scene<Fx>,
    entities: &[Entity],
) -> Vec<(Entity, Handle)> {
    let rigid = scene.rigid.get_or_insert_with(RigidDesc::default);
    let mut links = Vec::new();
    for &entity in entities {
        let Ok(e) = world.get_entity(entity) else {
            continue;
        };
        let (Some(body), Some(Collider(shape))) = (e.get::<RigidBody>(), e.get::<Collider>())
        else {
            continue;
        };
        let pose = e.get::<FixedTransform>().copied().unwrap_or_default();
        let velocity = e.get::<FixedVelocity>().copied().unwrap_or_default();
        let slot = rigid.body_count();
        let template = body.template(shape);
        let mut desc = BodyDesc::new(template.shape, pose.position);
        desc.kind = template.kind;
        desc.orientation = pose.orientation;
        desc.velocity = velocity.linear;
        desc.angular_velocity = velocity.angular;
        desc.density = template.density;
        desc.material = template.material;
        desc.linear_damping = template.linear_damping;
        desc.angular_damping = template.angular_damping;
        desc.filter = template.filter;
        desc.sensor = template.sensor;
        desc.bullet = template.bullet;
        rigid.bodies.push(desc);
        links.push((entity, Handle::new(slot, 0)));
    }
    links
}

fn add_joints(
    world: &BevyWorld,
    scene: &mut Scene<Fx>,
    entities: &[Entity],
    bodies: &[(Entity, Handle)],
) -> Vec<(Entity, Handle)> {
    // The handles are placeholders: `build_world` numbers the joints once they are built.
    let slot_of = |e: Entity| bodies.iter().find(|(b, _)| *b == e).map(|(_, h)| h.index);
    let mut links = Vec::new();
    for &entity in entities {
        let Some(joint) = world.get_entity(entity).ok().and_then(|e| e.get::<Joint>()) else {
            continue;
        };
        let (Some(a), Some(b)) = (slot_of(joint.a), slot_of(joint.b)) else {
            bevy::log::warn!("fixstep-bevy: joint {entity} names an entity without a body");
            continue;
        };
        let joints = scene.joints.get_or_insert_with(JointsDesc::default);
        let mut desc = joint.desc.clone();
        desc.bodies = (a, b);
        joints.list.push(desc);
        links.push((entity, Handle::new(0, 0)));
    }
    links
}

fn add_characters(
    world: &BevyWorld,
    scene: &mut Scene<Fx>,
    entities: &[Entity],
) -> Vec<(Entity, Handle)> {
    let mut links = Vec::new();
    for &entity in entities {
        let Ok(e) = world.get_entity(entity) else {
            continue;
        };
        let Some(Character(desc)) = e.get::<Character>() else {
            continue;
        };
        let desc = desc.clone();
        let index = u32::try_from(scene.characters.len()).unwrap_or(u32::MAX);
        scene.characters.push(desc);
        links.push((entity, Handle::new(index, 0)));
    }
    links
}
