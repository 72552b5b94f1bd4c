//! GJK (Gilbert–Johnson–Keerthi): the distance between two convex cores and their closest
//! points, from support points alone.
//!
//! The cores A and B are placed by their transforms; GJK works on the Minkowski difference
//! D = A − B = {a − b}, whose support point along d is s_A(d) − s_B(−d). The distance of
//! the two cores is the distance of D from the origin, and D contains the origin exactly
//! when the cores intersect. Each iteration keeps a simplex of 1 to 4 points of D, finds the
//! point v of the simplex closest to the origin (the sub-simplex solver below), and adds the
//! support point w of D along −v, until w brings no progress:
//!
//! ```text
//!   v · v − v · w ≤ 2⁻²⁰ v · v     (v · v − v · w bounds |v|² − dist², m²)
//! ```
//!
//! (a relative error of at most 2⁻²¹ on the distance), or the simplex encloses the origin, or |v|² stops decreasing (rounding), or
//! [`MAX_ITERATIONS`] have run. Polytopes converge in a few iterations; curved shapes (a
//! cylinder's rim, a cone's base) converge linearly and the tolerance stops them after at
//! most a dozen or so in practice.
//!
//! Sub-simplex solver (Johnson's, by enumeration): every sub-simplex (1 to 4 of the
//! points) gets the barycentric weights λ of the origin's projection onto its affine hull,
//! from ratios of edge lengths, triangle areas or tetrahedron volumes; a sub-simplex whose
//! weights are all positive holds that projection, and the closest point of the simplex is
//! the one of least |v|² among them. Sub-simplices are visited from the smallest up, in a
//! fixed order, and only a strictly smaller |v|² replaces a candidate, so ties always
//! resolve the same way. The weights are computed on the simplex scaled by a power of two
//! (exact) to a largest coordinate in [1/2, 1), so that the products of three or four
//! coordinates keep their bits in I32F32 whatever the size of the shapes; a sub-simplex
//! whose length, area or volume is within a fixed fraction of rounding (see
//! [`degenerate`]) is skipped, its faces covering it.
//!
//! Cores closer than 2⁻¹² m (|v|² ≤ 2⁻²⁴ m², the narrowphase's shortest direction) count
//! as overlapping: their normal would be mostly rounding, and EPA finds it instead.

use super::support::Rounded;
use crate::math::{Real, Vec3};
use crate::rigid::narrowphase::tolerance::{tiny_length_squared, unit_from_squared};
use crate::rigid::transform::Transform;

/// Most GJK iterations (support points added) for one pair. A polytope pair converges in
/// at most its number of vertex pairs and in practice in under 10; curved cores stop on
/// the progress tolerance well before this cap, which only bounds the worst case.
pub(crate) const MAX_ITERATIONS: usize = 32;

/// The outcome of [`gjk`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct GjkResult<R: Real> {
    /// The cores intersect, or are closer than 2⁻¹² m (where no normal can be trusted).
    pub overlap: bool,
    /// Distance between the cores, m; zero when `overlap`.
    pub distance: R,
    /// The closest point of core A, world frame, m (a point of the overlap when `overlap`).
    pub point_a: Vec3<R>,
    /// The closest point of core B, world frame, m.
    pub point_b: Vec3<R>,
    /// Unit vector from A towards B, (point_b − point_a) / distance; zero when `overlap`.
    pub normal: Vec3<R>,
}

/// A point w = a − b of the Minkowski difference with the two core points that made it
/// (world frame, m).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct SupportPoint<R: Real> {
    /// a − b, m.
    pub w: Vec3<R>,
    /// The point of core A, m.
    pub a: Vec3<R>,
    /// The point of core B, m.
    pub b: Vec3<R>,
}

/// Two cores, each placed by its transform: the support mapping of their difference.
#[derive(Clone, Copy, Debug)]
pub(crate) struct CorePair<'s, R: Real> {
    a: &'s Rounded<'s, R>,
    xf_a: &'s Transform<R>,
    b: &'s Rounded<'s, R>,
    xf_b: &'s Transform<R>,
}

impl<'s, R: Real> CorePair<'s, R> {
    /// The pair A, B.
    pub fn new(
        a: &'s Rounded<'s, R>,
        xf_a: &'s Transform<R>,
        b: &'s Rounded<'s, R>,
        xf_b: &'s Transform<R>,
    ) -> Self {
        Self { a, xf_a, b, xf_b }
    }

