//! The deterministic quickhull: [`ConvexHull::new`] builds the convex hull of at most
//! [`MAX_HULL_POINTS`] points with the same result on every machine and for every order of
//! the points.
//!
//! # Steps
//!
//! 1. Check the points (count, magnitude), sort them lexicographically by value and drop
//!    exact duplicates: the order of the input no longer matters.
//! 2. Move and scale them into the unit box: q = (p − c)/s, c the centre of their bounding
//!    box and s its largest half extent (m). Every later product stays below 12 in these
//!    units, far from the I32F32 limit of 2³¹ however large the coordinates (up to 10⁵ m),
//!    and the tolerance below is relative to the cloud's size.
//! 3. Quickhull (Barber, Dobkin and Huhdanpaa 1996) on triangles: a starting tetrahedron of
//!    extreme points, each remaining point in the outside set of the first face it is above;
//!    then, while an outside set is not empty, its farthest point (the eye) replaces the
//!    faces it sees by a cone of new faces on their boundary (the horizon).
//! 4. Merge adjacent triangles that lie in one plane into convex polygon faces, and find the
//!    corners: the points where at least three faces meet. A point on an edge or inside a
//!    face is not a corner.
//! 5. Repeat steps 2 to 4 on the corners alone until every point is a corner. The result is
//!    then the hull of its own vertices, so `ConvexHull::new(hull.vertices())` gives the
//!    same hull bit for bit (serialisation relies on it). Each round drops at least one
//!    point, so there are at most as many rounds as points; in practice one or two.
//!
//! # Tolerance
//!
//! A point is above a face when its distance to the face's plane exceeds
//! ε = max(2⁻²⁴, 64 ulp) in the scaled units, that is ε·s ≈ 6·10⁻⁸ s metres (6 nm for a
//! 10 cm cloud, 6 mm for a 10⁵ m one). The same ε decides coplanarity (a triangle joins a
//! face when its three vertices lie within ε of the plane of the face's largest triangle),
//! collinearity and the degenerate inputs. ε is some 250 times the rounding of an I32F32
//! plane distance in these units, so that a box's corners, rounded to the format after a
//! rotation, still make 6 quadrilaterals.
//!
//! # Robustness
//!
//! Every loop is bounded by the number of points or faces. The faces an eye sees are
//! collected by a walk from its own face over visible neighbours, so they are connected;
//! when rounding makes them anything else than a disc (their boundary not one simple loop),
//! the eye is skipped rather than the surface broken: the result is always a closed
//! surface with V − E + F = 2. Every face's offset is the largest n · v over all vertices,
//! so each face plane supports the hull whatever the rounding of its normal.
//!
//! # Limit
//!
//! A face normal comes from a cross product rounded to one ulp u of the format (2⁻³² in
//! the scaled units for I32F32), so a sliver face of height h has its normal tilted by up
//! to about u/h radians. Where h falls below about u/ε (0.4% of s for I32F32) that tilt can
//! exceed the tolerance, and a point the construction judged inside (a point of a slab
//! a few ε thick, say) may lie up to (u/h)·s outside the hull; the surface stays valid.

use super::hull::{ConvexHull, HullError, HullFace, MAX_HULL_POINTS};
use crate::math::{Real, Vec3};

/// The largest coordinate magnitude a hull's points may have, m.
const MAX_COORDINATE: i32 = 100_000;

/// No index: the end of a chain in the index tables below.
const NONE: u32 = u32::MAX;

impl<R: Real> ConvexHull<R> {
    /// The convex hull of `points` (m): its corners as vertices in lexicographic order, its
    /// faces as convex polygons counter-clockwise seen from outside, each starting at its
    /// lowest vertex index and listed in lexicographic order of their vertex lists.
    ///
    /// Errors: fewer than 4 or more than [`MAX_HULL_POINTS`] points, a coordinate beyond
    /// ±100 000 m, or points that span no volume (coincident, collinear or coplanar within
    /// the tolerance of the module documentation).
    pub fn new(points: &[Vec3<R>]) -> Result<Self, HullError> {
        if points.len() < 4 {
            return Err(HullError::TooFewPoints(points.len()));
        }
        if points.len() > MAX_HULL_POINTS {
            return Err(HullError::TooManyPoints(points.len()));
        }
        let limit = R::from_int(MAX_COORDINATE);
        let in_range = |v: R| v.abs() <= limit;
        if let Some(index) = points
            .iter()
            .position(|p| !(in_range(p.x) && in_range(p.y) && in_range(p.z)))
        {
            return Err(HullError::OutOfRange { index });
        }
        let mut set = canonical_order(points);
        // Each round keeps only corners; a round that keeps every point is final. The set
        // shrinks by at least one point per round, hence the bound.
        for _ in 0..points.len() {
            let round = Round::build(&set)?;
            if round.corners.len() == set.len() {
                return Ok(round.into_hull(&set));
            }
            set = round.corners.iter().map(|&i| set[i as usize]).collect();
        }
        Err(HullError::Degenerate("the construction did not settle"))
    }
}

