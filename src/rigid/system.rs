//! `RigidSystem`: the rigid bodies of a world, their contacts, and one step of their
//! motion.

use serde::{Deserialize, Serialize};

use super::aabb::Aabb;
use super::bodies::{Bodies, NewBody};
use super::broadphase::BroadPhase;
use super::contact::Contact;
use super::desc::{BodyKind, SolverSettings};
use super::events::Event;
use super::joints::JointEvent;
use super::joints::storage::Joints;
use super::query::QueryIndex;
use super::recycle::PairFrame;
use super::solver::Solver;
use super::spawn::{BodyTemplate, JointTemplate};
use super::transform::Transform;
use crate::math::{Fx, Real, Vec3};
use crate::types::Handle;

/// Rigid bodies and their contacts.
///
/// A step ([`RigidSystem::step`]) runs these stages, in order:
/// 1. **collide** ([`collide`](super::collide)): bounding boxes of the moving bodies,
///    broadphase pairs (less those of jointed bodies that do not collide), narrowphase
///    manifolds (or last step's, carried with the bodies: [`recycle`](super::recycle)),
///    impulses carried over by feature id;
/// 2. **wake** ([`sleep`](super::sleep)): sleeping islands touched or jointed to a moving
///    body;
/// 3. **solve** ([`solver`](super::solver)): soft-constraint sequential impulses over
///    joints and contacts with substeps, restitution, impulses stored, overloaded joints
///    broken ([`joints::breaking`](super::joints::breaking));
/// 4. **sleep** ([`sleep`](super::sleep)): islands that stayed slow long enough;
/// 5. **continuous** ([`continuous`](super::continuous)), once the query index is up to
///    date: fast bodies that would pass through a thin body are moved back to their time of
///    impact.
///
/// When every body sleeps or is static, a step does nothing but bring the query index up to
/// date.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct RigidSystem<R: Real = Fx> {
    pub(crate) settings: SolverSettings<R>,
    pub(crate) bodies: Bodies<R>,
    /// Touching shape pairs, sorted by key.
    pub(crate) contacts: Vec<Contact<R>>,
    /// The recycling frames the contacts name ([`Contact::frame`], [`super::recycle`]).
    pub(crate) frames: Vec<PairFrame<R>>,
    /// Joints between the bodies.
    pub(crate) joints: Joints<R>,
    /// Sensor and visitor slots (lower, higher) that overlap, ascending
    /// ([`super::sensors`]).
    pub(crate) sensor_overlaps: Vec<(u32, u32)>,
    /// What spawn commands create ([`super::spawn`]).
    pub(crate) templates: Vec<BodyTemplate<R>>,
    pub(crate) joint_templates: Vec<JointTemplate<R>>,
    #[serde(skip)]
    pub(crate) scratch: Scratch<R>,
}

/// Per-step working memory and caches derived from the state: never part of it, rebuilt
/// when missing, and equal to any other scratch. A clone starts empty.
#[derive(Debug, Default)]
pub(crate) struct Scratch<R: Real> {
    /// Whether `transforms` and `aabbs` hold every present body's current values; false
    /// after a restore, so the next step recomputes them all.
    pub cache_valid: bool,
    /// Placement of each body slot.
    pub transforms: Vec<Transform<R>>,
    /// Bounding box of each body slot, grown by the speculative distance.
    pub aabbs: Vec<Aabb<R>>,
    /// Whether each slot moves this step (awake dynamic or kinematic).
    pub active: Vec<bool>,
    /// Whether each slot takes part in the broadphase (alive and not a plane).
    pub present: Vec<bool>,
    /// Slots of the static planes.
    pub planes: Vec<u32>,
    pub broadphase: BroadPhase<R>,
    pub pairs: Vec<(u32, u32)>,
    /// For each pair of `pairs`, the index in last step's contacts of the contact it
    /// carries instead of running the narrowphase ([`super::recycle`]), or `u32::MAX`.
    pub carried: Vec<u32>,
    /// Last step's contacts and frames, cleared: their storage, for the next step's.
    pub spare_contacts: Vec<Contact<R>>,
    pub spare_frames: Vec<PairFrame<R>>,
    pub solver: Solver<R>,
    /// Union-find parents of the sleep stage, by slot.
    pub island_parent: Vec<u32>,
    /// The shortest sleep time of each island, at its root's slot.
    pub island_time: Vec<R>,
    /// Whether `joint_filter` holds the body pairs of the live joints that do not collide.
    pub joint_filter_valid: bool,
    /// Sorted (lower, higher) body slots of the jointed pairs that do not collide.
    pub joint_filter: Vec<(u32, u32)>,
    /// The joints that broke during the current tick.
    pub joint_events: Vec<JointEvent<R>>,
    /// The events of the current tick ([`super::events`]).
    pub events: Vec<Event>,
    /// The tick the events belong to.
    pub event_tick: u64,
    /// Whether some live body has a filter other than the default: only then does the
    /// collide stage filter pairs by layer. Computed with the bounds cache.
    pub layered: bool,
    /// Whether some live body is a sensor: only then does the collide stage set sensor
    /// pairs aside. Computed with the bounds cache.
    pub sensing: bool,
    /// The steps of the current tick whose broadphase hit its cap
    /// ([`RigidSystem::capped_steps`]).
    pub capped_steps: u32,
    /// This step's broadphase pairs with one sensor, which make no contact.
    pub sensor_pairs: Vec<(u32, u32)>,
    /// The bodies and the joints spawned during the current tick.
    pub spawned: Vec<Handle>,
    pub spawned_joints: Vec<Handle>,
    /// The bounding-volume tree of the scene queries ([`super::query`]).
    pub query: QueryIndex<R>,
}

