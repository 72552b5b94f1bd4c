//! Collision of vertices with static shapes (planes, spheres, boxes, capsules: the shapes
//! of [`rigid::Shape`](crate::rigid::Shape), so that rigid bodies can later be colliders
//! through the same code), with Coulomb friction.
//!
//! A vertex is a ball of radius r. A contact has a unit normal n̂ pointing out of the shape
//! and a depth δ > 0 (m). XPBD bodies project the vertex out, x ← x + δ n̂, then apply
//! position-level friction (Macklin et al. 2014): with Δxₜ the tangential part of the
//! substep's displacement, the vertex sticks (x ← x − Δxₜ) while |Δxₜ| < μ δ, and otherwise
//! slides back by μ δ along −Δxₜ. Spring-mass bodies project the same way and then remove
//! the approaching normal velocity vₙ and up to μ|vₙ| of the tangential velocity.

use serde::{Deserialize, Serialize};

use crate::math::{Real, Vec3};
use crate::rigid::Transform;

/// A static shape in world coordinates.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) enum Geometry<R: Real> {
    /// The half-space n̂·x ≤ offset.
    Plane { normal: Vec3<R>, offset: R },
    /// A ball.
    Sphere { centre: Vec3<R>, radius: R },
    /// A box of half extents `half_extents` in the frame (rotation, centre).
    Box {
        rotation: crate::math::Mat3<R>,
        centre: Vec3<R>,
        half_extents: Vec3<R>,
    },
    /// The points within `radius` of the segment a–b; `inv_length_squared` = 1/|b − a|²
    /// (0 for a ball).
    Capsule {
        a: Vec3<R>,
        b: Vec3<R>,
        radius: R,
        inv_length_squared: R,
    },
}

/// A static collider: its geometry and friction coefficient.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Collider<R: Real> {
    pub geometry: Geometry<R>,
    /// μ.
    pub friction: R,
}

/// The contact of a ball at `x` of radius `r` (m) with a ball at `centre` of radius
/// `radius`: normal from the centre, depth radius + r − |x − centre|.
fn ball_contact<R: Real>(x: Vec3<R>, r: R, centre: Vec3<R>, radius: R) -> Option<(Vec3<R>, R)> {
    let d = x - centre;
    let reach = radius + r;
    let distance_squared = d.length_squared();
    if distance_squared >= reach * reach {
        return None;
    }
    let distance = distance_squared.sqrt();
    let normal = if distance > R::ZERO {
        d * distance.recip()
    } else {
        Vec3::Y
    };
    Some((normal, reach - distance))
}

impl<R: Real> Geometry<R> {
    /// The contact (outward normal, depth) of a vertex ball at `x` of radius `r` (m), if it
    /// overlaps the shape.
    pub fn contact(&self, x: Vec3<R>, r: R) -> Option<(Vec3<R>, R)> {
        match *self {
            Self::Plane { normal, offset } => {
                let depth = offset + r - normal.dot(x);
                (depth > R::ZERO).then_some((normal, depth))
            }
            Self::Sphere { centre, radius } => ball_contact(x, r, centre, radius),
            Self::Capsule {
                a,
                b,
                radius,
                inv_length_squared,
            } => {
                let axis = b - a;
                let t = ((x - a).dot(axis) * inv_length_squared).clamp(R::ZERO, R::ONE);
                ball_contact(x, r, a + axis * t, radius)
            }
            Self::Box {
                rotation,
                centre,
                half_extents,
            } => {
                let frame = Transform {
                    rotation,
                    translation: centre,
                };
                let p = frame.inverse_point(x);
                let outside = p.abs() - half_extents;
                if outside.max_component() >= r {
                    return None;
                }
                let closest = p.max_elem(-half_extents).min_elem(half_extents);
                let d = p - closest;
                if d != Vec3::ZERO {
                    let (normal, depth) = ball_contact(p, r, closest, R::ZERO)?;
                    return Some((frame.vector(normal), depth));
                }
                // Inside: leave through the nearest face.
                let mut axis = 0;
                for k in 1..3 {
                    if outside[k] > outside[axis] {
                        axis = k;
                    }
                }
                let mut normal = Vec3::ZERO;
                let sign = if p[axis] < R::ZERO { -R::ONE } else { R::ONE };
                match axis {
                    0 => normal.x = sign,
                    1 => normal.y = sign,
                    _ => normal.z = sign,
                }
                Some((frame.vector(normal), r - outside[axis]))
            }
        }
    }
}

/// Pushes the vertices of `range` out of every collider with XPBD friction, `previous`
/// holding their positions at the start of the substep.
pub(crate) fn project_positions<R: Real>(
    colliders: &[Collider<R>],
    positions: &mut [Vec3<R>],
    previous: &[Vec3<R>],
    inv_mass: &[R],
    range: core::ops::Range<usize>,
    radius: R,
) {
    for i in range {
        if inv_mass[i] == R::ZERO {
            continue;
        }
        for collider in colliders {
            let Some((normal, depth)) = collider.geometry.contact(positions[i], radius) else {
                continue;
            };
            let mut x = positions[i].add_scaled(normal, depth);
            let moved = x - previous[i];
            let tangential = moved - normal * moved.dot(normal);
            let limit = collider.friction * depth;
            let slip_squared = tangential.length_squared();
            if slip_squared <= limit * limit {
                x -= tangential;
            } else {
                let slip = slip_squared.sqrt();
                x -= tangential * (limit / slip);
            }
            positions[i] = x;
        }
    }
}

/// Pushes the vertices of `range` out of every collider and removes their approaching
/// normal velocity, with Coulomb friction on the tangential velocity.
pub(crate) fn project_velocities<R: Real>(
    colliders: &[Collider<R>],
    positions: &mut [Vec3<R>],
    velocities: &mut [Vec3<R>],
    inv_mass: &[R],
    range: core::ops::Range<usize>,
    radius: R,
) {
    for i in range {
        if inv_mass[i] == R::ZERO {
            continue;
        }
        for collider in colliders {
            let Some((normal, depth)) = collider.geometry.contact(positions[i], radius) else {
                continue;
            };
            positions[i] = positions[i].add_scaled(normal, depth);
            let v = velocities[i];
            let normal_speed = v.dot(normal);
            if normal_speed >= R::ZERO {
                continue;
            }
            let tangential = v - normal * normal_speed;
            let limit = collider.friction * -normal_speed;
            let speed_squared = tangential.length_squared();
            velocities[i] = if speed_squared <= limit * limit {
                Vec3::ZERO
            } else {
                tangential - tangential * (limit / speed_squared.sqrt())
            };
        }
    }
}
