//! Box against box: separating axes (3 + 3 face normals, 9 edge cross products, in
//! `axes.rs`, and eight pairs at a time in `kernel.rs`), then a clipped reference face, or
//! one point between two edges. A face contact's points go to the world frame four at a
//! time (`world_points.rs`).

mod axes;
#[cfg(test)]
mod face_tests;
#[cfg(vector_kernels)]
mod kernel;
#[cfg(test)]
mod tests;
mod world_points;

pub(crate) use axes::{Axes, Choice, separating_axes};

use super::clip::{MAX_CLIPPED, Polygon, four_of};
use super::segments::{Segment, closest_parameters};
use super::tolerance::{side, unit};
use crate::math::{Real, Vec3};
use crate::rigid::manifold::{MAX_MANIFOLD_POINTS, Manifold, ManifoldPoint};
use crate::rigid::solver::LANES;
use crate::rigid::transform::Transform;

/// Id bit of an edge–edge point; face points use bits 0–12.
const EDGE_ID: u32 = 1 << 13;

/// One box–box pair of a batch: A's half extents (m) and placement, and B's.
#[derive(Clone, Copy)]
pub(crate) struct BoxPair<'a, R: Real> {
    pub half_a: Vec3<R>,
    pub xf_a: &'a Transform<R>,
    pub half_b: Vec3<R>,
    pub xf_b: &'a Transform<R>,
}

/// The contact of box A (half extents `half_a`, m, placed by `xf_a`) with box B: the
/// [separating-axis test](separating_axes), then [`contact`].
pub(super) fn box_box<R: Real>(
    half_a: Vec3<R>,
    xf_a: &Transform<R>,
    half_b: Vec3<R>,
    xf_b: &Transform<R>,
    margin: R,
) -> Manifold<R> {
    let pair = BoxPair {
        half_a,
        xf_a,
        half_b,
        xf_b,
    };
    separating_axes(half_a, xf_a, half_b, xf_b, margin)
        .map_or(Manifold::EMPTY, |axes| contact(&pair, &axes, margin))
}

