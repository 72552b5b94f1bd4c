//! Nozzles that add fluid during a run (the `pour` scene).

use serde::{Deserialize, Serialize};

use super::system::FluidSystem;
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

impl<R: Real> FluidSystem<R> {
    /// Stage 1: each nozzle, in scene order, tracks how far its last layer has moved
    /// (`travelled += |v| Δt`, m) and adds a new square layer each time that reaches one
    /// spacing, placed where the fluid would be had it left the nozzle on time:
    /// `position + offset + direction·(travelled − spacing)`. Particles within a layer are
    /// added with the horizontal offset's x fastest, then z.
    pub(crate) fn emit(&mut self, dt: R) {
        let dx = self.settings.spacing;
        for e in &mut self.emitters {
            if e.remaining == 0 {
                continue;
            }
            e.travelled = e.travelled.add_product(e.speed, dt);
            while e.travelled >= dx && e.remaining > 0 {
                e.travelled -= dx;
                let centre = e.position.add_scaled(e.direction, e.travelled);
                let half = R::from_ratio(i64::from(e.width) - 1, 2);
                for b in 0..e.width {
                    for a in 0..e.width {
                        if e.remaining == 0 {
                            break;
                        }
                        let offset = Vec3::new(
                            (R::from_int(a as i32) - half) * dx,
                            R::ZERO,
                            (R::from_int(b as i32) - half) * dx,
                        );
                        self.positions.push(centre + offset);
                        self.velocities.push(e.velocity);
                        e.remaining -= 1;
                    }
                }
            }
        }
    }
}
