//! A convex shape against one triangle of a mesh or a heightfield, with internal edges
//! removed.
//!
//! The triangle is a flat convex core ([`Convex::Triangle`]) and the pair goes through
//! the convex machinery of `convex_pair.rs`: GJK while the cores are apart, EPA when they
//! overlap (for a sphere's or a capsule's core, a point or a segment, whose difference
//! with a flat triangle has no volume for EPA to work on, the face normal instead, on the
//! side of the shape's centre), then the supporting features along the normal.
//!
//! **Internal edges.** A normal that is not the face normal ±n_f (|n · n_f| below
//! 1 − 2⁻¹⁴, about 0.9°) comes from an edge or a corner of the triangle: the corners
//! whose support n · v_k is within 2⁻¹⁶ m of the highest. When that edge or corner is
//! inactive (flat or concave with its neighbours, `mesh/edges.rs`), the neighbouring
//! triangles already hold the surface there: the normal is replaced by ±n_f (on the side
//! of the plane the shape's centre is on), the core gap is measured along it,
//! s = ±n_f · (s_B(∓n_f) − v₀), and only the points of the shape's supporting feature
//! that lie over the triangle are kept (past the edge, the neighbour's face holds the
//! shape). A body sliding over a flat mesh sees one flat floor, without bumps at the
//! seams. A triangle none of whose edges and corners is active (most of a smooth
//! terrain) therefore always gives the face normal, and skips GJK and EPA.
//!
//! The triangle is shape A: the normal points from the triangle towards the shape; the
//! ids are those of `convex_pair.rs` with the triangle's corners as vertex ids 0 to 2.

use super::convex_pair::{CoreContact, manifold_along, refine};
use crate::math::{Real, Vec3};
use crate::rigid::convex::epa::epa;
use crate::rigid::convex::gjk::{CorePair, gjk_simplex};
use crate::rigid::convex::{Convex, Rounded};
use crate::rigid::manifold::Manifold;
use crate::rigid::mesh::{EDGE_ACTIVE, TriMesh, TriangleFeature, VERTEX_ACTIVE, closest_point};
use crate::rigid::shape::Shape;
use crate::rigid::transform::Transform;

/// 1 − |n · n_f| (dimensionless) below which a normal is the face normal: 2⁻¹⁴.
fn face_slack<R: Real>() -> R {
    R::from_ratio(1, 1 << 14)
}

/// Distance (m) within which corners tie for the support along a normal: 2⁻¹⁶ m.
fn corner_slack<R: Real>() -> R {
    R::from_ratio(1, 1 << 16)
}

/// The manifold of triangle `triangle` of `mesh` placed by `xf_mesh` (A) and the convex
/// `shape` placed by `xf` (B), within `margin` (m); empty for a shape that is not convex
/// (a plane, a compound, a mesh). With `smooth`, internal edges are removed (see the
/// [module](self)), as contacts need; without, every edge and corner counts as active,
/// so that the separation is the true distance to this triangle alone, as a shape cast's
/// conservative advancement needs (far from the mesh, the shape need not lie over the
/// triangle whose surface it will reach).
pub(crate) fn collide_triangle<R: Real>(
    mesh: &TriMesh<R>,
    triangle: u32,
    xf_mesh: &Transform<R>,
    shape: &Shape<R>,
    xf: &Transform<R>,
    margin: R,
    smooth: bool,
) -> Manifold<R> {
    // Without `smooth`, every feature is active.
    let flags = if smooth {
        mesh.data.flags[triangle as usize]
    } else {
        u8::MAX
    };
    if let Shape::Sphere { radius } = shape {
        return sphere_triangle(
            mesh,
            triangle,
            flags,
            xf_mesh,
            xf.translation,
            *radius,
            margin,
        );
    }
    let Some(rb) = Rounded::of(shape) else {
        return Manifold::EMPTY;
    };
    let corners = mesh.corners(triangle);
    let local_normal = mesh.normal(triangle);
    let ra = Rounded {
        core: Convex::Triangle {
            corners,
            normal: local_normal,
        },
        radius: R::ZERO,
    };
    let face = xf_mesh.vector(local_normal);
    let origin = xf_mesh.point(corners[0]);
    // The core gap along ±n_f: from the triangle's plane to B's core's lowest point.
    let along_face = |side: Vec3<R>| -> CoreContact<R> {
        let lowest = xf.point(rb.core.support(xf.inverse_vector(-side)));
        (side, side.dot(lowest - origin), None)
    };
    let side_of = |n: Vec3<R>| if n.dot(face) >= R::ZERO { face } else { -face };
    // The side of the triangle's plane the shape's centre is on (+n_f when in it).
    let centre_side = side_of(xf.translation - origin);
    if flags == 0 {
        // No active edge or corner: whatever GJK found, the normal would become the face
        // normal, so it is used from the start.
        let contact = along_face(centre_side);
        if contact.1 - rb.radius > margin {
            return Manifold::EMPTY;
        }
        return manifold_along(&ra, xf_mesh, &rb, xf, contact, margin, false);
    }
    let flat_core = matches!(rb.core, Convex::Point | Convex::Segment { .. });
    let pair = CorePair::new(&ra, xf_mesh, &rb, xf);
    let (g, simplex) = gjk_simplex(&pair);
    let mut contact = if !g.overlap {
        (g.normal, g.distance, Some((g.point_a, g.point_b)))
    } else if flat_core {
        along_face(centre_side)
    } else {
        match epa(&pair, &simplex) {
            Some(p) if p.depth >= R::ZERO => refine(&ra, xf_mesh, &rb, xf, p.normal, p.depth),
            _ => along_face(centre_side),
        }
    };
    if contact.1 - rb.radius > margin {
        return Manifold::EMPTY;
    }
    let normal = contact.0;
    let aligned = normal.dot(face).abs();
    if aligned < R::ONE - face_slack::<R>()
        && !feature_active(&corners, xf_mesh.inverse_vector(normal), flags)
    {
        contact = along_face(centre_side);
        if contact.1 - rb.radius > margin {
            return Manifold::EMPTY;
        }
        // Only the points over this triangle: past its inactive edge, the neighbour's face
        // holds the shape.
        return manifold_along(&ra, xf_mesh, &rb, xf, contact, margin, false);
    }
    manifold_along(&ra, xf_mesh, &rb, xf, contact, margin, true)
}

