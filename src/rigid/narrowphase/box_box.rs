//! Box against box: separating axes (3 + 3 face normals, 9 edge cross products), then a
//! clipped reference face, or one point between two edges.

use super::clip::{MAX_CLIPPED, Polygon, four_of};
use super::segments::{Segment, closest_parameters};
use super::tolerance::{parallel_sine_squared, side, unit};
use crate::math::{Real, Vec3};
use crate::rigid::manifold::{MAX_MANIFOLD_POINTS, Manifold, ManifoldPoint};
use crate::rigid::transform::Transform;

/// Id bit of an edge–edge point; face points use bits 0–12.
const EDGE_ID: u32 = 1 << 13;

/// A face axis: which box (false A, true B), the axis index and its separation (m).
#[derive(Clone, Copy)]
struct FaceAxis<R: Real> {
    of_b: bool,
    axis: usize,
    separation: R,
}

/// The contact of box A (half extents `half_a`, m, placed by `xf_a`) with box B.
///
/// **Separating axes.** With d = c_B − c_A, t = R_Aᵀ d (B's centre in A's frame) and
/// C = R_Aᵀ R_B (C_ij = a_i·b_j), the separation along A's face axis i is
/// |t_i| − (hA_i + Σ_j hB_j |C_ij|), along B's axis j |d·b_j| − (hB_j + Σ_i hA_i |C_ij|), and
/// along a_i × b_j (Ericson, *Real-Time Collision Detection*, 4.4.1) it is
/// (|t·L| − rA − rB)/|L| with |L|² = C_i1j² + C_i2j² (i1, i2 the other two axes of A). The
/// first axis separated by more than `margin` returns an empty manifold; rows of C are
/// computed as A's face axes need them, so a pair separated along A's first axis needs
/// one. Edge axes within a sine of 2⁻¹⁰ of parallel are skipped (the face axes cover
/// them), and edge axes are compared by their squares, without square roots (see
/// [`ratio_greater`]). The deepest face axis of B is preferred to A's only when deeper by
/// more than 2⁻¹¹ m, and an edge axis to the chosen face only when deeper by more than
/// 2⁻¹⁰ m + 1/16 of the face's overlap, so that resting boxes keep the same reference face
/// from step to step.
///
/// **Face contact** ([`face_contact`]): the incident face of the other box is clipped
/// against the reference face's four side planes; points within the margin remain, and
/// more than four are reduced to four ([`four_of`]).
///
/// **Edge contact** ([`edge_contact`]): one point midway between the closest points of
/// the two edges.
pub(super) fn box_box<R: Real>(
    half_a: Vec3<R>,
    xf_a: &Transform<R>,
    half_b: Vec3<R>,
    xf_b: &Transform<R>,
    margin: R,
) -> Manifold<R> {
    let a = xf_a.rotation.cols;
    let b = xf_b.rotation.cols;
    let ha = half_a.to_array();
    let hb = half_b.to_array();
    let d = xf_b.translation - xf_a.translation;
    let t = [a[0].dot(d), a[1].dot(d), a[2].dot(d)];
    let mut c = [[R::ZERO; 3]; 3];
    let mut abs = [[R::ZERO; 3]; 3];

    // A's face axes, computing row i of C only when it is needed.
    let mut face_a = FaceAxis {
        of_b: false,
        axis: 0,
        separation: R::MIN,
    };
    for i in 0..3 {
        for j in 0..3 {
            c[i][j] = a[i].dot(b[j]);
            abs[i][j] = c[i][j].abs();
        }
        let reach = ha[i] + hb[0] * abs[i][0] + hb[1] * abs[i][1] + hb[2] * abs[i][2];
        let separation = t[i].abs() - reach;
        if separation > margin {
            return Manifold::EMPTY;
        }
        if separation > face_a.separation {
            face_a = FaceAxis {
                of_b: false,
                axis: i,
                separation,
            };
        }
    }
    let mut face_b = FaceAxis {
        of_b: true,
        axis: 0,
        separation: R::MIN,
    };
    let mut tb = [R::ZERO; 3];
    for j in 0..3 {
        tb[j] = t[0] * c[0][j] + t[1] * c[1][j] + t[2] * c[2][j];
        let reach = hb[j] + ha[0] * abs[0][j] + ha[1] * abs[1][j] + ha[2] * abs[2][j];
        let separation = tb[j].abs() - reach;
        if separation > margin {
            return Manifold::EMPTY;
        }
        if separation > face_b.separation {
            face_b = FaceAxis {
                of_b: true,
                axis: j,
                separation,
            };
        }
    }
    let face = if face_b.separation > face_a.separation + R::from_ratio(1, 1 << 11) {
        face_b
    } else {
        face_a
    };

    // Edge axes. An edge axis is kept only if its separation s/|L| exceeds the face's by
    // the bias; among those the largest wins. (i, j, s, |L|²) of the best so far.
    let threshold =
        face.separation + R::from_ratio(1, 1 << 10) + face.separation.abs() * R::from_ratio(1, 16);
    let threshold_squared = threshold * threshold;
    let parallel = parallel_sine_squared::<R>();
    let margin_squared = margin * margin;
    let mut square = [[R::ZERO; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            square[i][j] = c[i][j] * c[i][j];
        }
    }
    let mut edge: Option<(usize, usize, R, R)> = None;
    for i in 0..3 {
        let (i1, i2) = ((i + 1) % 3, (i + 2) % 3);
        for j in 0..3 {
            let (j1, j2) = ((j + 1) % 3, (j + 2) % 3);
            let length_squared = square[i1][j] + square[i2][j];
            if length_squared <= parallel {
                continue;
            }
            let ra = ha[i1] * abs[i2][j] + ha[i2] * abs[i1][j];
            let rb = hb[j1] * abs[i][j2] + hb[j2] * abs[i][j1];
            let separation = (t[i2] * c[i1][j] - t[i1] * c[i2][j]).abs() - (ra + rb);
            if separation > R::ZERO && separation * separation > margin_squared * length_squared {
                return Manifold::EMPTY;
            }
            let beats_face = match (separation >= R::ZERO, threshold >= R::ZERO) {
                (true, false) => true,
                (false, true) => false,
                (true, true) => separation * separation > threshold_squared * length_squared,
                (false, false) => separation * separation < threshold_squared * length_squared,
            };
            if beats_face
                && edge.is_none_or(|(_, _, s, l)| ratio_greater(separation, length_squared, s, l))
            {
                edge = Some((i, j, separation, length_squared));
            }
        }
    }
    if let Some((i, j, _, _)) = edge {
        return edge_contact(half_a, xf_a, half_b, xf_b, i, j, margin);
    }
    if face.of_b {
        // Reference B: A's centre is −tb in B's frame, A's axis i is row i of C.
        let row = |i: usize| Vec3::new(c[i][0], c[i][1], c[i][2]);
        let incident = Incident {
            centre: -Vec3::new(tb[0], tb[1], tb[2]),
            axes: [row(0), row(1), row(2)],
            half: half_a,
        };
        let sign = -side(tb[face.axis]);
        face_contact(half_b, xf_b, face.axis, sign, &incident, true, margin)
    } else {
        // Reference A: B's centre is t in A's frame, B's axis j is column j of C.
        let column = |j: usize| Vec3::new(c[0][j], c[1][j], c[2][j]);
        let incident = Incident {
            centre: Vec3::new(t[0], t[1], t[2]),
            axes: [column(0), column(1), column(2)],
            half: half_b,
        };
        let sign = side(t[face.axis]);
        face_contact(half_a, xf_a, face.axis, sign, &incident, false, margin)
    }
}

