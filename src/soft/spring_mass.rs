//! Spring-mass networks: Hooke springs with damping along each edge, advanced by the
//! particle integrators.
//!
//! A spring-mass body is a soft body, stepped in the soft stage, not a set of particles:
//! its vertices live with the other soft vertices (one stage per capability, one vertex
//! store for collision and metrics), and it reuses the particle system's integration
//! schemes ([`Integrator`]) and its damped-spring force. Each world substep h:
//! aᵢ = g + wᵢ (Σ springs Fᵢ + drag·(wind − vᵢ)), with the spring force
//! F = −(k (ℓ − ℓ₀) + c (v_rel·û)) û on the first end; then the integrator's step, the
//! body's damping v ← v/(1 + h c_body), and collisions.
//!
//! # Stability bound
//!
//! Semi-implicit Euler on m ẍ = −k x − c ẋ has the characteristic polynomial
//! z² − (2 − b − a) z + (1 − b), a = k h²/m, b = c h/m, whose roots lie in the unit disc
//! (Jury) iff b > 0 or = 0 and a + 2b < 4: (k h² + 2 c h)/m < 4, i.e. ωh < 2 without
//! damping. For a network, k/m becomes the largest eigenvalue of M⁻¹K. Gershgorin's theorem
//! on the symmetric M^{−½} K M^{−½}, whose row i holds Σₛ kₛ wᵢ (projected, ≤) on the
//! diagonal and kₛ √(wᵢ wⱼ) off it, bounds it by Λ = maxᵢ Σ_{springs s of i}
//! kₛ (wᵢ + √(wᵢ wⱼ)): 2k/m for one spring between equal masses (exact), k/m for a mass
//! on a spring to a pinned vertex (exact), 4k/m for a chain (the exact value as the chain
//! grows), and 2·(number of springs)·k/m at most for a lattice vertex. The build warns when
//! h² Λ_k + 2 h Λ_c ≥ 4 for semi-implicit Euler and leapfrog (which shares its undamped
//! bound), and for explicit Euler always (it adds energy to every undamped mode at any h).
//! At run time the world's divergence check sees the energy blow up.

use serde::{Deserialize, Serialize};

use super::collide::project_velocities;
use super::system::{Model, SoftSystem};
use crate::math::integration::{Integrator, kick_then_drift};
use crate::math::spring::{SpringDesc, spring_force};
use crate::math::{Real, Vec3};

/// Spring rows of every spring-mass body.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Springs<R: Real> {
    pub a: Vec<u32>,
    pub b: Vec<u32>,
    /// ℓ₀, m.
    pub rest: Vec<R>,
}

/// Whether a spring-mass body can use `integrator`: the schemes that keep no state between
/// steps.
pub(crate) fn supports(integrator: Integrator) -> bool {
    matches!(
        integrator,
        Integrator::ExplicitEuler
            | Integrator::SemiImplicitEuler
            | Integrator::Leapfrog
            | Integrator::ImplicitEuler
    )
}

/// The [stability](self) measure h² Λ_k + 2 h Λ_c of the springs `a`, `b` of stiffness
/// `stiffness` (N/m) and damping `damping` (N·s/m) at step `h` (s), with inverse masses
/// `inv_mass` (1/kg); the schemes are stable below 4.
pub(crate) fn stability_measure<R: Real>(
    a: &[u32],
    b: &[u32],
    inv_mass: &[R],
    stiffness: R,
    damping: R,
    h: R,
) -> f64 // ok-det: reporting (a build-time warning, never simulated)
{
    let mut row = vec![0.0f64; inv_mass.len()]; // ok-det: reporting
    for (&i, &j) in a.iter().zip(b) {
        let (wi, wj) = (inv_mass[i as usize].to_f64(), inv_mass[j as usize].to_f64());
        let cross = (wi * wj).sqrt();
        row[i as usize] += wi + cross;
        row[j as usize] += wj + cross;
    }
    let lambda = row.into_iter().fold(0.0, f64::max); // ok-det: reporting
    let h = h.to_f64();
    (h * h * stiffness.to_f64() + 2.0 * h * damping.to_f64()) * lambda
}

