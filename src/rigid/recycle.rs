//! Contact recycling (Jolt's body-pair cache, Rapier's contact recycling): a pair of shapes
//! whose relative pose has hardly changed since the narrowphase last ran for it keeps that
//! manifold, its points carried with the bodies, instead of running the narrowphase again.
//!
//! When the narrowphase makes the contact of a pair of convex shapes that are not spheres
//! or planes (box–box, box–capsule, capsule–capsule, whose narrowphase costs more than
//! this test), the contact gets, besides its world data, a [`PairFrame`]: the pose of B
//! in A's frame, t₀ = R_aᵀ(x_b − x_a) (m) and q₀ = q_a* ⊗ q_b, the normal in A's frame,
//! and each point's two surface points p ∓ n s/2 in the frame of its own body (m). The
//! frames live in a list of their own beside the contacts (cold data: read once a step),
//! each contact naming its frame by index ([`Contact::frame`]), so that contacts without
//! one (spheres, planes, compounds) stay as small as before. At the
//! next step, with the relative pose now t, q, every point of B has moved in A's frame by
//! at most
//!
//! ```text
//! |t − t₀| + 2 sin(Δθ/2) ρ_b,   sin²(Δθ/2) = 1 − (q·q₀)²
//! ```
//!
//! (ρ_b: the largest distance of a point of B from its origin, m). When
//! |t − t₀|² ≤ (d/2)² and 4 (1 − (q·q₀)²) ρ_b² ≤ (d/2)², with d the scene's
//! `contact_recycle_distance`, that bound is at most d, and the contact is carried instead
//! of recomputed ([`PairPose::carried`]): n = R_a n_a, the surface points p_a = R_a a + x_a and
//! p_b = R_b b + x_b, the separation s = (p_b − p_a)·n and the point (p_a + p_b)/2; ids,
//! impulses and the frame stay. The manifold found at the reference pose is then used for
//! poses up to d away from it: a point that would enter the speculative margin in that
//! time, or a clip polygon that would shift, waits for the next full update, as in Jolt and
//! Rapier. Frames are state (snapshots and checksums carry them), so a restored world
//! recycles exactly where the uninterrupted one does.

use super::contact::{Contact, ContactPoint};
use super::manifold::{MAX_MANIFOLD_POINTS, Manifold};
use super::shape::Shape;
use super::transform::Transform;
use crate::math::{Quat, Real, Vec3};
use serde::{Deserialize, Serialize};

/// Where the narrowphase last ran for a recyclable pair (see the [module](self)).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct PairFrame<R: Real> {
    /// B's origin in A's frame, R_aᵀ(x_b − x_a), m.
    pub translation: Vec3<R>,
    /// B's orientation relative to A's, q_a* ⊗ q_b.
    pub rotation: Quat<R>,
    /// The contact normal in A's frame.
    pub normal: Vec3<R>,
    /// Each point's surface point on A, point − n·separation/2, in A's frame, and on B,
    /// point + n·separation/2, in B's frame, m (the points the contact does not use: zero).
    pub anchors: [[Vec3<R>; 2]; MAX_MANIFOLD_POINTS],
}

/// Whether the contacts of shapes `a` and `b` keep a [`PairFrame`]: both convex, neither a
/// sphere (whose narrowphase costs less than the test) nor a plane (unbounded).
pub(crate) fn recyclable<R: Real>(a: &Shape<R>, b: &Shape<R>) -> bool {
    let costly = |s: &Shape<R>| {
        matches!(
            s,
            Shape::Box { .. }
                | Shape::Capsule { .. }
                | Shape::Cylinder { .. }
                | Shape::Cone { .. }
                | Shape::ConvexHull { .. }
        )
    };
    costly(a) && costly(b)
}

/// ρ², the square of the largest distance of a point of `shape` from its origin (m²), for
/// the shapes [`recyclable`] admits: |h|² for a box, (h + r)² for a capsule, r² + h² for a
/// cylinder or a cone, the largest |v|² for a hull.
fn reach_squared<R: Real>(shape: &Shape<R>) -> R {
    match *shape {
        Shape::Box { half_extents } => half_extents.length_squared(),
        Shape::Capsule {
            radius,
            half_height,
        } => (radius + half_height) * (radius + half_height),
        // The rim of a cap or base, the farthest points from the origin (a cone's apex is
        // nearer, at h).
        Shape::Cylinder {
            radius,
            half_height,
        }
        | Shape::Cone {
            radius,
            half_height,
        } => radius * radius + half_height * half_height,
        Shape::ConvexHull { ref hull } => hull.reach_squared(),
        // Not reached: `recyclable` admits no other shape.
        _ => R::MAX,
    }
}

