//! One scalar joint row: a position error C along one direction and the impulse that
//! keeps it, solved by sequential impulses with accumulated clamping.
//!
//! A row has the Jacobian J = (−u, −j_a, u, j_b): its velocity is
//!
//! ```text
//! Ċ = u·(v_b − v_a) + j_b·ω_b − j_a·ω_a      (m/s for a linear row, rad/s for an angular one)
//! ```
//!
//! with u the linear direction (zero for an angular row) and j_a, j_b the angular parts. An
//! impulse λ along the row changes the velocities by
//! v_a −= u λ/m_a, ω_a −= I_a⁻¹ j_a λ, v_b += u λ/m_b, ω_b += I_b⁻¹ j_b λ, and its effective
//! mass is 1/k with k = |u|²(1/m_a + 1/m_b) + j_a·I_a⁻¹ j_a + j_b·I_b⁻¹ j_b.
//!
//! A row may carry a drift ½ h κ (same units as Ċ), its error's second-order motion over
//! the substep h, C(t + h) = C + h Ċ + ½ h² κ: the solver then drives Ċ + ½ h κ where a
//! plain row drives Ċ, so the error is met at the end of the substep to second order (see
//! [`super::joint_point`] for why; the distance rows of rods, ropes and springs carry one).

use super::body::SolverBody;
use super::softness::Softness;
use crate::math::{Real, Vec3};

/// How a row's impulse is biased and bounded.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum RowRole<R: Real> {
    /// Keeps C = 0 (a lock): the joints' soft bias in the biased pass, none in the relax
    /// pass; the impulse is unbounded.
    Equality,
    /// Keeps C ≥ 0 (a limit, a rope): the accumulated impulse stays ≥ 0. While C > 0 the row
    /// only stops the approach that would close the gap within the substep (bias C/h, as
    /// Box2D's speculative limits); at or past the limit it is an [`RowRole::Equality`].
    Inequality,
    /// Drives Ċ to `speed` (m/s or rad/s) with an accumulated impulse of at most
    /// `max_impulse` in size (N·s or N·m·s per substep: the motor's force times h).
    Motor {
        /// Target velocity along the row.
        speed: R,
        /// The largest accumulated impulse.
        max_impulse: R,
    },
    /// A physical spring pulling C to 0 with its own softness, in every pass.
    Spring(Softness<R>),
}

/// The coefficients of one pass over the joints: the joints' softness, the inverse substep
/// (1/s) and whether the soft bias applies (false in the relax pass).
#[derive(Clone, Copy, Debug)]
pub(crate) struct JointPass<R: Real> {
    pub soft: Softness<R>,
    pub inv_h: R,
    pub use_bias: bool,
}

impl<R: Real> JointPass<R> {
    /// (bias, mass scale, impulse scale) of a lock with position error `c` (m or rad): the
    /// soft correction in the biased pass, a rigid velocity constraint in the relax pass.
    pub fn lock_terms(&self, c: R) -> (R, R, R) {
        if self.use_bias {
            (
                self.soft.bias_rate * c,
                self.soft.mass_scale,
                self.soft.impulse_scale,
            )
        } else {
            (R::ZERO, R::ONE, R::ZERO)
        }
    }
}

/// A row as the solver keeps it for one substep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct JointRow<R: Real> {
    /// Linear direction u (unit, or zero for an angular row).
    pub linear: Vec3<R>,
    /// Angular parts j_a and j_b (m for a linear row, 1 for an angular row).
    pub angular_a: Vec3<R>,
    pub angular_b: Vec3<R>,
    /// I_a⁻¹ j_a and I_b⁻¹ j_b with the world inverse inertias of the step.
    pub turn_a: Vec3<R>,
    pub turn_b: Vec3<R>,
    /// Effective mass 1/k, kg or kg·m², from the start of the step.
    pub mass: R,
    /// Position error C, m or rad.
    pub error: R,
    pub role: RowRole<R>,
    /// Which of the joint's stored impulses the row accumulates into.
    pub slot: u8,
    /// Accumulated impulse this step, N·s or N·m·s.
    pub impulse: R,
    /// ½ h κ, the error's second-order drift over the substep (m/s or rad/s; zero for rows
    /// without one), from the velocities when the row was built.
    pub drift: R,
}

