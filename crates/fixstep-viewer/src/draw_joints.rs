//! Joints that hold two separate anchors apart (rods, ropes, springs) as lines between
//! their anchors; the other kinds keep their bodies touching, which shows them.

use super::colour::JOINT;
use super::draw_list::{Figure, Layer, Paint, Primitive};
use fixstep::math::Real;
use fixstep::rigid::{JointKind, RigidSystem};

/// Appends a line from anchor to anchor for every live rod, rope and spring, in slot order.
pub fn draw_joints<R: Real>(rigid: &RigidSystem<R>, out: &mut Vec<Primitive>) {
    for joint in rigid.joint_handles() {
        let (Some(kind), Some((a, b))) = (rigid.joint_kind(joint), rigid.joint_anchors(joint))
        else {
            continue;
        };
        if matches!(
            kind,
            JointKind::Rod { .. } | JointKind::Rope { .. } | JointKind::Spring { .. }
        ) {
            out.push(Primitive {
                figure: Figure::Line {
                    a: a.to_f64(),
                    b: b.to_f64(),
                },
                paint: Paint::Rgb(JOINT),
                layer: Layer::Moving,
            });
        }
    }
}
