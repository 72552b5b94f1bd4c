//! The scene description of rigid bodies: what a RON scene file says under `rigid: (...)`.
//!
//! Plain data; [`RigidSystem::from_desc`](super::RigidSystem::from_desc) checks it and
//! compiles it into simulation state. Units: metres, seconds, kilograms.
//!
//! ```ron
//! rigid: (
//!     bodies: [
//!         (kind: Static, shape: Plane(normal: (x: 0.0, y: 1.0, z: 0.0), offset: 0.0)),
//!         (
//!             shape: Box(half_extents: (x: 0.5, y: 0.5, z: 0.5)),
//!             position: (x: 0.0, y: 0.5, z: 0.0),
//!             grid: (count: (1, 10, 1), spacing: (x: 0.0, y: 1.0, z: 0.0)),
//!         ),
//!     ],
//! )
//! ```

use serde::{Deserialize, Serialize};

use super::filter::CollisionFilter;
use super::material::Material;
use super::shape::Shape;
use super::spawn::{BodyTemplate, JointTemplate};
use crate::math::{Fx, Quat, Real, Vec3};

/// The most bodies a scene may create.
pub const MAX_BODIES: u32 = 1 << 18;
/// The most solver substeps per step a scene may ask for.
pub const MAX_SOLVER_SUBSTEPS: u32 = 64;

/// How a body moves.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum BodyKind {
    /// Never moves; infinite mass.
    Static,
    /// Moves at the velocity it is given, whatever hits it; infinite mass.
    Kinematic,
    /// Moves under forces and contacts.
    #[default]
    Dynamic,
}

impl BodyKind {
    /// The code hashed into checksums.
    pub const fn code(self) -> u8 {
        match self {
            Self::Static => 0,
            Self::Kinematic => 1,
            Self::Dynamic => 2,
        }
    }
}

/// Copies of a body on a regular lattice: copy (i, j, k) sits at
/// `position + (i·spacing.x, j·spacing.y, k·spacing.z)`, created in the order i fastest,
/// then j, then k.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct Grid<R: Real = Fx> {
    /// Copies along x, y and z (each at least 1).
    pub count: (u32, u32, u32),
    /// Distance between neighbouring copies along each axis, m.
    pub spacing: Vec3<R>,
}

/// One body, or a lattice of identical bodies.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct BodyDesc<R: Real = Fx> {
    /// Static, kinematic or dynamic. Default dynamic.
    #[serde(default)]
    pub kind: BodyKind,
    /// The collision shape, in the body frame. A plane may only be static.
    pub shape: Shape<R>,
    /// Position of the body frame's origin, m. For a compound whose centre of mass is not
    /// at the origin, the body's reported position is its centre of mass.
    #[serde(default)]
    pub position: Vec3<R>,
    /// Orientation (a unit quaternion; it is normalised). Default identity.
    #[serde(default = "identity")]
    pub orientation: Quat<R>,
    /// Linear velocity of the centre of mass, m/s.
    #[serde(default)]
    pub velocity: Vec3<R>,
    /// Angular velocity in the world frame, rad/s.
    #[serde(default)]
    pub angular_velocity: Vec3<R>,
    /// Density, kg/m³. Default 1000 (water).
    #[serde(default = "default_density")]
    pub density: R,
    /// Friction and restitution.
    #[serde(default)]
    pub material: Material<R>,
    /// Linear damping c, 1/s: v ← v / (1 + h c) each substep. Default 0.
    #[serde(default)]
    pub linear_damping: R,
    /// Angular damping c, 1/s: ω ← ω / (1 + h c) each substep. Default 0.
    #[serde(default)]
    pub angular_damping: R,
    /// Copies of the body on a lattice; absent means one body.
    #[serde(default)]
    pub grid: Option<Grid<R>>,
    /// The layers the body is on and interacts with ([`CollisionFilter`]). Default all ones
    /// (and not written out).
    #[serde(default, skip_serializing_if = "CollisionFilter::is_all")]
    pub filter: CollisionFilter,
    /// A sensor detects the bodies it overlaps (events `sensor_enter` and `sensor_exit`) but
    /// exerts no contact force and feels none. Default false (and not written out).
    #[serde(default, skip_serializing_if = "core::ops::Not::not")]
    pub sensor: bool,
    /// A bullet is a dynamic body whose fast motion is also swept against the other
    /// dynamic bodies (those that are not bullets), not only against static and kinematic
    /// ones ([continuous collision](super::continuous)). Default false (and not written
    /// out).
    #[serde(default, skip_serializing_if = "core::ops::Not::not")]
    pub bullet: bool,
}