/// The two bodies of a pair as the recycling sees them: placements and orientations.
#[derive(Clone, Copy)]
pub(crate) struct PairPose<'a, R: Real> {
    pub xf_a: &'a Transform<R>,
    pub q_a: Quat<R>,
    pub xf_b: &'a Transform<R>,
    pub q_b: Quat<R>,
}

/// R v for the rotation with rows `rows`, each component a dot product rounded once
/// ([`Vec3::dot_fused`]). Given a rotation's columns instead, it gives Rᵀ v: the vector in
/// the rotated frame.
#[inline(always)]
fn rotate<R: Real>(rows: &[Vec3<R>; 3], v: Vec3<R>) -> Vec3<R> {
    Vec3::new(
        rows[0].dot_fused(v),
        rows[1].dot_fused(v),
        rows[2].dot_fused(v),
    )
}

/// The rows of a placement's rotation (its columns are the local axes).
#[inline(always)]
fn rows<R: Real>(xf: &Transform<R>) -> [Vec3<R>; 3] {
    let [c0, c1, c2] = xf.rotation.cols;
    [
        Vec3::new(c0.x, c1.x, c2.x),
        Vec3::new(c0.y, c1.y, c2.y),
        Vec3::new(c0.z, c1.z, c2.z),
    ]
}

impl<R: Real> PairPose<'_, R> {
    /// B's origin in A's frame, Rₐᵀ(x_b − x_a), m.
    fn translation(&self) -> Vec3<R> {
        rotate(
            &self.xf_a.rotation.cols,
            self.xf_b.translation - self.xf_a.translation,
        )
    }

    /// B's orientation relative to A's, q_a* ⊗ q_b.
    fn rotation(&self) -> Quat<R> {
        self.q_a.conjugate() * self.q_b
    }

    /// The frame of the contact the narrowphase just found, `manifold`.
    pub fn frame(&self, manifold: &Manifold<R>) -> PairFrame<R> {
        let n = manifold.normal;
        // Rotating by the columns gives Rᵀ v: world vectors into each body's frame.
        let (to_a, to_b) = (&self.xf_a.rotation.cols, &self.xf_b.rotation.cols);
        let mut anchors = [[Vec3::ZERO; 2]; MAX_MANIFOLD_POINTS];
        for (anchor, found) in anchors.iter_mut().zip(manifold.points()) {
            let half_gap = n * (found.separation * R::HALF);
            *anchor = [
                rotate(to_a, found.point - half_gap - self.xf_a.translation),
                rotate(to_b, found.point + half_gap - self.xf_b.translation),
            ];
        }
        PairFrame {
            translation: self.translation(),
            rotation: self.rotation(),
            normal: rotate(to_a, n),
            anchors,
        }
    }

    /// Whether `frame` is within `distance` (m) of the pair's pose now, for B of shape
    /// `shape_b` (see the [module](self)).
    pub fn near(&self, frame: &PairFrame<R>, shape_b: &Shape<R>, distance: R) -> bool {
        let half = distance * R::HALF;
        let limit = half * half;
        if (self.translation() - frame.translation).length_squared() > limit {
            return false;
        }
        let cos = self.rotation().dot(frame.rotation);
        let sin_squared = R::ONE - cos * cos;
        R::from_int(4) * sin_squared * reach_squared(shape_b) <= limit
    }

    /// `contact`, whose frame is `frame`, carried to the bodies' current poses: normal,
    /// points and separations from the frame; key, ids, impulses and frame index unchanged.
    pub fn carried(&self, contact: &Contact<R>, frame: &PairFrame<R>) -> Contact<R> {
        let mut moved = *contact;
        let (rows_a, rows_b) = (rows(self.xf_a), rows(self.xf_b));
        let n = rotate(&rows_a, frame.normal);
        moved.normal = n;
        for (point, [on_a, on_b]) in moved.points_mut().iter_mut().zip(&frame.anchors) {
            let on_a = rotate(&rows_a, *on_a) + self.xf_a.translation;
            let on_b = rotate(&rows_b, *on_b) + self.xf_b.translation;
            *point = ContactPoint {
                point: (on_a + on_b) * R::HALF,
                separation: (on_b - on_a).dot_fused(n),
                ..*point
            };
        }
        moved
    }
}

#[cfg(test)]
mod tests;
