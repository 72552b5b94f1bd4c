//! Contacts of any pair with a cylinder, a cone or a hull (and of a plane with one).
//!
//! Normal and depth come from the cores: GJK while they are apart (separation
//! s = d − r_A − r_B), EPA when they overlap (s = −depth − r_A − r_B, made exact by GJK on
//! the cores moved apart along EPA's normal, see [`refine`]), and, when EPA finds no
//! polytope or only a touching one (the origin on D's boundary, where its faces can
//! mislead), [`refine`] from the line of centres. Points come
//! from the supporting features of both cores along ±n (`supporting_face.rs`), as in Jolt:
//!
//! - one of them a face well aligned with the normal (n · m ≥ 1/2, the better one, A on
//!   ties): the reference; the other feature is clipped against its side planes
//!   (`face_clip.rs`) and every clipped point p gets its own core gap t, the distance
//!   along n from p to the reference plane m · x = m · r₀: t = m · (p − r₀) / (m · n) for
//!   A's face, the same with −m for B's;
//! - two parallel segments (cylinder sides, capsules; within 1.8°): B's segment clipped to
//!   the slab of A's and each end's gap to A's segment; two crossing segments: one point,
//!   their closest points;
//! - otherwise one point, GJK's closest points (or the features' points when EPA ran).
//!
//! Each point lies midway between the surfaces (cores grown by their radii) with
//! separation t − r_A − r_B; points beyond `margin` are dropped and more than four reduced
//! to four with the deepest and the widest spread (`clip::four_of`). Ids: bit 31 when B's
//! face is the reference; a kept vertex has the incident shape's vertex id; a clipped
//! crossing has bit 29, the reference side's id in bits 14–27 and the incident edge's in
//! bits 0–13 (see `face_clip.rs`).

use super::clip::four_of;
use super::face_clip::{clip_to_face, clip_to_slab};
use super::plane::WorldPlane;
use super::segments::{Segment, closest_parameters};
use super::supporting_face::{Feature, supporting_feature};
use super::tolerance::{lying_sine, unit};
use crate::math::{Real, Vec3};
use crate::rigid::convex::Rounded;
use crate::rigid::convex::epa::epa;
use crate::rigid::convex::gjk::{CorePair, gjk, gjk_simplex};
use crate::rigid::manifold::{MAX_MANIFOLD_POINTS, Manifold, ManifoldPoint};
use crate::rigid::shape::Shape;
use crate::rigid::transform::Transform;

/// Slack (m) within which points count as equally deep when four are chosen: 2⁻¹² m.
fn depth_slack<R: Real>() -> R {
    R::from_ratio(1, 1 << 12)
}

/// The manifold of two convex shapes, at least one a cylinder, a cone or a hull (see the
/// [module](self)); empty beyond `margin` (m) or for a shape that is not convex. Computed
/// in the natural order of [`rank`] and flipped for the other.
pub(super) fn convex_pair<R: Real>(
    a: &Shape<R>,
    xf_a: &Transform<R>,
    b: &Shape<R>,
    xf_b: &Transform<R>,
    margin: R,
) -> Manifold<R> {
    if rank(b) < rank(a) {
        return convex_pair(b, xf_b, a, xf_a, margin).flipped();
    }
    let (Some(ra), Some(rb)) = (Rounded::of(a), Rounded::of(b)) else {
        return Manifold::EMPTY;
    };
    let (normal, gap, closest) = core_contact(&ra, xf_a, &rb, xf_b);
    manifold_along(&ra, xf_a, &rb, xf_b, (normal, gap, closest), margin, true)
}

