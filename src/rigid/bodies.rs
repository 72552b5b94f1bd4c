//! Structure-of-arrays body storage: one `Vec` per attribute, indexed by slot.
//!
//! Hot data (what every substep reads and writes: pose, velocities, inverse mass) and cold
//! data (shape, material, generation) live in separate arrays, so the solver's loops touch
//! only what they use.
//!
//! # Slots
//!
//! Slots are never freed. Removing a body marks its slot dead and bumps its generation, so
//! every [`Handle`] to it goes stale at once. A new body takes the lowest-index dead slot,
//! or a new slot at the end when none is dead, so the slot a body gets is a function of
//! the alive flags and the same on every peer.

use serde::{Deserialize, Serialize};

use super::desc::BodyKind;
use super::filter::CollisionFilter;
use super::material::Material;
use super::shape::Shape;
use crate::math::{Mat3, Quat, Real, Vec3};
use crate::types::Handle;

/// What a new body is made of, already checked and with its mass properties computed.
#[derive(Clone)]
pub(crate) struct NewBody<R: Real> {
    pub kind: BodyKind,
    pub shape: Shape<R>,
    pub material: Material<R>,
    pub mass: R,
    pub inertia: Mat3<R>,
    pub position: Vec3<R>,
    pub orientation: Quat<R>,
    pub linear_velocity: Vec3<R>,
    pub angular_velocity: Vec3<R>,
    pub linear_damping: R,
    pub angular_damping: R,
    pub filter: CollisionFilter,
    pub sensor: bool,
    pub bullet: bool,
}

/// Every body attribute, one array each, indexed by slot.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Bodies<R: Real> {
    // Hot: read and written every substep.
    /// Position of the centre of mass, m.
    pub position: Vec<Vec3<R>>,
    /// Orientation, a unit quaternion (body frame → world frame).
    pub orientation: Vec<Quat<R>>,
    /// Velocity of the centre of mass, m/s.
    pub linear_velocity: Vec<Vec3<R>>,
    /// Angular velocity in the world frame, rad/s.
    pub angular_velocity: Vec<Vec3<R>>,
    /// 1/m, 1/kg; 0 for static, kinematic and dead bodies.
    pub inv_mass: Vec<R>,
    /// Inverse inertia about the centre of mass in the body frame, 1/(kg·m²); zero for
    /// bodies that do not turn under contacts.
    pub inv_inertia: Vec<Mat3<R>>,
    /// Force applied by commands during the current tick, N.
    pub force: Vec<Vec3<R>>,
    /// Torque applied by commands during the current tick, N·m.
    pub torque: Vec<Vec3<R>>,

    // Cold: read when building contacts, for gyroscopic torque, and by commands.
    /// Static, kinematic or dynamic.
    pub kind: Vec<BodyKind>,
    /// Collision shape in the body frame, centred on the centre of mass.
    pub shape: Vec<Shape<R>>,
    /// Friction and restitution.
    pub material: Vec<Material<R>>,
    /// m, kg; 0 for static and kinematic bodies.
    pub mass: Vec<R>,
    /// Inertia about the centre of mass in the body frame, kg·m².
    pub inertia: Vec<Mat3<R>>,
    /// True when the inertia is a multiple of the identity, so the gyroscopic torque
    /// ω × Iω is zero and the implicit gyroscopic update is skipped.
    pub isotropic: Vec<bool>,
    /// Linear damping, 1/s.
    pub linear_damping: Vec<R>,
    /// Angular damping, 1/s.
    pub angular_damping: Vec<R>,
    /// Layers the body is on and interacts with.
    pub filter: Vec<CollisionFilter>,
    /// Whether the body is a sensor (detects overlaps, exerts and feels no contact force).
    pub sensor: Vec<bool>,
    /// Whether the body is a bullet (swept against dynamic bodies too:
    /// [`super::continuous`]).
    pub bullet: Vec<bool>,

    // Sleep.
    /// Seconds the body has been slower than the sleep speeds.
    pub sleep_time: Vec<R>,
    /// True while the body's island sleeps.
    pub asleep: Vec<bool>,
    /// For a sleeping body, the lowest slot of its island: the island wakes as a whole.
    pub island: Vec<u32>,

    // Slots.
    /// Whether the slot holds a body.
    pub alive: Vec<bool>,
    /// Bumped every time the slot's body is removed.
    pub generation: Vec<u32>,
    /// No dead slot lies below this index: where the search for a free slot starts.
    #[serde(skip)]
    free_from: SearchHint,
}

/// A lower bound on the lowest dead slot. It only speeds up the search, so it is not part
/// of the state: it is not serialised, and any two hints compare equal.
#[derive(Clone, Copy, Debug, Default)]
struct SearchHint(usize);

impl PartialEq for SearchHint {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl<R: Real> Bodies<R> {
    /// Number of slots, alive or dead.
    pub fn len(&self) -> usize {
        self.alive.len()
    }

    /// The handle of slot `i`.
    pub fn handle(&self, i: usize) -> Handle {
        Handle::new(i as u32, self.generation[i])
    }