/// The points sorted lexicographically by (x, y, z) in the format's total order, exact
/// duplicates removed.
fn canonical_order<R: Real>(points: &[Vec3<R>]) -> Vec<Vec3<R>> {
    let key = |a: &Vec3<R>, b: &Vec3<R>| {
        a.x.total_cmp(&b.x)
            .then(a.y.total_cmp(&b.y))
            .then(a.z.total_cmp(&b.z))
    };
    let mut sorted = points.to_vec();
    sorted.sort_by(key);
    sorted.dedup_by(|a, b| key(a, b).is_eq());
    sorted
}

/// |v| computed after doubling v until its largest component is at least ½ (at most 31
/// times, exact in fixed point), so that the square of a short vector keeps its digits: in
/// I32F32 |v|² of a vector of order 2⁻⁸ would otherwise keep only 16 bits (scaled units).
fn careful_length<R: Real>(v: Vec3<R>) -> R {
    let (scaled, doublings) = scaled_up(v);
    let length = scaled.length();
    if doublings == 0 {
        length
    } else {
        length.mul_pow2_recip(doublings)
    }
}

/// The unit vector along v, v/|v| after the doubling of [`careful_length`], each component
/// clamped to [−1, 1] (|v| may round an ulp short, and an axis then comes out exact);
/// `None` for zero.
fn careful_unit<R: Real>(v: Vec3<R>) -> Option<Vec3<R>> {
    let scaled = scaled_up(v).0;
    let length = scaled.length();
    let unit = |x: R| (x / length).clamp(-R::ONE, R::ONE);
    (length > R::ZERO).then(|| Vec3::new(unit(scaled.x), unit(scaled.y), unit(scaled.z)))
}

/// v · 2ᵏ for the smallest k ≤ 31 that makes the largest component at least ½, and k.
fn scaled_up<R: Real>(v: Vec3<R>) -> (Vec3<R>, u32) {
    let mut scaled = v;
    for doublings in 0..31 {
        if scaled.abs().max_component() >= R::HALF {
            return (scaled, doublings);
        }
        scaled *= R::TWO;
    }
    (scaled, 31)
}

/// A triangle of the hull under construction.
#[derive(Clone, Debug)]
struct Triangle<R: Real> {
    /// Point indices, counter-clockwise seen from outside.
    corners: [u32; 3],
    /// `neighbours[i]`: the triangle across the edge `corners[i]` → `corners[i + 1]`.
    neighbours: [u32; 3],
    /// Outward unit normal in the scaled units (zero when the triangle has no area).
    normal: Vec3<R>,
    /// normal · q for its points.
    offset: R,
    /// |(b − a) × (c − a)|: twice its area (scaled units).
    double_area: R,
    /// The points above it that no earlier face has claimed.
    outside: Vec<u32>,
    /// False once an eye has replaced it.
    alive: bool,
}

/// One round of the construction on a canonical point set.
struct Round<R: Real> {
    /// The points scaled into the unit box.
    scaled: Vec<Vec3<R>>,
    /// The distance tolerance ε (scaled units).
    tolerance: R,
    triangles: Vec<Triangle<R>>,
    /// The merged faces, each as a loop of point indices counter-clockwise from outside.
    faces: Vec<Vec<u32>>,
    /// The corners: points in at least three faces, ascending.
    corners: Vec<u32>,
}

/// The edge i of a triangle, as (from, to).
fn edge(corners: [u32; 3], i: usize) -> (u32, u32) {
    (corners[i], corners[(i + 1) % 3])
}