    /// s_D(d) = s_A(d) − s_B(−d) for a direction d of any length, each core's support taken
    /// in its own frame (Rᵀ d) and placed in the world (R s + t). The direction is first
    /// scaled by a power of two to a largest component in [1/2, 2), so that the shapes'
    /// supports see the same direction whether d is millimetres or kilometres long.
    pub fn support(&self, direction: Vec3<R>) -> SupportPoint<R> {
        let d = sized(direction);
        let a = self
            .xf_a
            .point(self.a.core.support(self.xf_a.inverse_vector(d)));
        let b = self
            .xf_b
            .point(self.b.core.support(self.xf_b.inverse_vector(-d)));
        SupportPoint { w: a - b, a, b }
    }
}

/// Up to four points of the Minkowski difference with the barycentric weights of the point
/// closest to the origin.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Simplex<R: Real> {
    /// The points; the first `count` are meaningful.
    pub points: [SupportPoint<R>; 4],
    /// The weights λ (Σλ = 1 up to rounding) of the closest point v = Σ λᵢ wᵢ.
    pub weights: [R; 4],
    /// Number of points, 1 to 4.
    pub count: usize,
}

impl<R: Real> Simplex<R> {
    /// Σ λᵢ fᵢ over the points: the closest point's counterpart on w, a or b.
    fn combine(&self, f: impl Fn(&SupportPoint<R>) -> Vec3<R>) -> Vec3<R> {
        (0..self.count).fold(Vec3::ZERO, |sum, i| {
            sum + f(&self.points[i]) * self.weights[i]
        })
    }

    /// v = Σ λᵢ wᵢ, m.
    pub fn closest(&self) -> Vec3<R> {
        self.combine(|p| p.w)
    }
}

/// Distance and closest points of the cores of `a` (placed by `xf_a`) and `b` (placed by
/// `xf_b`); the radii are not added. A point against a shape (a [`Convex::Point`] core of
/// radius 0) gives the shape's closest point to it; see the [module](self) for the
/// algorithm and its bounds.
///
/// [`Convex::Point`]: super::support::Convex::Point
pub(crate) fn gjk<R: Real>(
    a: &Rounded<R>,
    xf_a: &Transform<R>,
    b: &Rounded<R>,
    xf_b: &Transform<R>,
) -> GjkResult<R> {
    gjk_simplex(&CorePair::new(a, xf_a, b, xf_b)).0
}

/// [`gjk`] on a [`CorePair`], also returning the final simplex (which EPA starts from when
/// the cores overlap).
pub(crate) fn gjk_simplex<R: Real>(pair: &CorePair<R>) -> (GjkResult<R>, Simplex<R>) {
    let mut simplex = Simplex {
        count: 1,
        ..Simplex::default()
    };
    simplex.points[0] = pair.support(pair.xf_b.translation - pair.xf_a.translation);
    simplex.weights[0] = R::ONE;
    let mut v = simplex.points[0].w;
    let mut vv = v.length_squared();
    let mut overlap = false;
    for _ in 0..MAX_ITERATIONS {
        if vv <= tiny_length_squared() {
            overlap = true;
            break;
        }
        let w = pair.support(-v);
        if vv - v.dot(w.w) <= vv.mul_pow2_recip(20)
            || simplex.points[..simplex.count].iter().any(|p| p.w == w.w)
        {
            break;
        }
        let previous = simplex;
        simplex.points[simplex.count] = w;
        simplex.count += 1;
        if !solve(&mut simplex) {
            overlap = true;
            break;
        }
        let next = simplex.closest();
        let next_vv = next.length_squared();
        if next_vv >= vv {
            simplex = previous;
            break;
        }
        v = next;
        vv = next_vv;
    }
    let point_a = simplex.combine(|p| p.a);
    let point_b = simplex.combine(|p| p.b);
    let separated = if overlap {
        None
    } else {
        unit_from_squared(-v, vv)
    };
    let result = match separated {
        Some((normal, distance)) => GjkResult {
            overlap: false,
            distance,
            point_a,
            point_b,
            normal,
        },
        None => GjkResult {
            overlap: true,
            distance: R::ZERO,
            point_a,
            point_b,
            normal: Vec3::ZERO,
        },
    };
    (result, simplex)
}

