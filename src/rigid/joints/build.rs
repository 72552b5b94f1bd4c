//! Checking a scene's joint description and compiling it into the rigid system.

use super::desc::{
    JointDesc, JointKind, JointsDesc, Limits, MAX_JOINT_ITERATIONS, MAX_JOINTS, Motor, Spring,
};
use super::storage::{LocalFrame, NewJoint};
use crate::math::{Mat3, Quat, Real, Vec3};
use crate::rigid::build::{MAX_MAGNITUDE, check_lattice, check_total};
use crate::rigid::desc::BodyKind;
use crate::rigid::system::RigidSystem;
use crate::types::SceneError;

/// The shortest rod or rope, m: below it the direction between the anchors is lost in the
/// rounding of I32F32 products.
fn min_length<R: Real>() -> R {
    R::from_ratio(1, 1000)
}

impl<R: Real> RigidSystem<R> {
    /// Checks `desc` against the bodies already in the system and adds its joints, in
    /// order; the error names the offending field (relative to the `joints` section).
    pub fn add_joints(&mut self, desc: &JointsDesc<R>) -> Result<(), SceneError> {
        let limit = R::from_int(MAX_MAGNITUDE);
        SceneError::check_range("hertz", desc.hertz, R::ZERO, limit, "Hz")?;
        SceneError::check_range("damping_ratio", desc.damping_ratio, R::ZERO, limit, "")?;
        check_iterations("iterations", desc.iterations)?;
        let counts = desc.list.iter().map(|j| j.grid.map(|g| g.count));
        check_total(counts, MAX_JOINTS, "list", "joints")?;
        self.joints.hertz = desc.hertz;
        self.joints.damping_ratio = desc.damping_ratio;
        self.joints.iterations = desc.iterations;
        for (k, joint) in desc.list.iter().enumerate() {
            let field = format!("list[{k}]");
            check_joint(joint).map_err(|e| e.within(&field))?;
            for copy in lattice(joint).map_err(|e| e.within(&field))? {
                let new = self.compile_joint(joint, &copy).map_err(|e| {
                    let place = match joint.grid {
                        Some(_) => format!("{field} (copy {:?})", copy.index),
                        None => field.clone(),
                    };
                    e.within(&place)
                })?;
                self.joints.insert(new);
            }
        }
        self.scratch.joint_filter_valid = false;
        Ok(())
    }

    /// Checks the joints of a state that comes from outside (a snapshot): arrays of one
    /// length, live joints between two different live bodies with valid parameters.
    pub(crate) fn validate_joints(&self) -> Result<(), SceneError> {
        let j = &self.joints;
        let n = j.len();
        let lengths = [
            j.kind.len(),
            j.body_a.len(),
            j.body_b.len(),
            j.frame_a.len(),
            j.frame_b.len(),
            j.length.len(),
            j.collide.len(),
            j.break_force.len(),
            j.break_torque.len(),
            j.impulses.len(),
            j.generation.len(),
        ];
        if lengths.iter().any(|&len| len != n) || n > MAX_JOINTS as usize {
            return Err(SceneError::new(
                "joints",
                "the joint arrays have different lengths or too many slots",
            ));
        }
        let limit = R::from_int(MAX_MAGNITUDE);
        SceneError::check_range("joints.hertz", j.hertz, R::ZERO, limit, "Hz")?;
        SceneError::check_range("joints.damping_ratio", j.damping_ratio, R::ZERO, limit, "")?;
        if n > 0 {
            check_iterations("joints.iterations", j.iterations)?;
        }
        for i in j.live() {
            let field = format!("joints[{i}]");
            let (a, b) = (j.body_a[i] as usize, j.body_b[i] as usize);
            let bodies = &self.bodies;
            if a == b
                || a >= bodies.len()
                || b >= bodies.len()
                || !bodies.alive[a]
                || !bodies.alive[b]
            {
                return Err(SceneError::new(
                    field,
                    "does not join two different live bodies",
                ));
            }
            check_kind(&j.kind[i]).map_err(|e| e.within(&field))?;
            let unit = |q: Quat<R>| (q.length_squared() - R::ONE).abs() <= R::from_ratio(1, 1000);
            if !unit(j.frame_a[i].rotation) || !unit(j.frame_b[i].rotation) {
                return Err(SceneError::new(
                    format!("{field}.frame"),
                    "a frame's rotation is not a unit quaternion",
                ));
            }
        }
        Ok(())
    }

    /// Compiles a spawned joint between slots `joint.bodies` (no lattice).
    pub(crate) fn compile_spawned_joint(
        &self,
        joint: &JointDesc<R>,
    ) -> Result<NewJoint<R>, SceneError> {
        let copy = Copy {
            index: (0, 0, 0),
            bodies: joint.bodies,
            offset: Vec3::ZERO,
        };
        self.compile_joint(joint, &copy)
    }

