//! Rays against the solids of revolution about the y axis, in the shape's frame: the
//! cylinder x² + z² ≤ r², |y| ≤ h and the cone with base disc of radius r at y = −h and
//! apex (0, h, 0) (all lengths in m; the ray is x(t) = o + t·d, d unit, t in m).
//!
//! Each is the first of its curved side (a quadratic in t) and its flat caps (a plane
//! each), the side's hit kept only between the caps and a cap's hit only inside its disc.
//! As for the capsule, the ray first skips to t₀ = max(0, −o·d − (h + r)): the shape lies in
//! the ball of radius h + r about its centre, so no earlier point can be in it, and from
//! there the squares of the quadratic stay of the shape's size.
//!
//! The answers follow [`ray`](super::ray): [`Crossing::Inside`] when the origin is in the
//! solid (surface included), else the entry distance and the outward unit normal.

use super::ray::{Crossing, Ray, clamped_ratio, ray_tube};
use super::unit_direction;
use crate::math::{Real, Vec3};

/// Whether the point `p` (cylinder frame, m) is in the cylinder of radius `r` and half
/// height `h` (m): p_x² + p_z² ≤ r² and |p_y| ≤ h.
pub(super) fn cylinder_contains<R: Real>(radius: R, half_height: R, p: Vec3<R>) -> bool {
    p.x * p.x + p.z * p.z <= radius * radius && p.y.abs() <= half_height
}

/// The cone's side as the unit outward normal of its slant line in the (ρ, y) half-plane,
/// ρ = √(x² + z²): (cos α, sin α) = (2h, r) / √(4h² + r²). The slant line passes through
/// the apex (0, h); a point's signed distance from it is ρ cos α + (y − h) sin α (m).
#[derive(Clone, Copy, Debug)]
pub(super) struct Slant<R: Real> {
    /// cos α = 2h / √(4h² + r²): the radial part of the side's normal.
    pub cos: R,
    /// sin α = r / √(4h² + r²): the upward part of the side's normal.
    pub sin: R,
}

impl<R: Real> Slant<R> {
    /// The slant of the cone of base radius `r` and half height `h` (m); `None` when both
    /// are zero.
    pub fn of(radius: R, half_height: R) -> Option<Self> {
        let n = unit_direction(Vec3::new(half_height + half_height, radius, R::ZERO))?;
        Some(Self { cos: n.x, sin: n.y })
    }

    /// Signed distance (m) of the point at radius ρ and height y from the slant line:
    /// ρ cos α + (y − h) sin α, negative on the axis side.
    pub fn signed_distance(&self, rho: R, y: R, half_height: R) -> R {
        rho * self.cos + (y - half_height) * self.sin
    }
}

/// Whether the point `p` (cone frame, m) is in the cone: p_y ≥ −h and its signed distance
/// from the slant line is ≤ 0 (which also puts it at or below the apex).
pub(super) fn cone_contains<R: Real>(slant: &Slant<R>, half_height: R, p: Vec3<R>) -> bool {
    let rho = (p.x * p.x + p.z * p.z).sqrt();
    p.y >= -half_height && slant.signed_distance(rho, p.y, half_height) <= R::ZERO
}

/// The ray from the skip point t₀ (see the [module](self)) on, or `None` past `ray.max`.
fn skipped<R: Real>(ray: &Ray<R>, reach: R) -> Option<(R, Ray<R>)> {
    let skip = (-ray.origin.dot(ray.direction) - reach).max(R::ZERO);
    (skip <= ray.max).then(|| {
        (
            skip,
            Ray {
                origin: ray.at(skip),
                direction: ray.direction,
                max: ray.max - skip,
            },
        )
    })
}

/// Keeps the nearer of two hits (the first on ties).
fn nearer<R: Real>(best: Option<(R, Vec3<R>)>, hit: Option<(R, Vec3<R>)>) -> Option<(R, Vec3<R>)> {
    match (best, hit) {
        (Some(b), Some(h)) if h.0 < b.0 => Some(h),
        (None, h) => h,
        (b, _) => b,
    }
}

/// The hit of the flat cap y = `level` (m) facing `up` (the outward normal ±y), whose
/// disc has radius `radius` (m): for an origin beyond the cap moving towards it,
/// t = (o_y − level)/(−d_y) (upper cap; mirrored for the lower), kept when the point
/// there has x² + z² ≤ r².
fn cap<R: Real>(ray: &Ray<R>, level: R, up: bool, radius: R) -> Option<(R, Vec3<R>)> {
    let (o, d) = (ray.origin.y, ray.direction.y);
    let (beyond, speed) = if up { (o - level, -d) } else { (level - o, d) };
    if beyond <= R::ZERO || speed <= R::ZERO {
        return None;
    }
    let t = clamped_ratio(beyond, speed, ray.limit());
    let p = ray.at(t);
    let normal = if up { Vec3::Y } else { -Vec3::Y };
    (t <= ray.max && p.x * p.x + p.z * p.z <= radius * radius).then_some((t, normal))
}

