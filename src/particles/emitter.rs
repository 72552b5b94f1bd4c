//! Emitters: particle sources with a fixed-point rate accumulator and seeded randomness.
//!
//! # Emission
//!
//! Each step, a switched-on emitter adds `rate · dt` to its accumulator and emits one
//! particle per whole unit in it, keeping the fraction for later steps, so a rate of 2.5/s
//! at 60 steps/s emits exactly 5 particles every 2 s. A particle that finds the system full
//! is dropped (the unit is still consumed, and no random number is drawn for it). A
//! switched-off emitter keeps its accumulator as it is.
//!
//! # Random draws
//!
//! All randomness comes from the world's [`Pcg32`], one `unit()` (uniform in [0, 1)) per
//! number, in this order for each emitted particle:
//!
//! * cone: u₁ (polar angle), u₂ (azimuth), u₃ (speed), u₄ (lifetime);
//! * box: u₁, u₂, u₃ (x, y, z offset), u₄ (speed), u₅ (lifetime).
//!
//! Emitters run in scene order. Every number is drawn even when its range is a single value,
//! so the number of draws depends only on how many particles are emitted.

use serde::{Deserialize, Serialize};

use super::desc::Interval;
use super::storage::{NewParticle, ParticleStorage};
use crate::math::rng::Pcg32;
use crate::math::{Real, Vec3};

/// Where emitted particles start and which way they go, with everything that does not
/// change precomputed.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) enum EmissionShape<R: Real> {
    /// Directions uniform over the cone's solid angle: cos θ = 1 − u₁ (1 − cos α),
    /// φ = 2π u₂, d = cos θ · axis + sin θ (cos φ · tangent + sin φ · bitangent).
    Cone {
        /// Unit axis.
        axis: Vec3<R>,
        /// Unit vector perpendicular to `axis`.
        tangent: Vec3<R>,
        /// axis × tangent.
        bitangent: Vec3<R>,
        /// 1 − cos α, α the half-angle.
        one_minus_cos_half_angle: R,
    },
    /// Start offsets uniform in [−e, e] per axis; one unit direction.
    Box {
        half_extents: Vec3<R>,
        direction: Vec3<R>,
    },
}

/// A compiled emitter: its configuration and its state (on flag, accumulator).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Emitter<R: Real> {
    /// m.
    pub position: Vec3<R>,
    /// Particles per second.
    pub rate: R,
    pub shape: EmissionShape<R>,
    /// m/s.
    pub speed: Interval<R>,
    /// s; `[0, 0]` for immortal particles.
    pub lifetime: Interval<R>,
    /// kg; 0 pins.
    pub mass: R,
    /// 1/mass, or 0 when pinned.
    pub inv_mass: R,
    pub group: u16,
    pub on: bool,
    /// Particles owed but not yet emitted, in [0, 1) between steps.
    pub accumulator: R,
}

/// What one emitter did during one step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Emission {
    pub emitted: u32,
    pub dropped: u32,
}

impl<R: Real> Emitter<R> {
    /// Emits the particles owed after `dt` more seconds into `storage`, drawing from `rng`
    /// (see the module documentation for the order).
    pub fn emit(&mut self, dt: R, storage: &mut ParticleStorage<R>, rng: &mut Pcg32) -> Emission {
        let mut emission = Emission::default();
        if !self.on {
            return emission;
        }
        self.accumulator += self.rate * dt;
        while self.accumulator >= R::ONE {
            self.accumulator -= R::ONE;
            if storage.is_full() {
                emission.dropped += 1;
                continue;
            }
            let particle = self.draw_particle(rng);
            storage.allocate(particle);
            emission.emitted += 1;
        }
        emission
    }

    /// One particle: start position and velocity from the shape, speed and lifetime from
    /// their ranges.
    fn draw_particle(&self, rng: &mut Pcg32) -> NewParticle<R> {
        let (position, direction) = match self.shape {
            EmissionShape::Cone {
                axis,
                tangent,
                bitangent,
                one_minus_cos_half_angle,
            } => {
                let cos_theta = R::ONE - rng.unit::<R>() * one_minus_cos_half_angle;
                let sin_theta = (R::ONE - cos_theta * cos_theta).sqrt();
                let (sin_phi, cos_phi) = (R::TAU * rng.unit::<R>()).sin_cos();
                let around = tangent * cos_phi + bitangent * sin_phi;
                (self.position, axis * cos_theta + around * sin_theta)
            }
            EmissionShape::Box {
                half_extents,
                direction,
            } => {
                let mut symmetric_unit = || rng.unit::<R>() * R::TWO - R::ONE;
                let offset = Vec3::new(
                    symmetric_unit() * half_extents.x,
                    symmetric_unit() * half_extents.y,
                    symmetric_unit() * half_extents.z,
                );
                (self.position + offset, direction)
            }
        };
        let speed = draw(self.speed, rng);
        let lifetime = draw(self.lifetime, rng);
        NewParticle {
            position,
            velocity: direction * speed,
            mass: self.mass,
            inv_mass: self.inv_mass,
            group: self.group,
            lifetime,
        }
    }
}

/// min + (max − min) · u, u uniform in [0, 1).
fn draw<R: Real>(interval: Interval<R>, rng: &mut Pcg32) -> R {
    interval.min + (interval.max - interval.min) * rng.unit::<R>()
}