fn identity<R: Real>() -> Quat<R> {
    Quat::IDENTITY
}

fn default_density<R: Real>() -> R {
    R::from_int(1000)
}

impl<R: Real> BodyDesc<R> {
    /// A dynamic body of `shape` at `position`, at rest, with the default density and
    /// material.
    pub fn new(shape: Shape<R>, position: Vec3<R>) -> Self {
        Self {
            kind: BodyKind::Dynamic,
            shape,
            position,
            orientation: Quat::IDENTITY,
            velocity: Vec3::ZERO,
            angular_velocity: Vec3::ZERO,
            density: default_density(),
            material: Material::default(),
            linear_damping: R::ZERO,
            angular_damping: R::ZERO,
            grid: None,
            filter: CollisionFilter::ALL,
            sensor: false,
            bullet: false,
        }
    }

    /// The same body, static.
    pub fn fixed(mut self) -> Self {
        self.kind = BodyKind::Static;
        self
    }
}

/// The rigid-body part of a scene: the bodies and the solver settings.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct RigidDesc<R: Real = Fx> {
    /// Bodies present at tick 0; body `i` (counting lattice copies) gets slot `i`.
    #[serde(default)]
    pub bodies: Vec<BodyDesc<R>>,
    /// Solver settings.
    #[serde(default)]
    pub solver: SolverSettings<R>,
    /// What [`Command::SpawnBody`](crate::types::Command::SpawnBody) creates, by index.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub templates: Vec<BodyTemplate<R>>,
    /// What [`Command::SpawnJoint`](crate::types::Command::SpawnJoint) creates, by index.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub joint_templates: Vec<JointTemplate<R>>,
}

impl<R: Real> Default for RigidDesc<R> {
    /// No bodies, no templates, the default solver settings.
    fn default() -> Self {
        Self {
            bodies: Vec::new(),
            solver: SolverSettings::default(),
            templates: Vec::new(),
            joint_templates: Vec::new(),
        }
    }
}

impl<R: Real> RigidDesc<R> {
    /// How many bodies the description creates, lattice copies counted: the index the next
    /// body would get.
    pub fn body_count(&self) -> u32 {
        self.bodies
            .iter()
            .map(|b| {
                b.grid.map_or(1, |g| {
                    g.count
                        .0
                        .saturating_mul(g.count.1)
                        .saturating_mul(g.count.2)
                })
            })
            .fold(0, u32::saturating_add)
    }
}

