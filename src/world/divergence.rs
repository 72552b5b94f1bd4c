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
//! Dynamic rigid bodies are watched with the same limits on another scale: the mechanical
//! energy they gained per kilogram since the first sample, γ = (E − E₀) / M with
//! E = KE + PE (J/kg), against κ₀ = KE₀ / M at that sample (at least [`ENERGY_FLOOR`] J/kg,
//! a speed of 1.4 m/s). Per kilogram, because a rigid body weighs a thousand default
//! particles (a 1 m box of water is a tonne), so that a joule means as much for both; the
//! energy gained rather than the energy, because E is conserved in free fall (and lost in
//! contacts) while KE + |PE| grows without bound for a body falling off the world. In
//! fixed point a value cannot become infinite or NaN, so "diverged" cannot mean "not
//! finite" for rigid bodies as it does in `f64` worlds: a solve that blows up gains energy,
//! and once its speeds reach the numeric range it gains it with saturations, which the
//! tenfold limit catches. Forces the inputs apply add energy, as for particles.
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

/// What grew.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DivergenceScale {
    /// ε, the mechanical energy per particle or soft-body vertex, J.
    EnergyPerPoint,
    /// γ, the mechanical energy the dynamic rigid bodies gained per kilogram of them since
    /// the check started, J/kg, against κ₀, their kinetic energy per kilogram then.
    RigidEnergyGainPerKilogram,
}

/// A detected divergence.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Divergence {
    /// The tick at which the growth was first seen.
    pub tick: u64,
    /// The scale at that tick: ε in J per particle, or γ in J/kg (see `scale`).
    pub energy_scale: f64, // ok-det: reporting
    /// The scale's reference, ε₀ or κ₀.
    pub reference: f64, // ok-det: reporting
    /// Which scale grew.
    pub scale: DivergenceScale,
}

/// Samples metrics and remembers the first divergence.
#[derive(Clone, Debug)]
pub(crate) struct DivergenceMonitor {
    /// Ticks between samples.
    pub every: u64,
    reference: Option<f64>, // ok-det: reporting
    /// E₀ / M and κ₀, once the world has had dynamic rigid bodies at a sample.
    rigid_reference: Option<(f64, f64)>, // ok-det: reporting
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
            rigid_reference: None,
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
        if self.detected.is_some() {
            return;
        }
        let limit = if saturated {
            SATURATED_GROWTH_LIMIT
        } else {
            GROWTH_LIMIT
        };
        if points(metrics) > 0 {
            let scale = energy_scale(metrics);
            let reference = *self.reference.get_or_insert(scale.max(ENERGY_FLOOR));
            if !scale.is_finite() || scale > limit * reference {
                self.detected = Some(Divergence {
                    tick: metrics.tick,
                    energy_scale: scale,
                    reference,
                    scale: DivergenceScale::EnergyPerPoint,
                });
                return;
            }
        }
        if metrics.rigid_mass > 0.0 {
            let per_kilogram = |energy: f64| energy / metrics.rigid_mass; // ok-det: reporting
            let energy =
                per_kilogram(metrics.rigid_kinetic_energy + metrics.rigid_potential_energy);
            let (start, reference) = *self.rigid_reference.get_or_insert((
                energy,
                per_kilogram(metrics.rigid_kinetic_energy).max(ENERGY_FLOOR),
            ));
            let gain = energy - start;
            if !gain.is_finite() || gain > limit * reference {
                self.detected = Some(Divergence {
                    tick: metrics.tick,
                    energy_scale: gain,
                    reference,
                    scale: DivergenceScale::RigidEnergyGainPerKilogram,
                });
            }
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
