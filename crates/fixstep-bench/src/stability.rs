// ok-det: benchmark driver; the simulations run in the chosen Real format, the step sweep, amplitudes and theory values are f64 reporting values, never inside a tick.
//! Stability limits: the largest ωh for which each integrator keeps the amplitude of a
//! spring bounded, found by bisection and compared with linear-stability theory.
//!
//! # The test
//!
//! A 1 kg particle on an anchored spring with k = 1 N/m (ω = 1 rad/s) and damping
//! c = 2ζ N·s/m, released from rest 1 m from its 10 km rest length (so the force stays
//! linear in the displacement whatever the amplitude reaches), is stepped
//! [`STEPS`] times with h = ωh s. With A = √(u² + (u'/ω)²) the amplitude of the
//! displacement u, the step is **stable** when the largest A over the last quarter of the
//! run is at most [`GROWTH_LIMIT`] times the largest A over the first quarter, and A never
//! exceeds [`DIVERGED`] m. Comparing quarter-run maxima rather than single samples ignores
//! the bounded oscillation of A within a period, which grows without bound as a
//! symplectic scheme approaches its limit, while catching any growth rate above
//! about 10⁻⁷ per step: explicit Euler's (1 + (ωh)²)^{1/2} is caught even at
//! ωh = 10⁻³.
//!
//! The limit is bisected on ωh ∈ [[`LOWEST`], [`HIGHEST`]] down to [`RESOLUTION`]; the
//! reported value is the largest ωh found stable.
//!
//! # Theory
//!
//! Undamped (from `harmonic_oscillator_discrete_amplification.csv`, exact one-step maps
//! computed with mpmath): semi-implicit Euler, Störmer–Verlet, velocity Verlet and leapfrog
//! are stable up to ωh = 2, RK4 up to 2√2 ≈ 2.828, explicit Euler never.
//!
//! Implicit Euler is A-stable: its amplification 1/(1 − hλ) has modulus below 1 for every
//! eigenvalue λ of a damped or undamped spring (Re λ ≤ 0), so it has no limit at any ζ
//! (derived).
//!
//! Damped (from `damped_spring_stability_limits.csv`, forces evaluated at the start of the
//! step, mpmath): semi-implicit Euler up to 2(√(1 + ζ²) − ζ), explicit Euler up to 2ζ
//! (ζ ≤ 1). The file gives no limits for the other schemes with damping.

use super::format::NumberFormat;
use fixstep::math::rng::Pcg32;
use fixstep::math::{Fx, FxI40F24, FxI48F16, Real, Vec3};
use fixstep::particles::{
    ForceDesc, Integrator, ParticleDesc, ParticleSystem, ParticlesDesc, SpringDesc,
};

/// Steps per stability test, N.
pub const STEPS: u32 = 100_000;
/// The last quarter's largest amplitude may exceed the first quarter's by at most this
/// factor.
pub const GROWTH_LIMIT: f64 = 1.01;
/// An amplitude above this (m, from 1 m at the start) ends the test as unstable.
pub const DIVERGED: f64 = 1e3;
/// The smallest ωh tested; a scheme unstable there is reported as never stable.
pub const LOWEST: f64 = 1e-3;
/// The largest ωh tested.
pub const HIGHEST: f64 = 4.0;
/// Bisection stops when the bracket is narrower than this.
pub const RESOLUTION: f64 = 1e-3;
/// Rest length of the spring, m.
const REST_LENGTH: i32 = 10_000;

/// The damping ratios ζ > 0 of `damped_spring_stability_limits.csv` with the limits it
/// gives: (ζ, semi-implicit Euler `sympEuler_analytic`, explicit Euler `fwdEuler_analytic`).
/// Its ζ = 0 row (2 and 0) is the undamped case of [`theory`].
const DAMPED_LIMITS: [(f64, f64, f64); 6] = [
    (0.05, 1.90249843945008, 0.1),
    (0.1, 1.80997512422418, 0.2),
    (0.25, 1.56155281280883, 0.5),
    (0.5, 1.23606797749979, 1.0),
    (1.0, 0.82842712474619, 2.0),
    (2.0, 0.472135954999579, 0.535898384862245),
];

/// The largest stable ωh that linear-stability theory predicts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Theory {
    /// Stable for 0 < ωh < this.
    Limit(f64),
    /// Unstable at every ωh > 0.
    NeverStable,
    /// Stable at every ωh > 0 (A-stable: implicit Euler).
    AlwaysStable,
    /// No reference value.
    Unknown,
}

/// The largest stable ωh found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Measured {
    /// The largest ωh found stable (within [`RESOLUTION`] of the limit).
    Limit(f64),
    /// Unstable at [`LOWEST`] already.
    NeverStable,
    /// Stable at [`HIGHEST`].
    AtLeast(f64),
}

/// What to sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct StabilityConfig {
    /// Schemes, in report order.
    pub integrators: Vec<Integrator>,
    /// Damping ratios ζ (0 is the undamped spring).
    pub damping_ratios: Vec<f64>,
    /// Formats the limit is measured in.
    pub formats: Vec<NumberFormat>,
}

impl StabilityConfig {
    /// The number of limits the sweep measures: one per integrator, damping ratio and
    /// format.
    pub fn limits(&self) -> usize {
        self.integrators.len() * self.damping_ratios.len() * self.formats.len()
    }

    /// Every scheme; ζ = 0, 0.1, 0.5 and 1; f64 and I32F32.
    pub fn full() -> Self {
        Self {
            integrators: Integrator::ALL.to_vec(),
            damping_ratios: vec![0.0, 0.1, 0.5, 1.0],
            formats: vec![NumberFormat::F64, NumberFormat::I32F32],
        }
    }
}