/// Whether directed edges (from, to) form exactly one simple cycle: every `from` distinct,
/// every `to` some edge's `from`, and the walk from the first edge visits all of them.
/// `next_of` is scratch space, one entry per point, all [`NONE`] on entry and on return.
fn is_one_loop(edges: &[(u32, u32)], next_of: &mut [u32]) -> bool {
    let mut simple = edges.len() >= 3;
    let mut filled = 0;
    for (k, &(from, _)) in edges.iter().enumerate() {
        if next_of[from as usize] != NONE {
            simple = false;
            break;
        }
        next_of[from as usize] = k as u32;
        filled += 1;
    }
    if simple {
        let mut at = 0usize;
        let mut steps = 0;
        loop {
            let next = next_of[edges[at].1 as usize];
            steps += 1;
            if next == NONE || steps > edges.len() {
                simple = false;
                break;
            }
            at = next as usize;
            if at == 0 {
                simple = steps == edges.len();
                break;
            }
        }
    }
    for &(from, _) in &edges[..filled] {
        next_of[from as usize] = NONE;
    }
    simple
}

/// The loop of point indices that one simple cycle of directed edges makes, starting at
/// the edge whose `from` is lowest. The edges must pass [`is_one_loop`].
fn loop_from(edges: &[(u32, u32)], next_of: &mut [u32]) -> Vec<u32> {
    for (k, &(from, _)) in edges.iter().enumerate() {
        next_of[from as usize] = k as u32;
    }
    let start = edges
        .iter()
        .map(|&(from, _)| from)
        .min()
        .unwrap_or_default();
    let mut at = start;
    let mut cycle = Vec::with_capacity(edges.len());
    for _ in 0..edges.len() {
        cycle.push(at);
        at = edges[next_of[at as usize] as usize].1;
    }
    for &(from, _) in edges {
        next_of[from as usize] = NONE;
    }
    cycle
}

impl<R: Real> Round<R> {
    /// The hull of a canonical point set: triangles, merged faces and corners.
    fn build(points: &[Vec3<R>]) -> Result<Self, HullError> {
        let mut round = Self::scaled(points)?;
        let [a, b, c, d] = round.tetrahedron()?;
        round.start(a, b, c, d);
        round.grow();
        round.merge();
        Ok(round)
    }

    /// The points moved and scaled into the unit box (step 2), with the tolerance.
    fn scaled(points: &[Vec3<R>]) -> Result<Self, HullError> {
        let mut low = points[0];
        let mut high = points[0];
        for p in points {
            low = low.min_elem(*p);
            high = high.max_elem(*p);
        }
        let centre = (low + high) * R::HALF;
        let half = ((high - low) * R::HALF).max_component();
        if half <= R::ZERO {
            return Err(HullError::Degenerate("all points coincide"));
        }
        let scaled = points.iter().map(|&p| (p - centre) / half).collect();
        let tolerance = R::from_ratio(1, 1 << 24).max(R::EPSILON * R::from_int(64));
        Ok(Self {
            scaled,
            tolerance,
            triangles: Vec::new(),
            faces: Vec::new(),
            corners: Vec::new(),
        })
    }