    /// The slot of a live body, or `None` for a stale or unknown handle.
    pub fn slot(&self, handle: Handle) -> Option<usize> {
        let i = handle.index as usize;
        (i < self.len() && self.alive[i] && self.generation[i] == handle.generation).then_some(i)
    }

    /// True for a dynamic body that is awake: the bodies the solver moves under forces.
    #[inline]
    pub fn is_awake_dynamic(&self, i: usize) -> bool {
        self.alive[i] && self.kind[i] == BodyKind::Dynamic && !self.asleep[i]
    }

    /// True for a body the solver moves this step: awake dynamic, or kinematic.
    #[inline]
    pub fn is_moving(&self, i: usize) -> bool {
        self.alive[i]
            && match self.kind[i] {
                BodyKind::Static => false,
                BodyKind::Kinematic => true,
                BodyKind::Dynamic => !self.asleep[i],
            }
    }

    /// A bound on the speed of any point of slot `i`'s body, |v| + |ω| ρ (m/s), ρ the half
    /// diagonal of its bounding box (0 for a plane); the box's size does not depend on
    /// where the body is.
    pub fn point_speed_bound(&self, i: usize) -> R {
        let xf = super::transform::Transform::from_pose(self.position[i], self.orientation[i]);
        let radius = super::aabb::Aabb::of_shape(&self.shape[i], &xf)
            .map_or(R::ZERO, |a| (a.max - a.min).length() * R::HALF);
        self.linear_velocity[i].length() + self.angular_velocity[i].length() * radius
    }

    /// Stores a body in the lowest dead slot, or a new slot; returns its handle.
    pub fn insert(&mut self, body: NewBody<R>) -> Handle {
        let dynamic = body.kind == BodyKind::Dynamic;
        let inv_mass = if dynamic && body.mass > R::ZERO {
            R::ONE / body.mass
        } else {
            R::ZERO
        };
        let inv_inertia = if dynamic {
            body.inertia.safe_inverse_symmetric()
        } else {
            Mat3::ZERO
        };
        let d = body.inertia.diagonal();
        let isotropic = d.x == d.y && d.y == d.z && body.inertia == Mat3::from_diagonal(d);
        let start = self.free_from.0.min(self.len());
        let i = match self.alive[start..].iter().position(|alive| !alive) {
            Some(offset) => start + offset,
            None => {
                self.push_empty();
                self.len() - 1
            }
        };
        self.position[i] = body.position;
        self.orientation[i] = body.orientation;
        self.linear_velocity[i] = body.linear_velocity;
        self.angular_velocity[i] = body.angular_velocity;
        self.inv_mass[i] = inv_mass;
        self.inv_inertia[i] = inv_inertia;
        self.force[i] = Vec3::ZERO;
        self.torque[i] = Vec3::ZERO;
        self.kind[i] = body.kind;
        self.shape[i] = body.shape;
        self.material[i] = body.material;
        self.mass[i] = if dynamic { body.mass } else { R::ZERO };
        self.inertia[i] = body.inertia;
        self.isotropic[i] = isotropic;
        self.linear_damping[i] = body.linear_damping;
        self.angular_damping[i] = body.angular_damping;
        self.filter[i] = body.filter;
        self.sensor[i] = body.sensor;
        self.bullet[i] = body.bullet;
        self.sleep_time[i] = R::ZERO;
        self.asleep[i] = false;
        self.island[i] = i as u32;
        self.alive[i] = true;
        self.free_from.0 = i + 1;
        self.handle(i)
    }

    /// Removes the body in slot `i`: marks it dead and bumps the generation.
    pub fn remove(&mut self, i: usize) {
        self.alive[i] = false;
        self.free_from.0 = self.free_from.0.min(i);
        self.generation[i] = self.generation[i].wrapping_add(1);
        self.inv_mass[i] = R::ZERO;
        self.inv_inertia[i] = Mat3::ZERO;
        self.linear_velocity[i] = Vec3::ZERO;
        self.angular_velocity[i] = Vec3::ZERO;
        self.force[i] = Vec3::ZERO;
        self.torque[i] = Vec3::ZERO;
        self.asleep[i] = false;
        self.sleep_time[i] = R::ZERO;
    }

    fn push_empty(&mut self) {
        self.position.push(Vec3::ZERO);
        self.orientation.push(Quat::IDENTITY);
        self.linear_velocity.push(Vec3::ZERO);
        self.angular_velocity.push(Vec3::ZERO);
        self.inv_mass.push(R::ZERO);
        self.inv_inertia.push(Mat3::ZERO);
        self.force.push(Vec3::ZERO);
        self.torque.push(Vec3::ZERO);
        self.kind.push(BodyKind::Static);
        self.shape.push(Shape::Sphere { radius: R::ZERO });
        self.material.push(Material::default());
        self.mass.push(R::ZERO);
        self.inertia.push(Mat3::ZERO);
        self.isotropic.push(true);
        self.linear_damping.push(R::ZERO);
        self.angular_damping.push(R::ZERO);
        self.filter.push(CollisionFilter::ALL);
        self.sensor.push(false);
        self.bullet.push(false);
        self.sleep_time.push(R::ZERO);
        self.asleep.push(false);
        self.island.push(self.alive.len() as u32);
        self.alive.push(false);
        self.generation.push(0);
    }
}
