//! What each kind of joint keeps, as a point block and scalar rows, for its current pose.
//!
//! With a_x, a_y, a_z and b_x, b_y, b_z the axes of A's and B's joint frames (world), d the
//! vector from A's anchor to B's, q = q_A* ⊗ q_B the relative rotation (w ≥ 0) and θ its
//! twist about x ([`twist_angle`]), the constraints are as follows, with the joint's stored
//! impulse each one accumulates into (`[k]`). They are solved springs, motors and friction
//! first, then the point block, then the locks, then the limits. (Box2D v3 solves a
//! revolute joint's limits before its point; here, with the limits before the locks, the 4 ×
//! 30 `falling_hinges` pile kept jittering at 2 to 7 cm/s for thousands of ticks and never
//! slept; with the limits last it comes to rest.)
//!
//! | kind | point block | scalar rows |
//! |---|---|---|
//! | ball | `[0..3]` | — |
//! | cone-twist | `[0..3]` | friction: motors at speed 0 about x, y, z (world) `[6..9]`; swing: ψ_max − ψ ≥ 0 about −n `[3]`; twist: θ − θ_lo ≥ 0 `[4]` and θ_hi − θ ≥ 0 `[5]` about ±t |
//! | hinge | `[0..3]` | locks (a_x × b_x)·a_y = 0 about a_y `[3]`, (a_x × b_x)·a_z = 0 about a_z `[4]`; limits θ − θ_lo ≥ 0 `[5]`, θ_hi − θ ≥ 0 `[6]` about ±a_x; motor `[7]` and spring on θ `[8]` about a_x |
//! | slider | — | locks 2q_x, 2q_y, 2q_z = 0 about a_x, a_y, a_z `[0..3]`; d·a_y = 0 `[3]`, d·a_z = 0 `[4]` along a_y, a_z; limits s − s_lo ≥ 0 `[5]`, s_hi − s ≥ 0 `[6]` and motor `[7]` along ±a_x, with s = d·a_x |
//! | fixed | `[0..3]` | locks 2q_x, 2q_y, 2q_z = 0 about a_x, a_y, a_z `[3..6]` |
//! | rod | — | \|d\| − L = 0 along u = d/\|d\| `[0]` |
//! | rope | — | L_max − \|d\| ≥ 0 along −u `[0]` |
//! | spring | — | spring on \|d\| − L_rest along u `[0]` |
//!
//! For the cone-twist, ψ = atan2(|a_x × b_x|, a_x·b_x) is the swing angle between the two
//! x axes, n = (a_x × b_x)/|a_x × b_x| the axis it turns about, and t = (a_x + b_x)/|a_x + b_x|
//! the twist axis midway between them.
//!
//! A slider's linear row along a unit u fixed in A has angular parts j_a = (r_a + d) × u
//! and j_b = r_b × u (the time derivative of d·u, u turning with A); the row of a rod, rope
//! or spring joins two anchors, j_a = r_a × u, j_b = r_b × u; an angular row about a unit
//! axis has j_a = j_b = axis. Each error C is signed so that Ċ is the row's velocity.

use super::body::SolverBody;
use super::joint_point::PointBlock;
use super::joint_pose::{JointPose, twist_angle};
use super::joint_row::{JointRow, RowRole};
use super::softness::Softness;
use crate::math::{Mat3, Real, Vec3};
use crate::rigid::joints::desc::{JointKind, Limits};

/// A joint's constraints for one pose: an optional point block and its rows, appended to a
/// row list in solving order: the rows before `locks_from` (springs, motors, friction), then
/// the point block, then the rest (locks, then limits). Masses and impulses are zero.
pub(crate) struct JointRows<'a, R: Real> {
    pub point: Option<PointBlock<R>>,
    /// The list the rows are appended to, and where this joint's rows begin in it.
    rows: &'a mut Vec<JointRow<R>>,
    first: usize,
    pub locks_from: usize,
}

/// What the rows of one joint need besides its pose: its kind, its length (rod, rope,
/// spring), the substep h (s) and its spring's softness for that substep.
pub(crate) struct RowInputs<'a, R: Real> {
    pub kind: &'a JointKind<R>,
    pub length: R,
    pub h: R,
    pub spring: Softness<R>,
}

