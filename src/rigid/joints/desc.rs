//! The scene description of joints: what a RON scene file says under `joints: (...)`.
//!
//! Plain data; [`RigidSystem::add_joints`](crate::rigid::RigidSystem::add_joints) checks it
//! and compiles it into simulation state. Units: metres, seconds, kilograms, radians.
//!
//! A joint names two bodies by their index in the scene's rigid body list (lattice copies
//! counted, as in [`RigidDesc::bodies`](crate::rigid::RigidDesc)), and places its anchor and
//! axis in the world frame as the bodies stand at tick 0; the build turns them into frames
//! fixed in each body.
//!
//! ```ron
//! joints: (
//!     list: [
//!         // A door: body 1 turns about the vertical axis through (0, 1, 0) on the static
//!         // body 0, between −90° and +90°.
//!         (
//!             kind: Hinge(limits: (lower: -1.5708, upper: 1.5708)),
//!             bodies: (0, 1),
//!             anchor: (x: 0.0, y: 1.0, z: 0.0),
//!             axis: (x: 0.0, y: 1.0, z: 0.0),
//!         ),
//!     ],
//! )
//! ```

use serde::{Deserialize, Serialize};

use crate::math::{Fx, Real, Vec3};

/// The most joints a scene may create (lattice copies counted).
pub const MAX_JOINTS: u32 = 1 << 18;

/// The most solver iterations per pass the joints may ask for.
pub const MAX_JOINT_ITERATIONS: u32 = 8;

/// The joints of a scene, the stiffness of their position correction and their iterations.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct JointsDesc<R: Real = Fx> {
    /// The joints; joint `i` (counting lattice copies) gets slot `i`.
    #[serde(default)]
    pub list: Vec<JointDesc<R>>,
    /// Frequency of the soft position correction of every joint, Hz (Box2D v3's soft step),
    /// capped at a fifth of the substep rate per iteration: a joint loaded with force F
    /// settles at an error of F/(m_eff (2π f)²) (m_eff its effective mass). Default 120 (at 5
    /// substeps of 60 Hz ticks, the cap with 2 iterations): the top joints of a hanging chain
    /// of twenty 29 kg links stay within 0.7 mm; Box2D's 60 Hz would leave 2.6 mm.
    #[serde(default = "default_hertz")]
    pub hertz: R,
    /// Damping ratio of that correction. Default 2 (Box2D v3's).
    #[serde(default = "default_damping_ratio")]
    pub damping_ratio: R,
    /// Gauss–Seidel passes over the joints in each solver pass (1 to
    /// [`MAX_JOINT_ITERATIONS`]). Default 2: with one, a stiffness beyond about a third of
    /// the substep rate makes a long chain blow up.
    #[serde(default = "default_iterations")]
    pub iterations: u32,
}

fn default_hertz<R: Real>() -> R {
    R::from_int(120)
}

fn default_damping_ratio<R: Real>() -> R {
    R::TWO
}

fn default_iterations() -> u32 {
    2
}

impl<R: Real> Default for JointsDesc<R> {
    fn default() -> Self {
        Self {
            list: Vec::new(),
            hertz: default_hertz(),
            damping_ratio: default_damping_ratio(),
            iterations: default_iterations(),
        }
    }
}

impl<R: Real> JointsDesc<R> {
    /// The joints in `list`, with the default stiffness.
    pub fn new(list: Vec<JointDesc<R>>) -> Self {
        Self {
            list,
            ..Self::default()
        }
    }
}

/// Limits on a joint's free coordinate: an angle (rad) for a hinge, a translation (m) for
/// a slider, with `lower ≤ upper`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct Limits<R: Real = Fx> {
    /// The least value, rad or m.
    pub lower: R,
    /// The greatest value, rad or m.
    pub upper: R,
}

/// A motor on a joint's free coordinate: it drives the relative velocity to `speed` (rad/s
/// for a hinge, m/s for a slider) with at most `max_force` (N·m for a hinge, N for a
/// slider).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct Motor<R: Real = Fx> {
    /// Target relative speed, rad/s or m/s.
    pub speed: R,
    /// The largest torque (N·m) or force (N) the motor applies.
    pub max_force: R,
}

/// A spring on a joint's free coordinate, pulling it back to its value at tick 0 (hinge
/// angle 0): a damped oscillator of natural frequency `hertz` and damping ratio
/// `damping_ratio`, whatever the masses.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct Spring<R: Real = Fx> {
    /// Natural frequency, Hz.
    pub hertz: R,
    /// Damping ratio (1: critically damped).
    pub damping_ratio: R,
}

