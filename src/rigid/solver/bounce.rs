//! The separation speed a bouncing contact point leaves with: Newton's law of restitution
//! applied to the speed of the impact, not to the speed the step began with.
//!
//! The solver sees the approach speed v₀ at the start of a step, at separation s ≥ 0. If
//! gravity accelerates the approach, the point strikes faster than v₀ somewhere inside the
//! step, and the time the step has left after the impact is spent at rest on the surface.
//! Restitution applied to v₀ then loses height on every bounce: e·g·t of speed plus the
//! flight the rest of the step should have had, a loss that grows as the bounces get
//! smaller (measured: a ball dropped from 1 m with e = 0.8 reached 0.629, 0.394, 0.245,
//! 0.151 m at 60 Hz against e²ⁿ = 0.640, 0.410, 0.262, 0.168).
//!
//! Between contacts a body falls by semi-implicit Euler substeps of length h under a
//! constant approach acceleration a (m/s², the normal component of the two bodies' relative
//! gravity). With x the separation (m) and v the separation speed (m/s, negative while
//! approaching), that integrator keeps
//!
//! ```text
//! E = ½ v² + a x − ½ a h v                 (J/kg, exactly, substep after substep)
//! ```
//!
//! and its apex is E/a. A bounce that scales the height above the surface by e² therefore
//! maps E_before, at the start of the step (v = v₀, x = s₀), to e²·E_before at the end of
//! the step, where the point is at separation s₁ (m, from the solver's last relax pass:
//! about 0, or below 0 where the point arrived faster than the speculative distance could
//! foresee) moving away at u:
//!
//! ```text
//! ½ u² − ½ a h u + a s₁ = e² (½ v₀² + a s₀ − ½ a h v₀)
//! u = ½ (a h + √(a² h² + 8 (e² E_before − a s₁)))      (m/s)
//! ```
//!
//! With no relative acceleration (two bodies under the same gravity, or none) this is
//! u = e·|v₀|, Newton's law for the approach speed, which is then also the impact speed.
//! With e = 1 the body returns to the height it fell from and never above it.

use super::Solver;
use crate::math::{Real, Vec3};

/// What a step's restitution pass needs besides the contacts.
#[derive(Clone, Copy, Debug)]
pub(crate) struct BouncePass<R: Real> {
    /// Approach speeds below this (m/s) do not bounce.
    pub threshold: R,
    /// Gravity, m/s².
    pub gravity: Vec3<R>,
    /// The substep, s.
    pub h: R,
}

impl<R: Real> BouncePass<R> {
    /// The separation speed u (m/s, ≥ 0) a point leaves with, from its restitution e, its
    /// normal separation speed v₀ (m/s, negative: approaching) and separation s₀ (m) at the
    /// start of the step, its separation s₁ (m) at the end, and the relative acceleration of
    /// separation `separating` (m/s², (g_b − g_a)·n, with g the gravity of a body gravity
    /// moves, else 0): u = ½ (a h + √(a² h² + 8 (e² E − a s₁))) with a = −`separating` and
    /// E = ½ v₀² + a s₀ − ½ a h v₀, or e·|v₀| where a = 0.
    pub fn leaving_speed(&self, e: R, v0: R, (s0, s1): (R, R), separating: R) -> R {
        let a = -separating;
        let plain = -(e * v0);
        if a == R::ZERO {
            return plain;
        }
        let half = R::from_ratio(1, 2);
        let before = half * v0 * v0 + a * s0 - half * a * self.h * v0;
        let ah = a * self.h;
        let wanted = e * e * before - a * s1;
        let discriminant = (ah * ah + R::from_int(8) * wanted).max(R::ZERO);
        (half * (ah + discriminant.sqrt())).max(R::ZERO)
    }
}

impl<R: Real> Solver<R> {
    /// Whether a contact of this step may bounce: restitution and an approach faster than
    /// `threshold` (m/s) when the step began. Without one the restitution pass has nothing
    /// to do, and the substeps need not add up the impulses for it.
    pub fn may_bounce(&self, threshold: R) -> bool {
        self.blocks()
            .iter()
            .any(|block| block.may_bounce(threshold))
    }

    /// Adds every point's accumulated normal impulse after a substep's relax pass to the
    /// impulse it applied over the step, starting at the `first` substep (for the chains'
    /// pass, in steps that [may bounce](Self::may_bounce)).
    pub fn add_substep_impulses(&mut self, first: bool) {
        for block in &mut self.blocks[..self.block_count] {
            block.add_substep_impulses(first);
        }
    }

    /// Restitution, after the substeps: the chains of touching bodies a bounce reaches are
    /// resolved one contact at a time, the largest closing speed first
    /// ([`BounceChains`](super::contact_constraint::BounceChains)); every other bouncing
    /// contact separates at [`BouncePass::leaving_speed`]
    /// ([`ContactBlock::apply_restitution`](super::ContactBlock::apply_restitution)).
    pub fn restitution(&mut self, pass: &BouncePass<R>) {
        let blocks = &mut self.blocks[..self.block_count];
        self.chains.resolve(blocks, &mut self.bodies, pass);
        for block in blocks.iter_mut() {
            block.apply_restitution(&mut self.bodies, pass);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Fx;

    fn pass(h: Fx) -> BouncePass<Fx> {
        BouncePass {
            threshold: Fx::ONE,
            gravity: Vec3::new(Fx::ZERO, Fx::from_f64(-9.81), Fx::ZERO),
            h,
        }
    }

    #[test]
    fn without_relative_acceleration_it_is_newtons_law() {
        let u = pass(Fx::from_f64(1.0 / 300.0)).leaving_speed(
            Fx::from_f64(0.8),
            Fx::from_f64(-4.0),
            (Fx::ONE, Fx::ZERO),
            Fx::ZERO,
        );
        assert!((u.to_f64() - 3.2).abs() < 1e-8, "{u:?}");
    }

    /// The shadow energy after the bounce is e² times the one before, so the discrete
    /// flight's apex is e² times the height it fell from.
    #[test]
    fn the_apex_of_the_next_flight_is_e_squared_times_the_drop() {
        let (h, g, e) = (1.0 / 300.0, 9.81, 0.8);
        // A drop from 1 m at rest, integrated to the step before the surface.
        let (mut x, mut v) = (1.0f64, 0.0f64);
        while x + h * (v - g * h) > 0.0 {
            v -= g * h;
            x += h * v;
        }
        let u = pass(Fx::from_f64(h))
            .leaving_speed(
                Fx::from_f64(e),
                Fx::from_f64(v),
                (Fx::from_f64(x), Fx::ZERO),
                Fx::from_f64(-g),
            )
            .to_f64();
        let (mut y, mut w, mut apex) = (0.0f64, u, 0.0f64);
        while w > 0.0 {
            w -= g * h;
            y += h * w;
            apex = apex.max(y);
        }
        assert!((apex - e * e).abs() < 1e-3, "apex {apex}, u {u}");
    }
}
