//! Reporting figures of the soft bodies, as `f64` (never fed back into the simulation).

use super::system::{Model, SoftSystem};
use crate::math::{Real, Vec3};

/// Totals over the soft bodies.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SoftMetrics {
    /// Σ ½ m |v|² over the movable vertices, J.
    pub kinetic_energy: f64, // ok-det: reporting
    /// Σ −m g·x over the movable vertices plus the elastic energy: ½ C²/α per compliant
    /// XPBD row and ½ k (ℓ − ℓ₀)² per spring, J.
    pub potential_energy: f64, // ok-det: reporting
    /// Σ m v, kg·m/s.
    pub momentum: [f64; 3], // ok-det: reporting
    /// The largest vertex speed, m/s.
    pub max_speed: f64, // ok-det: reporting
    /// The largest stretch max(0, ℓ/ℓ₀ − 1) of an edge (XPBD distance row or spring).
    pub max_stretch: f64, // ok-det: reporting
    /// The mean stretch over the edges.
    pub mean_stretch: f64, // ok-det: reporting
    /// Number of vertices.
    pub vertices: u64,
}

impl<R: Real> SoftSystem<R> {
    /// The reporting figures under `gravity` (m/s²); each term is computed in the scalar and
    /// summed in `f64`.
    pub fn metrics(&self, gravity: Vec3<R>) -> SoftMetrics {
        let v = &self.vertices;
        let mut m = SoftMetrics {
            vertices: v.len() as u64,
            ..SoftMetrics::default()
        };
        for i in 0..v.len() {
            if v.inv_mass[i] == R::ZERO {
                continue;
            }
            let mass = v.mass[i].to_f64();
            let velocity = v.velocity[i].to_f64();
            let speed_squared: f64 = velocity.iter().map(|c| c * c).sum(); // ok-det: reporting
            m.kinetic_energy += 0.5 * mass * speed_squared;
            let g = gravity.to_f64();
            let x = v.position[i].to_f64();
            m.potential_energy -= mass * (g[0] * x[0] + g[1] * x[1] + g[2] * x[2]);
            for (total, part) in m.momentum.iter_mut().zip(velocity) {
                *total += mass * part;
            }
            m.max_speed = m.max_speed.max(speed_squared.sqrt());
        }
        let length = |a: u32, b: u32| -> f64 // ok-det: reporting
        {
            let d = (v.position[a as usize] - v.position[b as usize]).to_f64();
            (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
        };
        let mut stretch_sum = 0.0; // ok-det: reporting
        let mut edges = 0u64;
        let mut stretch = |length: f64, rest: f64| -> f64 // ok-det: reporting
        {
            let s = (length / rest - 1.0).max(0.0);
            m.max_stretch = m.max_stretch.max(s);
            stretch_sum += s;
            edges += 1;
            length - rest
        };
        let d = &self.distances;
        let mut elastic = 0.0; // ok-det: reporting
        for c in 0..d.a.len() {
            let extension = stretch(length(d.a[c], d.b[c]), d.rest[c].to_f64());
            let alpha = d.compliance[c].to_f64();
            if alpha > 0.0 {
                elastic += 0.5 * extension * extension / alpha;
            }
        }
        for body in &self.bodies {
            if let Model::SpringMass {
                stiffness, springs, ..
            } = body.model
            {
                let s = &self.springs;
                for k in springs.0 as usize..springs.1 as usize {
                    let extension = stretch(length(s.a[k], s.b[k]), s.rest[k].to_f64());
                    elastic += 0.5 * stiffness.to_f64() * extension * extension;
                }
            }
        }
        m.potential_energy += elastic;
        if edges > 0 {
            m.mean_stretch = stretch_sum / edges as f64; // ok-det: reporting
        }
        m
    }
}
