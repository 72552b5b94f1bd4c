//! Supporting features of a convex core along a direction: the face, edge or vertex that a
//! contact along that direction touches, as a polygon of 1 to [`MAX_FACE_POINTS`] points
//! in the world frame, each with a feature id of the shape.
//!
//! - point: the point (id 0); segment: both ends (ids 0, 1) when the direction is within
//!   the flat sine (1/4, see [`flat_sine_squared`]) of perpendicular to it, else the end;
//! - box: the face whose normal is nearest the direction (4 corners, id = corner index, bit
//!   k for the +h side of axis k);
//! - hull: the face whose normal is nearest the direction (its vertices, id = vertex index);
//!   a face of more than [`MAX_FACE_POINTS`] vertices gives its support vertex;
//! - cylinder: the cap as a regular octagon inscribed in its rim (ids 16 + k, + 8 for the
//!   top) when the direction is within the flat sine (1/4, see [`flat_sine_squared`]) of the axis; the side segment at the
//!   rim direction (ids 64 + 2 × octant + end) when within it of perpendicular; else the
//!   support point on the rim (id 64 + 2 × octant + end);
//! - cone: the base octagon (ids 16 + k) when the direction is within the flat sine (1/4, see [`flat_sine_squared`]) of −y,
//!   the side segment apex–rim (ids 1 and 64 + 2 × octant) when within it of the side's
//!   normal, else the support point (apex 1, rim 64 + 2 × octant).
//! - triangle: the whole triangle (ids 0, 1, 2, the corners) when the direction is within
//!   the flat sine of ±its normal; else the edge from the support corner that the direction
//!   is within the flat sine of perpendicular to (the nearer to perpendicular of the two),
//!   else the support corner.
//!
//! Polygons of 3 or more points are counter-clockwise seen from outside and come with the
//! face's outward unit normal.

use crate::math::{Real, Vec3};
use crate::rigid::convex::Convex;
use crate::rigid::transform::Transform;

/// Most points of a supporting face.
pub(super) const MAX_FACE_POINTS: usize = 32;

/// Sine of the angle (1/4, about 14.5°) within which a direction counts as along a cap's
/// axis or across a side: the face is then reported whole and each of its points gets its
/// own separation, so a tilted face still gets the right depths.
fn flat_sine_squared<R: Real>() -> R {
    R::from_ratio(1, 16)
}

/// A supporting feature: 1 point (vertex), 2 (edge) or more (face, counter-clockwise from
/// outside, with `normal`).
#[derive(Clone, Copy, Debug)]
pub(super) struct Feature<R: Real> {
    /// The points, world frame, m.
    pub points: [Vec3<R>; MAX_FACE_POINTS],
    /// Their feature ids.
    pub ids: [u32; MAX_FACE_POINTS],
    /// Number of points.
    pub count: usize,
    /// Outward unit normal of a face (3 or more points), world frame.
    pub normal: Vec3<R>,
}

impl<R: Real> Feature<R> {
    fn empty() -> Self {
        Self {
            points: [Vec3::ZERO; MAX_FACE_POINTS],
            ids: [0; MAX_FACE_POINTS],
            count: 0,
            normal: Vec3::ZERO,
        }
    }

    fn push(&mut self, point: Vec3<R>, id: u32) {
        if self.count < MAX_FACE_POINTS {
            self.points[self.count] = point;
            self.ids[self.count] = id;
            self.count += 1;
        }
    }

    /// The meaningful points.
    pub fn points(&self) -> &[Vec3<R>] {
        &self.points[..self.count]
    }
}

