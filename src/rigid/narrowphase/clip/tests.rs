//! [`Polygon::clip_to_rectangle`] against the four passes of the clipper as it was before
//! passes that keep every vertex stopped copying (`reference_clip`, kept here verbatim):
//! the same polygon (count, positions' bits, feature codes, outgoing lines) and the same
//! saturation count, on incident faces of random, tilted, resting and exactly stacked
//! boxes, and on polygons near the end of the range.

use super::{ClipVertex, Polygon, crossing};
use crate::math::saturation::count_saturations;
use crate::math::{Fx, Pcg32, Quat, Real, Vec3};

/// The pass as it was: Sutherland–Hodgman writing every kept vertex to `out`.
fn reference_clip(
    polygon: &Polygon<Fx>,
    out: &mut Polygon<Fx>,
    axis: usize,
    upper: bool,
    limit: Fx,
    line: u32,
    slack: Fx,
) {
    out.count = 0;
    let n = polygon.count;
    if n == 0 {
        return;
    }
    let distance = |v: &ClipVertex<Fx>| {
        if upper {
            limit - v.position[axis]
        } else {
            limit + v.position[axis]
        }
    };
    let at = if upper { limit } else { -limit };
    let mut s = polygon.vertices[n - 1];
    let mut ds = distance(&s);
    let mut last_leaves = false;
    for (i, &e) in polygon.vertices[..n].iter().enumerate() {
        let de = distance(&e);
        let s_inside = ds >= -slack;
        if de >= -slack {
            if !s_inside && de > Fx::ZERO {
                out.push(crossing(&s, &e, ds, de, axis, at, line, true));
            }
            out.push(e);
        } else if s_inside {
            if ds > Fx::ZERO {
                out.push(crossing(&s, &e, ds, de, axis, at, line, false));
            } else if i == 0 {
                last_leaves = true;
            } else if out.count > 0 {
                out.vertices[out.count - 1].out_line = line;
            }
        }
        s = e;
        ds = de;
    }
    if last_leaves && out.count > 0 {
        out.vertices[out.count - 1].out_line = line;
    }
}

/// The four passes as `face_contact` made them before.
pub(in crate::rigid::narrowphase) fn reference_rectangle(
    quad: &Polygon<Fx>,
    (u, hu): (usize, Fx),
    (w, hw): (usize, Fx),
    slack: Fx,
) -> Polygon<Fx> {
    let mut polygon = *quad;
    let mut other = Polygon::empty();
    reference_clip(&polygon, &mut other, u, true, hu, 4, slack);
    reference_clip(&other, &mut polygon, u, false, hu, 5, slack);
    reference_clip(&polygon, &mut other, w, true, hw, 6, slack);
    reference_clip(&other, &mut polygon, w, false, hw, 7, slack);
    polygon
}

/// Count, positions (raw bits), feature codes and outgoing lines of the vertices.
fn contents(p: &Polygon<Fx>) -> Vec<([i64; 3], u32, u32)> {
    p.vertices[..p.count]
        .iter()
        .map(|v| {
            let q = v.position;
            (
                [q.x.to_bits(), q.y.to_bits(), q.z.to_bits()],
                v.feature,
                v.out_line,
            )
        })
        .collect()
}

/// A value in [−scale, scale).
fn value(rng: &mut Pcg32, scale: f64) -> Fx // ok-det: test input
{
    rng.range(Fx::from_f64(-scale), Fx::from_f64(scale))
}

/// A value within 80 lattice steps of 2⁻¹² m around `around` (m): exactly on, within and
/// past the slack of a side.
fn lattice(rng: &mut Pcg32, around: Fx) -> Fx {
    around + Fx::from_ratio(rng.below(161) as i64 - 80, 4096)
}

/// `v` with component `axis` set to `x`.
fn with(mut v: Vec3<Fx>, axis: usize, x: Fx) -> Vec3<Fx> {
    match axis {
        0 => v.x = x,
        1 => v.y = x,
        _ => v.z = x,
    }
    v
}

