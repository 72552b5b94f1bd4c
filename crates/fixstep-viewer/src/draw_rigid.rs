//! Rigid bodies as shaded boxes, balls and capsules; planes as the ground.

use super::colour::{GROUND, STATIC, body_colour, id_colour};
use super::draw_list::{Figure, Layer, Paint, Primitive};
use super::geometry::{Pose, dot, normalize, scale};
use fixstep::math::Real;
use fixstep::rigid::{BodyKind, RigidSystem, Shape};

/// How bodies are coloured.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum BodyColours {
    /// A palette colour per moving body (greyed while asleep), grey scenery and ground.
    #[default]
    Palette,
    /// One distinct flat colour per body, static ones and planes included
    /// ([`id_colour`] of its rank among the live bodies), to count bodies in a picture.
    PerBody,
}

/// Appends the figures of every live body, in slot order.
pub fn draw_rigid<R: Real>(rigid: &RigidSystem<R>, colours: BodyColours, out: &mut Vec<Primitive>) {
    for (rank, handle) in rigid.handles().enumerate() {
        let (Some(position), Some(orientation), Some(shape), Some(kind), Some(sleeping)) = (
            rigid.position(handle),
            rigid.orientation(handle),
            rigid.shape(handle),
            rigid.kind(handle),
            rigid.is_sleeping(handle),
        ) else {
            continue;
        };
        let pose = Pose::from_quaternion(orientation.to_f64(), position.to_f64());
        let (colour, layer) = match (colours, kind) {
            (BodyColours::PerBody, BodyKind::Static) => (id_colour(rank), Layer::Scenery),
            (BodyColours::PerBody, _) => (id_colour(rank), Layer::Moving),
            (BodyColours::Palette, BodyKind::Static) => (STATIC, Layer::Scenery),
            (BodyColours::Palette, _) => {
                (body_colour(handle.index as usize, sleeping), Layer::Moving)
            }
        };
        draw_shape(shape, &pose, colour, layer, colours, out);
    }
}

/// Appends the figures of `shape` placed at `pose`.
fn draw_shape<R: Real>(
    shape: &Shape<R>,
    pose: &Pose,
    colour: [u8; 3],
    layer: Layer,
    colours: BodyColours,
    out: &mut Vec<Primitive>,
) {
    let mut push = |figure, colour, layer| {
        out.push(Primitive {
            figure,
            paint: Paint::Rgb(colour),
            layer,
        });
    };
    match shape {
        Shape::Sphere { radius } => push(
            Figure::Ball {
                centre: pose.origin,
                radius: radius.to_f64(),
            },
            colour,
            layer,
        ),
        Shape::Box { half_extents } => {
            let h = half_extents.to_f64();
            push(
                Figure::Cuboid {
                    centre: pose.origin,
                    half_axes: [0, 1, 2].map(|k| scale(pose.axes[k], h[k])),
                },
                colour,
                layer,
            );
        }
        Shape::Capsule {
            radius,
            half_height,
        } => {
            let h = half_height.to_f64();
            push(
                Figure::Capsule {
                    a: pose.point([0.0, -h, 0.0]),
                    b: pose.point([0.0, h, 0.0]),
                    radius: radius.to_f64(),
                },
                colour,
                layer,
            );
        }
        // The half-space n · x ≤ offset in the body frame is n_w · x ≤ offset + n_w · t in
        // the world, with n_w = R n.
        Shape::Plane { normal, offset } => {
            let normal = normalize(pose.vector(normal.to_f64()));
            let ground = match colours {
                BodyColours::Palette => GROUND,
                BodyColours::PerBody => colour,
            };
            push(
                Figure::Plane {
                    normal,
                    offset: offset.to_f64() + dot(normal, pose.origin),
                },
                ground,
                Layer::Ground,
            );
        }
        Shape::Compound { parts } => {
            for part in parts {
                let inner =
                    Pose::from_quaternion(part.rotation.to_f64(), part.translation.to_f64());
                draw_shape(
                    &part.shape,
                    &pose.compose(&inner),
                    colour,
                    layer,
                    colours,
                    out,
                );
            }
        }
    }
}