/// Sub-simplices as bit masks of the simplex's points, smallest first: the visiting order
/// of the sub-simplex solver.
const SUBSETS: [usize; 15] = [1, 2, 4, 8, 3, 5, 6, 9, 10, 12, 7, 11, 13, 14, 15];

/// Johnson's sub-simplex solver (see the [module](self)): reduces `simplex` to the
/// sub-simplex whose relative interior holds the point closest to the origin, with its
/// weights, keeping the points' order. Returns false when that sub-simplex is the whole
/// tetrahedron, i.e. the origin is inside and the cores overlap.
fn solve<R: Real>(simplex: &mut Simplex<R>) -> bool {
    let n = simplex.count;
    let scaled = scaled_points(simplex);
    let mut best: Option<(usize, [R; 4], R)> = None;
    for &mask in SUBSETS.iter().filter(|&&m| m < 1 << n) {
        let mut members = [0usize; 4];
        let mut k = 0;
        for (i, slot) in (0..n).filter(|i| mask & (1 << i) != 0).zip(0..) {
            members[slot] = i;
            k += 1;
        }
        let q: [Vec3<R>; 4] = core::array::from_fn(|j| scaled[members[j.min(k - 1)]]);
        let Some(weights) = affine_weights(&q, k) else {
            continue;
        };
        let v = (0..k).fold(Vec3::ZERO, |s, j| s + q[j] * weights[j]);
        let vv = v.length_squared();
        if best.is_none_or(|(_, _, b)| vv < b) {
            let mut full = [R::ZERO; 4];
            for j in 0..k {
                full[members[j]] = weights[j];
            }
            best = Some((mask, full, vv));
        }
    }
    // The single points always qualify, so there is always a best.
    let (mask, weights, _) = best.unwrap_or((1, [R::ONE, R::ZERO, R::ZERO, R::ZERO], R::ZERO));
    if mask == 15 {
        return false;
    }
    let mut kept = 0;
    for (i, &weight) in weights.iter().enumerate().take(n) {
        if mask & (1 << i) != 0 {
            simplex.points[kept] = simplex.points[i];
            simplex.weights[kept] = weight;
            kept += 1;
        }
    }
    simplex.count = kept;
    true
}

/// The simplex's points w scaled by one power of two 2ᵏ so that the largest coordinate is
/// in [1/2, 1) (exact when scaling up; the weights are unchanged by any scale).
fn scaled_points<R: Real>(simplex: &Simplex<R>) -> [Vec3<R>; 4] {
    let largest = simplex.points[..simplex.count]
        .iter()
        .map(|p| p.w.abs().max_component())
        .fold(R::ZERO, R::max);
    let factor = power_of_two_scale(largest, R::HALF);
    core::array::from_fn(|i| simplex.points[i].w * factor)
}

/// 2ᵏ such that 2ᵏ x ∈ [low, 2 low) for x > 0, with k at most 30 (so that 2ᵏ stays inside
/// I32F32's range: for the smallest values, 2³⁰ x stays below `low`) and at least −64; 1
/// for x = 0.
fn power_of_two_scale<R: Real>(x: R, low: R) -> R {
    let mut factor = R::ONE;
    let mut y = x;
    if y <= R::ZERO {
        return factor;
    }
    let largest = R::from_int(1 << 30);
    for _ in 0..64 {
        if y >= low || factor >= largest {
            break;
        }
        y *= R::TWO;
        factor *= R::TWO;
    }
    for _ in 0..64 {
        if y < low * R::TWO {
            break;
        }
        y *= R::HALF;
        factor *= R::HALF;
    }
    factor
}

/// `direction` scaled by a power of two to a largest component in [1/2, 1) (unchanged when
/// zero).
pub(crate) fn sized<R: Real>(direction: Vec3<R>) -> Vec3<R> {
    direction * power_of_two_scale(direction.abs().max_component(), R::HALF)
}

/// Whether a measure of a sub-simplex (squared length, squared doubled area or sextupled
/// volume, of points scaled to coordinates below 1) is too small for its ratios to be
/// more than rounding: ≤ 2⁻²⁸ (an edge shorter than 2⁻¹⁴ of the simplex's size, about
/// 2¹⁸ ulp of I32F32 in the measure).
fn degenerate<R: Real>(measure: R) -> bool {
    measure.abs() <= R::from_ratio(1, 1 << 28)
}

