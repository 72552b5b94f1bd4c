//! Persistent contacts: the manifolds of touching shape pairs and the impulses the solver
//! found for them, carried from step to step for warm starting.

use serde::{Deserialize, Serialize};

use super::manifold::{MAX_MANIFOLD_POINTS, Manifold};
use crate::math::{Real, Vec3};

/// Which shapes touch: two body slots (`body_a < body_b`) and the compound parts involved
/// (0 for a shape that is not a compound). Contacts are kept sorted by key, so the
/// solver visits them in the same order on every machine.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
pub(crate) struct ContactKey {
    pub body_a: u32,
    pub body_b: u32,
    pub part_a: u16,
    pub part_b: u16,
}

/// One contact point and its accumulated impulses.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct ContactPoint<R: Real> {
    /// World contact point, midway between the surfaces, m.
    pub point: Vec3<R>,
    /// Signed gap along the normal, m (negative: overlap).
    pub separation: R,
    /// Feature id from the narrowphase.
    pub id: u32,
    /// Accumulated normal impulse, N·s (≥ 0).
    pub normal_impulse: R,
    /// Accumulated friction impulse along the two tangents, N·s.
    pub tangent_impulse: [R; 2],
}

/// A touching pair of shapes.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Contact<R: Real> {
    pub key: ContactKey,
    /// Unit normal from A to B.
    pub normal: Vec3<R>,
    /// Number of points in use.
    pub count: u8,
    pub points: [ContactPoint<R>; MAX_MANIFOLD_POINTS],
}

impl<R: Real> Contact<R> {
    /// A contact from a fresh manifold, taking the accumulated impulses of points with the
    /// same feature id from `previous` (warm starting).
    pub fn from_manifold(key: ContactKey, manifold: &Manifold<R>, previous: Option<&Self>) -> Self {
        let mut points = [ContactPoint::default(); MAX_MANIFOLD_POINTS];
        for (slot, mp) in points.iter_mut().zip(manifold.points()) {
            *slot = ContactPoint {
                point: mp.point,
                separation: mp.separation,
                id: mp.id,
                normal_impulse: R::ZERO,
                tangent_impulse: [R::ZERO; 2],
            };
            if let Some(old) = previous.and_then(|c| c.points().iter().find(|p| p.id == mp.id)) {
                slot.normal_impulse = old.normal_impulse;
                slot.tangent_impulse = old.tangent_impulse;
            }
        }
        Self {
            key,
            normal: manifold.normal,
            count: manifold.count as u8,
            points,
        }
    }

    /// The points in use.
    pub fn points(&self) -> &[ContactPoint<R>] {
        &self.points[..usize::from(self.count)]
    }

    /// The points in use, mutable.
    pub fn points_mut(&mut self) -> &mut [ContactPoint<R>] {
        &mut self.points[..usize::from(self.count)]
    }
}
