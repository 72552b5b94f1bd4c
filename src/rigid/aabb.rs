//! Axis-aligned bounding boxes of shapes, for the broadphase.

use super::shape::Shape;
use super::transform::Transform;
use crate::math::{Fx, Real, Vec3};

/// The box `min ≤ x ≤ max` (m), componentwise, in the world frame.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Aabb<R: Real = Fx> {
    /// Lower corner, m.
    pub min: Vec3<R>,
    /// Upper corner, m.
    pub max: Vec3<R>,
}

impl<R: Real> Aabb<R> {
    /// True when the two boxes overlap or touch.
    #[inline]
    pub fn overlaps(&self, other: &Self) -> bool {
        self.min.x <= other.max.x
            && other.min.x <= self.max.x
            && self.min.y <= other.max.y
            && other.min.y <= self.max.y
            && self.min.z <= other.max.z
            && other.min.z <= self.max.z
    }

    /// The smallest box holding both.
    pub fn union(&self, other: &Self) -> Self {
        Self {
            min: self.min.min_elem(other.min),
            max: self.max.max_elem(other.max),
        }
    }

    /// The box grown by `margin` (m) on every side.
    pub fn expanded(&self, margin: R) -> Self {
        let m = Vec3::splat(margin);
        Self {
            min: self.min - m,
            max: self.max + m,
        }
    }

    /// The bounding box of `shape` placed by `transform`, or `None` for a shape with no
    /// finite extent (a plane, or a compound made only of planes). A box with half extents
    /// h rotated by R spans |R| h about its centre; a capsule spans its segment's ends plus
    /// the radius.
    pub fn of_shape(shape: &Shape<R>, transform: &Transform<R>) -> Option<Self> {
        let centre = transform.translation;
        let around = |half: Vec3<R>| Self {
            min: centre - half,
            max: centre + half,
        };
        match shape {
            Shape::Sphere { radius } => Some(around(Vec3::splat(*radius))),
            Shape::Box { half_extents } => {
                let [c0, c1, c2] = transform.rotation.cols;
                let half = c0.abs() * half_extents.x
                    + c1.abs() * half_extents.y
                    + c2.abs() * half_extents.z;
                Some(around(half))
            }
            Shape::Capsule {
                radius,
                half_height,
            } => {
                let axis = transform.rotation.cols[1].abs() * *half_height;
                Some(around(axis + Vec3::splat(*radius)))
            }
            Shape::Plane { .. } => None,
            Shape::Compound { parts } => parts
                .iter()
                .filter_map(|part| {
                    let local = Transform::from_pose(part.translation, part.rotation);
                    Self::of_shape(&part.shape, &transform.compose(&local))
                })
                .reduce(|a, b| a.union(&b)),
        }
    }
}
