//! Reporting figures of the fluid, as `f64`. Never fed back into the simulation.

use super::system::FluidSystem;
use crate::math::{Real, Vec3};

/// Figures of the fluid at one tick.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FluidMetrics {
    /// Σ ½ m v², J, with m = ρ₀ spacing³.
    pub kinetic_energy: f64, // ok-det: reporting
    /// Σ −m g·x, J.
    pub potential_energy: f64, // ok-det: reporting
    /// Σ m v, kg·m/s.
    pub momentum: [f64; 3], // ok-det: reporting
    /// The fastest particle, m/s.
    pub max_speed: f64, // ok-det: reporting
    /// Fluid particles.
    pub particles: u64,
    /// Mean over the particles of the compression max(ρ/ρ₀ − 1, 0), from the current
    /// positions.
    pub density_error_avg: f64, // ok-det: reporting
    /// The largest compression max(ρ/ρ₀ − 1, 0).
    pub density_error_max: f64, // ok-det: reporting
    /// The furthest x of the fluid touching the floor layer: the largest x of a particle
    /// whose centre is within one spacing of the floor, plus half a spacing (the extent of
    /// the particle's own volume), measured from the tank's back wall (min x), m; 0 without
    /// particles.
    pub front_x: f64, // ok-det: reporting
    /// Fluid substeps the last step took ([`FluidSystem::last_substeps`]; 0 before the
    /// first step of this copy of the system).
    pub substeps: u32,
}

impl<R: Real> FluidSystem<R> {
    /// The reporting figures under `gravity` (m/s²). Densities are computed afresh from the
    /// positions, on a copy: the state is not touched.
    pub fn metrics(&self, gravity: Vec3<R>) -> FluidMetrics {
        let s = &self.settings;
        let dx = s.spacing.to_f64(); // ok-det: reporting
        let mass = s.rest_density.to_f64() * dx * dx * dx; // ok-det: reporting
        let g = gravity.to_f64(); // ok-det: reporting
        let floor = s.tank.min.y.to_f64(); // ok-det: reporting
        let back = s.tank.min.x.to_f64(); // ok-det: reporting
        let mut m = FluidMetrics {
            particles: self.positions.len() as u64,
            substeps: self.last_substeps(),
            ..FluidMetrics::default()
        };
        for (x, v) in self.positions.iter().zip(&self.velocities) {
            let [px, py, pz] = x.to_f64(); // ok-det: reporting
            let [vx, vy, vz] = v.to_f64(); // ok-det: reporting
            let speed2 = vx * vx + vy * vy + vz * vz;
            m.kinetic_energy += 0.5 * mass * speed2; // ok-det: reporting
            m.potential_energy -= mass * (g[0] * px + g[1] * py + g[2] * pz);
            m.momentum[0] += mass * vx;
            m.momentum[1] += mass * vy;
            m.momentum[2] += mass * vz;
            m.max_speed = m.max_speed.max(speed2.sqrt());
            if py - floor <= dx {
                m.front_x = m.front_x.max(px - back + 0.5 * dx); // ok-det: reporting
            }
        }
        if !self.positions.is_empty() {
            let errors = self.density_errors();
            let count = errors.len() as f64; // ok-det: reporting
            m.density_error_max = errors.iter().copied().fold(0.0, f64::max); // ok-det: reporting
            m.density_error_avg = errors.iter().sum::<f64>() / count; // ok-det: reporting
        }
        m
    }

    /// max(ρᵢ/ρ₀ − 1, 0) of each particle at the current positions.
    pub fn density_errors(&self) -> Vec<f64> // ok-det: reporting
    {
        let mut copy = self.clone();
        copy.prepare();
        copy.search_neighbours();
        copy.compute_density();
        copy.scratch
            .density
            .iter()
            .map(|rho| (rho.to_f64() - 1.0).max(0.0)) // ok-det: reporting
            .collect()
    }
}