    /// Four points spanning a volume: the lowest and highest along the axis of largest
    /// extent, the point farthest from their line, then the point farthest from the plane
    /// of the three (the first in canonical order among equals), ordered so that the fourth
    /// is below the plane of the first three taken counter-clockwise.
    fn tetrahedron(&self) -> Result<[u32; 4], HullError> {
        let q = &self.scaled;
        let first_best = |score: &dyn Fn(Vec3<R>) -> R| {
            let mut best = (0u32, score(q[0]));
            for (i, &p) in q.iter().enumerate().skip(1) {
                let s = score(p);
                if s > best.1 {
                    best = (i as u32, s);
                }
            }
            best
        };
        let extent = q
            .iter()
            .fold(Vec3::ZERO, |m: Vec3<R>, p| m.max_elem(p.abs()));
        let axis = if extent.x >= extent.y && extent.x >= extent.z {
            0
        } else if extent.y >= extent.z {
            1
        } else {
            2
        };
        let (a, _) = first_best(&|p: Vec3<R>| -p[axis]);
        let (b, _) = first_best(&|p: Vec3<R>| p[axis]);
        let (qa, qb) = (q[a as usize], q[b as usize]);
        let along = careful_unit(qb - qa).ok_or(HullError::Degenerate("all points coincide"))?;
        let (c, off_line) = first_best(&|p: Vec3<R>| careful_length((p - qa).cross(along)));
        if off_line <= self.tolerance {
            return Err(HullError::Degenerate("the points lie on one line"));
        }
        let qc = q[c as usize];
        let normal = careful_unit((qb - qa).cross(qc - qa))
            .ok_or(HullError::Degenerate("the points lie on one line"))?;
        let (d, off_plane) = first_best(&|p: Vec3<R>| normal.dot_fused(p - qa).abs());
        if off_plane <= self.tolerance {
            return Err(HullError::Degenerate("the points lie in one plane"));
        }
        if normal.dot_fused(q[d as usize] - qa) > R::ZERO {
            Ok([a, c, b, d])
        } else {
            Ok([a, b, c, d])
        }
    }

    /// A new live triangle on `corners` with no neighbours yet and its plane.
    fn triangle(&self, corners: [u32; 3]) -> Triangle<R> {
        let [a, b, c] = corners.map(|i| self.scaled[i as usize]);
        let cross = (b - a).cross(c - a);
        let normal = careful_unit(cross).unwrap_or(Vec3::ZERO);
        Triangle {
            corners,
            neighbours: [NONE; 3],
            normal,
            offset: normal.dot_fused(a),
            double_area: careful_length(cross),
            outside: Vec::new(),
            alive: true,
        }
    }

    /// The signed distance of point `point` above triangle `t` (scaled units).
    fn height(&self, t: u32, point: u32) -> R {
        let t = &self.triangles[t as usize];
        t.normal.dot_fused(self.scaled[point as usize]) - t.offset
    }

    /// The starting tetrahedron (a, b, c) with d below, its neighbours, and every other
    /// point in the outside set of the first face it is above.
    fn start(&mut self, a: u32, b: u32, c: u32, d: u32) {
        for corners in [[a, b, c], [a, d, b], [b, d, c], [c, d, a]] {
            let t = self.triangle(corners);
            self.triangles.push(t);
        }
        for t in 0..4 {
            for i in 0..3 {
                let (from, to) = edge(self.triangles[t].corners, i);
                let across = (0..4)
                    .find(|&u| (0..3).any(|j| edge(self.triangles[u].corners, j) == (to, from)))
                    .unwrap_or(t);
                self.triangles[t].neighbours[i] = across as u32;
            }
        }
        let others = (0..self.scaled.len() as u32).filter(|p| ![a, b, c, d].contains(p));
        let candidates: Vec<u32> = others.collect();
        self.assign(&candidates, &[0, 1, 2, 3]);
    }

    /// Puts each point in the outside set of the first of `triangles` it is more than ε
    /// above; the others are inside the hull and are dropped.
    fn assign(&mut self, points: &[u32], triangles: &[u32]) {
        for &p in points {
            if let Some(&t) = triangles
                .iter()
                .find(|&&t| self.height(t, p) > self.tolerance)
            {
                self.triangles[t as usize].outside.push(p);
            }
        }
    }

    /// Step 3: adds eyes until no outside set is left. Each pass takes one point out of the
    /// outside sets for good, hence the bound.
    fn grow(&mut self) {
        let mut seen = Vec::new();
        let mut next_of = vec![NONE; self.scaled.len()];
        for _ in 0..self.scaled.len() {
            let Some(from) = self
                .triangles
                .iter()
                .position(|t| t.alive && !t.outside.is_empty())
            else {
                return;
            };
            let from = from as u32;
            let eye = self.farthest_outside(from);
            seen.clear();
            seen.resize(self.triangles.len(), false);
            let visible = self.visible_from(from, eye, &mut seen);
            let mut horizon = Vec::new();
            for &t in &visible {
                let tri = &self.triangles[t as usize];
                for i in 0..3 {
                    let across = tri.neighbours[i];
                    if !seen[across as usize] {
                        let (a, b) = edge(tri.corners, i);
                        horizon.push((a, b, across));
                    }
                }
            }
            let edges: Vec<(u32, u32)> = horizon.iter().map(|&(a, b, _)| (a, b)).collect();
            if !is_one_loop(&edges, &mut next_of) {
                // Rounding made the visible faces something other than a disc: leave the
                // eye out rather than break the surface.
                self.triangles[from as usize].outside.retain(|&p| p != eye);
                continue;
            }
            self.add_cone(eye, &visible, &horizon, &mut next_of);
        }
    }