impl<R: Real> JointRow<R> {
    /// A row along linear direction `linear` with angular parts `angular_a`, `angular_b` and
    /// position error `error`, its velocity responses computed from the bodies' inverse
    /// inertias; mass and impulse zero.
    pub fn new(
        linear: Vec3<R>,
        (angular_a, angular_b): (Vec3<R>, Vec3<R>),
        error: R,
        role: RowRole<R>,
        slot: u8,
        (ba, bb): (&SolverBody<R>, &SolverBody<R>),
    ) -> Self {
        Self {
            linear,
            angular_a,
            angular_b,
            turn_a: ba.inv_inertia * angular_a,
            turn_b: bb.inv_inertia * angular_b,
            mass: R::ZERO,
            error,
            role,
            slot,
            impulse: R::ZERO,
            drift: R::ZERO,
        }
    }

    /// An angular row about `axis` (unit): Ċ = axis·(ω_b − ω_a).
    pub fn angular(
        axis: Vec3<R>,
        error: R,
        role: RowRole<R>,
        slot: u8,
        bodies: (&SolverBody<R>, &SolverBody<R>),
    ) -> Self {
        Self::new(Vec3::ZERO, (axis, axis), error, role, slot, bodies)
    }

    /// 1/k for the row's current Jacobian (see the [module](self) documentation), 0 when
    /// neither body responds.
    pub fn effective_mass(&self, ba: &SolverBody<R>, bb: &SolverBody<R>) -> R {
        let k = self.linear.length_squared() * (ba.inv_mass + bb.inv_mass)
            + self.angular_a.dot_fused(self.turn_a)
            + self.angular_b.dot_fused(self.turn_b);
        if k > R::ZERO { k.recip() } else { R::ZERO }
    }

    /// Ċ + ½ h κ for the bodies' current velocities (Ċ alone for a row without drift).
    #[inline]
    pub fn velocity(&self, ba: &SolverBody<R>, bb: &SolverBody<R>) -> R {
        (bb.v - ba.v).dot_fused(self.linear) + bb.w.dot_fused(self.angular_b)
            - ba.w.dot_fused(self.angular_a)
            + self.drift
    }

    /// Applies impulse `lambda` along the row (A loses, B gains).
    pub fn apply(&self, ba: &mut SolverBody<R>, bb: &mut SolverBody<R>, lambda: R) {
        ba.v -= self.linear * (lambda * ba.inv_mass);
        ba.w -= self.turn_a * lambda;
        bb.v += self.linear * (lambda * bb.inv_mass);
        bb.w += self.turn_b * lambda;
    }

    /// Applies the accumulated impulse (warm starting).
    pub fn warm_start(&self, ba: &mut SolverBody<R>, bb: &mut SolverBody<R>) {
        if self.impulse != R::ZERO {
            self.apply(ba, bb, self.impulse);
        }
    }

    /// One sequential-impulse iteration: λ = −m·s_m·(Ċ + ½ h κ + bias) − s_i·λ_acc, accumulated and
    /// clamped as the row's [`RowRole`] says, the change applied to the bodies.
    pub fn solve(&mut self, ba: &mut SolverBody<R>, bb: &mut SolverBody<R>, pass: &JointPass<R>) {
        let cdot = self.velocity(ba, bb);
        let old = self.impulse;
        let new = match self.role {
            RowRole::Equality => {
                let (bias, mass_scale, impulse_scale) = pass.lock_terms(self.error);
                old - self.mass * mass_scale * (cdot + bias) - impulse_scale * old
            }
            RowRole::Inequality => {
                let (bias, mass_scale, impulse_scale) = if self.error > R::ZERO {
                    (self.error * pass.inv_h, R::ONE, R::ZERO)
                } else {
                    pass.lock_terms(self.error)
                };
                let lambda = -(self.mass * mass_scale * (cdot + bias)) - impulse_scale * old;
                (old + lambda).max(R::ZERO)
            }
            RowRole::Motor { speed, max_impulse } => {
                (old - self.mass * (cdot - speed)).clamp(-max_impulse, max_impulse)
            }
            RowRole::Spring(soft) => {
                old - self.mass * soft.mass_scale * (cdot + soft.bias_rate * self.error)
                    - soft.impulse_scale * old
            }
        };
        self.impulse = new;
        let applied = new - old;
        if applied != R::ZERO {
            self.apply(ba, bb, applied);
        }
    }
}