impl<R: Real> Clone for Scratch<R> {
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl<R: Real> PartialEq for Scratch<R> {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl<R: Real> RigidSystem<R> {
    /// An empty system with the given solver settings.
    pub fn new(settings: SolverSettings<R>) -> Self {
        Self {
            settings,
            bodies: Bodies::default(),
            contacts: Vec::new(),
            frames: Vec::new(),
            joints: Joints::default(),
            sensor_overlaps: Vec::new(),
            templates: Vec::new(),
            joint_templates: Vec::new(),
            scratch: Scratch::default(),
        }
    }

    /// The solver settings.
    pub fn settings(&self) -> &SolverSettings<R> {
        &self.settings
    }

    /// Adds a body; `body` must have passed the checks of
    /// [`from_desc`](RigidSystem::from_desc).
    pub(crate) fn insert(&mut self, body: NewBody<R>) -> Handle {
        self.scratch.cache_valid = false;
        self.scratch.query.invalidate();
        self.bodies.insert(body)
    }

    /// Advances the bodies by `dt` seconds under `gravity` (m/s²), then brings the query
    /// index up to date.
    pub fn step(&mut self, dt: R, gravity: Vec3<R>) {
        let moving = (0..self.bodies.len()).any(|i| self.bodies.is_moving(i));
        if moving {
            self.collide();
            self.wake_touched();
            self.solve(dt, gravity);
            self.update_sleep(dt);
        }
        self.update_query_index();
        if moving {
            self.solve_continuous();
        }
    }

    /// Clears the per-tick force and torque accumulators.
    pub fn end_tick(&mut self) {
        for f in &mut self.bodies.force {
            *f = Vec3::ZERO;
        }
        for t in &mut self.bodies.torque {
            *t = Vec3::ZERO;
        }
    }

    /// Puts `other`'s state in place, keeping this system's buffers.
    pub fn restore_from(&mut self, other: Self) {
        let scratch = core::mem::take(&mut self.scratch);
        *self = other;
        self.scratch = scratch;
        self.scratch.cache_valid = false;
        self.scratch.joint_filter_valid = false;
        self.scratch.query.discard();
    }

    /// Number of body slots, alive or dead.
    pub fn slot_count(&self) -> usize {
        self.bodies.len()
    }

    /// Handles of the live bodies, in slot order.
    pub fn handles(&self) -> impl Iterator<Item = Handle> + '_ {
        (0..self.bodies.len())
            .filter(|&i| self.bodies.alive[i])
            .map(|i| self.bodies.handle(i))
    }

    /// Number of live bodies.
    pub fn body_count(&self) -> usize {
        self.bodies.alive.iter().filter(|&&a| a).count()
    }

    /// The kind of a live body.
    pub fn kind(&self, handle: Handle) -> Option<BodyKind> {
        self.bodies.slot(handle).map(|i| self.bodies.kind[i])
    }

    /// Position of a live body's centre of mass, m.
    pub fn position(&self, handle: Handle) -> Option<Vec3<R>> {
        self.bodies.slot(handle).map(|i| self.bodies.position[i])
    }

    /// Places a live body's centre of mass at `position`, m, as it is: no wake, no contact
    /// update, no velocity change. For tools that edit a snapshot's state (the network
    /// peer's deliberate desync); a running game moves bodies with commands. False when
    /// `handle` names no live body.
    pub fn set_position(&mut self, handle: Handle, position: Vec3<R>) -> bool {
        let Some(i) = self.bodies.slot(handle) else {
            return false;
        };
        self.bodies.position[i] = position;
        self.scratch.query.discard();
        true
    }

    /// Orientation of a live body.
    pub fn orientation(&self, handle: Handle) -> Option<crate::math::Quat<R>> {
        self.bodies.slot(handle).map(|i| self.bodies.orientation[i])
    }

    /// Linear velocity of a live body, m/s.
    pub fn linear_velocity(&self, handle: Handle) -> Option<Vec3<R>> {
        self.bodies
            .slot(handle)
            .map(|i| self.bodies.linear_velocity[i])
    }

    /// Angular velocity of a live body (world frame), rad/s.
    pub fn angular_velocity(&self, handle: Handle) -> Option<Vec3<R>> {
        self.bodies
            .slot(handle)
            .map(|i| self.bodies.angular_velocity[i])
    }

    /// Mass of a live body, kg (0 for static and kinematic bodies).
    pub fn mass(&self, handle: Handle) -> Option<R> {
        self.bodies.slot(handle).map(|i| self.bodies.mass[i])
    }

    /// The shape of a live body, in its body frame.
    pub fn shape(&self, handle: Handle) -> Option<&super::Shape<R>> {
        self.bodies.slot(handle).map(|i| &self.bodies.shape[i])
    }

    /// Whether a live body sleeps.
    pub fn is_sleeping(&self, handle: Handle) -> Option<bool> {
        self.bodies.slot(handle).map(|i| self.bodies.asleep[i])
    }

    /// Number of touching shape pairs.
    pub fn contact_count(&self) -> usize {
        self.contacts.len()
    }
}