    /// The point of triangle `t`'s outside set farthest above it (the lowest index among
    /// equals).
    fn farthest_outside(&self, t: u32) -> u32 {
        let outside = &self.triangles[t as usize].outside;
        let mut best = (outside[0], self.height(t, outside[0]));
        for &p in &outside[1..] {
            let h = self.height(t, p);
            if h > best.1 || (h == best.1 && p < best.0) {
                best = (p, h);
            }
        }
        best.0
    }

    /// The triangles more than ε below `eye`, reached from `from` over such triangles
    /// (depth first, neighbours in edge order); `seen` marks them.
    fn visible_from(&self, from: u32, eye: u32, seen: &mut [bool]) -> Vec<u32> {
        seen[from as usize] = true;
        let mut visible = vec![from];
        let mut stack = vec![from];
        while let Some(t) = stack.pop() {
            for across in self.triangles[t as usize].neighbours {
                if !seen[across as usize] && self.height(across, eye) > self.tolerance {
                    seen[across as usize] = true;
                    visible.push(across);
                    stack.push(across);
                }
            }
        }
        visible
    }

    /// Replaces the `visible` triangles by the cone from `eye` to the `horizon` (edges
    /// (from, to, triangle beyond), one simple loop) and hands their outside points to the
    /// new triangles.
    fn add_cone(
        &mut self,
        eye: u32,
        visible: &[u32],
        horizon: &[(u32, u32, u32)],
        next_of: &mut [u32],
    ) {
        let first_new = self.triangles.len() as u32;
        for &(a, b, _) in horizon {
            let t = self.triangle([a, b, eye]);
            self.triangles.push(t);
        }
        let new: Vec<u32> = (first_new..self.triangles.len() as u32).collect();
        // new[k] starts at horizon[k].0: index them by that point to link the sides.
        for (k, &(a, _, _)) in horizon.iter().enumerate() {
            next_of[a as usize] = new[k];
        }
        for (k, &(a, b, beyond)) in horizon.iter().enumerate() {
            let t = new[k];
            let after = next_of[b as usize];
            self.triangles[t as usize].neighbours[0] = beyond;
            self.triangles[t as usize].neighbours[1] = after;
            self.triangles[after as usize].neighbours[2] = t;
            let outer = &mut self.triangles[beyond as usize];
            if let Some(i) = (0..3).find(|&i| edge(outer.corners, i) == (b, a)) {
                outer.neighbours[i] = t;
            }
        }
        for &(a, _, _) in horizon {
            next_of[a as usize] = NONE;
        }
        let mut orphans = Vec::new();
        for &t in visible {
            let tri = &mut self.triangles[t as usize];
            tri.alive = false;
            orphans.extend(tri.outside.drain(..).filter(|&p| p != eye));
        }
        self.assign(&orphans, &new);
    }

