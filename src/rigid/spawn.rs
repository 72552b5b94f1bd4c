//! Spawning by input: [`Command::SpawnBody`](crate::types::Command::SpawnBody) creates a body
//! from one of the scene's [`BodyTemplate`]s, and
//! [`Command::SpawnJoint`](crate::types::Command::SpawnJoint) a joint from one of its
//! [`JointTemplate`]s, during a run.
//!
//! A template holds what does not change from one copy to the next (shape, density,
//! material, filter, sensor and bullet flags; joint kind, collision, break thresholds); the command
//! gives the rest (pose and velocities; bodies, anchors and axis). A spawned body takes the
//! lowest dead slot, or a new slot at the end, so its handle is a function of the state and
//! the same on every peer; [`RigidSystem::spawned`] lists the handles a tick created. A
//! spawn that cannot be done (an unknown template, no slot left under
//! [`MAX_BODIES`], a pose out of range, joint bodies that do not exist) does nothing and
//! counts as an ignored command.

use serde::{Deserialize, Serialize};

use super::bodies::NewBody;
use super::build::{MAX_MAGNITUDE, compile_body};
use super::desc::{BodyDesc, BodyKind, MAX_BODIES};
use super::filter::CollisionFilter;
use super::joints::desc::{JointDesc, JointKind, JointsDesc, MAX_JOINTS};
use super::material::Material;
use super::shape::Shape;
use super::system::RigidSystem;
use crate::math::{Fx, Quat, Real, Vec3};
use crate::types::{Handle, SceneError};

/// What every body spawned from this template shares.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct BodyTemplate<R: Real = Fx> {
    /// Dynamic (default), kinematic or static.
    #[serde(default)]
    pub kind: BodyKind,
    /// The collision shape, in the body frame (not a plane).
    pub shape: Shape<R>,
    /// Density, kg/m³. Default 1000.
    #[serde(default = "default_density")]
    pub density: R,
    /// Friction and restitution.
    #[serde(default)]
    pub material: Material<R>,
    /// Linear damping, 1/s. Default 0.
    #[serde(default)]
    pub linear_damping: R,
    /// Angular damping, 1/s. Default 0.
    #[serde(default)]
    pub angular_damping: R,
    /// Layers and mask. Default all ones.
    #[serde(default)]
    pub filter: CollisionFilter,
    /// Whether the body is a sensor. Default false.
    #[serde(default)]
    pub sensor: bool,
    /// Whether the body is a bullet ([`BodyDesc::bullet`]). Default false.
    #[serde(default)]
    pub bullet: bool,
}

fn default_density<R: Real>() -> R {
    R::from_int(1000)
}

impl<R: Real> BodyTemplate<R> {
    /// A dynamic template of `shape` with the default density, material and filter.
    pub fn new(shape: Shape<R>) -> Self {
        Self {
            kind: BodyKind::Dynamic,
            shape,
            density: default_density(),
            material: Material::default(),
            linear_damping: R::ZERO,
            angular_damping: R::ZERO,
            filter: CollisionFilter::ALL,
            sensor: false,
            bullet: false,
        }
    }

    /// The body description of one copy at the given pose and velocities.
    fn at(
        &self,
        position: Vec3<R>,
        orientation: Quat<R>,
        velocity: Vec3<R>,
        angular_velocity: Vec3<R>,
    ) -> BodyDesc<R> {
        let mut desc = BodyDesc::new(self.shape.clone(), position);
        desc.kind = self.kind;
        desc.orientation = orientation;
        desc.velocity = velocity;
        desc.angular_velocity = angular_velocity;
        desc.density = self.density;
        desc.material = self.material;
        desc.linear_damping = self.linear_damping;
        desc.angular_damping = self.angular_damping;
        desc.filter = self.filter;
        desc.sensor = self.sensor;
        desc.bullet = self.bullet;
        desc
    }
}

/// What every joint spawned from this template shares.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct JointTemplate<R: Real = Fx> {
    /// What the joint keeps.
    pub kind: JointKind<R>,
    /// Whether the two bodies still collide with each other. Default false.
    #[serde(default)]
    pub collide: bool,
    /// Break force, N (absent: never).
    #[serde(default)]
    pub break_force: Option<R>,
    /// Break torque, N·m (absent: never).
    #[serde(default)]
    pub break_torque: Option<R>,
}

