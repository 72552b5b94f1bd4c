//! The point block of a joint: three rows that make the anchors of A and B coincide,
//! solved together (a ball-and-socket; hinges, cone-twist and fixed joints start with it).
//!
//! With r_a, r_b the anchors from the centres of mass (world, m), the error and velocity are
//!
//! ```text
//! C = (x_b + r_b) − (x_a + r_a)                         (m)
//! Ċ = (v_b + ω_b × r_b) − (v_a + ω_a × r_a)             (m/s)
//! ```
//!
//! Over a substep h the error does not move on by h Ċ alone: anchors carried by turning
//! bodies sweep arcs, C(t + h) = C + h Ċ + ½ h² κ + O(h³) with the centripetal term
//! κ = ω_b × (ω_b × r_b) − ω_a × (ω_a × r_a) (m/s²). The block drives Ċ + ½ h κ (not Ċ) to
//! its target, so that the anchors meet at the end of the substep to second order (the
//! velocity form of SHAKE/RATTLE). Without it each substep's velocity projection shortens
//! the anchors' velocity instead of turning it, a loss first order in h: a heavy top on a
//! ball joint gained spin and sank (issue \[energy\]).
//!
//! κ is taken when the block is built and again right after the positions are integrated,
//! from the velocities they were integrated with, so that the relax pass holds the anchors
//! with the turn the bodies made. For a body spinning at ω₃ about the axis through its
//! anchor, κ carries ω₃ e₃ × (ω_⊥ × r_b), and ω_⊥ moves by tens of percent between the build
//! and the positions (the gyroscopic update and the solve); with the built κ in the relax
//! pass the heavy top precessed 1.9 % slow at 5 substeps (issue \[energy\]).
//!
//! The 3 × 3 effective mass is K⁻¹ with
//! K = (1/m_a + 1/m_b) 𝟙 − \[r_a\]ₓ I_a⁻¹ \[r_a\]ₓ − \[r_b\]ₓ I_b⁻¹ \[r_b\]ₓ (1/kg), computed once per
//! step at the step's start. An impulse λ (N·s, a vector) changes the velocities by
//! v_a −= λ/m_a, ω_a −= I_a⁻¹(r_a × λ), v_b += λ/m_b, ω_b += I_b⁻¹(r_b × λ).

use super::body::SolverBody;
use super::joint_row::JointPass;
use crate::math::{Mat3, Real, Vec3};

/// The point block as the solver keeps it for one substep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PointBlock<R: Real> {
    /// Anchors from the centres of mass, world frame, m.
    pub r_a: Vec3<R>,
    pub r_b: Vec3<R>,
    /// C, m.
    pub error: Vec3<R>,
    /// K⁻¹, kg, from the start of the step.
    pub mass: Mat3<R>,
    /// Accumulated impulse this step, N·s.
    pub impulse: Vec3<R>,
    /// ½ h κ, the anchors' centripetal drift over the substep (m/s; see the
    /// [module](self) documentation), from the velocities when the block was built.
    pub drift: Vec3<R>,
}

impl<R: Real> PointBlock<R> {
    /// K⁻¹ for the current anchors (see the [module](self) documentation); zero when K is
    /// singular (neither body responds).
    pub fn effective_mass(&self, ba: &SolverBody<R>, bb: &SolverBody<R>) -> Mat3<R> {
        let (skew_a, skew_b) = (Mat3::skew(self.r_a), Mat3::skew(self.r_b));
        let k = Mat3::IDENTITY * (ba.inv_mass + bb.inv_mass)
            - skew_a * ba.inv_inertia * skew_a
            - skew_b * bb.inv_inertia * skew_b;
        k.inverse().unwrap_or(Mat3::ZERO)
    }

    /// ½ h κ for anchors `r_a`, `r_b` (m) on bodies turning at their current ω, over a
    /// substep of `h` seconds: κ = ω_b × (ω_b × r_b) − ω_a × (ω_a × r_a) (m/s²).
    #[inline]
    pub fn drift_of(
        r_a: Vec3<R>,
        r_b: Vec3<R>,
        ba: &SolverBody<R>,
        bb: &SolverBody<R>,
        h: R,
    ) -> Vec3<R> {
        let kappa = bb.w.cross(bb.w.cross(r_b)) - ba.w.cross(ba.w.cross(r_a));
        kappa * (h * R::HALF)
    }

    /// Ċ + ½ h κ for the bodies' current velocities, m/s.
    #[inline]
    pub fn velocity(&self, ba: &SolverBody<R>, bb: &SolverBody<R>) -> Vec3<R> {
        (bb.v + bb.w.cross(self.r_b)) - (ba.v + ba.w.cross(self.r_a)) + self.drift
    }

    /// Applies impulse `lambda` at the anchors (A loses, B gains).
    pub fn apply(&self, ba: &mut SolverBody<R>, bb: &mut SolverBody<R>, lambda: Vec3<R>) {
        ba.v -= lambda * ba.inv_mass;
        ba.w -= ba.inv_inertia * self.r_a.cross(lambda);
        bb.v += lambda * bb.inv_mass;
        bb.w += bb.inv_inertia * self.r_b.cross(lambda);
    }

    /// Applies the accumulated impulse (warm starting).
    pub fn warm_start(&self, ba: &mut SolverBody<R>, bb: &mut SolverBody<R>) {
        if self.impulse != Vec3::ZERO {
            self.apply(ba, bb, self.impulse);
        }
    }

    /// One iteration: λ = −s_m K⁻¹(Ċ + ½ h κ + bias) − s_i λ_acc with the pass's soft bias
    /// on C, accumulated and applied.
    pub fn solve(&mut self, ba: &mut SolverBody<R>, bb: &mut SolverBody<R>, pass: &JointPass<R>) {
        let cdot = self.velocity(ba, bb);
        let (bias, mass_scale, impulse_scale) = if pass.use_bias {
            (
                self.error * pass.soft.bias_rate,
                pass.soft.mass_scale,
                pass.soft.impulse_scale,
            )
        } else {
            (Vec3::ZERO, R::ONE, R::ZERO)
        };
        let lambda = -(self.mass * (cdot + bias)) * mass_scale - self.impulse * impulse_scale;
        self.impulse += lambda;
        self.apply(ba, bb, lambda);
    }
}