impl<'a, R: Real> JointRows<'a, R> {
    /// The constraints of a joint at `pose` between solver bodies `ba` and `bb`, its rows
    /// appended to `rows`.
    pub fn build(
        inputs: &RowInputs<'_, R>,
        pose: &JointPose<R>,
        (ba, bb): (&SolverBody<R>, &SolverBody<R>),
        rows: &'a mut Vec<JointRow<R>>,
    ) -> Self {
        let first = rows.len();
        let mut out = Self {
            point: None,
            rows,
            first,
            locks_from: 0,
        };
        let bodies = (ba, bb);
        let point = || PointBlock {
            r_a: pose.r_a,
            r_b: pose.r_b,
            error: pose.d,
            mass: Mat3::ZERO,
            impulse: Vec3::ZERO,
            drift: PointBlock::drift_of(pose.r_a, pose.r_b, ba, bb, inputs.h),
        };
        match *inputs.kind {
            JointKind::Ball => out.point = Some(point()),
            JointKind::ConeTwist {
                swing,
                twist_lower,
                twist_upper,
                friction,
            } => {
                out.point = Some(point());
                if friction > R::ZERO {
                    let role = RowRole::Motor {
                        speed: R::ZERO,
                        max_impulse: friction * inputs.h,
                    };
                    for (k, axis) in [Vec3::X, Vec3::Y, Vec3::Z].into_iter().enumerate() {
                        out.push(JointRow::angular(axis, R::ZERO, role, 6 + k as u8, bodies));
                    }
                }
                out.locks_from = out.count();
                let (a, b) = pose.axes();
                let across = a[0].cross(b[0]);
                let (n, sin) = across.try_normalize().unwrap_or((a[1], R::ZERO));
                let swing_angle = sin.atan2(a[0].dot_fused(b[0]));
                out.push(JointRow::angular(
                    -n,
                    swing - swing_angle,
                    RowRole::Inequality,
                    3,
                    bodies,
                ));
                let t = (a[0] + b[0]).normalize_or_zero();
                let twist = twist_angle(pose.relative());
                out.push_limits(
                    t,
                    twist,
                    Limits {
                        lower: twist_lower,
                        upper: twist_upper,
                    },
                    4,
                    bodies,
                );
            }
            JointKind::Hinge {
                limits,
                motor,
                spring,
            } => {
                out.point = Some(point());
                let (a, b) = pose.axes();
                let angle = twist_angle(pose.relative());
                if spring.is_some() {
                    let role = RowRole::Spring(inputs.spring);
                    out.push(JointRow::angular(a[0], angle, role, 8, bodies));
                }
                if let Some(motor) = motor {
                    let role = RowRole::Motor {
                        speed: motor.speed,
                        max_impulse: motor.max_force * inputs.h,
                    };
                    out.push(JointRow::angular(a[0], R::ZERO, role, 7, bodies));
                }
                out.locks_from = out.count();
                let across = a[0].cross(b[0]);
                for (k, axis) in [a[1], a[2]].into_iter().enumerate() {
                    let error = across.dot_fused(axis);
                    out.push(JointRow::angular(
                        axis,
                        error,
                        RowRole::Equality,
                        3 + k as u8,
                        bodies,
                    ));
                }
                if let Some(limits) = limits {
                    out.push_limits(a[0], angle, limits, 5, bodies);
                }
            }
            JointKind::Slider { limits, motor } => {
                let (a, _) = pose.axes();
                let translation = pose.d.dot_fused(a[0]);
                if let Some(motor) = motor {
                    let role = RowRole::Motor {
                        speed: motor.speed,
                        max_impulse: motor.max_force * inputs.h,
                    };
                    out.push(linear_row(a[0], pose, R::ZERO, role, 7, bodies));
                }
                out.locks_from = out.count();
                out.push_rotation_locks(a, pose, 0, bodies);
                for (k, axis) in [a[1], a[2]].into_iter().enumerate() {
                    let error = pose.d.dot_fused(axis);
                    out.push(linear_row(
                        axis,
                        pose,
                        error,
                        RowRole::Equality,
                        3 + k as u8,
                        bodies,
                    ));
                }
                if let Some(limits) = limits {
                    let lower = translation - limits.lower;
                    let upper = limits.upper - translation;
                    out.push(linear_row(
                        a[0],
                        pose,
                        lower,
                        RowRole::Inequality,
                        5,
                        bodies,
                    ));
                    out.push(linear_row(
                        -a[0],
                        pose,
                        upper,
                        RowRole::Inequality,
                        6,
                        bodies,
                    ));
                }
            }
            JointKind::Fixed => {
                out.point = Some(point());
                let (a, _) = pose.axes();
                out.push_rotation_locks(a, pose, 3, bodies);
            }
            JointKind::Rod { .. } | JointKind::Rope { .. } | JointKind::Spring { .. } => {
                // Coincident anchors have no direction: the row keeps x, harmlessly (a rod or
                // rope is at least 1 mm long, a spring at rest length 0 has no error there).
                let (u, distance) = pose.d.try_normalize().unwrap_or((Vec3::X, R::ZERO));
                let (direction, error, role) = match *inputs.kind {
                    JointKind::Rod { .. } => (u, distance - inputs.length, RowRole::Equality),
                    JointKind::Rope { .. } => (-u, inputs.length - distance, RowRole::Inequality),
                    _ => (u, distance - inputs.length, RowRole::Spring(inputs.spring)),
                };
                let angular = (pose.r_a.cross(direction), pose.r_b.cross(direction));
                let mut row = JointRow::new(direction, angular, error, role, 0, bodies);
                // The drift of |d|, along u; the rope's row points along −u.
                let drift = distance_drift(pose, u, distance, (ba, bb), inputs.h);
                row.drift = if direction == u { drift } else { -drift };
                out.push(row);
            }
        }
        out
    }

