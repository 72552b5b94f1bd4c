//! Polygon clipping for face contacts: Sutherland–Hodgman against the side planes of a
//! reference face, with a feature code for every vertex, and the choice of four points
//! out of more.
//!
//! Polygons live in the reference box's frame. Every vertex is where two lines meet: an
//! edge of the incident face (lines 0–3) or a side plane of the reference face (lines
//! 4–7). Its feature code is that unordered pair, so a point keeps its code while the
//! same edge crosses the same side, whatever else moves.

use crate::math::{Real, Vec3};

#[cfg(test)]
pub(super) mod tests;

/// Most vertices a quadrilateral clipped by four planes can have.
pub(super) const MAX_CLIPPED: usize = 8;

/// The feature code of the point where lines `a` and `b` (0–7) meet: 8 min + max, 0–63.
#[inline(always)]
pub(super) fn pair_code(a: u32, b: u32) -> u32 {
    if a < b { 8 * a + b } else { 8 * b + a }
}

/// A polygon vertex: position in the reference frame (m), its feature code, and the line
/// the polygon's edge leaving it lies on.
///
/// Code and line (both below 64) are `u32` so that a vertex fills 32 bytes without padding
/// and is copied in whole moves.
#[derive(Clone, Copy, Debug)]
pub(super) struct ClipVertex<R: Real> {
    /// Position, m.
    pub position: Vec3<R>,
    /// Feature code, see [`pair_code`].
    pub feature: u32,
    /// Line of the outgoing edge.
    pub out_line: u32,
}

/// A convex polygon of up to [`MAX_CLIPPED`] vertices, in order.
#[derive(Clone, Copy, Debug)]
pub(super) struct Polygon<R: Real> {
    /// The vertices; the first `count` are meaningful.
    pub vertices: [ClipVertex<R>; MAX_CLIPPED],
    /// Number of vertices.
    pub count: usize,
}

impl<R: Real> Polygon<R> {
    /// A polygon with no vertices, to clip into.
    pub fn empty() -> Self {
        let blank = ClipVertex {
            position: Vec3::ZERO,
            feature: 0,
            out_line: 0,
        };
        Self {
            vertices: [blank; MAX_CLIPPED],
            count: 0,
        }
    }

    /// The quadrilateral with corners `corners` in order: edge m runs from corner m to
    /// corner m + 1 (mod 4) on line m, and corner m is where lines m − 1 and m meet.
    pub fn quad(corners: [Vec3<R>; 4]) -> Self {
        let mut polygon = Self::empty();
        for (m, corner) in corners.into_iter().enumerate() {
            let line = m as u32;
            polygon.vertices[m] = ClipVertex {
                position: corner,
                feature: pair_code((line + 3) % 4, line),
                out_line: line,
            };
        }
        polygon.count = 4;
        polygon
    }

    /// The part of the polygon inside the rectangle |x_u| ≤ `half_u`, |x_w| ≤ `half_w`
    /// (m): [`clip`](Self::clip) against the side planes x_u ≤ h_u (line 4), −x_u ≤ h_u
    /// (5), x_w ≤ h_w (6) and −x_w ≤ h_w (7) in turn, `spare` taking each pass's output
    /// when it differs from its input. Returns whichever of the two holds the result.
    pub fn clip_to_rectangle<'p>(
        &'p mut self,
        spare: &'p mut Self,
        (u, half_u): (usize, R),
        (w, half_w): (usize, R),
        slack: R,
    ) -> &'p Self {
        let (mut polygon, mut other) = (self, spare);
        for (axis, upper, limit, line) in [
            (u, true, half_u, 4),
            (u, false, half_u, 5),
            (w, true, half_w, 6),
            (w, false, half_w, 7),
        ] {
            if polygon.clip(other, axis, upper, limit, line, slack) {
                core::mem::swap(&mut polygon, &mut other);
            }
        }
        polygon
    }

    /// The part of the polygon where x\[axis\] ≤ `limit` (`upper`) or −x\[axis\] ≤ `limit` (not
    /// `upper`), the side plane being line `line`, with vertices up to `slack` (m) beyond
    /// the plane kept as they are. When every vertex is kept, that part is the polygon
    /// itself: `out` is left alone and the result is `false`. Otherwise it is written to
    /// `out` and the result is `true`.
    ///
    /// Sutherland–Hodgman with signed distances d = limit ∓ x\[axis\]: walking the
    /// edges S → E, a vertex is kept when d ≥ −slack, and where an edge goes from d > 0 to
    /// d < −slack, or back, the point S + (E − S)·d_S/(d_S − d_E) on the plane is added,
    /// its coordinate along `axis` set exactly to the plane's. A kept vertex within the
    /// slack is itself where the polygon leaves or re-enters, so there is no duplicate. The
    /// slack lets a corner level with a side (equal boxes stacked) keep its feature code
    /// while it jitters across the side, instead of alternating with a clipped point.
    ///
    /// The walk copies nothing while every vertex so far is kept (S then is kept too, and
    /// each step would only append E); at the first vertex beyond the plane those before it
    /// go to `out` at once and the walk goes on as above. Each distance is computed as
    /// often either way (the last vertex's twice), so saturation counts do not change.
    fn clip(
        &self,
        out: &mut Self,
        axis: usize,
        upper: bool,
        limit: R,
        line: u32,
        slack: R,
    ) -> bool {
        let n = self.count;
        if n == 0 {
            return false;
        }
        let distance = |v: &ClipVertex<R>| {
            if upper {
                limit - v.position[axis]
            } else {
                limit + v.position[axis]
            }
        };
        let at = if upper { limit } else { -limit };
        let mut s = self.vertices[n - 1];
        let mut ds = distance(&s);
        // Whether `out` holds the output so far (otherwise it is the input's first i).
        let mut copied = ds < -slack;
        if copied {
            out.count = 0;
        }
        // The last vertex is where the polygon leaves: fixed up once it has been pushed.
        let mut last_leaves = false;
        for (i, &e) in self.vertices[..n].iter().enumerate() {
            let de = distance(&e);
            if !copied {
                if de >= -slack {
                    s = e;
                    ds = de;
                    continue;
                }
                out.vertices[..i].copy_from_slice(&self.vertices[..i]);
                out.count = i;
                copied = true;
            }
            let s_inside = ds >= -slack;
            if de >= -slack {
                if !s_inside && de > R::ZERO {
                    out.push(crossing(&s, &e, ds, de, axis, at, line, true));
                }
                out.push(e);
            } else if s_inside {
                if ds > R::ZERO {
                    out.push(crossing(&s, &e, ds, de, axis, at, line, false));
                } else if i == 0 {
                    last_leaves = true;
                } else if out.count > 0 {
                    // S, on the plane or within the slack, is where the polygon leaves: the
                    // edge from it now runs along the plane.
                    out.vertices[out.count - 1].out_line = line;
                }
            }
            s = e;
            ds = de;
        }
        if !copied {
            return false;
        }
        if last_leaves && out.count > 0 {
            out.vertices[out.count - 1].out_line = line;
        }
        true
    }

    /// Appends a vertex (there is always room: clipping a convex polygon adds at most one
    /// vertex per plane).
    #[inline(always)]
    fn push(&mut self, v: ClipVertex<R>) {
        if self.count < MAX_CLIPPED {
            self.vertices[self.count] = v;
            self.count += 1;
        }
    }
}