/// Barycentric weights of the origin's projection onto the affine hull of `q[..k]`, or
/// `None` when a weight is not positive (the projection is outside this sub-simplex) or
/// the sub-simplex is [`degenerate`].
///
/// - 1 point: λ₀ = 1.
/// - 2 points, e = q₁ − q₀: λ₀ = (q₁ · e) / (e · e), λ₁ = −(q₀ · e) / (e · e).
/// - 3 points, n = (q₁ − q₀) × (q₂ − q₀): λ₀ = n · (q₁ × q₂) / (n · n), and cyclically
///   (the sub-triangle areas of the projection, which sum to n · n).
/// - 4 points: λᵢ = V(q with the origin in place of qᵢ) / V(q), V the signed volume
///   (q₁ − q₀) · ((q₂ − q₀) × (q₃ − q₀)).
///
/// Each numerator's sign is tested before the one division, by a measure that is not
/// degenerate and so not zero.
fn affine_weights<R: Real>(q: &[Vec3<R>; 4], k: usize) -> Option<[R; 4]> {
    let (numerators, measure) = match k {
        1 => return Some([R::ONE, R::ZERO, R::ZERO, R::ZERO]),
        2 => {
            let e = q[1] - q[0];
            (
                [q[1].dot(e), -q[0].dot(e), R::ZERO, R::ZERO],
                e.length_squared(),
            )
        }
        3 => {
            let n = (q[1] - q[0]).cross(q[2] - q[0]);
            (
                [
                    n.dot(q[1].cross(q[2])),
                    n.dot(q[2].cross(q[0])),
                    n.dot(q[0].cross(q[1])),
                    R::ZERO,
                ],
                n.length_squared(),
            )
        }
        _ => {
            let volume =
                |a: Vec3<R>, b: Vec3<R>, c: Vec3<R>, d: Vec3<R>| (b - a).dot((c - a).cross(d - a));
            let o = Vec3::ZERO;
            let total = volume(q[0], q[1], q[2], q[3]);
            let sign = if total >= R::ZERO { R::ONE } else { -R::ONE };
            (
                [
                    volume(o, q[1], q[2], q[3]) * sign,
                    volume(q[0], o, q[2], q[3]) * sign,
                    volume(q[0], q[1], o, q[3]) * sign,
                    volume(q[0], q[1], q[2], o) * sign,
                ],
                total * sign,
            )
        }
    };
    if degenerate(measure) || numerators[..k].iter().any(|&x| x <= R::ZERO) {
        return None;
    }
    Some(core::array::from_fn(|i| numerators[i] / measure))
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::math::{Fx, Quat};
    use crate::rigid::convex::hull::{ConvexHull, HullFace};
    use crate::rigid::convex::support::Convex;
    use crate::rigid::query::unit_direction;

    /// A hull built by hand from its vertices and faces (vertex loops counter-clockwise
    /// from outside), for tests before the quickhull lands.
    pub(crate) fn hand_hull(vertices: &[Vec3<Fx>], loops: &[&[u16]]) -> ConvexHull<Fx> {
        let mut faces = Vec::new();
        let mut face_vertices = Vec::new();
        let mut edges = Vec::new();
        for face in loops {
            let [p0, p1, p2] = [0, 1, 2].map(|i| vertices[usize::from(face[i])]);
            let normal = unit_direction((p1 - p0).cross(p2 - p0)).expect("a face");
            faces.push(HullFace {
                normal,
                offset: normal.dot(p0),
                first: face_vertices.len() as u16,
                count: face.len() as u16,
            });
            face_vertices.extend_from_slice(face);
            for (i, &v) in face.iter().enumerate() {
                let u = face[(i + 1) % face.len()];
                edges.push([v.min(u), v.max(u)]);
            }
        }
        edges.sort_unstable();
        edges.dedup();
        ConvexHull {
            vertices: vertices.to_vec(),
            faces,
            face_vertices,
            edges,
        }
    }

    /// The cube of half extents (hx, hy, hz) as a hull; vertex i has bit k set for the +h
    /// side of axis k.
    pub(crate) fn cube_hull(half: Vec3<Fx>) -> ConvexHull<Fx> {
        let vertices: Vec<Vec3<Fx>> = (0..8)
            .map(|i| {
                let s = |bit: usize, h: Fx| if i & bit != 0 { h } else { -h };
                Vec3::new(s(1, half.x), s(2, half.y), s(4, half.z))
            })
            .collect();
        hand_hull(
            &vertices,
            &[
                &[0, 4, 6, 2],
                &[1, 3, 7, 5],
                &[0, 1, 5, 4],
                &[2, 6, 7, 3],
                &[0, 2, 3, 1],
                &[4, 5, 7, 6],
            ],
        )
    }

    /// A regular-ish tetrahedron with vertices (±1, 0, −1/√2) and (0, ±1, 1/√2) scaled by s.
    pub(crate) fn tetra_hull(s: Fx) -> ConvexHull<Fx> {
        let c = Fx::from_ratio(7071, 10000) * s;
        let vertices = [
            Vec3::new(-s, Fx::ZERO, -c),
            Vec3::new(s, Fx::ZERO, -c),
            Vec3::new(Fx::ZERO, -s, c),
            Vec3::new(Fx::ZERO, s, c),
        ];
        let mut loops: Vec<Vec<u16>> =
            vec![vec![0, 1, 2], vec![0, 1, 3], vec![0, 2, 3], vec![1, 2, 3]];
        for face in &mut loops {
            let [a, b, c] = [0, 1, 2].map(|i| vertices[usize::from(face[i])]);
            let centre = (a + b + c) * Fx::from_ratio(1, 3);
            if (b - a).cross(c - a).dot(centre) < Fx::ZERO {
                face.swap(1, 2);
            }
        }
        let refs: Vec<&[u16]> = loops.iter().map(|l| l.as_slice()).collect();
        hand_hull(&vertices, &refs)
    }

    fn v(x: f64, y: f64, z: f64) -> Vec3<Fx> // ok-det: reference
    {
        Vec3::from_f64(x, y, z) // ok-det: reference
    }

    fn at(x: f64, y: f64, z: f64) -> Transform<Fx> // ok-det: reference
    {
        Transform::from_pose(v(x, y, z), Quat::IDENTITY)
    }

    fn turned(p: Vec3<Fx>, axis: Vec3<Fx>, degrees: i64) -> Transform<Fx> {
        let angle = Fx::PI * Fx::from_ratio(degrees, 180);
        Transform::from_pose(p, Quat::from_axis_angle(axis, angle))
    }

    fn sharp(core: Convex<'_, Fx>) -> Rounded<'_, Fx> {
        Rounded {
            core,
            radius: Fx::ZERO,
        }
    }

    fn close(x: Fx, expected: f64, tolerance: f64) // ok-det: reference
    {
        let got = x.to_f64(); // ok-det: reference
        assert!((got - expected).abs() <= tolerance, "{got} vs {expected}"); // ok-det: reference
    }

    fn close_v(x: Vec3<Fx>, expected: [f64; 3], tolerance: f64) // ok-det: reference
    {
        for i in 0..3 {
            close(x[i], expected[i], tolerance);
        }
    }

    fn cuboid(h: Vec3<Fx>) -> Rounded<'static, Fx> {
        sharp(Convex::Cuboid { half_extents: h })
    }

    #[test]
    fn point_against_box_is_the_distance_to_the_face() {
        let point = sharp(Convex::Point);
        let unit_box = cuboid(Vec3::splat(Fx::ONE));
        let r = gjk(
            &point,
            &at(3.0, 0.5, -0.25),
            &unit_box,
            &Transform::IDENTITY,
        );
        assert!(!r.overlap);
        close(r.distance, 2.0, 1e-6);
        close_v(r.point_a, [3.0, 0.5, -0.25], 1e-6);
        close_v(r.point_b, [1.0, 0.5, -0.25], 1e-6);
        close_v(r.normal, [-1.0, 0.0, 0.0], 1e-6);
        // Towards a corner: distance √(1 + 4 + 9).
        let r = gjk(&point, &at(2.0, 3.0, -4.0), &unit_box, &Transform::IDENTITY);
        close(r.distance, 14f64.sqrt(), 1e-6); // ok-det: reference
        close_v(r.point_b, [1.0, 1.0, -1.0], 1e-6);
    }

    #[test]
    fn sphere_core_against_rotated_box() {
        // The sphere's core is its centre; a box turned 45° about z shows an edge.
        let point = sharp(Convex::Point);
        let b = cuboid(Vec3::splat(Fx::ONE));
        let r = gjk(
            &point,
            &at(0.0, 0.0, 0.0),
            &b,
            &turned(v(3.0, 0.0, 0.0), Vec3::Z, 45),
        );
        close(r.distance, 3.0 - 2f64.sqrt(), 1e-6); // ok-det: reference
        close_v(r.normal, [1.0, 0.0, 0.0], 1e-6);
    }

    #[test]
    fn box_against_turned_box_meets_at_an_edge() {
        let a = cuboid(Vec3::splat(Fx::ONE));
        let b = cuboid(Vec3::splat(Fx::ONE));
        let r = gjk(
            &a,
            &Transform::IDENTITY,
            &b,
            &turned(v(3.0, 0.2, 0.0), Vec3::Z, 45),
        );
        assert!(!r.overlap);
        close(r.distance, 2.0 - 2f64.sqrt(), 1e-6); // ok-det: reference
        close(r.point_a.x, 1.0, 1e-6);
        close(r.point_b.x, 3.0 - 2f64.sqrt(), 1e-6); // ok-det: reference
        close(r.point_b.y, 0.2, 1e-6);
        // Swapped: same distance, opposite normal.
        let s = gjk(
            &b,
            &turned(v(3.0, 0.2, 0.0), Vec3::Z, 45),
            &a,
            &Transform::IDENTITY,
        );
        assert_eq!(s.distance, r.distance);
        close_v(s.normal, [-1.0, 0.0, 0.0], 1e-6);
    }

    #[test]
    fn overlapping_boxes_overlap() {
        let a = cuboid(Vec3::splat(Fx::ONE));
        let r = gjk(
            &a,
            &Transform::IDENTITY,
            &a,
            &turned(v(1.5, 0.3, 0.2), Vec3::Y, 30),
        );
        assert!(r.overlap);
        assert_eq!(r.distance, Fx::ZERO);
        let r = gjk(&a, &Transform::IDENTITY, &a, &at(0.0, 0.0, 0.0));
        assert!(r.overlap);
    }

    #[test]
    fn cylinder_above_a_floor_box() {
        let floor = cuboid(v(10.0, 0.5, 10.0));
        let cyl = sharp(Convex::Cylinder {
            radius: Fx::from_ratio(1, 2),
            half_height: Fx::ONE,
        });
        // Standing: the cap is 0.25 m above the floor's top (y = 0).
        let r = gjk(&cyl, &at(0.3, 1.25, 0.0), &floor, &at(0.0, -0.5, 0.0));
        close(r.distance, 0.25, 1e-6);
        close_v(r.normal, [0.0, -1.0, 0.0], 1e-6);
        // Lying (axis along x): the side is 0.1 m above.
        let r = gjk(
            &cyl,
            &turned(v(0.0, 0.6, 0.0), Vec3::Z, 90),
            &floor,
            &at(0.0, -0.5, 0.0),
        );
        close(r.distance, 0.1, 1e-6);
        // Tilted 30° about z: the lowest rim point is h cos 30° + r sin 30° below the centre.
        let r = gjk(
            &cyl,
            &turned(v(0.0, 2.0, 0.0), Vec3::Z, 30),
            &floor,
            &at(0.0, -0.5, 0.0),
        );
        close(r.distance, 2.0 - (0.75f64.sqrt() + 0.25), 1e-5); // ok-det: reference
        close(r.point_a.y, 2.0 - (0.75f64.sqrt() + 0.25), 1e-5); // ok-det: reference
        close(r.point_b.y, 0.0, 1e-6);
        // Tilted 30° about x then 20° about y: the rim curves, GJK converges on it.
        let q = Quat::from_axis_angle(Vec3::Y, Fx::PI * Fx::from_ratio(20, 180))
            * Quat::from_axis_angle(Vec3::X, Fx::PI * Fx::from_ratio(30, 180));
        let r = gjk(
            &cyl,
            &Transform::from_pose(v(0.0, 2.0, 0.0), q),
            &floor,
            &at(0.0, -0.5, 0.0),
        );
        close(r.distance, 2.0 - (0.75f64.sqrt() + 0.25), 1e-5); // ok-det: reference
    }

    #[test]
    fn cylinder_rim_against_a_point_beside_it() {
        // A point beside a turned cylinder: distance to the curved side.
        let cyl = sharp(Convex::Cylinder {
            radius: Fx::ONE,
            half_height: Fx::ONE,
        });
        let point = sharp(Convex::Point);
        let r = gjk(
            &point,
            &at(1.2, 0.3, 1.6),
            &cyl,
            &turned(v(0.0, 0.0, 0.0), Vec3::Y, 17),
        );
        close(r.distance, 1.0, 1e-5);
        close_v(r.point_b, [0.6, 0.3, 0.8], 1e-5);
    }

    #[test]
    fn cone_apex_down_and_up() {
        let floor = cuboid(v(10.0, 0.5, 10.0));
        let cone = sharp(Convex::Cone {
            radius: Fx::from_ratio(1, 2),
            half_height: Fx::ONE,
        });
        let r = gjk(&cone, &at(0.0, 1.5, 0.0), &floor, &at(0.0, -0.5, 0.0));
        close(r.distance, 0.5, 1e-6);
        let r = gjk(
            &cone,
            &turned(v(0.0, 1.5, 0.0), Vec3::X, 180),
            &floor,
            &at(0.0, -0.5, 0.0),
        );
        close(r.distance, 0.5, 1e-6);
        close_v(r.point_a, [0.0, 0.5, 0.0], 1e-6);
    }

    #[test]
    fn hull_cube_matches_the_box() {
        let hull = cube_hull(v(1.0, 0.5, 0.75));
        let as_hull = sharp(Convex::Hull(&hull));
        let as_box = cuboid(v(1.0, 0.5, 0.75));
        let other = cuboid(v(0.5, 0.5, 0.5));
        let xf = turned(v(0.3, 2.2, -0.4), v(0.6, 0.0, 0.8), 33);
        let a = gjk(&as_hull, &Transform::IDENTITY, &other, &xf);
        let b = gjk(&as_box, &Transform::IDENTITY, &other, &xf);
        assert!(!a.overlap);
        assert!((a.distance - b.distance).abs() <= Fx::from_ratio(1, 1_000_000));
        close_v(a.normal, b.normal.to_f64(), 1e-5); // ok-det: reference
    }

    #[test]
    fn hull_against_hull() {
        // A tetrahedron's vertex (0, 0, −c)... its lowest face points down; another
        // tetrahedron above, turned so a vertex points down.
        let t = tetra_hull(Fx::ONE);
        let c = Fx::from_ratio(7071, 10000).to_f64(); // ok-det: reference
        let a = sharp(Convex::Hull(&t));
        // B is A moved up 3 along z: B's lowest points (z = −c + 3) face A's top edge
        // (z = c): distance 3 − 2c.
        let r = gjk(&a, &Transform::IDENTITY, &a, &at(0.1, 0.05, 3.0));
        close(r.distance, 3.0 - 2.0 * c, 1e-5);
        close_v(r.normal, [0.0, 0.0, 1.0], 1e-5);
        // A cube hull against the tetrahedron, beside it along x.
        let cube = cube_hull(Vec3::splat(Fx::HALF));
        let b = sharp(Convex::Hull(&cube));
        let r = gjk(&a, &Transform::IDENTITY, &b, &at(2.0, 0.0, -0.5));
        close(r.distance, 0.5, 1e-6);
    }

    #[test]
    fn same_inputs_same_bits() {
        let cyl = sharp(Convex::Cylinder {
            radius: Fx::from_ratio(3, 10),
            half_height: Fx::from_ratio(7, 10),
        });
        let t = tetra_hull(Fx::from_ratio(1, 2));
        let hull = sharp(Convex::Hull(&t));
        let xf = turned(v(0.4, 1.1, 0.2), v(0.0, 0.6, 0.8), 71);
        let r1 = gjk(&cyl, &xf, &hull, &Transform::IDENTITY);
        let r2 = gjk(&cyl, &xf, &hull, &Transform::IDENTITY);
        assert_eq!(r1, r2);
        let s = gjk(&hull, &Transform::IDENTITY, &cyl, &xf);
        assert!((s.distance - r1.distance).abs() <= Fx::from_ratio(1, 100_000));
    }

    #[test]
    fn tiny_and_far_shapes() {
        // Millimetre boxes 2 mm apart, and metre boxes a kilometre apart.
        let small = cuboid(Vec3::splat(Fx::from_ratio(1, 1000)));
        let r = gjk(
            &small,
            &Transform::IDENTITY,
            &small,
            &at(0.004, 0.0005, 0.0),
        );
        close(r.distance, 0.002, 1e-8);
        let big = cuboid(Vec3::splat(Fx::ONE));
        let r = gjk(&big, &Transform::IDENTITY, &big, &at(1000.0, 0.5, 0.0));
        // The progress tolerance bounds the relative error by 2⁻²¹.
        close(r.distance, 998.0, 1e-3);
    }
}