/// Normal (unit, A to B), core gap (m, negative when the cores overlap) and, when known,
/// the closest points of the cores of A and B: GJK while apart, EPA and [`refine`] when
/// they overlap (see the [module](self)).
pub(super) fn core_contact<R: Real>(
    ra: &Rounded<R>,
    xf_a: &Transform<R>,
    rb: &Rounded<R>,
    xf_b: &Transform<R>,
) -> CoreContact<R> {
    let pair = CorePair::new(ra, xf_a, rb, xf_b);
    let (g, simplex) = gjk_simplex(&pair);
    if g.overlap {
        match epa(&pair, &simplex) {
            Some(p) if p.depth >= R::ZERO => refine(ra, xf_a, rb, xf_b, p.normal, p.depth),
            _ => {
                let n = unit(xf_b.translation - xf_a.translation).map_or(Vec3::Y, |(n, _)| n);
                refine(ra, xf_a, rb, xf_b, n, R::ZERO)
            }
        }
    } else {
        (g.normal, g.distance, Some((g.point_a, g.point_b)))
    }
}

/// A contact of two cores: unit normal from A to B, core gap (m) and, when known, the
/// cores' closest points (m).
pub(super) type CoreContact<R> = (Vec3<R>, R, Option<(Vec3<R>, Vec3<R>)>);

/// The manifold of two rounded cores touching along `contact` (see [`core_contact`]):
/// empty when the surfaces are more than `margin` (m) apart, else the points of the
/// cores' supporting features along ±n (see the [module](self)). When the features give
/// no point, one point from the closest points (or the features) if `single_point`, else
/// none.
pub(super) fn manifold_along<R: Real>(
    ra: &Rounded<R>,
    xf_a: &Transform<R>,
    rb: &Rounded<R>,
    xf_b: &Transform<R>,
    (normal, gap, closest): CoreContact<R>,
    margin: R,
    single_point: bool,
) -> Manifold<R> {
    let radii = ra.radius + rb.radius;
    if gap - radii > margin {
        return Manifold::EMPTY;
    }
    let fa = supporting_feature(&ra.core, xf_a, normal);
    let fb = supporting_feature(&rb.core, xf_b, -normal);
    let mut points = Candidates::new(normal, ra.radius, rb.radius);
    let align_a = face_alignment(&fa, normal);
    let align_b = face_alignment(&fb, -normal);
    if align_a.max(align_b) >= R::HALF {
        let b_reference = align_b > align_a;
        let (reference, incident, towards) = if b_reference {
            (&fb, &fa, -normal)
        } else {
            (&fa, &fb, normal)
        };
        let clipped = clip_to_face(reference, incident);
        let r0 = reference.points[0];
        let m = reference.normal;
        let denominator = m.dot(towards);
        for (p, id) in clipped.iter() {
            let t = m.dot(p - r0) / denominator;
            let flag = if b_reference { 1 << 31 } else { 0 };
            if b_reference {
                points.add(p, p + normal * t, t, id | flag);
            } else {
                points.add(p - normal * t, p, t, id);
            }
        }
    } else if let (Some(sa), Some(sb)) = (segment_of(&fa), segment_of(&fb)) {
        if parallel(&sa, &sb) {
            for (p, id) in clip_to_slab(&fa, &fb).iter() {
                let on_a = sa.at(sa.closest_parameter(p));
                points.add(on_a, p, normal.dot(p - on_a), id);
            }
        } else {
            let (s, t) = closest_parameters(&sa, &sb);
            let (on_a, on_b) = (sa.at(s), sb.at(t));
            points.add(on_a, on_b, normal.dot(on_b - on_a), 0);
        }
    }
    if points.count == 0 && single_point {
        let (core_a, core_b) = closest.unwrap_or_else(|| {
            let p = if fa.count == 1 {
                fa.points[0]
            } else if fb.count == 1 {
                fb.points[0] - normal * gap
            } else {
                centroid(&fa)
            };
            (p, p + normal * gap)
        });
        points.add(core_a, core_b, gap, 0);
    }
    points.manifold(margin)
}

/// Distance (m) by which [`refine`] moves B beyond EPA's contact: 2⁻⁶ m ≈ 16 mm.
fn refine_shift<R: Real>() -> R {
    R::from_ratio(1, 1 << 6)
}