/// Triangle A against the sphere of centre `centre` and `radius` (m) B, in closed form,
/// with the triangle's active-feature `flags` (all set: every feature active):
/// the closest point q of the triangle to the centre c, in the mesh's frame
/// ([`closest_point`]). On the face, or on an inactive edge or corner (see the [module](self)), the
/// normal is ±n_f on c's side and the separation |n_f · (c − v₀)| − r; on an active edge
/// or corner, the normal is (c − q)/|c − q| and the separation |c − q| − r. One point, id
/// 0, midway between the surfaces; empty beyond `margin` (m).
fn sphere_triangle<R: Real>(
    mesh: &TriMesh<R>,
    triangle: u32,
    flags: u8,
    xf_mesh: &Transform<R>,
    centre: Vec3<R>,
    radius: R,
    margin: R,
) -> Manifold<R> {
    let c = xf_mesh.inverse_point(centre);
    let v = mesh.corners(triangle);
    let n = mesh.normal(triangle);
    let height = n.dot(c - v[0]);
    let reach = radius + margin;
    if height.abs() > reach {
        return Manifold::EMPTY;
    }
    // The closest point and whether its feature pushes along the face normal.
    let (q, feature) = closest_point(&v, n, c);
    let flat = match feature {
        TriangleFeature::Face => true,
        TriangleFeature::Edge(k) => flags & (EDGE_ACTIVE << k) == 0,
        TriangleFeature::Corner(k) => flags & (VERTEX_ACTIVE << k) == 0,
    };
    let side = if height >= R::ZERO { n } else { -n };
    let (local_normal, separation) = if flat {
        (side, height.abs() - radius)
    } else {
        match super::tolerance::unit(c - q) {
            Some((u, distance)) => (u, distance - radius),
            None => (side, height.abs() - radius),
        }
    };
    if separation > margin {
        return Manifold::EMPTY;
    }
    let normal = xf_mesh.vector(local_normal);
    let mut manifold = Manifold {
        normal,
        ..Manifold::EMPTY
    };
    manifold.push(crate::rigid::manifold::ManifoldPoint {
        point: centre - normal * (radius + separation * R::HALF),
        separation,
        id: 0,
    });
    manifold
}

/// Whether the triangle's feature along local direction `d` (the corners whose d · v_k
/// is within [`corner_slack`] of the highest, for a unit d) is active: an edge's bit for
/// two corners, a corner's bit for one, true for all three (a face).
fn feature_active<R: Real>(corners: &[Vec3<R>; 3], d: Vec3<R>, flags: u8) -> bool {
    let reach = corners.map(|c| d.dot(c));
    let top = reach[0].max(reach[1]).max(reach[2]);
    let near = reach.map(|r| top - r <= corner_slack::<R>());
    match near {
        [true, true, true] => true,
        [true, true, false] => flags & EDGE_ACTIVE != 0,
        [false, true, true] => flags & (EDGE_ACTIVE << 1) != 0,
        [true, false, true] => flags & (EDGE_ACTIVE << 2) != 0,
        [true, false, false] => flags & VERTEX_ACTIVE != 0,
        [false, true, false] => flags & (VERTEX_ACTIVE << 1) != 0,
        _ => flags & (VERTEX_ACTIVE << 2) != 0,
    }
}
