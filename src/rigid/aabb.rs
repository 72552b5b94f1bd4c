//! Axis-aligned bounding boxes of shapes, for the broadphase.

use super::convex::{Convex, Rounded};
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

    /// True when `p` lies in the box, faces included.
    #[inline]
    pub fn contains_point(&self, p: Vec3<R>) -> bool {
        self.min.x <= p.x
            && self.min.y <= p.y
            && self.min.z <= p.z
            && p.x <= self.max.x
            && p.y <= self.max.y
            && p.z <= self.max.z
    }

    /// The smallest box holding both.
    pub fn union(&self, other: &Self) -> Self {
        Self {
            min: self.min.min_elem(other.min),
            max: self.max.max_elem(other.max),
        }
    }

    /// The box, given in the world frame, as seen from the frame placed by `xf`: the
    /// smallest box in that frame holding it, centre Rᵀ(c − t) and half extents |Rᵀ| h.
    pub fn seen_from(&self, xf: &Transform<R>) -> Self {
        let centre = xf.inverse_point((self.min + self.max) * R::HALF);
        let h = (self.max - self.min) * R::HALF;
        let [r0, r1, r2] = xf.rotation.transpose().cols;
        let half = r0.abs() * h.x + r1.abs() * h.y + r2.abs() * h.z;
        Self {
            min: centre - half,
            max: centre + half,
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
            Shape::Cylinder { .. } | Shape::Cone { .. } | Shape::ConvexHull { .. } => {
                Rounded::of(shape).map(|convex| Self::of_convex(&convex.core, transform))
            }
            Shape::Plane { .. } => None,
            Shape::TriMesh { .. } | Shape::HeightField { .. } => {
                let bounds = shape.triangles()?.bounds();
                let local_centre = (bounds.min + bounds.max) * R::HALF;
                let h = (bounds.max - bounds.min) * R::HALF;
                let [c0, c1, c2] = transform.rotation.cols;
                let half = c0.abs() * h.x + c1.abs() * h.y + c2.abs() * h.z;
                let centre = transform.point(local_centre);
                Some(Self {
                    min: centre - half,
                    max: centre + half,
                })
            }
            Shape::Compound { parts } => parts
                .iter()
                .filter_map(|part| {
                    let local = Transform::from_pose(part.translation, part.rotation);
                    Self::of_shape(&part.shape, &transform.compose(&local))
                })
                .reduce(|a, b| a.union(&b)),
        }
    }

    /// The bounding box of a convex core placed by `transform`, from its support points
    /// along ±x, ±y, ±z (local directions Rᵀ e_k, the rows of R), grown by
    /// 2⁻²⁰ m ([`SUPPORT_PAD_INVERSE`]) for the rounding of curved supports.
    fn of_convex(core: &Convex<'_, R>, transform: &Transform<R>) -> Self {
        let rows = transform.rotation.transpose().cols;
        let pad = R::from_ratio(1, SUPPORT_PAD_INVERSE);
        let mut min = [R::ZERO; 3];
        let mut max = [R::ZERO; 3];
        for (k, row) in rows.into_iter().enumerate() {
            let high = transform.point(core.support(row)).to_array()[k];
            let low = transform.point(core.support(-row)).to_array()[k];
            min[k] = low - pad;
            max[k] = high + pad;
        }
        Self {
            min: Vec3::new(min[0], min[1], min[2]),
            max: Vec3::new(max[0], max[1], max[2]),
        }
    }
}

/// 1/pad: the bounding box of a cylinder, cone or hull is grown by 2⁻²⁰ m so that the
/// rounding of its support points (a unit vector times the radius) never leaves a point of
/// the shape outside it.
const SUPPORT_PAD_INVERSE: i64 = 1 << 20;
