//! Integration of the moving bodies over one substep.

#[cfg(vector_kernels)]
mod kernel;
#[cfg(test)]
mod tests;

use super::Solver;
use super::lanes::LANES;
#[cfg(doc)]
use crate::math::Quat;
use crate::math::{Real, Vec3};
use crate::parallel::for_each_mut;
use crate::rigid::bodies::Bodies;
use crate::rigid::desc::BodyKind;
use crate::rigid::gyroscopic;

/// Bodies a worker takes at a time in the velocity update ([`crate::parallel`]).
const BODY_CHUNK: usize = 1024;

impl<R: Real> Solver<R> {
    /// Semi-implicit velocity update of every awake dynamic body over substep `h` (s):
    ///
    /// ```text
    /// v ← v / (1 + h c_v) + h (g + F/m)
    /// ω ← G(ω) / (1 + h c_ω) + h I⁻¹ τ
    /// ```
    ///
    /// with g gravity (m/s²), F and τ the tick's commanded force (N) and torque (N·m), c the
    /// damping rates (1/s), and G the implicit-midpoint gyroscopic update of
    /// [`gyroscopic::step`] (skipped for isotropic inertia, where ω × Iω = 0). Kinematic
    /// bodies keep their velocity.
    pub fn integrate_velocities(&mut self, bodies: &Bodies<R>, h: R, gravity: Vec3<R>) {
        let dv_gravity = gravity * h;
        let slots = &self.slots[1..];
        // Each body's update reads only its own slot: the bodies may go to the workers.
        for_each_mut(&mut self.bodies[1..], BODY_CHUNK, |k, sb| {
            let i = slots[k] as usize;
            if bodies.kind[i] != BodyKind::Dynamic {
                return;
            }
            let mut v = sb.v;
            let mut w = sb.w;
            if !bodies.isotropic[i] {
                w = gyroscopic::step(w, bodies.orientation[i], bodies.inertia[i], h);
            }
            let c_v = bodies.linear_damping[i];
            if c_v != R::ZERO {
                v /= R::ONE + h * c_v;
            }
            let c_w = bodies.angular_damping[i];
            if c_w != R::ZERO {
                w /= R::ONE + h * c_w;
            }
            v += dv_gravity;
            let force = bodies.force[i];
            if force != Vec3::ZERO {
                v += force * (h * sb.inv_mass);
            }
            let torque = bodies.torque[i];
            if torque != Vec3::ZERO {
                w += sb.inv_inertia * torque * h;
            }
            sb.v = v;
            sb.w = w;
        });
    }

    /// Turns every awake dynamic body's world inverse inertia R I⁻¹ Rᵀ (1/(kg·m²)) to its
    /// current orientation R, for the joints' next substep (isotropic bodies, whose world
    /// inverse inertia does not turn, keep theirs). Contacts keep the step's: their
    /// responses I⁻¹(r × n) were fixed when they were prepared.
    ///
    /// A joint solved with the step's inverse inertia applies its angular impulses about
    /// axes that lag the body by up to one step's turn: a heavy top on a ball joint,
    /// precessing by Ω Δt per step, then gains spin about its own axis at a rate set by Δt,
    /// not by the substep (measured: 0.6 rad/s per second at 5, 20 and 50 substeps alike).
    pub fn refresh_inverse_inertias(&mut self, bodies: &Bodies<R>) {
        let slots = &self.slots[1..];
        for (sb, &slot) in self.bodies[1..].iter_mut().zip(slots) {
            let i = slot as usize;
            if bodies.kind[i] == BodyKind::Dynamic && !bodies.isotropic[i] {
                sb.inv_inertia = bodies.orientation[i]
                    .to_mat3()
                    .rotate_inertia(bodies.inv_inertia[i]);
            }
        }
    }

    /// Position update over substep `h`: x ← x + h v, q ← normalize(q + ½ h (0, ω) ⊗ q)
    /// ([`Quat::integrate`], skipped when ω = 0), and the step's accumulated motion
    /// Δp += h v, Δθ += h ω.
    ///
    /// On I32F32 the orientations go [`LANES`] bodies at a time to a kernel when the
    /// processor has AVX-512 or AVX2, which gives the same bits; the bodies it leaves (far
    /// from unit length, or values past its bound) are integrated one by one.
    pub fn integrate_positions(&mut self, bodies: &mut Bodies<R>, h: R) {
        let moving = self.bodies[1..]
            .chunks_mut(LANES)
            .zip(self.slots[1..].chunks(LANES));
        for (chunk, slots) in moving {
            for (sb, &slot) in chunk.iter_mut().zip(slots) {
                let dx = sb.v * h;
                sb.dp += dx;
                sb.dtheta += sb.w * h;
                bodies.position[slot as usize] += dx;
            }
            if chunk.iter().all(|sb| sb.w == Vec3::ZERO) {
                // Nothing turns (bodies falling straight, say): no orientation to update.
                continue;
            }
            #[cfg(vector_kernels)]
            let done = kernel::integrate_orientations(chunk, slots, &mut bodies.orientation, h);
            #[cfg(not(vector_kernels))]
            let done = 0u8;
            for (l, (sb, &slot)) in chunk.iter().zip(slots).enumerate() {
                let i = slot as usize;
                if done & (1 << l) == 0 && sb.w != Vec3::ZERO {
                    bodies.orientation[i] = bodies.orientation[i].integrate(sb.w, h);
                }
            }
        }
    }
}
