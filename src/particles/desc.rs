//! The scene description of a particle system: what a RON scene file says under
//! `particles: Some((...))`.
//!
//! Every type here is plain data; [`ParticleSystem::from_desc`](super::ParticleSystem::from_desc)
//! checks it and compiles it into simulation state. Units: metres, seconds, kilograms,
//! newtons. Fields with a natural default may be left out of a scene file.
//!
//! ```ron
//! (
//!     integrator: VelocityVerlet,
//!     capacity: 256,
//!     particles: [(position: (x: 1.0, y: 0.0, z: 0.0), velocity: (x: 0.0, y: 1.0, z: 0.0))],
//!     emitters: [(
//!         position: (x: 0.0, y: 0.0, z: 0.0),
//!         rate: 30.0,
//!         spread: Cone(axis: (x: 0.0, y: 1.0, z: 0.0), half_angle: 0.3),
//!         speed: (min: 4.0, max: 6.0),
//!         lifetime: (min: 1.0, max: 2.0),
//!     )],
//!     forces: [Gravity(), QuadraticDrag(coefficient: 0.01)],
//! )
//! ```

use serde::{Deserialize, Serialize};

pub use super::contact_desc::{ContactPlaneDesc, ContactsDesc, LinkDesc};
pub use crate::math::integration::Integrator;
pub use crate::math::spring::SpringDesc;
use crate::math::{Fx, Real, Vec3};
use crate::rigid::CollisionFilter;

/// Capacity of a particle system whose scene does not give one.
pub const DEFAULT_CAPACITY: u32 = 1024;
/// The largest capacity a scene may ask for (slots are never freed, so this bounds memory).
pub const MAX_CAPACITY: u32 = 1 << 20;
/// The highest emission rate a scene may ask for, particles per second per emitter.
pub const MAX_EMISSION_RATE: i32 = 1_000_000;

/// A particle system: its integrator, its capacity, the particles present at tick 0, the
/// templates that [`Command::Spawn`](crate::types::Command::Spawn) creates from, the
/// emitters and the force generators.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct ParticlesDesc<R: Real = Fx> {
    /// The integration scheme. Default [`Integrator::SemiImplicitEuler`].
    #[serde(default)]
    pub integrator: Integrator,
    /// The most particles alive at once (1 to [`MAX_CAPACITY`]). Default
    /// [`DEFAULT_CAPACITY`]. Emission and spawning beyond it are dropped.
    #[serde(default = "default_capacity")]
    pub capacity: u32,
    /// Particles present at tick 0. Particle `i` occupies slot `i`, so springs refer to it
    /// by its index in this list.
    #[serde(default)]
    pub particles: Vec<ParticleDesc<R>>,
    /// What `Command::Spawn { template, .. }` creates, by index.
    #[serde(default)]
    pub templates: Vec<ParticleTemplate<R>>,
    /// Particle sources.
    #[serde(default)]
    pub emitters: Vec<EmitterDesc<R>>,
    /// Force generators, evaluated in this order.
    #[serde(default)]
    pub forces: Vec<ForceDesc<R>>,
    /// The groups whose particles collide with the rigid bodies, at most one entry per
    /// group. Default none: particles pass through everything.
    #[serde(default)]
    pub collisions: Vec<CollisionDesc<R>>,
    /// Contacts between the particles and with planes, and rods and cables between them
    /// (the mass-aggregate engine). Default none.
    #[serde(default)]
    pub contacts: Option<ContactsDesc<R>>,
}

impl<R: Real> Default for ParticlesDesc<R> {
    /// No particles, emitters or forces; semi-implicit Euler; the default capacity.
    fn default() -> Self {
        Self {
            integrator: Integrator::default(),
            capacity: DEFAULT_CAPACITY,
            particles: Vec::new(),
            templates: Vec::new(),
            emitters: Vec::new(),
            forces: Vec::new(),
            collisions: Vec::new(),
            contacts: None,
        }
    }
}