/// The shape's crossing from hits found on the skipped ray.
fn entered<R: Real>(skip: R, hit: Option<(R, Vec3<R>)>) -> Option<Crossing<R>> {
    hit.map(|(t, normal)| Crossing::Enters {
        distance: skip + t,
        normal,
    })
}

/// Ray (in the cylinder frame) against the solid cylinder x² + z² ≤ r², |y| ≤ h (m).
///
/// Inside when the origin is in it. Otherwise, from the skip point: the side
/// ([`ray_tube`]) and the caps y = ±h, normal ±y. A ray along the axis meets only the
/// caps. The nearest wins, the side on ties (a ray through the rim).
pub(super) fn ray_cylinder<R: Real>(
    radius: R,
    half_height: R,
    ray: &Ray<R>,
) -> Option<Crossing<R>> {
    if cylinder_contains(radius, half_height, ray.origin) {
        return Some(Crossing::Inside);
    }
    let (skip, near) = skipped(ray, half_height + radius)?;
    let mut best = ray_tube(radius, half_height, &near);
    best = nearer(best, cap(&near, half_height, true, radius));
    best = nearer(best, cap(&near, -half_height, false, radius));
    entered(skip, best)
}

/// Ray (in the cone frame) against the solid cone with base disc of radius r at y = −h and
/// apex (0, h, 0) (m).
///
/// Inside when the origin is in it ([`cone_contains`]). Otherwise, from the skip point o,
/// with w = h − o_y (m) and the [`Slant`] (cos α, sin α): the side is the lower nappe of
/// the double cone cos²α (x² + z²) = sin²α (h − y)², i.e. a t² + 2b t + c = 0 with
/// a = cos²α (d_x² + d_z²) − sin²α d_y², b = cos²α (o_x d_x + o_z d_z) + sin²α w d_y,
/// c = cos²α (o_x² + o_z²) − sin²α w² (m²; scaled by the unit slant so that they stay of
/// the size of the squared distances). Whatever the sign of a, the ray enters the double
/// cone (f' ≤ 0) at the root t = (−b − √D)/a = c / (√D − b), D = b² − ac: formed as
/// c / (√D − b) when √D > b and as (b + √D)/(−a) when √D < b (then a < 0), so that neither
/// form cancels. It is kept when t ≥ 0 and −h ≤ y ≤ h there (the lower nappe between the
/// base and the apex); normal (cos α · (x, z)/ρ, sin α) (+y at the apex). The base disc
/// y = −h, normal −y, competes; the nearest wins, the side on ties.
pub(super) fn ray_cone<R: Real>(radius: R, half_height: R, ray: &Ray<R>) -> Option<Crossing<R>> {
    let slant = Slant::of(radius, half_height)?;
    if cone_contains(&slant, half_height, ray.origin) {
        return Some(Crossing::Inside);
    }
    let (skip, near) = skipped(ray, half_height + radius)?;
    let (o, d) = (near.origin, near.direction);
    let (cos2, sin2) = (slant.cos * slant.cos, slant.sin * slant.sin);
    let w = half_height - o.y;
    let a = cos2 * (d.x * d.x + d.z * d.z) - sin2 * (d.y * d.y);
    let b = cos2 * (o.x * d.x + o.z * d.z) + sin2 * (w * d.y);
    let c = cos2 * (o.x * o.x + o.z * o.z) - sin2 * (w * w);
    let discriminant = b * b - a * c;
    let mut best = None;
    if discriminant >= R::ZERO {
        let root = discriminant.sqrt();
        let t = if root > b {
            Some(clamped_ratio(c, root - b, near.limit()))
        } else if root < b && a < R::ZERO {
            Some(clamped_ratio(b + root, -a, near.limit()))
        } else {
            None
        };
        if let Some(t) = t.filter(|&t| t >= R::ZERO && t <= near.max) {
            let p = near.at(t);
            if p.y.abs() <= half_height {
                let normal = match Vec3::new(p.x, R::ZERO, p.z).try_normalize() {
                    Some((e, _)) => Vec3::new(e.x * slant.cos, slant.sin, e.z * slant.cos),
                    None => Vec3::Y,
                };
                best = Some((t, normal));
            }
        }
    }
    best = nearer(best, cap(&near, -half_height, false, radius));
    entered(skip, best)
}