/// The point where edge S → E crosses the plane x\[axis\] = `at`, with d_S and d_E of
/// opposite signs: S + (E − S)·d_S/(d_S − d_E). Entering (S outside), the new vertex's
/// outgoing edge continues along S's edge; leaving, it runs along the plane `line`.
#[allow(clippy::too_many_arguments)]
#[inline]
fn crossing<R: Real>(
    s: &ClipVertex<R>,
    e: &ClipVertex<R>,
    ds: R,
    de: R,
    axis: usize,
    at: R,
    line: u32,
    entering: bool,
) -> ClipVertex<R> {
    let mut position = s.position + (e.position - s.position) * (ds / (ds - de));
    match axis {
        0 => position.x = at,
        1 => position.y = at,
        _ => position.z = at,
    }
    ClipVertex {
        position,
        feature: pair_code(s.out_line, line),
        out_line: if entering { s.out_line } else { line },
    }
}

/// The twice-signed area of the triangle (a, b, c) projected on the plane of axes `u`,
/// `w`: (b − a)ᵤ(c − a)_w − (b − a)_w(c − a)ᵤ, m².
#[inline(always)]
fn area<R: Real>(a: Vec3<R>, b: Vec3<R>, c: Vec3<R>, u: usize, w: usize) -> R {
    (b[u] - a[u]) * (c[w] - a[w]) - (b[w] - a[w]) * (c[u] - a[u])
}

/// Indices of four of `positions` (more than four, with separations `separations`, m, and
/// ids `ids`) that keep the contact stable: the deepest, the one farthest from it, the one
/// making the largest triangle with those two, and the one adding the most area to that
/// triangle (as Box2D and Bullet reduce manifolds). Areas are taken on the reference
/// face's plane, axes `u` and `w`.
///
/// "The deepest" is, among the points within `slack` (m) of the least separation, the one
/// with the lowest id, so that a face resting flat keeps the same four points while its
/// depths jitter. Other ties go to the lower index.
pub(super) fn four_of<R: Real>(
    positions: &[Vec3<R>],
    separations: &[R],
    ids: &[u32],
    slack: R,
    u: usize,
    w: usize,
) -> [usize; 4] {
    let n = positions.len();
    let argmax = |score: &dyn Fn(usize) -> Option<R>| {
        let mut best: Option<(usize, R)> = None;
        for i in 0..n {
            if let Some(value) = score(i)
                && best.is_none_or(|(_, b)| value > b)
            {
                best = Some((i, value));
            }
        }
        best.map_or(0, |(i, _)| i)
    };
    let deepest = separations[argmax(&|i| Some(-separations[i]))];
    let mut first = 0;
    let mut first_id = u32::MAX;
    for i in 0..n {
        if separations[i] <= deepest + slack && ids[i] < first_id {
            (first, first_id) = (i, ids[i]);
        }
    }
    let p0 = positions[first];
    let second = argmax(&|i| {
        (i != first).then(|| {
            let d = positions[i] - p0;
            d[u] * d[u] + d[w] * d[w]
        })
    });
    let p1 = positions[second];
    let third =
        argmax(&|i| (i != first && i != second).then(|| area(p0, p1, positions[i], u, w).abs()));
    let p2 = positions[third];
    // Orient the triangle counter-clockwise so that a point outside an edge has a negative
    // area with it.
    let (a, b, c) = if area(p0, p1, p2, u, w) >= R::ZERO {
        (p0, p1, p2)
    } else {
        (p0, p2, p1)
    };
    let fourth = argmax(&|i| {
        (i != first && i != second && i != third).then(|| {
            let p = positions[i];
            (-area(a, b, p, u, w))
                .max(-area(b, c, p, u, w))
                .max(-area(c, a, p, u, w))
        })
    });
    [first, second, third, fourth]
}
