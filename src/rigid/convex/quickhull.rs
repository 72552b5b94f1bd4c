//! The deterministic quickhull (placeholder until the construction lands).

use super::hull::{ConvexHull, HullError};
use crate::math::{Real, Vec3};

impl<R: Real> ConvexHull<R> {
    /// The convex hull of `points` (m).
    pub fn new(points: &[Vec3<R>]) -> Result<Self, HullError> {
        if points.len() < 4 {
            return Err(HullError::TooFewPoints(points.len()));
        }
        Err(HullError::Degenerate("construction not implemented"))
    }
}