/// The supporting feature of `core` placed by `xf` along the world `direction` (unit).
pub(super) fn supporting_feature<R: Real>(
    core: &Convex<R>,
    xf: &Transform<R>,
    direction: Vec3<R>,
) -> Feature<R> {
    let d = xf.inverse_vector(direction);
    let mut local = Feature::empty();
    let across = d.x * d.x + d.z * d.z;
    let along = d.y * d.y;
    let near_axis = across <= flat_sine_squared::<R>() * (across + along);
    let near_perpendicular = along <= flat_sine_squared::<R>() * (across + along);
    match *core {
        Convex::Point => local.push(Vec3::ZERO, 0),
        Convex::Segment { half_height } => {
            let end = |s: R| Vec3::new(R::ZERO, s, R::ZERO);
            if near_perpendicular {
                local.push(end(-half_height), 0);
                local.push(end(half_height), 1);
            } else if d.y >= R::ZERO {
                local.push(end(half_height), 1);
            } else {
                local.push(end(-half_height), 0);
            }
        }
        Convex::Cuboid { half_extents } => box_face(&mut local, half_extents, d),
        Convex::Hull(hull) => {
            let mut best = 0;
            for (f, face) in hull.faces.iter().enumerate() {
                if face.normal.dot(d) > hull.faces[best].normal.dot(d) {
                    best = f;
                }
            }
            let face = &hull.faces[best];
            let indices = hull.face_indices(face);
            if indices.len() <= MAX_FACE_POINTS {
                for &i in indices {
                    local.push(hull.vertices[usize::from(i)], u32::from(i));
                }
                local.normal = face.normal;
            } else {
                let i = hull.support_index(d);
                local.push(hull.vertices[i], i as u32);
            }
        }
        Convex::Cylinder {
            radius,
            half_height,
        } => {
            let top = d.y >= R::ZERO;
            let y = if top { half_height } else { -half_height };
            if near_axis {
                octagon(&mut local, radius, y, 16 + if top { 8 } else { 0 });
                local.normal = Vec3::new(R::ZERO, if top { R::ONE } else { -R::ONE }, R::ZERO);
            } else {
                let (rim, octant) = rim_point(d, radius);
                let id = 64 + 2 * octant;
                if near_perpendicular {
                    local.push(Vec3::new(rim.x, -half_height, rim.z), id);
                    local.push(Vec3::new(rim.x, half_height, rim.z), id + 1);
                } else {
                    local.push(Vec3::new(rim.x, y, rim.z), id + u32::from(top));
                }
            }
        }
        Convex::Cone {
            radius,
            half_height,
        } => cone_feature(&mut local, radius, half_height, d, near_axis),
        Convex::Triangle { corners, normal } => triangle_feature(&mut local, &corners, normal, d),
    }
    if local.count >= 3 {
        orient(&mut local);
    }
    let mut world = local;
    for p in &mut world.points[..world.count] {
        *p = xf.point(*p);
    }
    world.normal = xf.vector(local.normal);
    world
}

/// The box face whose outward normal ±e_k has the largest d_k in magnitude (the lowest k
/// on ties), its corners pushed with ids bit j = +h side of axis j.
fn box_face<R: Real>(out: &mut Feature<R>, h: Vec3<R>, d: Vec3<R>) {
    let a = d.abs();
    let k = if a.x >= a.y && a.x >= a.z {
        0
    } else if a.y >= a.z {
        1
    } else {
        2
    };
    let positive = d[k] >= R::ZERO;
    let (u, w) = ((k + 1) % 3, (k + 2) % 3);
    for (su, sw) in [(false, false), (true, false), (true, true), (false, true)] {
        let mut id = 0u32;
        let mut corner = [R::ZERO; 3];
        for (axis, plus) in [(k, positive), (u, su), (w, sw)] {
            corner[axis] = if plus { h[axis] } else { -h[axis] };
            id |= u32::from(plus) << axis;
        }
        out.push(Vec3::new(corner[0], corner[1], corner[2]), id);
    }
    let mut normal = [R::ZERO; 3];
    normal[k] = if positive { R::ONE } else { -R::ONE };
    out.normal = Vec3::new(normal[0], normal[1], normal[2]);
}

/// The regular octagon inscribed in the circle of radius r at height y: points
/// (r cos(kπ/4), y, r sin(kπ/4)), ids `first` + k.
fn octagon<R: Real>(out: &mut Feature<R>, radius: R, y: R, first: u32) {
    let c = radius * R::from_ratio(7_071_067_812, 10_000_000_000);
    let ring = [
        (radius, R::ZERO),
        (c, c),
        (R::ZERO, radius),
        (-c, c),
        (-radius, R::ZERO),
        (-c, -c),
        (R::ZERO, -radius),
        (c, -c),
    ];
    for (k, (x, z)) in ring.into_iter().enumerate() {
        out.push(Vec3::new(x, y, z), first + k as u32);
    }
}

