//! The plugin's components: what an entity says about its body, and the link to it.

use bevy::prelude::{Component, Entity};
use fixstep::character::CharacterDesc;
use fixstep::math::{Fx, Quat, Real, Vec3};
use fixstep::rigid::{BodyKind, BodyTemplate, CollisionFilter, JointDesc, Material, Shape};
use fixstep::world::Handle;

use super::link;

/// A rigid body: how it moves and what it is made of. With a [`Collider`] (its shape) and a
/// [`FixedTransform`] (its pose), the plugin creates the body in the fixstep world:
/// entities present at startup become the scene's bodies, later ones `SpawnBody` commands
/// of the scene's body template with the same settings and shape.
#[derive(Component, Clone, Debug, PartialEq)]
#[component(on_add = link::on_body_added, on_remove = link::on_body_removed)]
#[require(FixedTransform, RenderPose)]
pub struct RigidBody {
    /// Static, kinematic or dynamic.
    pub kind: BodyKind,
    /// Density, kg/m³.
    pub density: Fx,
    /// Friction and restitution.
    pub material: Material<Fx>,
    /// Linear damping, 1/s.
    pub linear_damping: Fx,
    /// Angular damping, 1/s.
    pub angular_damping: Fx,
    /// Collision layers and mask.
    pub filter: CollisionFilter,
    /// Detects overlaps without contact forces.
    pub sensor: bool,
    /// Swept against dynamic bodies too.
    pub bullet: bool,
}

impl RigidBody {
    /// A body of `kind` with density 1000 kg/m³, the default material, no damping, every
    /// layer.
    pub fn new(kind: BodyKind) -> Self {
        Self {
            kind,
            density: Fx::from_int(1000),
            material: Material::default(),
            linear_damping: Fx::ZERO,
            angular_damping: Fx::ZERO,
            filter: CollisionFilter::ALL,
            sensor: false,
            bullet: false,
        }
    }

    /// A dynamic body.
    pub fn dynamic() -> Self {
        Self::new(BodyKind::Dynamic)
    }

    /// A static body.
    pub fn fixed() -> Self {
        Self::new(BodyKind::Static)
    }

    /// A kinematic body.
    pub fn kinematic() -> Self {
        Self::new(BodyKind::Kinematic)
    }

    /// The body template of this body with `shape`: what a run-time spawn looks up among
    /// the scene's templates.
    pub fn template(&self, shape: &Shape<Fx>) -> BodyTemplate<Fx> {
        BodyTemplate {
            kind: self.kind,
            shape: shape.clone(),
            density: self.density,
            material: self.material,
            linear_damping: self.linear_damping,
            angular_damping: self.angular_damping,
            filter: self.filter,
            sensor: self.sensor,
            bullet: self.bullet,
        }
    }
}

/// The collision shape of a [`RigidBody`] in its body frame: any fixstep shape (sphere, box,
/// capsule, cylinder, cone, convex hull, plane, compound, triangle mesh, heightfield).
#[derive(Component, Clone, Debug, PartialEq)]
pub struct Collider(pub Shape<Fx>);

/// A body's or character's pose in fixed point: set it before the body exists (its initial
/// pose); the plugin overwrites it with the world's pose after every step and after a
/// rollback, so game logic reads exact values.
#[derive(Component, Clone, Copy, Debug, PartialEq)]
pub struct FixedTransform {
    /// Position, m.
    pub position: Vec3<Fx>,
    /// Orientation (unit quaternion).
    pub orientation: Quat<Fx>,
}

impl Default for FixedTransform {
    fn default() -> Self {
        Self::from_position(Vec3::ZERO)
    }
}

impl FixedTransform {
    /// At `position`, unrotated.
    pub fn from_position(position: Vec3<Fx>) -> Self {
        Self {
            position,
            orientation: Quat::IDENTITY,
        }
    }
}

/// A body's initial velocities (m/s, rad/s, world frame); read when the body is created.
#[derive(Component, Clone, Copy, Debug, Default, PartialEq)]
pub struct FixedVelocity {
    /// Linear velocity, m/s.
    pub linear: Vec3<Fx>,
    /// Angular velocity, rad/s.
    pub angular: Vec3<Fx>,
}

/// The fixstep body of an entity. Rolled back with bevy_ggrs.
#[derive(Component, Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[component(on_remove = link::on_link_removed)]
pub struct BodyLink(pub Handle);

/// A joint between the bodies of two entities present at startup; `desc.bodies` is
/// replaced by theirs. Joints made later are `SpawnJoint` commands
/// ([`FixstepWorld::push`](super::FixstepWorld::push)).
#[derive(Component, Clone, Debug, PartialEq)]
#[component(on_add = link::on_joint_added)]
pub struct Joint {
    /// Body A's entity.
    pub a: Entity,
    /// Body B's entity.
    pub b: Entity,
    /// The joint's kind, anchors, axis and limits (world frame at tick 0).
    pub desc: JointDesc<Fx>,
}

/// The fixstep joint of an entity.
#[derive(Component, Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct JointLink(pub Handle);

/// A kinematic character present at startup (fixstep characters are scene objects);
/// drive it with `Command::MoveCharacter` on its [`CharacterLink`].
#[derive(Component, Clone, Debug, PartialEq)]
#[component(on_add = link::on_character_added)]
#[require(FixedTransform, RenderPose)]
pub struct Character(pub CharacterDesc<Fx>);

/// The fixstep character of an entity.
#[derive(Component, Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct CharacterLink(pub Handle);

/// The last two poses of a body in floats, for rendering only: the plugin sets `Transform`
/// to the interpolation between them.
#[derive(Component, Clone, Copy, Debug, Default, PartialEq)]
#[require(bevy::prelude::Transform)]
pub struct RenderPose {
    /// The pose before the last step.
    pub previous: bevy::prelude::Isometry3d,
    /// The pose after the last step.
    pub current: bevy::prelude::Isometry3d,
}