    fn push(&mut self, row: JointRow<R>) {
        self.rows.push(row);
    }

    /// How many rows this joint has so far.
    pub fn count(&self) -> usize {
        self.rows.len() - self.first
    }

    /// The rows that keep B's frame turned as A's: 2q_x, 2q_y, 2q_z = 0 about A's axes, into
    /// slots `first..first + 3`.
    fn push_rotation_locks(
        &mut self,
        a: [Vec3<R>; 3],
        pose: &JointPose<R>,
        first: u8,
        bodies: (&SolverBody<R>, &SolverBody<R>),
    ) {
        let q = pose.relative();
        for (k, (axis, half)) in a.into_iter().zip([q.x, q.y, q.z]).enumerate() {
            let row = JointRow::angular(
                axis,
                R::TWO * half,
                RowRole::Equality,
                first + k as u8,
                bodies,
            );
            self.push(row);
        }
    }

    /// The two limit rows on an angle about unit `axis`: angle − lower ≥ 0 about the axis
    /// into slot `first`, upper − angle ≥ 0 about −axis into `first + 1`.
    fn push_limits(
        &mut self,
        axis: Vec3<R>,
        angle: R,
        limits: Limits<R>,
        first: u8,
        bodies: (&SolverBody<R>, &SolverBody<R>),
    ) {
        let lower = angle - limits.lower;
        let upper = limits.upper - angle;
        self.push(JointRow::angular(
            axis,
            lower,
            RowRole::Inequality,
            first,
            bodies,
        ));
        self.push(JointRow::angular(
            -axis,
            upper,
            RowRole::Inequality,
            first + 1,
            bodies,
        ));
    }
}

/// ½ h κ for the distance |d| between two anchors (m/s; the rows of rods, ropes and
/// springs), over a substep of `h` seconds: with ḋ the anchors' relative velocity and
/// d̈ = ω_b × (ω_b × r_b) − ω_a × (ω_a × r_a) their centripetal acceleration,
///
/// ```text
/// κ = d²|d|/dt² at fixed velocities = u·d̈ + (|ḋ|² − (u·ḋ)²) / |d|     (m/s²)
/// ```
///
/// the second term being the distance's growth as the anchors pass each other sideways (a
/// pendulum's bob moving along its circle). Zero at zero distance, where u is undefined.
fn distance_drift<R: Real>(
    pose: &JointPose<R>,
    u: Vec3<R>,
    distance: R,
    (ba, bb): (&SolverBody<R>, &SolverBody<R>),
    h: R,
) -> R {
    if distance <= R::ZERO {
        return R::ZERO;
    }
    let d_dot = (bb.v + bb.w.cross(pose.r_b)) - (ba.v + ba.w.cross(pose.r_a));
    let along = d_dot.dot_fused(u);
    let sideways = d_dot.dot_fused(d_dot) - along * along;
    let centripetal = PointBlock::drift_of(pose.r_a, pose.r_b, ba, bb, h);
    centripetal.dot_fused(u) + sideways / distance * (h * R::HALF)
}

/// A slider's linear row along unit `u` fixed in A (see the [module](self) documentation).
fn linear_row<R: Real>(
    u: Vec3<R>,
    pose: &JointPose<R>,
    error: R,
    role: RowRole<R>,
    slot: u8,
    bodies: (&SolverBody<R>, &SolverBody<R>),
) -> JointRow<R> {
    let angular_a = (pose.r_a + pose.d).cross(u);
    JointRow::new(u, (angular_a, pose.r_b.cross(u)), error, role, slot, bodies)
}
