//! The separating-axis test of two boxes, one pair at a time: which axis separates them,
//! or which face or pair of edges the contact is built on.

use crate::math::{Real, Vec3};
use crate::rigid::narrowphase::tolerance::parallel_sine_squared;
use crate::rigid::transform::Transform;

/// The axis a contact of two boxes that do not separate is built on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Choice {
    /// Face `axis` of B (`of_b`) or of A is the reference face.
    Face { of_b: bool, axis: usize },
    /// The edge axis a_i × b_j.
    Edge { i: usize, j: usize },
}

/// What the separating-axis test of a pair that does not separate leaves to the contact:
/// C = R_Aᵀ R_B, t = R_Aᵀ (c_B − c_A), t_B = Cᵀ t, and the chosen axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Axes<R: Real> {
    /// C_ij = a_i·b_j.
    pub c: [[R; 3]; 3],
    /// B's centre in A's frame, m.
    pub t: [R; 3],
    /// The same offset along B's axes, (t_B)_j = Σ_i t_i C_ij, m.
    pub tb: [R; 3],
    /// The axis the contact is built on.
    pub choice: Choice,
}

/// A face axis: which box (false A, true B), the axis index and its separation (m).
#[derive(Clone, Copy)]
struct FaceAxis<R: Real> {
    of_b: bool,
    axis: usize,
    separation: R,
}

/// The separating-axis test of box A (half extents `half_a`, m, placed by `xf_a`) with box
/// B: `None` when an axis separates them by more than `margin`.
///
/// With d = c_B − c_A, t = R_Aᵀ d (B's centre in A's frame) and C = R_Aᵀ R_B (C_ij =
/// a_i·b_j), the separation along A's face axis i is |t_i| − (hA_i + Σ_j hB_j |C_ij|), along
/// B's axis j |d·b_j| − (hB_j + Σ_i hA_i |C_ij|), and along a_i × b_j (Ericson, *Real-Time
/// Collision Detection*, 4.4.1) it is (|t·L| − rA − rB)/|L| with |L|² = C_i1j² + C_i2j² (i1,
/// i2 the other two axes of A). The first axis separated by more than `margin` ends the
/// test; rows of C are computed as A's face axes need them, so a pair separated along A's
/// first axis needs one. Edge axes within a sine of 2⁻¹⁰ of parallel are skipped (the face
/// axes cover them), and edge axes are compared by their squares, without square roots
/// (see [`ratio_greater`]). The deepest face axis of B is preferred to A's only when deeper
/// by more than 2⁻¹¹ m, and an edge axis to the chosen face only when deeper by more than
/// 2⁻¹⁰ m + 1/16 of the face's overlap, so that resting boxes keep the same reference face
/// from step to step.
pub(crate) fn separating_axes<R: Real>(
    half_a: Vec3<R>,
    xf_a: &Transform<R>,
    half_b: Vec3<R>,
    xf_b: &Transform<R>,
    margin: R,
) -> Option<Axes<R>> {
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
            return None;
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
            return None;
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
                return None;
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
    let choice = match edge {
        Some((i, j, _, _)) => Choice::Edge { i, j },
        None => Choice::Face {
            of_b: face.of_b,
            axis: face.axis,
        },
    };
    Some(Axes { c, t, tb, choice })
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
