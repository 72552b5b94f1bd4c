//! Divergence detection: noticing that a simulation is blowing up (an integrator past its
//! stability limit, a spring too stiff for the step) before its values hit the numeric range.
//!
//! The monitor samples the world's [`Metrics`] when it is switched on and then every few
//! ticks, and compares the mechanical energy scale per simulated point (live particles and soft-body vertices), ε = (KE + |PE|) / n
//! (J), with the scale at its first sample, ε₀ (never taken below [`ENERGY_FLOOR`], so that
//! a world starting at rest has a scale). A stable simulation keeps ε within a small factor of ε₀ (energy is conserved or
//! dissipated; forces the inputs apply add energy, but at game rates not 10⁴-fold). An
//! unstable one grows geometrically: explicit Euler on a spring multiplies the energy by
//! 1 + (ωh)² per step, semi-implicit Euler past ωh = 2 by more than 1 per step. The world
//! reports divergence once ε > [`GROWTH_LIMIT`] · ε₀, a hundredfold growth of the speed
//! scale, or once ε > [`SATURATED_GROWTH_LIMIT`] · ε₀ with saturations since the previous
//! sample: a blow-up fast enough to reach the numeric range (where the energies themselves
//! stop growing, I32F32 energies saturate near 2³¹ J) before it grew 10⁴-fold. Using the energy per particle keeps emitters, which add particles with their own
//! energy, from looking like growth.
//!
//! The monitor is reporting, outside the simulated state: it reads the state in `f64` and
//! never changes it. It is off unless asked for ([`World::enable_divergence_check`]), so a
//! world that does not use it pays nothing.
//!
//! [`World::enable_divergence_check`]: super::World::enable_divergence_check

use crate::types::Metrics;

/// The growth of ε over ε₀ that counts as divergence: 10⁴ in energy, 10² in speed.
pub const GROWTH_LIMIT: f64 = 1e4; // ok-det: reporting

/// The growth that counts as divergence when the world saturated since the last sample.
pub const SATURATED_GROWTH_LIMIT: f64 = 10.0; // ok-det: reporting

/// The least reference energy scale, J per particle: 1 J, the energy of a 1 kg particle at
/// 1.4 m/s.
pub const ENERGY_FLOOR: f64 = 1.0; // ok-det: reporting

/// A detected divergence.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Divergence {
    /// The tick at which the growth was first seen.
    pub tick: u64,
    /// ε at that tick, J per particle.
    pub energy_scale: f64, // ok-det: reporting
    /// ε₀, J per particle.
    pub reference: f64, // ok-det: reporting
}

/// Samples metrics and remembers the first divergence.
#[derive(Clone, Debug)]
pub(crate) struct DivergenceMonitor {
    /// Ticks between samples.
    pub every: u64,
    reference: Option<f64>, // ok-det: reporting
    /// The world's saturation count at the previous sample.
    saturations: u64,
    detected: Option<Divergence>,
}

impl DivergenceMonitor {
    /// A monitor sampling every `every` ticks (at least 1).
    pub fn new(every: u64) -> Self {
        Self {
            every: every.max(1),
            reference: None,
            saturations: 0,
            detected: None,
        }
    }

    /// The first divergence seen, if any.
    pub fn detected(&self) -> Option<Divergence> {
        self.detected
    }

    /// Takes one sample.
    pub fn sample(&mut self, metrics: &Metrics) {
        let saturated = metrics.saturations > self.saturations;
        self.saturations = metrics.saturations;
        if self.detected.is_some() || points(metrics) == 0 {
            return;
        }
        let scale = energy_scale(metrics);
        let reference = *self.reference.get_or_insert(scale.max(ENERGY_FLOOR));
        let limit = if saturated {
            SATURATED_GROWTH_LIMIT
        } else {
            GROWTH_LIMIT
        };
        if !scale.is_finite() || scale > limit * reference {
            self.detected = Some(Divergence {
                tick: metrics.tick,
                energy_scale: scale,
                reference,
            });
        }
    }
}

/// n: live particles plus soft-body vertices.
fn points(metrics: &Metrics) -> u64 {
    metrics.particles + metrics.soft_vertices
}

/// ε = (KE + |PE|) / n, J per point.
fn energy_scale(metrics: &Metrics) -> f64 // ok-det: reporting
{
    let points = points(metrics) as f64; // ok-det: reporting
    (metrics.kinetic_energy + metrics.potential_energy.abs()) / points
}
