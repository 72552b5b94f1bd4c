//! The gyroscopic term of jointed bodies, solved together with their joints.
//!
//! The velocity update turns every body's angular velocity by the free body's implicit
//! midpoint step ([`crate::rigid::gyroscopic`]): I (ω − ω₀) + h ω̄ × I ω̄ = 0, ω̄ = (ω + ω₀)/2,
//! I the inertia about the centre of mass. A joint then projects the result: it removes
//! the part the joint does not allow, and with it the energy of that part. For a heavy top
//! on a ball joint the free body nutates at (I₃ − I₁) ω₃ / I₁ = 55 rad/s about its centre
//! of mass where the joined top nutates at 10 rad/s about its pivot, and the projection
//! drains the precession: the top sank by 10° per second at 60 Hz (first order in the
//! substep).
//!
//! Here the implicit midpoint equation of each jointed body is solved with its joints'
//! impulses in it, by nonlinear Gauss–Seidel: before each relax pass over the joints, and
//! once more after the last, one Newton step on
//!
//! ```text
//! f(ω) = I (ω − ω_c) + h ω̄ × I ω̄ = 0,   ω_c = ω − γ,   ω̄ = (ω + ω₀)/2
//! ```
//!
//! with ω₀ the angular velocity at the substep's start, γ the gyroscopic change the body
//! carries so far (so ω_c is ω₀ plus everything the constraints, torques and damping did),
//! I = R I_body Rᵀ the world inertia at the substep's start (kg·m²), ω in rad/s, h in s:
//! ω ← ω − J⁻¹ f(ω), J = I + (h/2)(\[ω̄\]ₓ I − \[I ω̄\]ₓ) formed at the substep's first step
//! and kept for its later ones, γ changed by as much. The fixed point is
//! the implicit midpoint step of the joined system. Measured on the heavy top at 60 Hz: the
//! tilt holds within 0.2° over 10 s where it sank 90°. The last step matters: ending on a
//! joint projection leaves the gyroscopic term blind to that projection's change of ω (a
//! residual of order ω h times it), and the top's tilt then crept by 0.085° per second; the
//! joint's velocity error the last step leaves is the next substep's solve pass's to remove.
//!
//! Only dynamic bodies with a joint and an anisotropic inertia take part (an isotropic
//! body has no gyroscopic term), in solver order; a scene without joints never gets here.

use super::Solver;
use super::body::STATIC_BODY;
use crate::math::{Mat3, Real, Vec3};
use crate::rigid::bodies::Bodies;
use crate::rigid::desc::BodyKind;

/// One jointed body whose gyroscopic term is solved with its joints.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Spinning<R: Real> {
    /// Solver index.
    pub body: u32,
    /// Body slot.
    pub slot: u32,
    /// ω₀, rad/s, world frame.
    pub omega_start: Vec3<R>,
    /// γ, rad/s, world frame.
    pub gyro: Vec3<R>,
    /// I = R I_body Rᵀ at the substep's start, kg·m².
    pub inertia: Mat3<R>,
    /// J⁻¹ of the substep's first Newton step (zero where J is singular), 1/(kg·m²).
    pub newton: Mat3<R>,
}

impl<R: Real> Solver<R> {
    /// Lists, in solver order, the dynamic anisotropic bodies the step's joints hold.
    pub fn list_spinning(&mut self, bodies: &Bodies<R>) {
        self.spinning.clear();
        self.joined.clear();
        self.joined.resize(self.bodies.len(), false);
        for c in &self.joints {
            for b in [c.a, c.b] {
                if b != STATIC_BODY {
                    self.joined[b as usize] = true;
                }
            }
        }
        for (k, &joined) in self.joined.iter().enumerate().skip(1) {
            let slot = self.slots[k];
            let i = slot as usize;
            if joined && bodies.kind[i] == BodyKind::Dynamic && !bodies.isotropic[i] {
                self.spinning.push(Spinning {
                    body: k as u32,
                    slot,
                    omega_start: Vec3::ZERO,
                    gyro: Vec3::ZERO,
                    inertia: Mat3::ZERO,
                    newton: Mat3::ZERO,
                });
            }
        }
    }

    /// Records each listed body's ω₀ and world inertia at the start of a substep, before
    /// the velocity update.
    pub fn begin_spinning(&mut self, bodies: &Bodies<R>) {
        for s in &mut self.spinning {
            let i = s.slot as usize;
            s.omega_start = self.bodies[s.body as usize].w;
            s.inertia = bodies.orientation[i]
                .to_mat3()
                .rotate_inertia(bodies.inertia[i]);
        }
    }

    /// Records the gyroscopic change γ = −h I⁻¹ (ω̄ × I ω̄) the velocity update gave each
    /// listed body over substep `h` (s), from its angular velocity now.
    pub fn record_spinning(&mut self, h: R) {
        for s in &mut self.spinning {
            let w = self.bodies[s.body as usize].w;
            let mid = (w + s.omega_start) * R::HALF;
            let torque = mid.cross(s.inertia * mid);
            s.gyro = match s.inertia.inverse() {
                Some(inverse) => -(inverse * torque) * h,
                None => Vec3::ZERO,
            };
        }
    }

    /// One Newton step of every listed body's implicit midpoint equation with the impulses
    /// it has received (see the [module](self) documentation), over substep `h` (s). The
    /// substep's first step (`first`) forms and inverts J; the later ones reuse that J⁻¹
    /// (measured on the heavy top: the same to the printed digits as a fresh J each time).
    pub fn correct_spinning(&mut self, h: R, first: bool) {
        let half_h = h * R::HALF;
        for s in &mut self.spinning {
            let sb = &mut self.bodies[s.body as usize];
            let mid = (sb.w + s.omega_start) * R::HALF;
            let momentum = s.inertia * mid;
            let residual = s.inertia * s.gyro + mid.cross(momentum) * h;
            if first {
                let jacobian =
                    s.inertia + (Mat3::skew(mid) * s.inertia - Mat3::skew(momentum)) * half_h;
                s.newton = jacobian.inverse().unwrap_or(Mat3::ZERO);
            }
            let change = -(s.newton * residual);
            sb.w += change;
            s.gyro += change;
        }
    }
}