/// The separating-axis tests of up to [`LANES`] pairs, in order: lane l is what
/// [`separating_axes`] gives for `pairs[l]`, bit for bit (lanes past the pairs are `None`).
///
/// On I32F32 the pairs go to a kernel together when the processor has AVX-512 or AVX2;
/// the lanes it leaves (values past its bound) are tested one by one.
pub(crate) fn separating_axes_batch<R: Real>(
    pairs: &[BoxPair<'_, R>],
    margin: R,
) -> [Option<Axes<R>>; LANES] {
    let mut out = [None; LANES];
    #[cfg(vector_kernels)]
    let done = kernel::separating_axes_lanes(pairs, margin, &mut out);
    #[cfg(not(vector_kernels))]
    let done = 0u8;
    for (l, pair) in pairs.iter().enumerate().take(LANES) {
        if done & (1 << l) == 0 {
            out[l] = separating_axes(pair.half_a, pair.xf_a, pair.half_b, pair.xf_b, margin);
        }
    }
    out
}

/// The contact of a pair that the separating-axis test did not separate, on the axis it
/// chose:
///
/// **Face contact** ([`face_contact`]): the incident face of the other box is clipped
/// against the reference face's four side planes; points within the margin remain, and
/// more than four are reduced to four ([`four_of`]).
///
/// **Edge contact** ([`edge_contact`]): one point midway between the closest points of
/// the two edges.
pub(crate) fn contact<R: Real>(pair: &BoxPair<'_, R>, axes: &Axes<R>, margin: R) -> Manifold<R> {
    let BoxPair {
        half_a,
        xf_a,
        half_b,
        xf_b,
    } = *pair;
    let Axes { c, t, tb, choice } = *axes;
    match choice {
        Choice::Edge { i, j } => edge_contact(half_a, xf_a, half_b, xf_b, i, j, margin),
        Choice::Face { of_b: true, axis } => {
            // Reference B: A's centre is −tb in B's frame, A's axis i is row i of C.
            let row = |i: usize| Vec3::new(c[i][0], c[i][1], c[i][2]);
            let incident = Incident {
                centre: -Vec3::new(tb[0], tb[1], tb[2]),
                axes: [row(0), row(1), row(2)],
                half: half_a,
            };
            let sign = -side(tb[axis]);
            face_contact(half_b, xf_b, axis, sign, &incident, true, margin)
        }
        Choice::Face { of_b: false, axis } => {
            // Reference A: B's centre is t in A's frame, B's axis j is column j of C.
            let column = |j: usize| Vec3::new(c[0][j], c[1][j], c[2][j]);
            let incident = Incident {
                centre: Vec3::new(t[0], t[1], t[2]),
                axes: [column(0), column(1), column(2)],
                half: half_b,
            };
            let sign = side(t[axis]);
            face_contact(half_a, xf_a, axis, sign, &incident, false, margin)
        }
    }
}

/// The incident box as seen from the reference box's frame.
struct Incident<R: Real> {
    /// Centre, m.
    centre: Vec3<R>,
    /// Unit axes.
    axes: [Vec3<R>; 3],
    /// Half extents, m.
    half: Vec3<R>,
}

/// How far (m) an incident corner may lie beyond a side of the reference face and still be
/// kept as it is (2⁻¹² m ≈ 0.24 mm): a corner level with a side (boxes of equal size
/// stacked) then stays one corner with one id while it jitters, rather than alternating
/// with a clipped point.
#[inline(always)]
fn clip_slack<R: Real>() -> R {
    R::from_ratio(1, 1 << 12)
}

/// The face contact on reference face (`axis`, `sign`) of the reference box (half extents
/// `half`, placed by `xf`): outward normal σ e_k in its frame.
///
/// The incident face is the face of the other box whose outward normal is most opposed to
/// the reference normal (the largest |axis_j · e_k|, lowest j on ties). Its four corners,
/// in the reference frame, are clipped against |x_u| ≤ h_u and |x_w| ≤ h_w (u, w the face's
/// tangent axes; corners up to [`clip_slack`] beyond a side are kept); each vertex x has
/// separation σ x_k − h_k and is kept within the margin. Points are moved half their
/// separation towards the reference face (midway between the surfaces).
///
/// Id: bit 0 the reference box (0 A, 1 B), bits 1–3 the reference face (2k, or 2k + 1 for
/// the − face), bits 4–6 the incident face, bits 7–12 the vertex's feature code (the pair
/// of incident edges or reference sides that meet there, see
/// [`pair_code`](super::clip::pair_code)).
fn face_contact<R: Real>(
    half: Vec3<R>,
    xf: &Transform<R>,
    axis: usize,
    sign: R,
    incident: &Incident<R>,
    reference_is_b: bool,
    margin: R,
) -> Manifold<R> {
    let k = axis;
    let (u, w) = ((k + 1) % 3, (k + 2) % 3);
    let ax = &incident.axes;
    let j = if ax[0][k].abs() >= ax[1][k].abs() && ax[0][k].abs() >= ax[2][k].abs() {
        0
    } else if ax[1][k].abs() >= ax[2][k].abs() {
        1
    } else {
        2
    };
    let incident_sign = -side(sign * ax[j][k]);
    let (j1, j2) = ((j + 1) % 3, (j + 2) % 3);
    let hi = incident.half.to_array();
    let centre = incident.centre + ax[j] * (incident_sign * hi[j]);
    let e1 = ax[j1] * hi[j1];
    let e2 = ax[j2] * hi[j2];
    let mut polygon = Polygon::quad([
        centre + e1 + e2,
        centre - e1 + e2,
        centre - e1 - e2,
        centre + e1 - e2,
    ]);
    let h = half.to_array();
    let slack = clip_slack::<R>();
    let mut spare = Polygon::empty();
    let polygon = polygon.clip_to_rectangle(&mut spare, (u, h[u]), (w, h[w]), slack);

    let reference_face = 2 * k as u32 + u32::from(sign < R::ZERO);
    let incident_face = 2 * j as u32 + u32::from(incident_sign < R::ZERO);
    let base = u32::from(reference_is_b) | reference_face << 1 | incident_face << 4;
    let mut positions = [Vec3::ZERO; MAX_CLIPPED];
    let mut separations = [R::ZERO; MAX_CLIPPED];
    let mut ids = [0u32; MAX_CLIPPED];
    let mut count = 0;
    let positive = sign > R::ZERO;
    for v in &polygon.vertices[..polygon.count] {
        let height = v.position[k];
        let separation = if positive { height } else { -height } - h[k];
        if separation <= margin {
            positions[count] = v.position;
            separations[count] = separation;
            ids[count] = base | v.feature << 7;
            count += 1;
        }
    }

    let outward = xf.rotation.cols[k] * sign;
    let mut manifold = Manifold {
        normal: if reference_is_b { -outward } else { outward },
        ..Manifold::EMPTY
    };
    let chosen = if count <= MAX_MANIFOLD_POINTS {
        [0, 1, 2, 3]
    } else {
        four_of(
            &positions[..count],
            &separations[..count],
            &ids[..count],
            slack,
            u,
            w,
        )
    };
    let count = count.min(MAX_MANIFOLD_POINTS);
    let mut local = [Vec3::ZERO; MAX_MANIFOLD_POINTS];
    for (p, &index) in local.iter_mut().zip(&chosen).take(count) {
        *p = positions[index];
        let half = separations[index] * R::HALF;
        let shift = if positive { half } else { -half };
        match k {
            0 => p.x -= shift,
            1 => p.y -= shift,
            _ => p.z -= shift,
        }
    }
    let world = world_points::to_world(xf, &local, count);
    for (&point, &index) in world.iter().zip(&chosen).take(count) {
        manifold.push(ManifoldPoint {
            point,
            separation: separations[index],
            id: ids[index],
        });
    }
    manifold
}

/// The index of the box edge along axis `k` on the side (s_k1, s_k2) of the other two
/// axes: 4k + \[s_k1 > 0\] + 2 \[s_k2 > 0\], 0–11.
#[inline]
fn edge_index<R: Real>(k: usize, sides: [R; 3]) -> u32 {
    let (k1, k2) = ((k + 1) % 3, (k + 2) % 3);
    4 * k as u32 + u32::from(sides[k1] > R::ZERO) + 2 * u32::from(sides[k2] > R::ZERO)
}

/// The edge–edge contact on the axis a_i × b_j: the normal n = unit(a_i × b_j) turned
/// from A towards B, A's edge along a_i on the side of A facing +n (the corner offsets
/// ±hA_m a_m with sign(n·a_m), m ≠ i), B's edge along b_j on the side facing −n, and one
/// point midway between their closest points, with separation (p_B − p_A)·n. Empty when
/// that is beyond the margin. Id: [`EDGE_ID`] | A's edge index << 4 | B's edge index.
fn edge_contact<R: Real>(
    half_a: Vec3<R>,
    xf_a: &Transform<R>,
    half_b: Vec3<R>,
    xf_b: &Transform<R>,
    i: usize,
    j: usize,
    margin: R,
) -> Manifold<R> {
    let a = xf_a.rotation.cols;
    let b = xf_b.rotation.cols;
    let d = xf_b.translation - xf_a.translation;
    let Some((mut n, _)) = unit(a[i].cross(b[j])) else {
        return Manifold::EMPTY;
    };
    if n.dot(d) < R::ZERO {
        n = -n;
    }
    let sides_a = [side(n.dot(a[0])), side(n.dot(a[1])), side(n.dot(a[2]))];
    let sides_b = [side(-n.dot(b[0])), side(-n.dot(b[1])), side(-n.dot(b[2]))];
    let (ha, hb) = (half_a.to_array(), half_b.to_array());
    let mut centre_a = xf_a.translation;
    let mut centre_b = xf_b.translation;
    for m in 0..3 {
        if m != i {
            centre_a += a[m] * (sides_a[m] * ha[m]);
        }
        if m != j {
            centre_b += b[m] * (sides_b[m] * hb[m]);
        }
    }
    let edge_a = Segment {
        centre: centre_a,
        axis: a[i],
        half_length: ha[i],
    };
    let edge_b = Segment {
        centre: centre_b,
        axis: b[j],
        half_length: hb[j],
    };
    let (s, t) = closest_parameters(&edge_a, &edge_b);
    let (pa, pb) = (edge_a.at(s), edge_b.at(t));
    let separation = (pb - pa).dot(n);
    if separation > margin {
        return Manifold::EMPTY;
    }
    let mut manifold = Manifold {
        normal: n,
        ..Manifold::EMPTY
    };
    manifold.push(ManifoldPoint {
        point: (pa + pb) * R::HALF,
        separation,
        id: EDGE_ID | edge_index(i, sides_a) << 4 | edge_index(j, sides_b),
    });
    manifold
}