impl<R: Real> SoftSystem<R> {
    /// Advances spring-mass body `b` by `dt` seconds under `gravity` (m/s²).
    pub(crate) fn step_spring_mass(&mut self, b: usize, dt: R, gravity: Vec3<R>) {
        let body = &self.bodies[b];
        let Model::SpringMass { integrator, .. } = body.model else {
            return;
        };
        let range = body.range();
        self.scratch
            .acceleration
            .resize(self.vertices.len(), Vec3::ZERO);
        let half = dt * R::HALF;
        match integrator {
            Integrator::ExplicitEuler => {
                self.spring_accelerations(b, gravity);
                let v = &mut self.vertices.velocity;
                let x = &mut self.vertices.position;
                for i in range.clone() {
                    if self.vertices.inv_mass[i] != R::ZERO {
                        x[i] = x[i].add_scaled(v[i], dt);
                        v[i] = v[i].add_scaled(self.scratch.acceleration[i], dt);
                    }
                }
            }
            Integrator::ImplicitEuler => {
                self.spring_accelerations(b, gravity);
                self.implicit_spring_mass_step(b, dt);
            }
            Integrator::Leapfrog => {
                self.drift(range.clone(), half);
                self.spring_accelerations(b, gravity);
                self.kick_then_drift(range.clone(), dt, half);
            }
            _ => {
                self.spring_accelerations(b, gravity);
                self.kick_then_drift(range.clone(), dt, dt);
            }
        }
        let body = &self.bodies[b];
        if body.damping != R::ZERO {
            let retain = (R::ONE + dt * body.damping).recip();
            for v in &mut self.vertices.velocity[range.clone()] {
                *v *= retain;
            }
        }
        if !self.colliders.is_empty() {
            project_velocities(
                &self.colliders,
                &mut self.vertices.position,
                &mut self.vertices.velocity,
                &self.vertices.inv_mass,
                range,
                body.radius,
            );
        }
    }

    /// x ← x + h v for the movable vertices of `range`.
    fn drift(&mut self, range: core::ops::Range<usize>, h: R) {
        for i in range {
            if self.vertices.inv_mass[i] != R::ZERO {
                self.vertices.position[i] =
                    self.vertices.position[i].add_scaled(self.vertices.velocity[i], h);
            }
        }
    }

    /// The particle integrators' kick then drift over `range`.
    fn kick_then_drift(&mut self, range: core::ops::Range<usize>, h_kick: R, h_drift: R) {
        kick_then_drift(
            &self.scratch.acceleration[range.clone()],
            &self.vertices.inv_mass[range.clone()],
            &mut self.vertices.velocity[range.clone()],
            &mut self.vertices.position[range],
            h_kick,
            h_drift,
        );
    }

    /// aᵢ = g + wᵢ (Σ springs Fᵢ + drag (wind − vᵢ)) for the vertices of body `b` (m/s²),
    /// 0 for pinned vertices, into the scratch accelerations.
    fn spring_accelerations(&mut self, b: usize, gravity: Vec3<R>) {
        let body = &self.bodies[b];
        let Model::SpringMass {
            stiffness,
            damping,
            springs,
            ..
        } = body.model
        else {
            return;
        };
        let x = &self.vertices.position;
        let v = &self.vertices.velocity;
        let w = &self.vertices.inv_mass;
        let force = &mut self.scratch.acceleration;
        for i in body.range() {
            force[i] = (body.wind - v[i]) * body.drag;
        }
        let s = &self.springs;
        for k in springs.0 as usize..springs.1 as usize {
            let (i, j) = (s.a[k] as usize, s.b[k] as usize);
            let spring = SpringDesc {
                stiffness,
                damping,
                rest_length: s.rest[k],
            };
            let f = spring_force(&spring, x[i] - x[j], v[i] - v[j]);
            force[i] += f;
            force[j] -= f;
        }
        for i in body.range() {
            force[i] = if w[i] == R::ZERO {
                Vec3::ZERO
            } else {
                gravity.add_scaled(force[i], w[i])
            };
        }
    }
}
