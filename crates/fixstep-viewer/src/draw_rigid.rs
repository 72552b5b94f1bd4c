//! Rigid bodies as shaded boxes, balls and capsules, cylinders, cones and hulls as shaded
//! polygons; planes as the ground.

use super::colour::{GROUND, STATIC, body_colour, id_colour};
use super::draw_list::{Figure, Layer, Paint, Primitive};
use super::geometry::{P3, Pose, dot, normalize, scale};
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
        Shape::Cylinder {
            radius,
            half_height,
        } => {
            let (r, h) = (radius.to_f64(), half_height.to_f64());
            let bottom = circle(r, -h);
            let top = circle(r, h);
            let mut faces: Vec<Vec<P3>> = (0..SIDES)
                .map(|k| {
                    let next = (k + 1) % SIDES;
                    vec![bottom[k], bottom[next], top[next], top[k]]
                })
                .collect();
            faces.push(top.clone());
            faces.push(bottom.iter().rev().copied().collect());
            push_faces(&faces, pose, colour, layer, out);
        }
        Shape::Cone {
            radius,
            half_height,
        } => {
            let (r, h) = (radius.to_f64(), half_height.to_f64());
            let base = circle(r, -h);
            let apex = [0.0, h, 0.0];
            let mut faces: Vec<Vec<P3>> = (0..SIDES)
                .map(|k| vec![base[k], base[(k + 1) % SIDES], apex])
                .collect();
            faces.push(base.iter().rev().copied().collect());
            push_faces(&faces, pose, colour, layer, out);
        }
        Shape::ConvexHull { hull } => {
            let vertices: Vec<P3> = hull.vertices().iter().map(|v| v.to_f64()).collect();
            let faces: Vec<Vec<P3>> = hull
                .faces()
                .iter()
                .map(|face| {
                    hull.face_indices(face)
                        .iter()
                        .map(|&i| vertices[usize::from(i)])
                        .collect()
                })
                .collect();
            push_faces(&faces, pose, colour, layer, out);
        }
        Shape::TriMesh { .. } | Shape::HeightField { .. } => {
            let Some(mesh) = shape.triangles() else {
                return;
            };
            let vertices: Vec<P3> = mesh.vertices().iter().map(|v| v.to_f64()).collect();
            let faces: Vec<Vec<P3>> = mesh
                .triangles()
                .iter()
                .map(|t| t.iter().map(|&i| vertices[i as usize]).collect())
                .collect();
            push_faces(&faces, pose, colour, layer, out);
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

/// Sides of the polygon that stands for a cylinder's or cone's circle.
const SIDES: usize = 24;

/// The circle of radius `radius` (m) in the plane y = `y`, as [`SIDES`] points
/// counter-clockwise seen from +y.
fn circle(radius: f64, y: f64) -> Vec<P3> {
    (0..SIDES)
        .map(|k| {
            let angle = std::f64::consts::TAU * k as f64 / SIDES as f64;
            [radius * angle.cos(), y, -radius * angle.sin()]
        })
        .collect()
}

/// Appends each face (corners in the body frame, counter-clockwise seen from outside)
/// placed at `pose`, as a shaded polygon.
fn push_faces(
    faces: &[Vec<P3>],
    pose: &Pose,
    colour: [u8; 3],
    layer: Layer,
    out: &mut Vec<Primitive>,
) {
    for face in faces {
        out.push(Primitive {
            figure: Figure::Polygon {
                corners: face.iter().map(|&c| pose.point(c)).collect(),
            },
            paint: Paint::Rgb(colour),
            layer,
        });
    }
}