/// What a joint keeps between its two bodies.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub enum JointKind<R: Real = Fx> {
    /// Ball-and-socket: the anchors coincide; the bodies turn freely about it.
    Ball,
    /// Ball-and-socket with a cone and twist limit (a shoulder or a hip): B's copy of the
    /// axis stays within `swing` rad of A's, and B twists about it between `twist_lower` and
    /// `twist_upper` rad; `friction` resists relative turning with a torque of up to that
    /// much about each axis (N·m), as a stiff joint of a ragdoll does.
    ConeTwist {
        /// Half-angle of the cone, rad (0 to π).
        swing: R,
        /// Least twist, rad (−π to `twist_upper`).
        twist_lower: R,
        /// Greatest twist, rad (`twist_lower` to π).
        twist_upper: R,
        /// The largest friction torque about each axis, N·m. Default 0.
        #[serde(default)]
        friction: R,
    },
    /// Hinge (revolute): the anchors coincide and B turns relative to A only about the
    /// axis. The hinge angle is 0 at tick 0.
    Hinge {
        /// Limits on the hinge angle, rad (within ±π).
        #[serde(default)]
        limits: Option<Limits<R>>,
        /// A motor driving the relative angular speed about the axis.
        #[serde(default)]
        motor: Option<Motor<R>>,
        /// A spring pulling the angle back to 0.
        #[serde(default)]
        spring: Option<Spring<R>>,
    },
    /// Slider (prismatic): B keeps its orientation relative to A and moves only along the
    /// axis. The translation is (`anchor_b` − `anchor`)·axis at tick 0.
    Slider {
        /// Limits on the translation, m.
        #[serde(default)]
        limits: Option<Limits<R>>,
        /// A motor driving the relative speed along the axis.
        #[serde(default)]
        motor: Option<Motor<R>>,
    },
    /// Fixed (weld): B keeps its position and orientation relative to A.
    Fixed,
    /// A rigid rod between the anchor on A and `anchor_b` on B: their distance stays
    /// `length` (m; absent: their distance at tick 0).
    Rod {
        /// The distance kept, m.
        #[serde(default)]
        length: Option<R>,
    },
    /// A rope between the anchor on A and `anchor_b` on B: their distance is at most
    /// `max_length` (m; absent: their distance at tick 0). It pulls, never pushes.
    Rope {
        /// The greatest distance, m.
        #[serde(default)]
        max_length: Option<R>,
    },
    /// A soft spring between the anchor on A and `anchor_b` on B, of rest length
    /// `rest_length` (m; absent: their distance at tick 0).
    Spring {
        /// The distance at which the spring is relaxed, m.
        #[serde(default)]
        rest_length: Option<R>,
        /// Natural frequency (Hz) and damping ratio.
        spring: Spring<R>,
    },
}

impl<R: Real> JointKind<R> {
    /// The code hashed into checksums.
    pub const fn code(&self) -> u8 {
        match self {
            Self::Ball => 0,
            Self::ConeTwist { .. } => 1,
            Self::Hinge { .. } => 2,
            Self::Slider { .. } => 3,
            Self::Fixed => 4,
            Self::Rod { .. } => 5,
            Self::Rope { .. } => 6,
            Self::Spring { .. } => 7,
        }
    }
}

/// Copies of a joint on a lattice, to build chains and grids: copy (i, j, k) joins bodies
/// `bodies.0 + i·stride_a.0 + j·stride_a.1 + k·stride_a.2` and
/// `bodies.1 + i·stride_b.0 + j·stride_b.1 + k·stride_b.2`, with its anchors moved by
/// (i·spacing.x, j·spacing.y, k·spacing.z); copies are created i fastest, then j, then k.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct JointGrid<R: Real = Fx> {
    /// Copies along the three lattice directions (each at least 1).
    pub count: (u32, u32, u32),
    /// How far body A's index moves per step along each direction.
    #[serde(default)]
    pub stride_a: (u32, u32, u32),
    /// How far body B's index moves per step along each direction.
    #[serde(default)]
    pub stride_b: (u32, u32, u32),
    /// How far the anchors move per step along x, y and z, m.
    #[serde(default)]
    pub spacing: Vec3<R>,
}

/// One joint, or a lattice of joints.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct JointDesc<R: Real = Fx> {
    /// What the joint keeps.
    pub kind: JointKind<R>,
    /// Bodies A and B, by index in the scene's rigid body list. At least one must be
    /// dynamic, and they must differ.
    pub bodies: (u32, u32),
    /// A's anchor in the world frame at tick 0, m: the pivot, or for a rod, rope or spring
    /// the end on body A.
    pub anchor: Vec3<R>,
    /// B's anchor, world frame at tick 0, m: for a rod, rope or spring its end on B; for
    /// the other kinds the point of B that the joint pulls onto A's anchor from the first
    /// step (Box2D's and Rapier's separate local anchors). Absent: the same point as
    /// `anchor`.
    #[serde(default)]
    pub anchor_b: Option<Vec3<R>>,
    /// The joint axis in the world frame at tick 0 (unit length): the hinge axis, the
    /// slider direction, the axis of a cone-twist limit. Default x.
    #[serde(default = "default_axis")]
    pub axis: Vec3<R>,
    /// Whether the two bodies still collide with each other. Default false.
    #[serde(default)]
    pub collide: bool,
    /// The joint breaks when the force it transmits exceeds this, N (absent: never).
    #[serde(default)]
    pub break_force: Option<R>,
    /// The joint breaks when the torque it transmits exceeds this, N·m (absent: never).
    #[serde(default)]
    pub break_torque: Option<R>,
    /// Copies of the joint on a lattice; absent means one joint.
    #[serde(default)]
    pub grid: Option<JointGrid<R>>,
}

fn default_axis<R: Real>() -> Vec3<R> {
    Vec3::X
}

impl<R: Real> JointDesc<R> {
    /// A joint of `kind` between bodies `a` and `b` at `anchor` (world, m), axis x, bodies
    /// not colliding, unbreakable.
    pub fn new(kind: JointKind<R>, a: u32, b: u32, anchor: Vec3<R>) -> Self {
        Self {
            kind,
            bodies: (a, b),
            anchor,
            anchor_b: None,
            axis: default_axis(),
            collide: false,
            break_force: None,
            break_torque: None,
            grid: None,
        }
    }

    /// The same joint with axis `axis` (world, unit).
    pub fn with_axis(mut self, axis: Vec3<R>) -> Self {
        self.axis = axis;
        self
    }

    /// The same joint with B's end at `anchor_b` (world, m).
    pub fn with_anchor_b(mut self, anchor_b: Vec3<R>) -> Self {
        self.anchor_b = Some(anchor_b);
        self
    }
}