    /// One joint of the lattice: checks its bodies and computes its frames in them.
    fn compile_joint(
        &self,
        joint: &JointDesc<R>,
        copy: &Copy<R>,
    ) -> Result<NewJoint<R>, SceneError> {
        let bodies = &self.bodies;
        let (a, b) = copy.bodies;
        for (name, slot) in [("bodies.0", a), ("bodies.1", b)] {
            if slot as usize >= bodies.len() {
                return Err(SceneError::new(
                    name,
                    format!(
                        "names body {slot}, but the scene has {} rigid bodies",
                        bodies.len()
                    ),
                ));
            }
        }
        if a == b {
            return Err(SceneError::new(
                "bodies",
                format!("joins body {a} to itself"),
            ));
        }
        let (ia, ib) = (a as usize, b as usize);
        if bodies.kind[ia] != BodyKind::Dynamic && bodies.kind[ib] != BodyKind::Dynamic {
            return Err(SceneError::new(
                "bodies",
                format!("bodies {a} and {b} are both static or kinematic: one must be dynamic"),
            ));
        }
        let anchor_a = joint.anchor + copy.offset;
        let anchor_b = joint.anchor_b.unwrap_or(joint.anchor) + copy.offset;
        let limit = R::from_int(MAX_MAGNITUDE);
        if anchor_a.abs().max_component() > limit || anchor_b.abs().max_component() > limit {
            return Err(SceneError::new(
                "anchor",
                format!("components must be within ±{MAX_MAGNITUDE} m"),
            ));
        }
        let world_frame = frame_of_axis(joint.axis);
        let local = |i: usize, anchor: Vec3<R>| {
            let q = bodies.orientation[i];
            LocalFrame {
                origin: q.conjugate().rotate(anchor - bodies.position[i]),
                rotation: (q.conjugate() * world_frame).normalize(),
            }
        };
        let distance = (anchor_b - anchor_a).length();
        let length = match joint.kind {
            JointKind::Rod { length } => length.unwrap_or(distance),
            JointKind::Rope { max_length } => max_length.unwrap_or(distance),
            JointKind::Spring { rest_length, .. } => rest_length.unwrap_or(distance),
            _ => R::ZERO,
        };
        if matches!(joint.kind, JointKind::Rod { .. } | JointKind::Rope { .. })
            && length < min_length()
        {
            return Err(SceneError::new(
                "kind",
                format!(
                    "the length must be at least {} m (got {length})",
                    min_length::<R>()
                ),
            ));
        }
        Ok(NewJoint {
            kind: joint.kind,
            body_a: a,
            body_b: b,
            frame_a: local(ia, anchor_a),
            frame_b: local(ib, anchor_b),
            length,
            collide: joint.collide,
            break_force: joint.break_force,
            break_torque: joint.break_torque,
        })
    }
}

/// The rotation whose x axis is `axis` (unit): columns x = axis, y = a unit vector
/// perpendicular to it ([`Vec3::any_orthonormal`]), z = x × y.
fn frame_of_axis<R: Real>(axis: Vec3<R>) -> Quat<R> {
    let y = axis.any_orthonormal();
    Quat::from_mat3(Mat3::from_cols(axis, y, axis.cross(y)))
}

/// One lattice copy of a joint: its lattice index, its bodies and its anchors' offset.
struct Copy<R: Real> {
    index: (u32, u32, u32),
    bodies: (u32, u32),
    offset: Vec3<R>,
}

/// The copies of `joint` (one without a grid); body indices that leave `u32` are refused.
fn lattice<R: Real>(joint: &JointDesc<R>) -> Result<Vec<Copy<R>>, SceneError> {
    let Some(grid) = joint.grid else {
        return Ok(vec![Copy {
            index: (0, 0, 0),
            bodies: joint.bodies,
            offset: Vec3::ZERO,
        }]);
    };
    check_lattice(grid.count, grid.spacing, MAX_JOINTS)?;
    let (nx, ny, nz) = grid.count;
    let step = |base: u32, stride: (u32, u32, u32), (i, j, k): (u32, u32, u32)| {
        u64::from(base)
            + u64::from(i) * u64::from(stride.0)
            + u64::from(j) * u64::from(stride.1)
            + u64::from(k) * u64::from(stride.2)
    };
    let mut copies = Vec::new();
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                let index = (i, j, k);
                let a = step(joint.bodies.0, grid.stride_a, index);
                let b = step(joint.bodies.1, grid.stride_b, index);
                let (Ok(a), Ok(b)) = (u32::try_from(a), u32::try_from(b)) else {
                    return Err(SceneError::new(
                        "grid",
                        format!("copy {index:?} names a body index beyond 2³²"),
                    ));
                };
                copies.push(Copy {
                    index,
                    bodies: (a, b),
                    offset: Vec3::new(
                        grid.spacing.x * R::from_int(i as i32),
                        grid.spacing.y * R::from_int(j as i32),
                        grid.spacing.z * R::from_int(k as i32),
                    ),
                });
            }
        }
    }
    Ok(copies)
}

