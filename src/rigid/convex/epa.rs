//! EPA (expanding polytope algorithm): the penetration normal and depth of two overlapping
//! cores.
//!
//! When the cores overlap, the Minkowski difference D = A − B contains the origin and the
//! penetration is the distance from the origin to D's boundary, along the boundary's
//! outward normal m there. EPA grows a polytope inside D from GJK's last simplex (completed
//! to a tetrahedron with support points along fixed directions when GJK stopped on fewer
//! points): it takes the face nearest the origin (plane m · x = d, m outward unit), adds
//! D's support point w along m, and rebuilds the hull around w (the faces that see w are
//! removed and the horizon is joined to w), until
//!
//! ```text
//!   m · w − d ≤ 2⁻²⁴ m + 2⁻²² d
//! ```
//!
//! (the face is on D's boundary to within about 0.06 µm, which on a curved boundary of
//! radius ρ puts the normal within about √(2 · 2⁻²⁴ m / ρ) ≈ 3·10⁻⁴ rad for ρ = 1 m), or [`MAX_ITERATIONS`] support
//! points were added, or the polytope would exceed [`MAX_FACES`] faces. The nearest face
//! then gives the depth d and the normal from A to B, m (D's points a − b reach farthest
//! along m, so moving B by d m brings D's face to the origin). Faces are visited in creation
//! order and ties go to the first, so the result is the same everywhere.
//!
//! Cores that only touch (GJK's "overlap" includes gaps under 2⁻¹² m) leave the origin on
//! or just outside the polytope; signed face distances handle that case, d then being
//! zero or slightly negative (a gap).
//!
//! Degenerate cases (a flat or thin D whose tetrahedron cannot be completed, a face too
//! small to have a normal) give `None`; the caller falls back to another direction.

use super::gjk::{CorePair, Simplex, SupportPoint, sized};
use crate::math::{Real, Vec3};
use crate::rigid::narrowphase::tolerance::{tiny_length_squared, unit};

/// Most support points EPA adds beyond the starting tetrahedron.
pub(crate) const MAX_ITERATIONS: usize = 48;

/// Most faces the polytope may ever create (removed faces count): each new point adds at
/// most a handful, so 256 covers [`MAX_ITERATIONS`] on typical shapes.
pub(crate) const MAX_FACES: usize = 256;

/// The penetration found by [`epa`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Penetration<R: Real> {
    /// Unit normal from A towards B: moving B by `depth` along it separates the cores.
    pub normal: Vec3<R>,
    /// Penetration depth of the cores, m (slightly negative for cores that only touch).
    pub depth: R,
}

/// One triangle of the polytope: vertex indices counter-clockwise from outside, the outward
/// unit normal m and the plane's offset d = m · (a vertex), m.
#[derive(Clone, Copy, Debug)]
struct Face<R: Real> {
    vertices: [usize; 3],
    normal: Vec3<R>,
    distance: R,
    alive: bool,
}

/// The polytope: points of D and faces.
struct Polytope<R: Real> {
    points: [Vec3<R>; 4 + MAX_ITERATIONS],
    count: usize,
    faces: [Option<Face<R>>; MAX_FACES],
    face_count: usize,
}

impl<R: Real> Polytope<R> {
    /// Adds the face (i, j, k) with its normal from (p_j − p_i) × (p_k − p_i) (edges scaled
    /// by a power of two first, so that a small face keeps its direction); false when the
    /// face is full or degenerate.
    fn add_face(&mut self, [i, j, k]: [usize; 3]) -> bool {
        if self.face_count == MAX_FACES {
            return false;
        }
        let (a, b, c) = (self.points[i], self.points[j], self.points[k]);
        let Some((normal, _)) = unit(sized(b - a).cross(sized(c - a))) else {
            return false;
        };
        self.faces[self.face_count] = Some(Face {
            vertices: [i, j, k],
            normal,
            distance: normal.dot(a),
            alive: true,
        });
        self.face_count += 1;
        true
    }

    /// The alive face of least distance (the first among equals).
    fn nearest(&self) -> Option<Face<R>> {
        let mut best: Option<Face<R>> = None;
        for face in self.faces[..self.face_count].iter().flatten() {
            if face.alive && best.is_none_or(|b| face.distance < b.distance) {
                best = Some(*face);
            }
        }
        best
    }
}