/// One row of `stability.csv`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StabilityRow {
    /// The scheme.
    pub integrator: Integrator,
    /// Damping ratio ζ.
    pub damping_ratio: f64,
    /// The format the limit was measured in.
    pub format: NumberFormat,
    /// The measured limit.
    pub measured: Measured,
    /// The theoretical limit.
    pub theory: Theory,
}

/// Measures every limit of `config`, by integrator, then ζ, then format.
pub fn run_stability(config: &StabilityConfig) -> Vec<StabilityRow> {
    run_stability_with_progress(config, |_| {})
}

/// [`run_stability`], calling `on_limit` with the number of limits measured after each one
/// (of [`StabilityConfig::limits`]), to show progress.
pub fn run_stability_with_progress(
    config: &StabilityConfig,
    mut on_limit: impl FnMut(usize),
) -> Vec<StabilityRow> {
    let mut rows = Vec::new();
    for &integrator in &config.integrators {
        for &damping_ratio in &config.damping_ratios {
            for &format in &config.formats {
                rows.push(StabilityRow {
                    integrator,
                    damping_ratio,
                    format,
                    measured: bisect(|omega_h| {
                        is_stable_in(format, integrator, damping_ratio, omega_h)
                    }),
                    theory: theory(integrator, damping_ratio),
                });
                on_limit(rows.len());
            }
        }
    }
    rows
}

/// The theoretical limit of `integrator` on the spring with damping ratio ζ (see the
/// module documentation for the sources).
pub fn theory(integrator: Integrator, damping_ratio: f64) -> Theory {
    if integrator == Integrator::ImplicitEuler {
        return Theory::AlwaysStable;
    }
    if damping_ratio == 0.0 {
        return match integrator {
            Integrator::ExplicitEuler => Theory::NeverStable,
            Integrator::Rk4 => Theory::Limit(2.0 * core::f64::consts::SQRT_2),
            _ => Theory::Limit(2.0),
        };
    }
    let Some(&(_, semi_implicit, explicit)) = DAMPED_LIMITS
        .iter()
        .find(|(zeta, _, _)| *zeta == damping_ratio)
    else {
        return Theory::Unknown;
    };
    match integrator {
        Integrator::SemiImplicitEuler => Theory::Limit(semi_implicit),
        Integrator::ExplicitEuler => Theory::Limit(explicit),
        _ => Theory::Unknown,
    }
}

/// The largest ωh in [[`LOWEST`], [`HIGHEST`]] for which `stable` holds, by bisection.
fn bisect(stable: impl Fn(f64) -> bool) -> Measured {
    if !stable(LOWEST) {
        return Measured::NeverStable;
    }
    if stable(HIGHEST) {
        return Measured::AtLeast(HIGHEST);
    }
    let (mut lo, mut hi) = (LOWEST, HIGHEST);
    while hi - lo > RESOLUTION {
        let mid = 0.5 * (lo + hi);
        if stable(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Measured::Limit(lo)
}

/// [`is_stable`] in the scalar type `format` stands for.
pub fn is_stable_in(
    format: NumberFormat,
    integrator: Integrator,
    damping_ratio: f64,
    omega_h: f64,
) -> bool {
    match format {
        NumberFormat::F64 => is_stable::<f64>(integrator, damping_ratio, omega_h),
        NumberFormat::I32F32 => is_stable::<Fx>(integrator, damping_ratio, omega_h),
        NumberFormat::I40F24 => is_stable::<FxI40F24>(integrator, damping_ratio, omega_h),
        NumberFormat::I48F16 => is_stable::<FxI48F16>(integrator, damping_ratio, omega_h),
    }
}

/// Whether `integrator` keeps the spring's amplitude bounded at step ωh with damping
/// ratio ζ, by the test of the module documentation.
pub fn is_stable<R: Real>(integrator: Integrator, damping_ratio: f64, omega_h: f64) -> bool {
    let rest = R::from_int(REST_LENGTH);
    let desc = ParticlesDesc {
        integrator,
        capacity: 1,
        particles: vec![ParticleDesc {
            position: Vec3::new(rest + R::ONE, R::ZERO, R::ZERO),
            velocity: Vec3::ZERO,
            mass: R::ONE,
            group: 0,
            lifetime: R::ZERO,
        }],
        forces: vec![ForceDesc::AnchoredSpring {
            particle: 0,
            anchor: Vec3::ZERO,
            spring: SpringDesc {
                stiffness: R::ONE,
                damping: R::from_f64(2.0 * damping_ratio),
                rest_length: rest,
            },
        }],
        ..ParticlesDesc::default()
    };
    let mut system = ParticleSystem::from_desc(&desc).expect("a valid spring");
    let h = R::from_f64(omega_h);
    let rest_m = f64::from(REST_LENGTH);
    let mut rng = Pcg32::new(1, 1);
    let quarter = STEPS / 4;
    let (mut first_max, mut last_max) = (0.0f64, 0.0f64);
    for n in 0..STEPS {
        system.step(h, Vec3::ZERO, &mut rng);
        let u = system.positions()[0].x.to_f64() - rest_m;
        let u_dot = system.velocities()[0].x.to_f64();
        let amplitude = u.hypot(u_dot);
        if !amplitude.is_finite() || amplitude > DIVERGED {
            return false;
        }
        if n < quarter {
            first_max = first_max.max(amplitude);
        } else if n >= STEPS - quarter {
            last_max = last_max.max(amplitude);
        }
    }
    last_max <= GROWTH_LIMIT * first_max
}
