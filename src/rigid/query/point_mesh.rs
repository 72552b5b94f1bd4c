//! The closest point of a triangle mesh or a heightfield to a point, in the mesh's frame:
//! the bounding-volume tree pruned by the distance to each box against the nearest
//! triangle so far. A mesh is a surface: a point is never inside it.

use core::cell::Cell;

use crate::math::{Real, Vec3};
use crate::rigid::aabb::Aabb;
use crate::rigid::mesh::{TriMesh, closest_point};

/// The point of `mesh` closest to `p` (mesh frame, m) and its squared distance (m²): the
/// nearest of the triangles' closest points, the lowest triangle index on ties. Boxes
/// farther than the best so far, |p − clamp(p, min, max)|² > d², are skipped.
pub(super) fn project_mesh<R: Real>(mesh: &TriMesh<R>, p: Vec3<R>) -> (Vec3<R>, R) {
    let best: Cell<Option<(R, u32, Vec3<R>)>> = Cell::new(None);
    mesh.walk_tree(
        |bounds| {
            best.get()
                .is_none_or(|(d2, _, _)| box_distance_squared(bounds, p) <= d2)
        },
        |triangles| {
            for &t in triangles {
                let (q, _) = closest_point(&mesh.corners(t), mesh.normal(t), p);
                let d2 = (p - q).length_squared();
                let nearer = best
                    .get()
                    .is_none_or(|(bd2, bt, _)| d2 < bd2 || (d2 == bd2 && t < bt));
                if nearer {
                    best.set(Some((d2, t, q)));
                }
            }
        },
    );
    best.get().map_or((p, R::MAX), |(d2, _, q)| (q, d2))
}

/// |p − clamp(p, min, max)|²: the squared distance (m²) from `p` to the box.
fn box_distance_squared<R: Real>(aabb: &Aabb<R>, p: Vec3<R>) -> R {
    let q = p.max_elem(aabb.min).min_elem(aabb.max);
    (p - q).length_squared()
}