/// Penetration of the two cores of `pair`, starting from GJK's final `simplex`; `None` when
/// the polytope is degenerate. See the [module](self).
pub(crate) fn epa<R: Real>(pair: &CorePair<R>, simplex: &Simplex<R>) -> Option<Penetration<R>> {
    let mut points = [SupportPoint::default(); 4];
    points[..simplex.count].copy_from_slice(&simplex.points[..simplex.count]);
    let tetrahedron = complete(pair, points, simplex.count)?;
    let mut polytope = Polytope {
        points: [Vec3::ZERO; 4 + MAX_ITERATIONS],
        count: 4,
        faces: [None; MAX_FACES],
        face_count: 0,
    };
    polytope.points[..4].copy_from_slice(&tetrahedron);
    // Orient the four faces away from the opposite vertex.
    for (face, opposite) in [
        ([0, 1, 2], 3),
        ([0, 3, 1], 2),
        ([0, 2, 3], 1),
        ([1, 3, 2], 0),
    ] {
        let [i, j, k] = face;
        let p = &polytope.points;
        let outward = (p[j] - p[i]).cross(p[k] - p[i]).dot(p[opposite] - p[i]) <= R::ZERO;
        if !polytope.add_face(if outward { face } else { [i, k, j] }) {
            return None;
        }
    }
    let mut best = polytope.nearest()?;
    for _ in 0..MAX_ITERATIONS {
        let w = pair.support(best.normal).w;
        let gain = best.normal.dot(w) - best.distance;
        let tolerance = R::from_ratio(1, 1 << 24) + best.distance.abs().mul_pow2_recip(22);
        if gain <= tolerance || polytope.count == polytope.points.len() {
            break;
        }
        let index = polytope.count;
        polytope.points[index] = w;
        polytope.count += 1;
        if !expand(&mut polytope, index) {
            break;
        }
        match polytope.nearest() {
            Some(face) => best = face,
            None => break,
        }
    }
    Some(Penetration {
        normal: best.normal,
        depth: best.distance,
    })
}

/// Removes every face that sees point `index` (m · (w − p) > 0) and joins the horizon (the
/// edges of removed faces whose twin is kept) to it; false when a new face could not be
/// made, leaving the polytope as it was before the last faces (the caller stops).
fn expand<R: Real>(polytope: &mut Polytope<R>, index: usize) -> bool {
    let w = polytope.points[index];
    let n = polytope.face_count;
    let mut seen = [false; MAX_FACES];
    for (f, slot) in polytope.faces[..n].iter().enumerate() {
        if let Some(face) = slot {
            seen[f] =
                face.alive && face.normal.dot(w - polytope.points[face.vertices[0]]) > R::ZERO;
        }
    }
    let mut horizon: [[usize; 2]; MAX_FACES] = [[0; 2]; MAX_FACES];
    let mut edges = 0;
    for f in (0..n).filter(|&f| seen[f]) {
        let Some(face) = polytope.faces[f] else {
            continue;
        };
        for e in 0..3 {
            let (i, j) = (face.vertices[e], face.vertices[(e + 1) % 3]);
            let twin_kept = (0..n).any(|g| {
                !seen[g]
                    && polytope.faces[g].is_some_and(|other| {
                        other.alive
                            && (0..3)
                                .any(|k| other.vertices[k] == j && other.vertices[(k + 1) % 3] == i)
                    })
            });
            if twin_kept && edges < MAX_FACES {
                horizon[edges] = [i, j];
                edges += 1;
            }
        }
    }
    if edges == 0 || polytope.face_count + edges > MAX_FACES {
        return false;
    }
    for f in (0..n).filter(|&f| seen[f]) {
        if let Some(face) = &mut polytope.faces[f] {
            face.alive = false;
        }
    }
    horizon[..edges]
        .iter()
        .all(|&[i, j]| polytope.add_face([i, j, index]))
}

/// Fixed search directions, in the order tried: ±x, ±y, ±z.
fn axes<R: Real>() -> [Vec3<R>; 6] {
    [Vec3::X, -Vec3::X, Vec3::Y, -Vec3::Y, Vec3::Z, -Vec3::Z]
}