/// Solver settings. The defaults are Box2D v3's, but for a stiffer contact.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct SolverSettings<R: Real = Fx> {
    /// Substeps per world substep (1 to [`MAX_SOLVER_SUBSTEPS`]). Default 5: with 4 (Box2D's
    /// and Rapier's default) the 45 Hz contacts below leave the 20-row, one-box-deep
    /// `pyramid` rocking about its long axis (each row on the one below, up to 0.35 m/s,
    /// in I32F32 and in `f64` alike), so that whether it falls asleep depends on a quiet
    /// spell after settling: starts shifted by 1 µm either sleep by tick 80 or never. With
    /// 5 it comes to rest, sleeping off too, from every start tried.
    #[serde(default = "default_substeps")]
    pub substeps: u32,
    /// Stiffness of the soft contact, Hz; capped at a quarter of the substep rate. Default
    /// 45. A contact under a load of acceleration a (m/s²) settles at an overlap of
    /// a/(2π f)², so the stiffer the spring, the less a tall stack sinks: at Box2D's 30 Hz the
    /// top of the 20-row `pyramid` sinks 26 mm, at 45 Hz 13 mm. At 60 Hz (the cap with 4
    /// substeps) the pyramid no longer comes to rest.
    #[serde(default = "default_contact_hertz")]
    pub contact_hertz: R,
    /// Damping ratio of the soft contact. Default 10.
    #[serde(default = "default_damping_ratio")]
    pub contact_damping_ratio: R,
    /// The fastest the solver pushes overlapping bodies apart, m/s. Default 3.
    #[serde(default = "default_push_velocity")]
    pub max_push_velocity: R,
    /// Approach speeds below this do not bounce, m/s. Default 1.
    #[serde(default = "default_restitution_threshold")]
    pub restitution_threshold: R,
    /// Contacts are created when shapes are closer than this, m. Default 0.02.
    #[serde(default = "default_speculative_distance")]
    pub speculative_distance: R,
    /// Whether resting islands go to sleep. Default true.
    #[serde(default = "default_true")]
    pub sleeping: bool,
    /// How long an island must stay slow before it sleeps, s. Default 0.5.
    #[serde(default = "default_time_to_sleep")]
    pub time_to_sleep: R,
    /// A body slower than this (m/s), and turning slower than `angular_sleep_speed`, counts
    /// as resting. Default 0.05.
    #[serde(default = "default_linear_sleep_speed")]
    pub linear_sleep_speed: R,
    /// Angular speed below which a body counts as resting, rad/s. Default 0.035 (2°/s).
    #[serde(default = "default_angular_sleep_speed")]
    pub angular_sleep_speed: R,
    /// How far, m, the shapes of a pair (box–box, box–capsule, capsule–capsule) may move
    /// relative to each other before the narrowphase runs for it again; until then its
    /// contact points are carried with the bodies (contact recycling, as Jolt's body-pair
    /// cache and Rapier's `contact_recycling`). Default 0.001 (Jolt's); 0 runs the
    /// narrowphase every step.
    #[serde(default = "default_contact_recycle_distance")]
    pub contact_recycle_distance: R,
}

fn default_substeps() -> u32 {
    5
}
fn default_contact_hertz<R: Real>() -> R {
    R::from_int(45)
}
fn default_damping_ratio<R: Real>() -> R {
    R::from_int(10)
}
fn default_push_velocity<R: Real>() -> R {
    R::from_int(3)
}
fn default_restitution_threshold<R: Real>() -> R {
    R::ONE
}
fn default_speculative_distance<R: Real>() -> R {
    R::from_ratio(2, 100)
}
fn default_contact_recycle_distance<R: Real>() -> R {
    R::from_ratio(1, 1000)
}
fn default_true() -> bool {
    true
}
fn default_time_to_sleep<R: Real>() -> R {
    R::HALF
}
fn default_linear_sleep_speed<R: Real>() -> R {
    R::from_ratio(5, 100)
}
fn default_angular_sleep_speed<R: Real>() -> R {
    R::from_ratio(35, 1000)
}

impl<R: Real> Default for SolverSettings<R> {
    fn default() -> Self {
        Self {
            substeps: default_substeps(),
            contact_hertz: default_contact_hertz(),
            contact_damping_ratio: default_damping_ratio(),
            max_push_velocity: default_push_velocity(),
            restitution_threshold: default_restitution_threshold(),
            speculative_distance: default_speculative_distance(),
            sleeping: true,
            time_to_sleep: default_time_to_sleep(),
            linear_sleep_speed: default_linear_sleep_speed(),
            angular_sleep_speed: default_angular_sleep_speed(),
            contact_recycle_distance: default_contact_recycle_distance(),
        }
    }
}
