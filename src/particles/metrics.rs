//! Figures of the current state for reports and conservation tests: energies, momenta,
//! speed. They read the state and never change it; sums run in ascending slot order.

use super::forces::{AccelerationField, ForceGenerator};
use super::groups::applies_to;
use super::system::ParticleSystem;
use crate::math::{Real, Vec3};

impl<R: Real> ParticleSystem<R> {
    /// Kinetic energy, J: Σ ½ m |v|² over live particles (pinned ones have m = 0).
    pub fn kinetic_energy(&self) -> R {
        let a = &self.storage.attributes;
        let twice: R = self
            .storage
            .kinematics
            .velocities
            .iter()
            .zip(&a.masses)
            .fold(R::ZERO, |sum, (v, &m)| sum + m * v.length_squared());
        twice * R::HALF
    }

    /// Potential energy, J, of the conservative force generators under the world gravity
    /// `gravity` (m/s²), summed over live movable particles:
    ///
    /// * gravity: −m (s g) · x for each `Gravity` entry of scale s acting on the particle;
    /// * point gravity: −GM m / √(|r|² + ε²), r = x − centre;
    /// * springs: ½ k (ℓ − ℓ₀)² for each spring whose particles are alive.
    ///
    /// Drag, damping, external and user forces have no potential and are left out.
    pub fn potential_energy(&self, gravity: Vec3<R>) -> R {
        let a = &self.storage.attributes;
        let x = &self.storage.kinematics.positions;
        let mut energy = R::ZERO;
        for field in &self.forces.fields {
            for (i, &position) in x.iter().enumerate() {
                let m = a.masses[i];
                if m == R::ZERO {
                    continue;
                }
                match *field {
                    AccelerationField::Gravity { scale, group }
                        if applies_to(group, a.groups[i]) =>
                    {
                        energy -= m * (gravity * scale).dot(position);
                    }
                    AccelerationField::PointGravity {
                        centre,
                        gm,
                        softening_squared,
                        group,
                    } if applies_to(group, a.groups[i]) => {
                        let inv_distance =
                            ((position - centre).length_squared() + softening_squared).rsqrt();
                        energy -= gm * m * inv_distance;
                    }
                    _ => {}
                }
            }
        }
        for generator in &self.forces.generators {
            let stretch = match *generator {
                ForceGenerator::AnchoredSpring {
                    particle,
                    anchor,
                    ref spring,
                } => a
                    .resolve(particle)
                    .map(|i| (spring, (x[i] - anchor).length() - spring.rest_length)),
                ForceGenerator::Spring {
                    first,
                    second,
                    ref spring,
                } => a
                    .resolve(first)
                    .zip(a.resolve(second))
                    .map(|(i, j)| (spring, (x[i] - x[j]).length() - spring.rest_length)),
                _ => None,
            };
            if let Some((spring, stretch)) = stretch {
                energy += spring.stiffness * stretch * stretch * R::HALF;
            }
        }
        energy
    }

    /// Linear momentum, kg·m/s: Σ m v over live particles.
    pub fn momentum(&self) -> Vec3<R> {
        self.storage
            .kinematics
            .velocities
            .iter()
            .zip(&self.storage.attributes.masses)
            .fold(Vec3::ZERO, |sum, (&v, &m)| sum + v * m)
    }

    /// Angular momentum about `origin` (m), kg·m²/s: Σ m (x − origin) × v over live
    /// particles.
    pub fn angular_momentum(&self, origin: Vec3<R>) -> Vec3<R> {
        let k = &self.storage.kinematics;
        k.positions
            .iter()
            .zip(&k.velocities)
            .zip(&self.storage.attributes.masses)
            .fold(Vec3::ZERO, |sum, ((&x, &v), &m)| {
                sum + (x - origin).cross(v) * m
            })
    }

    /// The largest speed of a live particle, m/s: √(max |v|²), one square root.
    pub fn max_speed(&self) -> R {
        let a = &self.storage.attributes;
        self.storage
            .kinematics
            .velocities
            .iter()
            .zip(&a.alive)
            .filter(|&(_, &alive)| alive)
            .fold(R::ZERO, |max, (v, _)| max.max(v.length_squared()))
            .sqrt()
    }
}
