//! Persistent contacts: the manifolds of touching shape pairs and the impulses the solver
//! found for them, carried from step to step for warm starting.
//!
//! Each point keeps its normal impulse; friction is one constraint per contact (at the
//! centre of its points, with a twist about the normal), so the contact keeps one
//! friction impulse along the two tangents and one twist impulse.

use serde::{Deserialize, Serialize};

use super::manifold::{MAX_MANIFOLD_POINTS, Manifold};
use crate::math::{Real, Vec3};

/// Which shapes touch: two body slots (`body_a < body_b`) and the parts involved: a
/// compound's part, a mesh's or a heightfield's triangle, 0 for any other shape. Contacts are kept sorted by key, so the
/// solver visits them in the same order on every machine.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
pub(crate) struct ContactKey {
    pub body_a: u32,
    pub body_b: u32,
    pub part_a: u32,
    pub part_b: u32,
}

/// One contact point and its accumulated normal impulse.
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
    /// Accumulated friction impulse at the centre of the points, along the two tangents
    /// of the normal, N·s.
    pub friction_impulse: [R; 2],
    /// Accumulated twist friction impulse about the normal, N·m·s.
    pub twist_impulse: R,
    /// The index in the system's frames of this contact's [`PairFrame`]: the pair's pose
    /// when the narrowphase last ran for it, for pairs whose manifold may be carried
    /// instead of recomputed ([`super::recycle`]); [`NO_FRAME`] for the others. The frames
    /// are kept apart so that the contacts that have none stay small.
    ///
    /// [`PairFrame`]: super::recycle::PairFrame
    pub frame: u32,
}

/// The [`Contact::frame`] of a contact without one.
pub(crate) const NO_FRAME: u32 = u32::MAX;

impl<R: Real> Contact<R> {
    /// A contact from a fresh manifold, with impulses carried from `previous` (the same
    /// pair's contact last step) for warm starting: each point takes the normal impulse of
    /// the previous point with the same feature id, and the contact takes the previous
    /// friction and twist impulses when at least one point id matched (the same features
    /// still touch, so the friction centre has not jumped).
    pub fn from_manifold(key: ContactKey, manifold: &Manifold<R>, previous: Option<&Self>) -> Self {
        let mut points = [ContactPoint::default(); MAX_MANIFOLD_POINTS];
        let mut matched = false;
        for (slot, mp) in points.iter_mut().zip(manifold.points()) {
            *slot = ContactPoint {
                point: mp.point,
                separation: mp.separation,
                id: mp.id,
                normal_impulse: R::ZERO,
            };
            if let Some(old) = previous.and_then(|c| c.points().iter().find(|p| p.id == mp.id)) {
                slot.normal_impulse = old.normal_impulse;
                matched = true;
            }
        }
        let (friction_impulse, twist_impulse) = match previous {
            Some(old) if matched => (old.friction_impulse, old.twist_impulse),
            _ => ([R::ZERO; 2], R::ZERO),
        };
        Self {
            key,
            normal: manifold.normal,
            count: manifold.count as u8,
            points,
            friction_impulse,
            twist_impulse,
            frame: NO_FRAME,
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
