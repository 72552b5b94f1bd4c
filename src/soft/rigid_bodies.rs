//! The rigid bodies as the soft bodies see them: the two traits through which the soft
//! subsystem couples to the rigid one without depending on it. The world implements them
//! (`world/soft_coupling.rs`).

use crate::math::{Real, Vec3};
use crate::rigid::{Aabb, CollisionFilter, Transform};
use crate::types::Handle;

/// The bodies a scene's soft bodies may be tied to, while the soft system is built.
pub(crate) trait BodyFrames<R: Real> {
    /// The handle and placement of the rigid body with index `index` in the scene, or
    /// `None` when there is no such body.
    fn frame(&self, index: u32) -> Option<(Handle, Transform<R>)>;
    /// Number of rigid bodies in the scene.
    fn count(&self) -> usize;
}

/// A world without rigid bodies.
pub(crate) struct NoBodies;

impl<R: Real> BodyFrames<R> for NoBodies {
    fn frame(&self, _: u32) -> Option<(Handle, Transform<R>)> {
        None
    }
    fn count(&self) -> usize {
        0
    }
}

/// The rigid bodies during one world substep of the soft stage, which the rigid stage has
/// already advanced. Bodies are named by a proxy index, valid until the substep ends. The
/// soft solver splits the substep into its own substeps and calls [`advance`] at the
/// start of each; positions are those of the current soft substep.
///
/// [`advance`]: RigidBodies::advance
pub(crate) trait RigidBodies<R: Real> {
    /// Starts a world substep of `dt` seconds split into `substeps` soft substeps.
    fn begin(&mut self, dt: R, substeps: u32);
    /// The bodies accepted by `filter` that may come within `aabb` (m) during the world
    /// substep, in a canonical order, written to `out`.
    fn near(&mut self, aabb: &Aabb<R>, filter: CollisionFilter, out: &mut Vec<u32>);
    /// The body with handle `body`, or `None` when it was removed.
    fn of_body(&mut self, body: Handle) -> Option<u32>;
    /// Starts a soft substep: the bodies move on by it.
    fn advance(&mut self);
    /// Whether body `i`'s box grown by `margin` (m) may hold `x` (m).
    fn may_touch(&self, i: u32, x: Vec3<R>, margin: R) -> bool;
    /// The contact (outward unit normal, depth in m) of the vertex ball of radius `r` at
    /// `x` with body `i`, the vertex having been at `previous` at the start of the soft
    /// substep (m).
    fn contact(&self, i: u32, x: Vec3<R>, previous: Vec3<R>, r: R) -> Option<(Vec3<R>, R)>;
    /// The world position of body `i`'s body-frame point `local`, m.
    fn point(&self, i: u32, local: Vec3<R>) -> Vec3<R>;
    /// The velocity of body `i`'s material point at `p` (m), m/s.
    fn velocity_at(&self, i: u32, p: Vec3<R>) -> Vec3<R>;
    /// Body `i`'s generalised inverse mass at `p` (m) along the unit `n`, 1/kg (0 for a
    /// body that does not give way).
    fn inverse_mass(&self, i: u32, p: Vec3<R>, n: Vec3<R>) -> R;
    /// Moves body `i` by the positional impulse `impulse` (kg·m) at `p` (m).
    fn correct(&mut self, i: u32, p: Vec3<R>, impulse: Vec3<R>);
    /// Changes body `i`'s velocities by the impulse `impulse` (N·s) at `p` (m).
    fn push(&mut self, i: u32, p: Vec3<R>, impulse: Vec3<R>);
    /// Ends the world substep: the bodies keep their corrections.
    fn finish(&mut self);
}
