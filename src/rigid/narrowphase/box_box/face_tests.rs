//! Face contacts against the face contact as it was before its clipping passes stopped
//! copying (`reference_face_contact`, kept here as it was, clipping with the former passes
//! of [`reference_rectangle`]): pair by pair on random, resting, stacked, edge and lattice
//! poses, the same manifold (normal, points, separations, ids, order) and the same
//! saturation count.

use super::tests::pair;
use super::{Axes, BoxPair, Choice, Incident, clip_slack, contact, separating_axes};
use crate::math::saturation::count_saturations;
use crate::math::{Fx, Pcg32, Real, Vec3};
use crate::rigid::manifold::{MAX_MANIFOLD_POINTS, Manifold, ManifoldPoint};
use crate::rigid::narrowphase::clip::tests::reference_rectangle;
use crate::rigid::narrowphase::clip::{MAX_CLIPPED, Polygon, four_of};
use crate::rigid::narrowphase::tolerance::side;
use crate::rigid::transform::Transform;

/// `contact` on a face axis as it was (the incident box as `contact` sets it up).
fn reference_contact(pair: &BoxPair<'_, Fx>, axes: &Axes<Fx>, margin: Fx) -> Manifold<Fx> {
    let Axes { c, t, tb, choice } = *axes;
    match choice {
        Choice::Edge { .. } => contact(pair, axes, margin),
        Choice::Face { of_b: true, axis } => {
            let row = |i: usize| Vec3::new(c[i][0], c[i][1], c[i][2]);
            let incident = Incident {
                centre: -Vec3::new(tb[0], tb[1], tb[2]),
                axes: [row(0), row(1), row(2)],
                half: pair.half_a,
            };
            let sign = -side(tb[axis]);
            reference_face_contact(pair.half_b, pair.xf_b, axis, sign, &incident, true, margin)
        }
        Choice::Face { of_b: false, axis } => {
            let column = |j: usize| Vec3::new(c[0][j], c[1][j], c[2][j]);
            let incident = Incident {
                centre: Vec3::new(t[0], t[1], t[2]),
                axes: [column(0), column(1), column(2)],
                half: pair.half_b,
            };
            let sign = side(t[axis]);
            reference_face_contact(pair.half_a, pair.xf_a, axis, sign, &incident, false, margin)
        }
    }
}

/// The face contact as it was.
fn reference_face_contact(
    half: Vec3<Fx>,
    xf: &Transform<Fx>,
    axis: usize,
    sign: Fx,
    incident: &Incident<Fx>,
    reference_is_b: bool,
    margin: Fx,
) -> Manifold<Fx> {
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
    let quad = Polygon::quad([
        centre + e1 + e2,
        centre - e1 + e2,
        centre - e1 - e2,
        centre + e1 - e2,
    ]);
    let h = half.to_array();
    let slack = clip_slack::<Fx>();
    let polygon = reference_rectangle(&quad, (u, h[u]), (w, h[w]), slack);

    let reference_face = 2 * k as u32 + u32::from(sign < Fx::ZERO);
    let incident_face = 2 * j as u32 + u32::from(incident_sign < Fx::ZERO);
    let base = u32::from(reference_is_b) | reference_face << 1 | incident_face << 4;
    let mut positions = [Vec3::ZERO; MAX_CLIPPED];
    let mut separations = [Fx::ZERO; MAX_CLIPPED];
    let mut ids = [0u32; MAX_CLIPPED];
    let mut count = 0;
    let positive = sign > Fx::ZERO;
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
    let mut emit = |index: usize| {
        let mut p = positions[index];
        let half = separations[index] * Fx::HALF;
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

#[test]
fn face_contacts_match_the_former_clipping_pair_by_pair() {
    let mut rng = Pcg32::new(0xface_c11b, 31);
    let mut faces = [0usize; MAX_MANIFOLD_POINTS + 1];
    for trial in 0..60_000 {
        let margin = [Fx::from_ratio(1, 50), Fx::ZERO, Fx::from_ratio(1, 5)][trial % 3];
        let (ha, xa, hb, xb) = pair(&mut rng, [0, 1, 2, 3, 6][trial % 5]);
        let Some(axes) = separating_axes(ha, &xa, hb, &xb, margin) else {
            continue;
        };
        let p = BoxPair {
            half_a: ha,
            xf_a: &xa,
            half_b: hb,
            xf_b: &xb,
        };
        let (expected, reference_saturations) =
            count_saturations(|| reference_contact(&p, &axes, margin));
        let (manifold, saturations) = count_saturations(|| contact(&p, &axes, margin));
        assert_eq!(manifold, expected, "trial {trial}");
        assert_eq!(saturations, reference_saturations, "trial {trial}");
        if matches!(axes.choice, Choice::Face { .. }) {
            faces[manifold.count] += 1;
        }
    }
    // Face contacts of every size are met, most of them with four points.
    assert!(faces.iter().all(|&n| n > 50), "{faces:?}");
    assert!(faces[4] > 5000, "{faces:?}");
}