/// An incident face and the reference rectangle's axes and half sizes, of kind 0 a random
/// box in a cube around the face, 1 a box resting on it tilted by up to 0.05 rad, 2 an
/// equal box stacked axis-aligned with corners on the 2⁻¹² m lattice around the sides
/// (corners level with a side, within the slack and past it), 3 within 8 m of the end of the range, where the
/// positions and distances saturate.
#[allow(clippy::type_complexity)]
fn case(rng: &mut Pcg32, kind: u32) -> (Polygon<Fx>, (usize, Fx), (usize, Fx)) {
    let k = rng.below(3) as usize;
    let (u, w) = ((k + 1) % 3, (k + 2) % 3);
    let half = |rng: &mut Pcg32| rng.range(Fx::from_f64(0.05), Fx::from_f64(1.5));
    let (hu, hw) = (half(rng), half(rng));
    let (centre, e1, e2) = match kind {
        0 | 1 => {
            let angle = if kind == 0 { 3.2 } else { 0.05 };
            let rotation = Quat::from_axis_angle(rng.unit_vector(), value(rng, angle)).to_mat3();
            let reach = (hu + hw).to_f64() + 1.0;
            let centre = Vec3::new(value(rng, reach), value(rng, reach), value(rng, reach));
            let (a, b) = (half(rng), half(rng));
            let (j1, j2) = (rng.below(3) as usize, rng.below(2) as usize);
            let j2 = if j2 >= j1 { j2 + 1 } else { j2 };
            (centre, rotation.cols[j1] * a, rotation.cols[j2] * b)
        }
        2 => {
            let lattice_half = |rng: &mut Pcg32| Fx::from_ratio(1 + rng.below(8) as i64, 4);
            let (a, b) = (lattice_half(rng), lattice_half(rng));
            let sides = [Fx::ONE, -Fx::ONE];
            let (su, sw) = (sides[rng.below(2) as usize], sides[rng.below(2) as usize]);
            let (cu, cw) = (lattice(rng, hu - a) * su, lattice(rng, hw - b) * sw);
            let centre = with(with(Vec3::ZERO, u, cu), w, cw);
            (centre, with(Vec3::ZERO, u, a), with(Vec3::ZERO, w, b))
        }
        _ => {
            let far = Fx::from_f64(2_147_483_640.0);
            let offset = Vec3::new(value(rng, 8.0), value(rng, 8.0), value(rng, 8.0));
            let sign = if rng.below(2) == 0 { Fx::ONE } else { -Fx::ONE };
            let centre = Vec3::new(far, far, far) * sign + offset;
            (centre, rng.unit_vector::<Fx>(), rng.unit_vector::<Fx>())
        }
    };
    let quad = Polygon::quad([
        centre + e1 + e2,
        centre - e1 + e2,
        centre - e1 - e2,
        centre + e1 - e2,
    ]);
    (quad, (u, hu), (w, hw))
}

#[test]
fn rectangle_clip_matches_the_reference_pass_by_pass() {
    let slack = Fx::from_ratio(1, 1 << 12);
    let mut rng = Pcg32::new(0x0c11_9e0f_1a7e, 29);
    let mut shapes = [0usize; super::MAX_CLIPPED + 1];
    let mut saturated = 0;
    for trial in 0..200_000 {
        let kind = trial % 4;
        let (quad, (u, hu), (w, hw)) = case(&mut rng, kind);
        let (expected, reference_saturations) =
            count_saturations(|| reference_rectangle(&quad, (u, hu), (w, hw), slack));
        let (clipped, saturations) = count_saturations(|| {
            let mut polygon = quad;
            let mut spare = Polygon::empty();
            *polygon.clip_to_rectangle(&mut spare, (u, hu), (w, hw), slack)
        });
        assert_eq!(contents(&clipped), contents(&expected), "trial {trial}");
        assert_eq!(saturations, reference_saturations, "trial {trial}");
        shapes[clipped.count] += 1;
        saturated += usize::from(saturations > 0);
    }
    // Every outcome is met: nothing left, the quad untouched, and clipped shapes.
    assert!(
        shapes[0] > 1000 && shapes[4] > 1000 && shapes[5] > 100,
        "{shapes:?}"
    );
    assert!(saturated > 100, "{saturated}");
}
