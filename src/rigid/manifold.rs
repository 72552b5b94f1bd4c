//! Contact manifolds: what the narrowphase reports for one pair of shapes.

use crate::math::{Fx, Real, Vec3};

/// Most points in one manifold (a face resting on a face is clipped to 4).
pub const MAX_MANIFOLD_POINTS: usize = 4;

/// One contact point.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ManifoldPoint<R: Real = Fx> {
    /// The contact point in the world frame, midway between the two surfaces, m.
    pub point: Vec3<R>,
    /// Signed distance between the surfaces along the manifold normal, m: negative when
    /// they overlap. Points up to the speculative margin apart (positive) are reported too.
    pub separation: R,
    /// Feature id: which features of the two shapes made this point (a box's face, edge or
    /// vertex, a capsule's end). It stays the same while the same features touch, so the
    /// solver can carry the point's impulses from one step to the next (warm starting).
    pub id: u32,
}

/// The contact between two shapes: a shared normal and up to [`MAX_MANIFOLD_POINTS`]
/// points. An empty manifold (`count == 0`) means no contact within the margin.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Manifold<R: Real = Fx> {
    /// Unit contact normal in the world frame, pointing from shape A towards shape B.
    pub normal: Vec3<R>,
    /// The points; only the first `count` are meaningful.
    pub points: [ManifoldPoint<R>; MAX_MANIFOLD_POINTS],
    /// Number of points, 0 to [`MAX_MANIFOLD_POINTS`].
    pub count: usize,
}

impl<R: Real> Manifold<R> {
    /// No contact.
    pub const EMPTY: Self = Self {
        normal: Vec3::ZERO,
        points: [ManifoldPoint {
            point: Vec3::ZERO,
            separation: R::ZERO,
            id: 0,
        }; MAX_MANIFOLD_POINTS],
        count: 0,
    };

    /// The meaningful points.
    pub fn points(&self) -> &[ManifoldPoint<R>] {
        &self.points[..self.count]
    }

    /// Adds a point; ignored when the manifold is full.
    pub fn push(&mut self, point: ManifoldPoint<R>) {
        if self.count < MAX_MANIFOLD_POINTS {
            self.points[self.count] = point;
            self.count += 1;
        }
    }

    /// The same contact seen from the other shape: the normal reversed, the points kept.
    pub fn flipped(mut self) -> Self {
        self.normal = -self.normal;
        self
    }
}
