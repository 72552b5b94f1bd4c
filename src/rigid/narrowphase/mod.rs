//! Narrowphase: the contact manifold of two shapes.
//!
//! [`collide`] dispatches on the pair of shapes to one routine per pair, each in its own
//! file and each written for one order of the two shapes (its "natural" order). For the
//! other order it is called with the shapes swapped and its manifold is
//! [`flipped`](Manifold::flipped): the normal reversed, the points, separations and ids
//! unchanged. Feature ids are therefore always those of the natural order, whichever shape
//! the caller passes first, and stay the same from step to step as long as the caller
//! keeps its order.
//!
//! Conventions (see [`Manifold`]): the normal is a unit vector from A towards B; a point's
//! separation is the signed distance between the two surfaces along the normal (m,
//! negative when they overlap); the point lies midway between the two surfaces; points
//! whose separation exceeds the speculative `margin` are not reported.
//!
//! Everything is generic over [`Real`] and meant for the fixed-point [`Fx`](crate::math::Fx):
//! no floating point, no division by a length that can be zero (directions shorter than
//! 0.24 mm fall back to fixed choices, see `tolerance.rs`), and square roots only where a
//! squared comparison cannot do.
//!
//! # Files
//!
//! | pair (natural order) | file | points |
//! |---|---|---|
//! | sphere–sphere | `sphere_sphere.rs` | 1 |
//! | sphere–box | `sphere_box.rs` | 1 |
//! | sphere–capsule | `sphere_capsule.rs` | 1 |
//! | capsule–capsule | `capsule_capsule.rs` | 1, or 2 side by side |
//! | capsule–box | `capsule_box.rs` | 1, or 2 lying on a face |
//! | box–box | `box_box.rs` (with `clip.rs`; separating axes in `box_box/axes.rs`, eight pairs at a time in `box_box/avx512.rs`; a face contact's points to the world frame in `box_box/world_points.rs`) | 1 to 4 |
//! | plane–sphere, plane–capsule, plane–box | `plane.rs` | 1, 1–2, 1–4 |
//! | any pair with a cylinder, a cone or a hull; plane against one | `convex_pair.rs` (GJK and EPA on the cores, supporting features in `supporting_face.rs`, clipped in `face_clip.rs`) | 1 to 4 |
//! | a triangle of a mesh or a heightfield against any convex shape | `triangle.rs` (the convex machinery, internal edges removed), called once per triangle under the shape by the collide stage | 1 to 4 |
//!
//! Shared helpers: `segments.rs` (closest points on segments), `clip.rs` (face clipping and
//! the choice of four points), `tolerance.rs` (thresholds and guarded normalisation).
//!
//! # Feature ids
//!
//! Distinct within a manifold, and the same while the same features touch (the solver
//! matches points between steps by id):
//!
//! - sphere–sphere, sphere–box, sphere–capsule, plane–sphere: 0;
//! - plane–capsule: the capsule end, 0 for −h, 1 for +h; plane–box: the corner index, bit
//!   k set for the +h_k side of the box's axis k;
//! - capsule–capsule: A's feature + 4 × B's, a feature being 0 or 1 for an end and 2 for a
//!   point between the ends;
//! - capsule–box: the capsule feature (as above), the side of the face that clipped the
//!   point (bits 2–4) and the box face or edge (bits 5 and up);
//! - box–box, face contact: reference box, reference face, incident face, and the pair of
//!   incident edges or reference sides meeting at the point (bits 0–12); edge contact: bit
//!   13 with the two edges' indices;
//! - pairs with a cylinder, a cone or a hull: see `convex_pair.rs` (the shapes' vertex ids
//!   in `supporting_face.rs`, the cut points' in `face_clip.rs`).

mod box_box;
mod capsule_box;
mod capsule_capsule;
mod clip;
mod convex_pair;
mod face_clip;
mod plane;
mod segments;
mod sphere_box;
mod sphere_capsule;
mod sphere_sphere;
mod supporting_face;
pub(crate) mod tolerance;
mod triangle;

pub(crate) use self::box_box::{BoxPair, contact as box_box_contact, separating_axes_batch};
use self::plane::WorldPlane;
use self::segments::Segment;
pub(crate) use self::triangle::collide_triangle;
use super::manifold::Manifold;
use super::shape::Shape;
use super::transform::Transform;
use crate::math::Real;

/// The capsule's segment in the world frame: centre t, unit axis R e_y, half length h.
#[inline(always)]
fn capsule_segment<R: Real>(half_height: R, xf: &Transform<R>) -> Segment<R> {
    Segment {
        centre: xf.translation,
        axis: xf.rotation.cols[1],
        half_length: half_height,
    }
}