impl<R: Real> RigidSystem<R> {
    /// Checks the templates of a scene (errors name `templates[k]` or
    /// `joint_templates[k]`) and keeps them.
    pub(crate) fn set_templates(
        &mut self,
        bodies: &[BodyTemplate<R>],
        joints: &[JointTemplate<R>],
    ) -> Result<(), SceneError> {
        for (k, template) in bodies.iter().enumerate() {
            if matches!(template.shape, Shape::Plane { .. }) {
                return Err(SceneError::new(
                    format!("templates[{k}].shape"),
                    "a spawned body cannot be a plane",
                ));
            }
            let desc = template.at(Vec3::ZERO, Quat::IDENTITY, Vec3::ZERO, Vec3::ZERO);
            compile_body(&desc).map_err(|e| e.within(&format!("templates[{k}]")))?;
        }
        for (k, template) in joints.iter().enumerate() {
            let desc = JointDesc::new(template.kind, 0, 1, Vec3::ZERO);
            super::joints::check_joint(&desc)
                .map_err(|e| e.within(&format!("joint_templates[{k}]")))?;
        }
        self.templates = bodies.to_vec();
        self.joint_templates = joints.to_vec();
        Ok(())
    }

    /// The body templates of the scene.
    pub fn templates(&self) -> &[BodyTemplate<R>] {
        &self.templates
    }

    /// The joint templates of the scene.
    pub fn joint_templates(&self) -> &[JointTemplate<R>] {
        &self.joint_templates
    }

    /// The bodies spawned during the last tick, in command order.
    pub fn spawned(&self) -> &[Handle] {
        &self.scratch.spawned
    }

    /// The joints spawned during the last tick, in command order.
    pub fn spawned_joints(&self) -> &[Handle] {
        &self.scratch.spawned_joints
    }

    /// Spawns a body from template `template` at the given pose (m; the orientation is
    /// normalised) with the given velocities (m/s, rad/s); its handle, or `None` when the
    /// template does not exist, every one of [`MAX_BODIES`] slots is taken, or a value is
    /// out of range.
    pub fn spawn_body(
        &mut self,
        template: u32,
        position: Vec3<R>,
        orientation: Quat<R>,
        velocity: Vec3<R>,
        angular_velocity: Vec3<R>,
    ) -> Option<Handle> {
        let template = self.templates.get(template as usize)?;
        let full = self.bodies.len() >= MAX_BODIES as usize && self.bodies.alive.iter().all(|&a| a);
        if full {
            return None;
        }
        let desc = template.at(position, orientation, velocity, angular_velocity);
        let body: NewBody<R> = compile_body(&desc).ok()?;
        let handle = self.insert(body);
        self.scratch.spawned.push(handle);
        Some(handle)
    }

    /// Spawns a joint from template `template` between bodies `a` and `b`, with A's anchor
    /// `anchor` and B's `anchor_b` (world, m; absent: the same point) and the joint axis
    /// `axis` (world, unit); its handle, or `None` when the template or a body does not
    /// exist, the bodies are the same or neither is dynamic, every one of [`MAX_JOINTS`]
    /// slots is taken, or a value is out of range. Wakes both bodies.
    pub fn spawn_joint(
        &mut self,
        template: u32,
        (a, b): (Handle, Handle),
        anchor: Vec3<R>,
        anchor_b: Option<Vec3<R>>,
        axis: Vec3<R>,
    ) -> Option<Handle> {
        let template = self.joint_templates.get(template as usize)?;
        let (ia, ib) = (self.bodies.slot(a)?, self.bodies.slot(b)?);
        let full = self.joints.len() >= MAX_JOINTS as usize
            && self.joints.live().count() == self.joints.len();
        let limit = R::from_int(MAX_MAGNITUDE);
        if full || anchor.abs().max_component() > limit {
            return None;
        }
        let mut desc = JointDesc::new(template.kind, ia as u32, ib as u32, anchor);
        desc.anchor_b = anchor_b;
        desc.axis = axis;
        desc.collide = template.collide;
        desc.break_force = template.break_force;
        desc.break_torque = template.break_torque;
        super::joints::check_joint(&desc).ok()?;
        let joint = self.compile_spawned_joint(&desc).ok()?;
        if self.joints.iterations == 0 {
            // The scene had no joints: the default stiffness and iterations.
            let defaults = JointsDesc::<R>::default();
            self.joints.hertz = defaults.hertz;
            self.joints.damping_ratio = defaults.damping_ratio;
            self.joints.iterations = defaults.iterations;
        }
        let handle = self.joints.insert(joint);
        self.scratch.joint_filter_valid = false;
        self.wake_body(ia);
        self.wake_body(ib);
        self.scratch.spawned_joints.push(handle);
        Some(handle)
    }
}