/// EPA's normal n and depth d sharpened on curved cores: B moved by (d + δ) n
/// (δ = [`refine_shift`]) is apart from A, and GJK there gives the normal n' of the
/// separated cores, with closest points (B's moved back). Of n and n', the one along which
/// the cores overlap least, depth(u) = u · s_D(u) (D = A − B), is the penetration normal
/// (the least overlap over directions defines it), n on ties; the result is that normal,
/// the gap −depth (m) and n''s closest points when n' is chosen. (EPA's polytope
/// approximates a curved boundary only to its tolerance, which leaves the normal off by up
/// to √(2 tol / ρ); GJK on separated cores converges closer, but on flat contacts may stop
/// a little off, where EPA is exact.)
pub(super) fn refine<R: Real>(
    a: &Rounded<R>,
    xf_a: &Transform<R>,
    b: &Rounded<R>,
    xf_b: &Transform<R>,
    normal: Vec3<R>,
    depth: R,
) -> CoreContact<R> {
    let shift = depth + refine_shift();
    let offset = normal * shift;
    let moved = Transform {
        translation: xf_b.translation + offset,
        ..*xf_b
    };
    let g = gjk(a, xf_a, b, &moved);
    let pair = CorePair::new(a, xf_a, b, xf_b);
    let reach = |n: Vec3<R>| n.dot(pair.support(n).w);
    if g.overlap || reach(g.normal) >= reach(normal) {
        return (normal, -reach(normal), None);
    }
    (
        g.normal,
        -reach(g.normal),
        Some((g.point_a, g.point_b - offset)),
    )
}

/// The shape's place in the natural order of a pair (sphere, capsule, box, cylinder, cone,
/// hull): the lower one is A, so that swapping two shapes of different kinds flips the
/// manifold exactly.
fn rank<R: Real>(shape: &Shape<R>) -> u8 {
    match shape {
        Shape::Sphere { .. } => 0,
        Shape::Capsule { .. } => 1,
        Shape::Box { .. } => 2,
        Shape::Cylinder { .. } => 3,
        Shape::Cone { .. } => 4,
        Shape::ConvexHull { .. } => 5,
        Shape::Plane { .. }
        | Shape::Compound { .. }
        | Shape::TriMesh { .. }
        | Shape::HeightField { .. } => 6,
    }
}

/// n · m for a face (3 or more points) with outward normal m seen along `towards`; −1 for
/// an edge or a vertex.
fn face_alignment<R: Real>(feature: &Feature<R>, towards: Vec3<R>) -> R {
    if feature.count >= 3 {
        feature.normal.dot(towards)
    } else {
        -R::ONE
    }
}

/// A two-point feature as a [`Segment`]; `None` for other features or a segment too short
/// to have a direction.
fn segment_of<R: Real>(feature: &Feature<R>) -> Option<Segment<R>> {
    if feature.count != 2 {
        return None;
    }
    let (p0, p1) = (feature.points[0], feature.points[1]);
    let (axis, length) = unit(p1 - p0)?;
    Some(Segment {
        centre: (p0 + p1) * R::HALF,
        axis,
        half_length: length * R::HALF,
    })
}

/// Whether two segments are parallel enough to touch along a line: |u_a × u_b| within
/// [`lying_sine`] (1.8°).
fn parallel<R: Real>(a: &Segment<R>, b: &Segment<R>) -> bool {
    let sine = lying_sine::<R>();
    a.axis.cross(b.axis).length_squared() <= sine * sine
}

/// The mean of a feature's points, m.
fn centroid<R: Real>(feature: &Feature<R>) -> Vec3<R> {
    let sum = feature.points().iter().fold(Vec3::ZERO, |s, &p| s + p);
    sum * (R::from_int(feature.count as i32)).recip()
}

/// Most contact candidates before the reduction to four.
const MAX_CANDIDATES: usize = 2 * super::supporting_face::MAX_FACE_POINTS;

/// Contact candidates: core points, gaps and ids, turned into manifold points.
struct Candidates<R: Real> {
    normal: Vec3<R>,
    radius_a: R,
    radius_b: R,
    positions: [Vec3<R>; MAX_CANDIDATES],
    separations: [R; MAX_CANDIDATES],
    ids: [u32; MAX_CANDIDATES],
    count: usize,
}