/// One particle present at tick 0.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct ParticleDesc<R: Real = Fx> {
    /// Position, m.
    pub position: Vec3<R>,
    /// Velocity, m/s. Default zero; must be zero for a pinned particle.
    #[serde(default)]
    pub velocity: Vec3<R>,
    /// Mass, kg (≥ 0). 0 pins the particle: forces do not move it, only
    /// `Command::MoveKinematic` does. Default 1.
    #[serde(default = "one")]
    pub mass: R,
    /// Group, for group commands and group-restricted forces. Default 0.
    #[serde(default)]
    pub group: u16,
    /// Seconds until the particle dies (≥ 0); 0 means it never does. Default 0.
    #[serde(default)]
    pub lifetime: R,
}

/// What a spawn command creates (position and velocity come with the command).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct ParticleTemplate<R: Real = Fx> {
    /// Mass, kg (≥ 0; 0 pins). Default 1.
    #[serde(default = "one")]
    pub mass: R,
    /// Group. Default 0.
    #[serde(default)]
    pub group: u16,
    /// Seconds until the particle dies (≥ 0); 0 means never. Default 0.
    #[serde(default)]
    pub lifetime: R,
}

impl<R: Real> Default for ParticleTemplate<R> {
    /// A 1 kg immortal particle in group 0.
    fn default() -> Self {
        Self {
            mass: R::ONE,
            group: 0,
            lifetime: R::ZERO,
        }
    }
}

/// How the particles of one group collide with the rigid bodies (of every shape, level
/// meshes and heightfields included): as points that bounce with restitution `e` and
/// Coulomb friction `μ` relative to the surface's own velocity (see
/// [`collisions`](super::collisions)).
///
/// ```ron
/// collisions: [(group: 0, restitution: 0.4, friction: 0.3, push: true)]
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct CollisionDesc<R: Real = Fx> {
    /// The particle group this entry is for.
    pub group: u16,
    /// e in [0, 1]: the fraction of the approaching normal speed kept after a bounce.
    /// Default 0.5.
    #[serde(default = "half")]
    pub restitution: R,
    /// μ ≥ 0: the tangential impulse is at most μ times the normal one. Default 0.3.
    #[serde(default = "three_tenths")]
    pub friction: R,
    /// Whether each bounce pushes a dynamic body back with the opposite impulse. Default
    /// false: the particles bounce off bodies without moving them.
    #[serde(default)]
    pub push: bool,
    /// The layers the particles are on and collide with (a body is hit when the two filters
    /// interact; sensors never are). Default all.
    #[serde(default)]
    pub filter: CollisionFilter,
}

impl<R: Real> CollisionDesc<R> {
    /// Group `group` with the defaults: e = 0.5, μ = 0.3, no push, every layer.
    pub fn new(group: u16) -> Self {
        Self {
            group,
            restitution: half(),
            friction: three_tenths(),
            push: false,
            filter: CollisionFilter::ALL,
        }
    }
}

/// A closed interval `[min, max]` that emitters draw uniformly from.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct Interval<R: Real = Fx> {
    /// Lower end.
    pub min: R,
    /// Upper end (≥ `min`).
    pub max: R,
}

impl<R: Real> Interval<R> {
    /// `[min, max]`.
    pub const fn new(min: R, max: R) -> Self {
        Self { min, max }
    }

    /// `[value, value]`.
    pub const fn exactly(value: R) -> Self {
        Self::new(value, value)
    }
}

impl<R: Real> Default for Interval<R> {
    /// `[0, 0]`.
    fn default() -> Self {
        Self::exactly(R::ZERO)
    }
}

/// A particle source.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct EmitterDesc<R: Real = Fx> {
    /// Where particles appear, m.
    pub position: Vec3<R>,
    /// Particles per second (0 to [`MAX_EMISSION_RATE`]). Fractional rates work: the
    /// emitter accumulates `rate · dt` each step and emits the whole part.
    pub rate: R,
    /// Directions (cone) or start positions (box).
    pub spread: Spread<R>,
    /// Launch speed range, m/s (0 ≤ min ≤ max).
    pub speed: Interval<R>,
    /// Lifetime range, s: both 0 for immortal particles, otherwise 0 < min ≤ max.
    /// Default `[0, 0]`.
    #[serde(default)]
    pub lifetime: Interval<R>,
    /// Mass of each particle, kg (≥ 0; 0 pins). Default 1.
    #[serde(default = "one")]
    pub mass: R,
    /// Group of each particle. Default 0.
    #[serde(default)]
    pub group: u16,
    /// Whether the emitter starts switched on. Default true.
    #[serde(default = "yes")]
    pub on: bool,
}