/// The rim point r (d_x, d_z)/|(d_x, d_z)| (the axis when that is zero) and its octant
/// (0–7: the signs of x and z and whether |x| ≥ |z|), a coarse angle that stays the same
/// while the rim direction moves within it.
fn rim_point<R: Real>(d: Vec3<R>, radius: R) -> (Vec3<R>, u32) {
    let across = Vec3::new(d.x, R::ZERO, d.z);
    let unit = super::tolerance::unit(across).map_or(Vec3::ZERO, |(u, _)| u);
    let octant = u32::from(unit.x < R::ZERO)
        | u32::from(unit.z < R::ZERO) << 1
        | u32::from(unit.x.abs() < unit.z.abs()) << 2;
    (unit * radius, octant)
}

/// The cone's supporting feature along local d: base octagon, side segment or support
/// point (see the module).
fn cone_feature<R: Real>(
    out: &mut Feature<R>,
    radius: R,
    half_height: R,
    d: Vec3<R>,
    near_axis: bool,
) {
    if near_axis && d.y < R::ZERO {
        octagon(out, radius, -half_height, 16);
        out.normal = -Vec3::Y;
        return;
    }
    let (rim, octant) = rim_point(d, radius);
    let base = Vec3::new(rim.x, -half_height, rim.z);
    let apex = Vec3::new(R::ZERO, half_height, R::ZERO);
    // The side's outward normal at this rim direction, unnormalised: (2h u, r).
    let u_scale = half_height * R::TWO;
    let side = Vec3::new(rim.x * u_scale, radius * radius, rim.z * u_scale);
    let dn = d.dot(side);
    let near_side = dn > R::ZERO
        && dn * dn * R::from_int(16)
            >= R::from_int(15) * d.length_squared() * side.length_squared();
    let cone = Convex::Cone {
        radius,
        half_height,
    };
    if near_side {
        out.push(apex, 1);
        out.push(base, 64 + 2 * octant);
    } else if cone.support(d) == apex {
        out.push(apex, 1);
    } else {
        out.push(base, 64 + 2 * octant);
    }
}

/// The triangle's supporting feature along local d (see the module).
fn triangle_feature<R: Real>(
    out: &mut Feature<R>,
    corners: &[Vec3<R>; 3],
    normal: Vec3<R>,
    d: Vec3<R>,
) {
    let dn = d.dot(normal);
    let d2 = d.length_squared();
    if dn * dn >= (R::ONE - flat_sine_squared::<R>()) * d2 {
        for (k, &corner) in corners.iter().enumerate() {
            out.push(corner, k as u32);
        }
        out.normal = if dn >= R::ZERO { normal } else { -normal };
        return;
    }
    let k = crate::rigid::convex::support::triangle_support_index(corners, d);
    // The edges at corner k, as (other corner, |d · u|² / |u|²) with u the edge: the
    // direction is across an edge when d · u is small against |d| |u|.
    let mut best: Option<(usize, R, R)> = None;
    for other in [(k + 1) % 3, (k + 2) % 3] {
        let u = corners[other] - corners[k];
        let (du, u2) = (d.dot(u), u.length_squared());
        let across = du * du <= flat_sine_squared::<R>() * d2 * u2;
        // Compare du²/u² between the two edges without dividing: du₁² u₂² < du₂² u₁².
        let nearer =
            best.is_none_or(|(_, du_best, u2_best)| du * du * u2_best < du_best * du_best * u2);
        if across && nearer {
            best = Some((other, du, u2));
        }
    }
    match best {
        Some((other, _, _)) => {
            let (first, second) = if k < other { (k, other) } else { (other, k) };
            out.push(corners[first], first as u32);
            out.push(corners[second], second as u32);
        }
        None => out.push(corners[k], k as u32),
    }
}

/// Reverses a polygon whose winding disagrees with its outward normal, so that it is
/// counter-clockwise seen from outside.
fn orient<R: Real>(f: &mut Feature<R>) {
    let (a, b, c) = (f.points[0], f.points[1], f.points[2]);
    if (b - a).cross(c - a).dot(f.normal) < R::ZERO {
        f.points[..f.count].reverse();
        f.ids[..f.count].reverse();
    }
}
