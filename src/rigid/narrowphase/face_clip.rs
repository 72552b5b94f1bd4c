//! Clipping a supporting feature (polygon, segment or point) against a reference face's
//! side planes, or a segment against the slab of another, in the world frame, with a
//! feature id for every resulting point.
//!
//! The side plane of the reference edge r_j → r_{j+1} has the outward normal
//! s_j = (r_{j+1} − r_j) × m (m the face's outward normal, the polygon counter-clockwise
//! from outside); a point p is inside when s_j · (p − r_j) ≤ 0. An edge S → E crossing
//! it is cut at S + (E − S) d_S / (d_S − d_E), the d of opposite signs so that the
//! denominator is not zero. Ids: a vertex kept from the incident feature keeps its id (bits
//! 0–13); a cut point has bit 29, the reference side's id (the id of its first vertex) in
//! bits 14–27 and the id of the incident edge it lies on (its first vertex's) in bits 0–13.

use super::supporting_face::{Feature, MAX_FACE_POINTS};
use crate::math::{Real, Vec3};

/// Most points of a clipped polygon: a convex polygon cut by k planes gains at most k.
pub(super) const MAX_CLIPPED: usize = 2 * MAX_FACE_POINTS;

/// The points of a clipping result, with their ids.
#[derive(Clone, Copy, Debug)]
pub(super) struct Clipped<R: Real> {
    points: [Vec3<R>; MAX_CLIPPED],
    ids: [u32; MAX_CLIPPED],
    /// The id of the edge leaving each point (see the module), for the next cut.
    edges: [u32; MAX_CLIPPED],
    count: usize,
}

impl<R: Real> Clipped<R> {
    fn empty() -> Self {
        Self {
            points: [Vec3::ZERO; MAX_CLIPPED],
            ids: [0; MAX_CLIPPED],
            edges: [0; MAX_CLIPPED],
            count: 0,
        }
    }

    fn push(&mut self, point: Vec3<R>, id: u32, edge: u32) {
        if self.count < MAX_CLIPPED {
            self.points[self.count] = point;
            self.ids[self.count] = id;
            self.edges[self.count] = edge;
            self.count += 1;
        }
    }

    /// The points and ids.
    pub fn iter(&self) -> impl Iterator<Item = (Vec3<R>, u32)> + '_ {
        (0..self.count).map(|i| (self.points[i], self.ids[i]))
    }
}

/// The id of the point where incident edge `edge` crosses reference side `side`.
fn cut_id(side: u32, edge: u32) -> u32 {
    1 << 29 | (side & 0x3FFF) << 14 | (edge & 0x3FFF)
}

/// The part of `incident` inside every side plane of the face `reference` (3 or more
/// points): Sutherland–Hodgman for a polygon, the parameter interval for a segment, the
/// point itself or nothing for a point.
pub(super) fn clip_to_face<R: Real>(reference: &Feature<R>, incident: &Feature<R>) -> Clipped<R> {
    let mut current = Clipped::empty();
    for (&p, &id) in incident.points().iter().zip(&incident.ids) {
        current.push(p, id, id);
    }
    let m = reference.normal;
    let n = reference.count;
    for j in 0..n {
        let r = reference.points[j];
        let side = (reference.points[(j + 1) % n] - r).cross(m);
        let distance = |p: Vec3<R>| side.dot(p - r);
        current = match current.count {
            0 => return current,
            1 => {
                if distance(current.points[0]) > R::ZERO {
                    Clipped::empty()
                } else {
                    current
                }
            }
            2 => cut_segment(&current, distance, reference.ids[j]),
            _ => cut_polygon(&current, distance, reference.ids[j]),
        };
    }
    current
}

/// The cut of `polygon` by one side plane (signed distance `distance`, outside > 0, id
/// `side`).
fn cut_polygon<R: Real>(
    polygon: &Clipped<R>,
    distance: impl Fn(Vec3<R>) -> R,
    side: u32,
) -> Clipped<R> {
    let mut out = Clipped::empty();
    let n = polygon.count;
    for i in 0..n {
        let s = (i + n - 1) % n;
        let (ps, pe) = (polygon.points[s], polygon.points[i]);
        let (ds, de) = (distance(ps), distance(pe));
        let cut = || ps + (pe - ps) * (ds / (ds - de));
        if de <= R::ZERO {
            if ds > R::ZERO {
                out.push(cut(), cut_id(side, polygon.edges[s]), polygon.edges[s]);
            }
            out.push(pe, polygon.ids[i], polygon.edges[i]);
        } else if ds <= R::ZERO {
            // Leaving: the new edge runs along the side plane.
            out.push(cut(), cut_id(side, polygon.edges[s]), 1 << 28 | side);
        }
    }
    out
}

/// The cut of a segment (two points) by one side plane.
fn cut_segment<R: Real>(
    segment: &Clipped<R>,
    distance: impl Fn(Vec3<R>) -> R,
    side: u32,
) -> Clipped<R> {
    let (p0, p1) = (segment.points[0], segment.points[1]);
    let (d0, d1) = (distance(p0), distance(p1));
    if d0 > R::ZERO && d1 > R::ZERO {
        return Clipped::empty();
    }
    let mut out = *segment;
    if d0 > R::ZERO {
        out.points[0] = p0 + (p1 - p0) * (d0 / (d0 - d1));
        out.ids[0] = cut_id(side, segment.edges[0]);
    } else if d1 > R::ZERO {
        out.points[1] = p0 + (p1 - p0) * (d0 / (d0 - d1));
        out.ids[1] = cut_id(side, segment.edges[0]);
    }
    out
}

/// The part of segment `b` (2 points) between the planes through segment `a`'s ends
/// perpendicular to it: (p − a₀) · e ≥ 0 and (p − a₁) · e ≤ 0, e = a₁ − a₀.
pub(super) fn clip_to_slab<R: Real>(a: &Feature<R>, b: &Feature<R>) -> Clipped<R> {
    let mut current = Clipped::empty();
    for i in 0..2 {
        current.push(b.points[i], b.ids[i], b.ids[0]);
    }
    let (a0, a1) = (a.points[0], a.points[1]);
    let e = a1 - a0;
    current = cut_segment(&current, |p| -e.dot(p - a0), a.ids[0]);
    if current.count == 0 {
        return current;
    }
    cut_segment(&current, |p| e.dot(p - a1), a.ids[1])
}
