//! The systems of one tick, in order: turn the queued component changes into commands,
//! step the world, link the spawned bodies, copy the poses back.

use bevy::prelude::*;
use bevy_ggrs::RollbackDespawned;
use fixstep::world::{Command, Handle, Target};

use super::components::{
    BodyLink, CharacterLink, Collider, FixedTransform, FixedVelocity, JointLink, RenderPose,
    RigidBody,
};
use super::events::{PhysicsEvent, entity_table};
use super::link::LinkQueue;
use super::world::{FixstepWorld, PLUGIN_PLAYER};

/// The entities whose `SpawnBody` commands are in the coming tick's input, in command order.
#[derive(Resource, Default, Debug)]
pub(crate) struct Spawning(Vec<Entity>);

/// Turns the queued spawns and removals into the plugin player's commands: a body spawned
/// at run time becomes `SpawnBody` of the scene's body template equal to its `RigidBody`
/// and `Collider` (an entity whose body matches no template gets no body, with a warning),
/// a lost link or a rollback despawn becomes `Remove` of a live body.
pub(crate) fn queue_commands(
    fixstep: Option<ResMut<FixstepWorld>>,
    mut queue: ResMut<LinkQueue>,
    mut spawning: ResMut<Spawning>,
    new_bodies: Query<
        (
            &RigidBody,
            &Collider,
            &FixedTransform,
            Option<&FixedVelocity>,
        ),
        Without<BodyLink>,
    >,
    despawned: Query<&BodyLink, With<RollbackDespawned>>,
) {
    let Some(mut fixstep) = fixstep else {
        return;
    };
    spawning.0.clear();
    for entity in core::mem::take(&mut queue.bodies) {
        let Ok((body, Collider(shape), pose, velocity)) = new_bodies.get(entity) else {
            continue;
        };
        let wanted = body.template(shape);
        let templates = fixstep.scene.rigid.as_ref().map(|r| r.templates.as_slice());
        let Some(template) = templates
            .unwrap_or_default()
            .iter()
            .position(|t| *t == wanted)
        else {
            warn!(
                "fixstep-bevy: entity {entity} spawned a body that is none of the scene's body \
                 templates; it gets no body (add the template to the plugin's scene)"
            );
            continue;
        };
        let velocity = velocity.copied().unwrap_or_default();
        fixstep.push(
            PLUGIN_PLAYER,
            Command::SpawnBody {
                template: u32::try_from(template).unwrap_or(u32::MAX),
                position: pose.position,
                orientation: pose.orientation,
                velocity: velocity.linear,
                angular_velocity: velocity.angular,
            },
        );
        spawning.0.push(entity);
    }
    let mut removals = core::mem::take(&mut queue.removals);
    // Rollback despawns, in handle order (query order is not deterministic).
    let mut marked: Vec<Handle> = despawned.iter().map(|l| l.0).collect();
    marked.sort_unstable();
    removals.extend(marked);
    for handle in removals {
        let alive = fixstep
            .world
            .rigid()
            .is_some_and(|r| r.position(handle).is_some());
        let queued = fixstep.input.players.iter().any(|p| {
            p.commands
                .iter()
                .any(|c| matches!(c, Command::Remove { target: Target::Body(h) } if *h == handle))
        });
        if alive && !queued {
            fixstep.push(
                PLUGIN_PLAYER,
                Command::Remove {
                    target: Target::Body(handle),
                },
            );
        }
    }
}

/// Steps the world one tick, links the bodies the plugin spawned (the last ones of the
/// tick: its player comes after every game player) and sends the tick's events.
pub(crate) fn step_world(
    fixstep: Option<ResMut<FixstepWorld>>,
    mut spawning: ResMut<Spawning>,
    mut commands: Commands,
    mut events: MessageWriter<PhysicsEvent>,
    bodies: Query<(Entity, &BodyLink)>,
    characters: Query<(Entity, &CharacterLink)>,
    joints: Query<(Entity, &JointLink)>,
) {
    let Some(mut fixstep) = fixstep else {
        return;
    };
    fixstep.step();
    let world = &fixstep.world;
    let spawned = world.rigid().map(|r| r.spawned()).unwrap_or_default();
    let first = spawned.len().saturating_sub(spawning.0.len());
    for (&entity, &handle) in spawning.0.iter().zip(&spawned[first..]) {
        commands.entity(entity).insert(BodyLink(handle));
    }
    spawning.0.clear();
    let tick_events = world.events();
    if !tick_events.is_empty() {
        let table = entity_table(&bodies, &characters, &joints);
        events.write_batch(tick_events.iter().map(|e| table.event(e)));
    }
}

/// Copies the world's poses into `FixedTransform` and the render poses of the linked
/// entities.
pub(crate) fn sync_poses(
    fixstep: Option<Res<FixstepWorld>>,
    mut bodies: Query<(Ref<BodyLink>, &mut FixedTransform, &mut RenderPose)>,
    mut characters: Query<
        (Ref<CharacterLink>, &mut FixedTransform, &mut RenderPose),
        Without<BodyLink>,
    >,
) {
    let Some(fixstep) = fixstep else {
        return;
    };
    if let Some(rigid) = fixstep.world.rigid() {
        for (link, mut pose, mut render) in &mut bodies {
            let (Some(position), Some(orientation)) =
                (rigid.position(link.0), rigid.orientation(link.0))
            else {
                continue;
            };
            pose.position = position;
            pose.orientation = orientation;
            advance(&mut render, isometry(&pose), link.is_added());
        }
    }
    if let Some(system) = fixstep.world.characters() {
        for (link, mut pose, mut render) in &mut characters {
            let Some(character) = system.get(link.0) else {
                continue;
            };
            pose.position = character.position;
            advance(&mut render, isometry(&pose), link.is_added());
        }
    }
}

/// Makes `now` the current render pose; a newly linked entity has no pose before it, so
/// it starts at rest there.
fn advance(render: &mut RenderPose, now: Isometry3d, new: bool) {
    render.previous = if new { now } else { render.current };
    render.current = now;
}

/// After a rollback: forget the queued changes (they are made again as the frames are
/// simulated again) and set `FixedTransform` to the restored world's poses.
pub(crate) fn after_load(
    mut queue: ResMut<LinkQueue>,
    fixstep: Option<Res<FixstepWorld>>,
    mut bodies: Query<(&BodyLink, &mut FixedTransform)>,
    mut characters: Query<(&CharacterLink, &mut FixedTransform), Without<BodyLink>>,
) {
    queue.clear();
    let Some(fixstep) = fixstep else {
        return;
    };
    if let Some(rigid) = fixstep.world.rigid() {
        for (link, mut pose) in &mut bodies {
            if let (Some(p), Some(q)) = (rigid.position(link.0), rigid.orientation(link.0)) {
                pose.position = p;
                pose.orientation = q;
            }
        }
    }
    if let Some(system) = fixstep.world.characters() {
        for (link, mut pose) in &mut characters {
            if let Some(character) = system.get(link.0) {
                pose.position = character.position;
            }
        }
    }
}

/// A fixed-point pose in floats, for rendering.
pub(crate) fn isometry(pose: &FixedTransform) -> Isometry3d {
    let [x, y, z] = pose.position.to_f64();
    let [w, i, j, k] = pose.orientation.to_f64();
    Isometry3d::new(
        Vec3::new(x as f32, y as f32, z as f32),
        Quat::from_xyzw(i as f32, j as f32, k as f32, w as f32),
    )
}
