//! Frame-rate independent velocity damping: v ← v · d^Δt.
//!
//! `d` is the fraction of velocity kept after one second. Scaling by d^Δt every step is the
//! exact solution of v' = ln(d) · v over the step, so n steps of Δt = 1/n s give v · d after
//! one second for every n (up to rounding). It is applied after the integrator's update
//! (operator splitting), so it adds no stiffness and never reverses a velocity.

use serde::{Deserialize, Serialize};

use super::groups::applies_to;
use super::storage::{Attributes, Kinematics};
use crate::math::Real;

/// One damping generator and its cached per-step factor.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Damping<R: Real> {
    /// d, the fraction of velocity kept per second (0 < d ≤ 1).
    pub kept_per_second: R,
    /// Group restriction.
    pub group: Option<u16>,
    /// The step length `cached_factor` belongs to, s. A pure function of the other fields
    /// and Δt, so it is not hashed.
    cached_dt: R,
    /// d^cached_dt.
    cached_factor: R,
}

impl<R: Real> Damping<R> {
    /// Damping that keeps the fraction `kept_per_second` of velocity per second.
    pub fn new(kept_per_second: R, group: Option<u16>) -> Self {
        Self {
            kept_per_second,
            group,
            cached_dt: R::ZERO,
            cached_factor: R::ONE,
        }
    }

    /// d^Δt (dimensionless), computed with `powf` once per distinct step length `dt` (s).
    pub fn factor(&mut self, dt: R) -> R {
        if dt != self.cached_dt {
            self.cached_factor = self.kept_per_second.powf(dt);
            self.cached_dt = dt;
        }
        self.cached_factor
    }

    /// v ← v · d^Δt for every movable particle it applies to, Δt = `dt` seconds.
    ///
    /// A particle that carries a previous position (Störmer–Verlet) has its implicit
    /// velocity (x − x_prev)/Δt scaled the same way: x_prev ← x − (x − x_prev) · d^Δt.
    pub fn apply(&mut self, dt: R, kinematics: &mut Kinematics<R>, attributes: &Attributes<R>) {
        let factor = self.factor(dt);
        for i in 0..kinematics.velocities.len() {
            if !attributes.is_movable(i) || !applies_to(self.group, attributes.groups[i]) {
                continue;
            }
            kinematics.velocities[i] *= factor;
            if kinematics.has_previous_position[i] {
                let x = kinematics.positions[i];
                kinematics.previous_positions[i] =
                    x - (x - kinematics.previous_positions[i]) * factor;
            }
        }
    }
}