/// How an emitter spreads its particles.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub enum Spread<R: Real = Fx> {
    /// Particles start at the emitter position, moving in directions uniformly distributed
    /// over the solid angle of a cone.
    Cone {
        /// Cone axis (any non-zero length).
        axis: Vec3<R>,
        /// Angle between the axis and the cone's edge, radians, in [0, π].
        half_angle: R,
    },
    /// Particles start at points uniformly distributed in the box `position ± half_extents`,
    /// all moving along one direction.
    Box {
        /// Half the box size along x, y and z, m (each ≥ 0).
        half_extents: Vec3<R>,
        /// Launch direction (any non-zero length).
        direction: Vec3<R>,
    },
}

/// A force generator.
///
/// `group: Some(g)` restricts a generator to particles of group `g`; `None` (the default)
/// applies it to every particle. Pinned particles (mass 0) feel nothing.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub enum ForceDesc<R: Real = Fx> {
    /// The world's gravity times `scale`: a = scale · g (m/s²). Without a `Gravity` entry,
    /// particles do not feel the world's gravity.
    Gravity {
        /// Multiplier of the world gravity. Default 1.
        #[serde(default = "one")]
        scale: R,
        /// Group restriction.
        #[serde(default)]
        group: Option<u16>,
    },
    /// F = −k v (N), with k in kg/s (≥ 0).
    LinearDrag {
        /// k, kg/s.
        coefficient: R,
        /// Group restriction.
        #[serde(default)]
        group: Option<u16>,
    },
    /// F = −k |v| v (N), with k in kg/m (≥ 0).
    QuadraticDrag {
        /// k, kg/m.
        coefficient: R,
        /// Group restriction.
        #[serde(default)]
        group: Option<u16>,
    },
    /// v ← v · d^Δt after every step: the particle keeps the fraction d of its velocity per
    /// second whatever the step length (0 < d ≤ 1).
    Damping {
        /// d, the fraction of velocity kept after one second.
        kept_per_second: R,
        /// Group restriction.
        #[serde(default)]
        group: Option<u16>,
    },
    /// A spring from a fixed point to a particle (Hooke's law plus damping along the
    /// spring axis; see [`SpringDesc`]).
    AnchoredSpring {
        /// Index of the particle in the scene's `particles` list.
        particle: u32,
        /// The fixed end, m.
        anchor: Vec3<R>,
        /// Stiffness, damping and rest length.
        spring: SpringDesc<R>,
    },
    /// A spring between two particles of the scene's `particles` list.
    Spring {
        /// Index of one end in the scene's `particles` list.
        first: u32,
        /// Index of the other end (≠ `first`).
        second: u32,
        /// Stiffness, damping and rest length.
        spring: SpringDesc<R>,
    },
    /// Softened attraction to a fixed point: a = −GM r / (|r|² + ε²)^{3/2} (m/s²), with r
    /// the particle's position relative to `centre`.
    PointGravity {
        /// The attracting point, m.
        centre: Vec3<R>,
        /// GM, m³/s² (negative repels).
        gm: R,
        /// ε, m (≥ 0): keeps the force finite at the centre.
        #[serde(default)]
        softening: R,
        /// Group restriction.
        #[serde(default)]
        group: Option<u16>,
    },
    /// A generator written in Rust and registered under `name` with
    /// [`ParticleSystem::register_user_force`](super::ParticleSystem::register_user_force).
    User {
        /// The registered name.
        name: String,
    },
}

fn default_capacity() -> u32 {
    DEFAULT_CAPACITY
}

fn one<R: Real>() -> R {
    R::ONE
}

fn half<R: Real>() -> R {
    R::HALF
}

fn three_tenths<R: Real>() -> R {
    R::from_ratio(3, 10)
}

fn yes() -> bool {
    true
}
