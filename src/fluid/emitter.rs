//! Nozzles that add fluid during a run (the `pour` scene).

use serde::{Deserialize, Serialize};

use crate::math::{Fx, Real, Vec3};

/// The state of one nozzle.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct EmitterState<R: Real = Fx> {
    /// Centre of the nozzle, m.
    pub position: Vec3<R>,
    /// Velocity of the emitted particles, m/s.
    pub velocity: Vec3<R>,
    /// |velocity|, m/s.
    pub speed: R,
    /// velocity / |velocity|.
    pub direction: Vec3<R>,
    /// Particles per side of the square nozzle.
    pub width: u32,
    /// Particles still to add.
    pub remaining: u32,
    /// How far the last layer has moved since it was added, m.
    pub travelled: R,
}

impl<R: Real> EmitterState<R> {
    /// Stage 1, for this nozzle (the fluid runs its nozzles in scene order): tracks how far
    /// its last layer has moved (`travelled += |v| Δt`, m) and adds a new square layer of
    /// `spacing` (m) to `positions` and `velocities` each time that reaches one spacing,
    /// placed where the fluid would be had it left the nozzle on time:
    /// `position + offset + direction·(travelled − spacing)`. Particles within a layer are
    /// added with the horizontal offset's x fastest, then z.
    pub(crate) fn emit(
        &mut self,
        dt: R,
        spacing: R,
        positions: &mut Vec<Vec3<R>>,
        velocities: &mut Vec<Vec3<R>>,
    ) {
        if self.remaining == 0 {
            return;
        }
        self.travelled = self.travelled.add_product(self.speed, dt);
        while self.travelled >= spacing && self.remaining > 0 {
            self.travelled -= spacing;
            let centre = self.position.add_scaled(self.direction, self.travelled);
            let half = R::from_ratio(i64::from(self.width) - 1, 2);
            for b in 0..self.width {
                for a in 0..self.width {
                    if self.remaining == 0 {
                        break;
                    }
                    let offset = Vec3::new(
                        (R::from_int(a as i32) - half) * spacing,
                        R::ZERO,
                        (R::from_int(b as i32) - half) * spacing,
                    );
                    positions.push(centre + offset);
                    velocities.push(self.velocity);
                    self.remaining -= 1;
                }
            }
        }
    }
}