/// Whether s1/√l1 > s2/√l2 (l1, l2 > 0), without square roots: by the signs of s1 and
/// s2, and otherwise by comparing s1² l2 with s2² l1 (reversed when both are negative).
#[inline]
fn ratio_greater<R: Real>(s1: R, l1: R, s2: R, l2: R) -> bool {
    match (s1 >= R::ZERO, s2 >= R::ZERO) {
        (true, false) => true,
        (false, true) => false,
        (true, true) => s1 * s1 * l2 > s2 * s2 * l1,
        (false, false) => s1 * s1 * l2 < s2 * s2 * l1,
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
    let mut other = Polygon::empty();
    polygon.clip(&mut other, u, true, h[u], 4, slack);
    other.clip(&mut polygon, u, false, h[u], 5, slack);
    polygon.clip(&mut other, w, true, h[w], 6, slack);
    other.clip(&mut polygon, w, false, h[w], 7, slack);

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
            ids[count] = base | u32::from(v.feature) << 7;
            count += 1;
        }
    }

    let outward = xf.rotation.cols[k] * sign;
    let mut manifold = Manifold {
        normal: if reference_is_b { -outward } else { outward },
        ..Manifold::EMPTY
    };
    let mut emit = |index: usize| {
        let mut p = positions[index];
        let half = separations[index] * R::HALF;
        let shift = if positive { half } else { -half };
        match k {
            0 => p.x -= shift,
            1 => p.y -= shift,
            _ => p.z -= shift,
        }
        manifold.push(ManifoldPoint {
            point: xf.point(p),
            separation: separations[index],
            id: ids[index],
        });
    };
    if count <= MAX_MANIFOLD_POINTS {
        (0..count).for_each(&mut emit);
    } else {
        four_of(
            &positions[..count],
            &separations[..count],
            &ids[..count],
            slack,
            u,
            w,
        )
        .into_iter()
        .for_each(&mut emit);
    }
    manifold
}

/// The index of the box edge along axis `k` on the side (s_k1, s_k2) of the other two
/// axes: 4k + [s_k1 > 0] + 2 [s_k2 > 0], 0–11.
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