/// Contacts between two convex shapes or a convex shape and a plane, within `margin` (m,
/// speculative distance: points whose separation ≤ margin are reported).
///
/// Handles every pair of [`Shape::Sphere`], [`Shape::Box`], [`Shape::Capsule`],
/// [`Shape::Cylinder`], [`Shape::Cone`] and [`Shape::ConvexHull`], and any of them against
/// a [`Shape::Plane`] (as A or as B). Two planes give an empty manifold.
/// [`Shape::Compound`] is not handled here and also gives an empty manifold: the caller
/// iterates over the parts, placing each with [`Transform::compose`], and collides them
/// one by one. `margin` is expected to be ≥ 0.
///
/// The normal points from A to B; swapping A and B reverses it and keeps the points,
/// separations and ids.
pub fn collide<R: Real>(
    a: &Shape<R>,
    xf_a: &Transform<R>,
    b: &Shape<R>,
    xf_b: &Transform<R>,
    margin: R,
) -> Manifold<R> {
    use Shape::{Box, Capsule, Plane, Sphere};
    match (a, b) {
        (Sphere { radius: ra }, Sphere { radius: rb }) => {
            sphere_sphere::sphere_sphere(xf_a.translation, *ra, xf_b.translation, *rb, margin)
        }
        (Sphere { radius }, Box { half_extents }) => {
            sphere_box::sphere_box(xf_a.translation, *radius, *half_extents, xf_b, margin)
        }
        (Box { half_extents }, Sphere { radius }) => {
            sphere_box::sphere_box(xf_b.translation, *radius, *half_extents, xf_a, margin).flipped()
        }
        (
            Sphere { radius },
            Capsule {
                radius: rc,
                half_height,
            },
        ) => sphere_capsule::sphere_capsule(
            xf_a.translation,
            *radius,
            &capsule_segment(*half_height, xf_b),
            *rc,
            margin,
        ),
        (
            Capsule {
                radius: rc,
                half_height,
            },
            Sphere { radius },
        ) => sphere_capsule::sphere_capsule(
            xf_b.translation,
            *radius,
            &capsule_segment(*half_height, xf_a),
            *rc,
            margin,
        )
        .flipped(),
        (
            Capsule {
                radius: ra,
                half_height: ha,
            },
            Capsule {
                radius: rb,
                half_height: hb,
            },
        ) => capsule_capsule::capsule_capsule(
            &capsule_segment(*ha, xf_a),
            *ra,
            &capsule_segment(*hb, xf_b),
            *rb,
            margin,
        ),
        (
            Capsule {
                radius,
                half_height,
            },
            Box { half_extents },
        ) => capsule_box::capsule_box(
            &capsule_segment(*half_height, xf_a),
            *radius,
            *half_extents,
            xf_b,
            margin,
        ),
        (
            Box { half_extents },
            Capsule {
                radius,
                half_height,
            },
        ) => capsule_box::capsule_box(
            &capsule_segment(*half_height, xf_b),
            *radius,
            *half_extents,
            xf_a,
            margin,
        )
        .flipped(),
        (Box { half_extents: ha }, Box { half_extents: hb }) => {
            box_box::box_box(*ha, xf_a, *hb, xf_b, margin)
        }
        (Plane { normal, offset }, other) => plane_against(
            &WorldPlane::new(*normal, *offset, xf_a),
            other,
            xf_b,
            margin,
        ),
        (other, Plane { normal, offset }) => plane_against(
            &WorldPlane::new(*normal, *offset, xf_b),
            other,
            xf_a,
            margin,
        )
        .flipped(),
        (Shape::Compound { .. }, _) | (_, Shape::Compound { .. }) => Manifold::EMPTY,
        (Shape::TriMesh { .. } | Shape::HeightField { .. }, _)
        | (_, Shape::TriMesh { .. } | Shape::HeightField { .. }) => Manifold::EMPTY,
        // Every other pair has a cylinder, a cone or a hull.
        _ => convex_pair::convex_pair(a, xf_a, b, xf_b, margin),
    }
}

/// Plane A against `shape` B placed by `xf`; empty for a plane or a compound.
fn plane_against<R: Real>(
    plane: &WorldPlane<R>,
    shape: &Shape<R>,
    xf: &Transform<R>,
    margin: R,
) -> Manifold<R> {
    match shape {
        Shape::Sphere { radius } => plane::plane_sphere(plane, xf.translation, *radius, margin),
        Shape::Capsule {
            radius,
            half_height,
        } => plane::plane_capsule(plane, &capsule_segment(*half_height, xf), *radius, margin),
        Shape::Box { half_extents } => plane::plane_box(plane, *half_extents, xf, margin),
        Shape::Cylinder { .. } | Shape::Cone { .. } | Shape::ConvexHull { .. } => {
            convex_pair::plane_convex(plane, shape, xf, margin)
        }
        Shape::Plane { .. }
        | Shape::Compound { .. }
        | Shape::TriMesh { .. }
        | Shape::HeightField { .. } => Manifold::EMPTY,
    }
}
