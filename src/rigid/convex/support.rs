//! Support mappings: for a convex shape K and a direction d, a point s(d) of K with
//! d · s(d) = max over x in K of d · x. GJK, EPA and the shape queries see every convex
//! shape through this one function.
//!
//! Round shapes are split into a core and a radius (a sphere is a point grown by its
//! radius, a capsule a segment): GJK then works on the cores, which have corners, and adds
//! the radii at the end, which is both faster and more exact in fixed point than sampling
//! a curved surface.
//!
//! Ties (a direction normal to a face or an edge) resolve to a fixed choice: the positive
//! side for a zero component, the first vertex in canonical order for a hull, and the
//! centre of a cap for a direction along a cylinder's or cone's axis, so the same direction
//! gives the same point everywhere.

use super::hull::ConvexHull;
use crate::math::{Real, Vec3};
use crate::rigid::shape::Shape;

/// The core of a convex shape, in the shape's own frame.
#[derive(Clone, Copy, Debug)]
pub enum Convex<'a, R: Real> {
    /// The origin (a sphere's core).
    Point,
    /// The segment from (0, −h, 0) to (0, h, 0) (a capsule's core), h = `half_height` (m).
    Segment { half_height: R },
    /// A box of half extents `half_extents` (m).
    Cuboid { half_extents: Vec3<R> },
    /// A solid cylinder along y (see [`Shape::Cylinder`]).
    Cylinder { radius: R, half_height: R },
    /// A solid cone along y, apex up (see [`Shape::Cone`]).
    Cone { radius: R, half_height: R },
    /// A convex hull.
    Hull(&'a ConvexHull<R>),
    /// A triangle of a mesh: its corners (m) and unit face normal, in the mesh's frame.
    Triangle {
        corners: [Vec3<R>; 3],
        normal: Vec3<R>,
    },
}

/// A convex shape as a core grown by `radius` (m): the points within `radius` of the core.
#[derive(Clone, Copy, Debug)]
pub struct Rounded<'a, R: Real> {
    /// The core.
    pub core: Convex<'a, R>,
    /// The radius added around the core, m (zero for shapes with corners).
    pub radius: R,
}

impl<'a, R: Real> Rounded<'a, R> {
    /// The shape as a rounded core, or `None` for a plane, a compound, a mesh or a
    /// heightfield (not convex, or unbounded).
    pub fn of(shape: &'a Shape<R>) -> Option<Self> {
        let sharp = |core| Self {
            core,
            radius: R::ZERO,
        };
        Some(match shape {
            Shape::Sphere { radius } => Self {
                core: Convex::Point,
                radius: *radius,
            },
            Shape::Capsule {
                radius,
                half_height,
            } => Self {
                core: Convex::Segment {
                    half_height: *half_height,
                },
                radius: *radius,
            },
            Shape::Box { half_extents } => sharp(Convex::Cuboid {
                half_extents: *half_extents,
            }),
            Shape::Cylinder {
                radius,
                half_height,
            } => sharp(Convex::Cylinder {
                radius: *radius,
                half_height: *half_height,
            }),
            Shape::Cone {
                radius,
                half_height,
            } => sharp(Convex::Cone {
                radius: *radius,
                half_height: *half_height,
            }),
            Shape::ConvexHull { hull } => sharp(Convex::Hull(hull)),
            Shape::Plane { .. }
            | Shape::Compound { .. }
            | Shape::TriMesh { .. }
            | Shape::HeightField { .. } => return None,
        })
    }

    /// A support point of the whole rounded shape along `direction`: the core's support
    /// point plus `radius` times the unit direction (the core's alone when the direction is
    /// too short to normalise or the radius is zero).
    pub fn support(&self, direction: Vec3<R>) -> Vec3<R> {
        let core = self.core.support(direction);
        if self.radius == R::ZERO {
            return core;
        }
        match direction.try_normalize() {
            Some((unit, _)) => core + unit * self.radius,
            None => core,
        }
    }
}

impl<R: Real> Convex<'_, R> {
    /// A point of the core farthest along `direction` (any length, m⁰), in the shape's
    /// frame, m.
    ///
    /// Cylinder: (r d_⊥/|d_⊥|, ±h), d_⊥ = (d_x, 0, d_z), the sign of d_y (+ for 0), the
    /// cap's centre when |d_⊥| is zero. Cone: the apex (0, h, 0) when h d_y ≥ r |d_⊥| − h d_y,
    /// otherwise the base rim point (r d_⊥/|d_⊥|, −h) (the base centre when |d_⊥| is zero).
    pub fn support(&self, direction: Vec3<R>) -> Vec3<R> {
        let up = |h: R| if direction.y >= R::ZERO { h } else { -h };
        match *self {
            Self::Point => Vec3::ZERO,
            Self::Segment { half_height } => Vec3::new(R::ZERO, up(half_height), R::ZERO),
            Self::Cuboid { half_extents } => {
                let side = |d: R, h: R| if d >= R::ZERO { h } else { -h };
                Vec3::new(
                    side(direction.x, half_extents.x),
                    side(direction.y, half_extents.y),
                    side(direction.z, half_extents.z),
                )
            }
            Self::Cylinder {
                radius,
                half_height,
            } => {
                let (x, z) = rim(direction, radius);
                Vec3::new(x, up(half_height), z)
            }
            Self::Cone {
                radius,
                half_height,
            } => {
                let across = Vec3::new(direction.x, R::ZERO, direction.z);
                let length = across.length();
                let apex = half_height * direction.y;
                if apex >= radius * length - apex {
                    Vec3::new(R::ZERO, half_height, R::ZERO)
                } else {
                    let (x, z) = rim(direction, radius);
                    Vec3::new(x, -half_height, z)
                }
            }
            Self::Hull(hull) => hull.vertices[hull.support_index(direction)],
            Self::Triangle { corners, .. } => corners[triangle_support_index(&corners, direction)],
        }
    }
}

/// The corner k of a triangle with the largest d · v_k, the lowest k on ties.
pub(crate) fn triangle_support_index<R: Real>(corners: &[Vec3<R>; 3], direction: Vec3<R>) -> usize {
    let mut best = 0;
    for k in 1..3 {
        if direction.dot(corners[k]) > direction.dot(corners[best]) {
            best = k;
        }
    }
    best
}

/// The point of the circle of radius r in the xz plane farthest along d: r (d_x, d_z) /
/// |(d_x, d_z)|, or the centre when that is zero.
fn rim<R: Real>(direction: Vec3<R>, radius: R) -> (R, R) {
    let across = Vec3::new(direction.x, R::ZERO, direction.z);
    match across.try_normalize() {
        Some((unit, _)) => (unit.x * radius, unit.z * radius),
        None => (R::ZERO, R::ZERO),
    }
}