/// GJK's simplex (`count` points) completed to a tetrahedron of D with a volume: a point
/// away from the first, then one off the line, then one off the plane (on the origin's side
/// first), each the support point along the first fixed direction that gives one. `None`
/// when D is too thin in some direction.
fn complete<R: Real>(
    pair: &CorePair<R>,
    mut points: [SupportPoint<R>; 4],
    mut count: usize,
) -> Option<[Vec3<R>; 4]> {
    let tiny = tiny_length_squared::<R>();
    if count == 1 {
        let w0 = points[0].w;
        points[1] = axes()
            .into_iter()
            .map(|d| pair.support(d))
            .find(|p| (p.w - w0).length_squared() > tiny)?;
        count = 2;
    }
    if count == 2 {
        let (w0, e) = (points[0].w, sized(points[1].w - points[0].w));
        points[2] = axes()
            .into_iter()
            .map(|d| pair.support(e.cross(d)))
            .find(|p| sized(p.w - w0).cross(e).length_squared() > tiny)?;
        count = 3;
    }
    if count == 3 {
        let w0 = points[0].w;
        let normal = sized(points[1].w - w0).cross(sized(points[2].w - w0));
        let toward_origin = if normal.dot(w0) <= R::ZERO {
            normal
        } else {
            -normal
        };
        points[3] = [toward_origin, -toward_origin]
            .into_iter()
            .map(|d| pair.support(d))
            .find(|p| sized(p.w - w0).dot(normal).abs() > tiny)?;
    }
    Some(points.map(|p| p.w))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::{Fx, Quat};
    use crate::rigid::convex::gjk::gjk_simplex;
    use crate::rigid::convex::gjk::tests::{cube_hull, tetra_hull};
    use crate::rigid::convex::support::{Convex, Rounded};
    use crate::rigid::transform::Transform;

    fn sharp(core: Convex<'_, Fx>) -> Rounded<'_, Fx> {
        Rounded {
            core,
            radius: Fx::ZERO,
        }
    }

    fn at(x: i64, y: i64, z: i64) -> Transform<Fx> {
        let c = |v: i64| Fx::from_ratio(v, 100);
        Transform::from_pose(Vec3::new(c(x), c(y), c(z)), Quat::IDENTITY)
    }

    fn penetration(
        a: &Rounded<Fx>,
        xa: &Transform<Fx>,
        b: &Rounded<Fx>,
        xb: &Transform<Fx>,
    ) -> Penetration<Fx> {
        let pair = CorePair::new(a, xa, b, xb);
        let (g, simplex) = gjk_simplex(&pair);
        assert!(g.overlap);
        epa(&pair, &simplex).expect("a polytope")
    }

    fn near(x: Fx, y: Fx) -> bool {
        (x - y).abs() <= Fx::from_ratio(1, 1 << 20)
    }

    #[test]
    fn overlapping_boxes_push_apart_along_the_shallow_axis() {
        let cube = sharp(Convex::Cuboid {
            half_extents: Vec3::splat(Fx::ONE),
        });
        let p = penetration(&cube, &at(0, 0, 0), &cube, &at(150, 20, 10));
        assert!(near(p.depth, Fx::HALF), "{p:?}");
        assert!(near(p.normal.x, Fx::ONE), "{p:?}");
        // Swapped: the normal reverses.
        let q = penetration(&cube, &at(150, 20, 10), &cube, &at(0, 0, 0));
        assert!(
            near(q.depth, Fx::HALF) && near(q.normal.x, -Fx::ONE),
            "{q:?}"
        );
    }

    #[test]
    fn a_point_inside_a_box_leaves_through_the_nearest_face() {
        let point = sharp(Convex::Point);
        let cube = sharp(Convex::Cuboid {
            half_extents: Vec3::splat(Fx::ONE),
        });
        let p = penetration(&point, &at(30, 90, -20), &cube, &at(0, 0, 0));
        assert!(near(p.depth, Fx::from_ratio(1, 10)), "{p:?}");
        assert!(near(p.normal.y, -Fx::ONE), "{p:?}");
    }

    #[test]
    fn hulls_and_touching_cores() {
        let cube = cube_hull(Vec3::splat(Fx::HALF));
        let tetra = tetra_hull(Fx::ONE);
        let (a, b) = (sharp(Convex::Hull(&cube)), sharp(Convex::Hull(&tetra)));
        // The tetrahedron's vertex (1, 0, −c) 0.2 m into the cube's +x face... from the
        // cube's side: the cube at x = 1.3 overlaps it by 0.2 along x.
        let p = penetration(&b, &at(0, 0, 0), &a, &at(130, 0, -60));
        assert!(near(p.depth, Fx::from_ratio(2, 10)), "{p:?}");
        assert!(near(p.normal.x, Fx::ONE), "{p:?}");
        // Faces exactly touching: depth zero.
        let p = penetration(&a, &at(0, 0, 0), &a, &at(0, 100, 0));
        assert!(
            near(p.depth, Fx::ZERO) && near(p.normal.y, Fx::ONE),
            "{p:?}"
        );
    }
}