/// The checks that do not depend on the bodies: the axis, the kind's parameters and the
/// break thresholds.
pub(crate) fn check_joint<R: Real>(joint: &JointDesc<R>) -> Result<(), SceneError> {
    let tolerance = R::from_ratio(1, 1000);
    if (joint.axis.length_squared() - R::ONE).abs() > tolerance {
        return Err(SceneError::new("axis", "must have length 1"));
    }
    for (name, threshold) in [
        ("break_force", joint.break_force),
        ("break_torque", joint.break_torque),
    ] {
        if let Some(value) = threshold
            && (value <= R::ZERO || value > R::MAX * R::from_ratio(1, 4))
        {
            return Err(SceneError::new(
                name,
                format!("must be above 0 and below a quarter of the format's range (got {value})"),
            ));
        }
    }
    check_kind(&joint.kind).map_err(|e| e.within("kind"))
}

/// The parameters of a joint kind: angles within ±π, lower ≤ upper, non-negative forces,
/// frequencies and damping ratios, lengths within range.
fn check_kind<R: Real>(kind: &JointKind<R>) -> Result<(), SceneError> {
    let limit = R::from_int(MAX_MAGNITUDE);
    match *kind {
        JointKind::Ball | JointKind::Fixed => Ok(()),
        JointKind::ConeTwist {
            swing,
            twist_lower,
            twist_upper,
            friction,
        } => {
            SceneError::check_range("ConeTwist.swing", swing, R::ZERO, R::PI, "rad")?;
            SceneError::check_range(
                "ConeTwist.friction",
                friction,
                R::ZERO,
                R::MAX * R::from_ratio(1, 4),
                "N·m",
            )?;
            check_limits(
                "ConeTwist",
                Limits {
                    lower: twist_lower,
                    upper: twist_upper,
                },
                R::PI,
            )
        }
        JointKind::Hinge {
            limits,
            motor,
            spring,
        } => {
            if let Some(limits) = limits {
                check_limits("Hinge.limits", limits, R::PI)?;
            }
            if let Some(motor) = motor {
                check_motor("Hinge.motor", motor)?;
            }
            if let Some(spring) = spring {
                check_spring("Hinge.spring", spring)?;
            }
            Ok(())
        }
        JointKind::Slider { limits, motor } => {
            if let Some(limits) = limits {
                check_limits("Slider.limits", limits, limit)?;
            }
            if let Some(motor) = motor {
                check_motor("Slider.motor", motor)?;
            }
            Ok(())
        }
        JointKind::Rod { length } => check_length("Rod.length", length),
        JointKind::Rope { max_length } => check_length("Rope.max_length", max_length),
        JointKind::Spring {
            rest_length,
            spring,
        } => {
            if let Some(length) = rest_length {
                SceneError::check_range("Spring.rest_length", length, R::ZERO, limit, "m")?;
            }
            check_spring("Spring.spring", spring)
        }
    }
}

fn check_iterations(name: &str, iterations: u32) -> Result<(), SceneError> {
    if (1..=MAX_JOINT_ITERATIONS).contains(&iterations) {
        Ok(())
    } else {
        Err(SceneError::new(
            name,
            format!("must be 1 to {MAX_JOINT_ITERATIONS} (got {iterations})"),
        ))
    }
}

fn check_limits<R: Real>(name: &str, limits: Limits<R>, bound: R) -> Result<(), SceneError> {
    SceneError::check_range(format!("{name}.lower"), limits.lower, -bound, bound, "")?;
    SceneError::check_range(
        format!("{name}.upper"),
        limits.upper,
        limits.lower,
        bound,
        "",
    )
}

fn check_motor<R: Real>(name: &str, motor: Motor<R>) -> Result<(), SceneError> {
    let limit = R::from_int(MAX_MAGNITUDE);
    SceneError::check_range(format!("{name}.speed"), motor.speed, -limit, limit, "")?;
    SceneError::check_range(
        format!("{name}.max_force"),
        motor.max_force,
        R::ZERO,
        R::MAX * R::from_ratio(1, 4),
        "",
    )
}

fn check_spring<R: Real>(name: &str, spring: Spring<R>) -> Result<(), SceneError> {
    let limit = R::from_int(MAX_MAGNITUDE);
    SceneError::check_range(format!("{name}.hertz"), spring.hertz, R::ZERO, limit, "Hz")?;
    SceneError::check_range(
        format!("{name}.damping_ratio"),
        spring.damping_ratio,
        R::ZERO,
        limit,
        "",
    )
}

fn check_length<R: Real>(name: &str, length: Option<R>) -> Result<(), SceneError> {
    match length {
        Some(length) => {
            SceneError::check_range(name, length, min_length(), R::from_int(MAX_MAGNITUDE), "m")
        }
        None => Ok(()),
    }
}