impl<R: Real> Candidates<R> {
    fn new(normal: Vec3<R>, radius_a: R, radius_b: R) -> Self {
        Self {
            normal,
            radius_a,
            radius_b,
            positions: [Vec3::ZERO; MAX_CANDIDATES],
            separations: [R::ZERO; MAX_CANDIDATES],
            ids: [0; MAX_CANDIDATES],
            count: 0,
        }
    }

    /// A candidate from the core points `core_a`, `core_b` with core gap `gap` (m): the
    /// surfaces at core_a + r_A n and core_b − r_B n, the point midway, separation
    /// gap − r_A − r_B. An id already taken (two cuts whose truncated feature codes
    /// coincide, which is rare) is made distinct with bit 30 and the candidate's index in
    /// bits 22–29.
    fn add(&mut self, core_a: Vec3<R>, core_b: Vec3<R>, gap: R, id: u32) {
        if self.count == MAX_CANDIDATES {
            return;
        }
        let id = if self.ids[..self.count].contains(&id) {
            1 << 30 | (self.count as u32) << 22 | (id & 0x3F_FFFF)
        } else {
            id
        };
        let on_a = core_a + self.normal * self.radius_a;
        let on_b = core_b - self.normal * self.radius_b;
        self.positions[self.count] = (on_a + on_b) * R::HALF;
        self.separations[self.count] = gap - self.radius_a - self.radius_b;
        self.ids[self.count] = id;
        self.count += 1;
    }

    /// The candidates within `margin`, reduced to four by [`four_of`] on the plane across
    /// the normal when more.
    fn manifold(&self, margin: R) -> Manifold<R> {
        let mut manifold = Manifold {
            normal: self.normal,
            ..Manifold::EMPTY
        };
        let mut kept = [0usize; MAX_CANDIDATES];
        let mut n = 0;
        for i in 0..self.count {
            if self.separations[i] <= margin {
                kept[n] = i;
                n += 1;
            }
        }
        if n <= MAX_MANIFOLD_POINTS {
            for &i in &kept[..n] {
                manifold.push(self.point(i));
            }
            return manifold;
        }
        let t1 = self.normal.any_orthonormal();
        let t2 = self.normal.cross(t1);
        let mut local = [Vec3::ZERO; MAX_CANDIDATES];
        let mut separations = [R::ZERO; MAX_CANDIDATES];
        let mut ids = [0u32; MAX_CANDIDATES];
        for (j, &i) in kept[..n].iter().enumerate() {
            let p = self.positions[i];
            local[j] = Vec3::new(p.dot(t1), p.dot(self.normal), p.dot(t2));
            separations[j] = self.separations[i];
            ids[j] = self.ids[i];
        }
        let chosen = four_of(
            &local[..n],
            &separations[..n],
            &ids[..n],
            depth_slack(),
            0,
            2,
        );
        for j in chosen {
            manifold.push(self.point(kept[j]));
        }
        manifold
    }

    fn point(&self, i: usize) -> ManifoldPoint<R> {
        ManifoldPoint {
            point: self.positions[i],
            separation: self.separations[i],
            id: self.ids[i],
        }
    }
}

/// The manifold of a plane (A, outward normal n) and a cylinder, a cone or a hull (B): the
/// supporting feature of B's core along −n, each point p with separation n · p − d − r_B,
/// those within `margin` (m), at most four (the deepest and widest spread). Ids: B's
/// feature ids.
pub(super) fn plane_convex<R: Real>(
    plane: &WorldPlane<R>,
    shape: &Shape<R>,
    xf: &Transform<R>,
    margin: R,
) -> Manifold<R> {
    let Some(rounded) = Rounded::of(shape) else {
        return Manifold::EMPTY;
    };
    let n = plane.normal;
    let feature = supporting_feature(&rounded.core, xf, -n);
    let mut points = Candidates::new(n, R::ZERO, rounded.radius);
    for (&p, &id) in feature.points().iter().zip(&feature.ids) {
        let gap = plane.distance(p);
        points.add(p - n * gap, p, gap, id);
    }
    points.manifold(margin)
}