    /// Step 4: groups live triangles into plane faces, then finds the corners. Triangles
    /// are taken largest first (lowest index among equals); each one not yet in a face
    /// starts one, which grows over neighbours whose three corners lie within ε of the
    /// starting triangle's plane. A face whose boundary is not one simple loop falls back to
    /// its separate triangles.
    fn merge(&mut self) {
        let live: Vec<u32> = (0..self.triangles.len() as u32)
            .filter(|&t| self.triangles[t as usize].alive)
            .collect();
        let mut order = live.clone();
        order.sort_by(|&s, &t| {
            let (s_area, t_area) = (
                self.triangles[s as usize].double_area,
                self.triangles[t as usize].double_area,
            );
            t_area.total_cmp(&s_area).then(s.cmp(&t))
        });
        let mut face_of = vec![NONE; self.triangles.len()];
        let mut members: Vec<Vec<u32>> = Vec::new();
        for &seed in &order {
            if face_of[seed as usize] != NONE {
                continue;
            }
            let face = members.len() as u32;
            face_of[seed as usize] = face;
            let mut group = vec![seed];
            let mut k = 0;
            while k < group.len() {
                let t = group[k];
                k += 1;
                for across in self.triangles[t as usize].neighbours {
                    if face_of[across as usize] == NONE
                        && self.triangles[across as usize].alive
                        && self.lies_on(across, seed)
                    {
                        face_of[across as usize] = face;
                        group.push(across);
                    }
                }
            }
            members.push(group);
        }
        let mut next_of = vec![NONE; self.scaled.len()];
        let mut loops = Vec::new();
        for (face, group) in members.iter().enumerate() {
            let boundary = |t: &u32| {
                let tri = &self.triangles[*t as usize];
                (0..3)
                    .filter(|&i| face_of[tri.neighbours[i] as usize] != face as u32)
                    .map(|i| edge(tri.corners, i))
                    .collect::<Vec<_>>()
            };
            let edges: Vec<(u32, u32)> = group.iter().flat_map(boundary).collect();
            if is_one_loop(&edges, &mut next_of) {
                loops.push(loop_from(&edges, &mut next_of));
            } else {
                for &t in group {
                    let tri = &self.triangles[t as usize];
                    let edges: Vec<_> = (0..3).map(|i| edge(tri.corners, i)).collect();
                    loops.push(loop_from(&edges, &mut next_of));
                }
            }
        }
        let mut faces_at = vec![0u32; self.scaled.len()];
        for point in loops.iter().flatten() {
            faces_at[*point as usize] += 1;
        }
        self.corners = (0..self.scaled.len() as u32)
            .filter(|&p| faces_at[p as usize] >= 3)
            .collect();
        self.faces = loops;
    }

    /// Whether the three corners of triangle `t` lie within ε of the plane of `seed`.
    fn lies_on(&self, t: u32, seed: u32) -> bool {
        let seed_tri = &self.triangles[seed as usize];
        seed_tri.normal != Vec3::ZERO
            && self.triangles[t as usize].corners.iter().all(|&p| {
                (seed_tri.normal.dot_fused(self.scaled[p as usize]) - seed_tri.offset).abs()
                    <= self.tolerance
            })
    }

    /// The finished hull, once every point of `points` is a corner: faces rotated to start
    /// at their lowest index and sorted, normals by Newell's rule n ∝ Σ (qᵢ − q₀) × (qᵢ₊₁ − q₀)
    /// in the scaled units, and offset d = max over all vertices of n · v (m): each face's
    /// plane supports the hull, no vertex above it, even where rounding tilts the normal of
    /// a sliver (a face's own vertices then lie a little below its plane).
    fn into_hull(self, points: &[Vec3<R>]) -> ConvexHull<R> {
        let mut loops: Vec<Vec<u32>> = self
            .faces
            .iter()
            .map(|face| {
                let start = (0..face.len()).min_by_key(|&k| face[k]).unwrap_or(0);
                face[start..]
                    .iter()
                    .chain(&face[..start])
                    .copied()
                    .collect()
            })
            .collect();
        loops.sort();
        let mut faces = Vec::with_capacity(loops.len());
        let mut face_vertices = Vec::new();
        let mut edges = Vec::new();
        for face in &loops {
            let q0 = self.scaled[face[0] as usize];
            let area = face.windows(2).skip(1).fold(Vec3::ZERO, |sum, pair| {
                let (qi, qj) = (self.scaled[pair[0] as usize], self.scaled[pair[1] as usize]);
                sum + (qi - q0).cross(qj - q0)
            });
            let normal = careful_unit(area).unwrap_or(Vec3::ZERO);
            let offset = points
                .iter()
                .map(|&p| normal.dot_fused(p))
                .fold(R::MIN, R::max);
            faces.push(HullFace {
                normal,
                offset,
                first: face_vertices.len() as u16,
                count: face.len() as u16,
            });
            for (k, &p) in face.iter().enumerate() {
                face_vertices.push(p as u16);
                let next = face[(k + 1) % face.len()];
                if p < next {
                    edges.push([p as u16, next as u16]);
                }
            }
        }
        edges.sort_unstable();
        ConvexHull {
            vertices: points.to_vec(),
            faces,
            face_vertices,
            edges,
        }
    }
}
