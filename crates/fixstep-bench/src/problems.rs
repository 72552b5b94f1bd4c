// ok-det: benchmark problems; the simulation runs in the chosen Real format, only the set-up values and the error against the f64 reference solution are f64.
//! The five accuracy problems, each simulated with the engine's [`ParticleSystem`] and
//! measured against its exact solution.
//!
//! | problem | forces | measured at | error |
//! |---|---|---|---|
//! | `harmonic` | anchored spring k = 1 N/m, m = 1 kg (ω = 1 rad/s) | t = 10 s | position, m |
//! | `damped` | the same spring with damping c = 0.2 N·s/m (ζ = 0.1) | t = 10 s | position, m |
//! | `kepler` | point gravity GM = 1 m³/s², e = 0.5 | t = 10 s | position, m |
//! | `projectile` | gravity 9.81 m/s², linear drag b = 0.5 kg/s (τ = 2 s), 20 m/s at 45° | t = 2 s | position, m |
//! | `pendulum` | θ'' = −sin θ as a user force, θ₀ = 90° | t = 12 s | period, s |
//!
//! The springs have a rest length of 2 m and start stretched by 1 m, so the particle never
//! comes near its anchor and the force is exactly linear in the displacement.
//!
//! The pendulum needs a constraint the particle system does not have, so its 1-D equation
//! θ'' = −(g/L) sin θ (g/L = 1/s²) is integrated by the particle system with θ as the x
//! coordinate and [`PendulumForce`] as a registered user force: the same seven integrators
//! and the format's own `sin`, and no integrator code outside the engine. Its period is
//! measured between the first and third zero crossings of θ (at T/4 and 5T/4), each located
//! within its step by cubic Hermite interpolation of (θ, θ'), which is accurate to O(h⁴)
//! and so does not hide the order of any scheme.

use super::elliptic::pendulum_period;
use super::exact::{damped_displacement, harmonic_displacement, projectile_position};
use super::kepler_equation::{kepler_position, periapsis_speed};
use super::pendulum_force::PendulumForce;
use fixstep::math::rng::Pcg32;
use fixstep::math::{Real, Vec3};
use fixstep::particles::{
    ForceDesc, Integrator, ParticleDesc, ParticleSystem, ParticlesDesc, SpringDesc,
};

/// One accuracy problem.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Problem {
    /// x'' = −x, x(0) = 1 m, v(0) = 0; exact x = cos t.
    Harmonic,
    /// x'' + 0.2 x' + x = 0 (ζ = 0.1), x(0) = 1 m, v(0) = 0; exact closed form.
    Damped,
    /// q'' = −q/|q|³, e = 0.5 from periapsis; exact from Kepler's equation.
    Kepler,
    /// v' = g − v/τ, τ = 2 s, 20 m/s at 45°; exact closed form.
    Projectile,
    /// θ'' = −sin θ, θ₀ = π/2; exact period 4 K(sin(π/4)) ≈ 7.4163 s.
    Pendulum,
}

/// What one run of a problem measured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Outcome {
    /// Distance from the exact answer (m, or s for the pendulum's period); infinite when
    /// the run did not produce an answer (the pendulum went over the top).
    pub error: f64,
    /// The measured quantity itself (the final position, or the period in the first
    /// component), to compare formats with each other at the same step.
    pub observable: [f64; 3],
    /// Steps taken.
    pub steps: u64,
}

/// Rest length of the oscillators' springs, m.
const SPRING_REST_LENGTH: i32 = 2;
/// Damping ratio of the damped oscillator.
const DAMPING_RATIO: f64 = 0.1;
/// Eccentricity of the Kepler orbit.
const ECCENTRICITY: f64 = 0.5;
/// Standard gravity for the projectile, m/s².
const GRAVITY: f64 = 9.81;
/// Drag time constant τ = m/b of the projectile, s (m = 1 kg, b = 0.5 kg/s).
const DRAG_TIME_CONSTANT: f64 = 2.0;
/// Launch speed of the projectile, m/s, at 45°.
const LAUNCH_SPEED: f64 = 20.0;
/// Pendulum amplitude, rad (90°).
const PENDULUM_AMPLITUDE: f64 = core::f64::consts::FRAC_PI_2;

const BODY: usize = 0;

impl Problem {
    /// Every problem, in report order.
    pub const ALL: [Self; 5] = [
        Self::Harmonic,
        Self::Damped,
        Self::Kepler,
        Self::Projectile,
        Self::Pendulum,
    ];

    /// The name used in reports and CSV files.
    pub const fn name(self) -> &'static str {
        match self {
            Self::Harmonic => "harmonic",
            Self::Damped => "damped",
            Self::Kepler => "kepler",
            Self::Projectile => "projectile",
            Self::Pendulum => "pendulum",
        }
    }

    /// A one-line description for tables and plots.
    pub const fn title(self) -> &'static str {
        match self {
            Self::Harmonic => "harmonic oscillator, ω = 1, x(10 s)",
            Self::Damped => "damped oscillator, ζ = 0.1, x(10 s)",
            Self::Kepler => "Kepler orbit, e = 0.5, q(10 s)",
            Self::Projectile => "projectile, linear drag τ = 2 s, x(2 s)",
            Self::Pendulum => "pendulum, 90° amplitude, period",
        }
    }

    /// Simulated time, s.
    pub const fn end_time(self) -> u32 {
        match self {
            Self::Harmonic | Self::Damped | Self::Kepler => 10,
            Self::Projectile => 2,
            Self::Pendulum => 12,
        }
    }

    /// The coarsest step of the sweep is 2^−k s for this k.
    pub const fn coarsest_log2_inverse_step(self) -> u32 {
        match self {
            Self::Harmonic | Self::Damped | Self::Projectile => 2,
            Self::Kepler | Self::Pendulum => 4,
        }
    }

    /// True when a force depends on the velocity (spring damping, drag). The schemes then
    /// evaluate it with the velocity they have at hand and may lose an order (see
    /// [`fixstep::particles::integrators`]).
    pub const fn has_velocity_dependent_force(self) -> bool {
        matches!(self, Self::Damped | Self::Projectile)
    }

    /// Simulates the problem in format `R` with `integrator` and step h = 2^−`log2_inverse_step`
    /// s, and measures the result against the exact solution.
    pub fn run<R: Real>(self, integrator: Integrator, log2_inverse_step: u32) -> Outcome {
        let h = R::from_ratio(1, 1 << log2_inverse_step);
        let steps = u64::from(self.end_time()) << log2_inverse_step;
        let t = f64::from(self.end_time());
        let rest = f64::from(SPRING_REST_LENGTH);
        match self {
            Self::Harmonic => {
                let exact = [rest + harmonic_displacement(1.0, 1.0, t), 0.0, 0.0];
                let system = oscillator(integrator, R::ZERO);
                run_to_end(system, Vec3::ZERO, h, steps, exact)
            }
            Self::Damped => {
                let displacement = damped_displacement(1.0, 1.0, DAMPING_RATIO, t);
                let system = oscillator(integrator, R::from_f64(2.0 * DAMPING_RATIO));
                run_to_end(
                    system,
                    Vec3::ZERO,
                    h,
                    steps,
                    [rest + displacement, 0.0, 0.0],
                )
            }
            Self::Kepler => {
                let [x, y] = kepler_position(ECCENTRICITY, t);
                run_to_end(kepler(integrator), Vec3::ZERO, h, steps, [x, y, 0.0])
            }
            Self::Projectile => {
                let component = LAUNCH_SPEED * core::f64::consts::FRAC_1_SQRT_2;
                let [x, y] =
                    projectile_position([component, component], GRAVITY, DRAG_TIME_CONSTANT, t);
                let gravity = Vec3::new(R::ZERO, R::from_f64(-GRAVITY), R::ZERO);
                run_to_end(projectile(integrator), gravity, h, steps, [x, y, 0.0])
            }
            Self::Pendulum => run_pendulum(integrator, h, steps),
        }
    }
}

/// Steps `system` `steps` times by `h` under `gravity` (m/s²) and measures the distance of
/// the particle from `exact` (m).
fn run_to_end<R: Real>(
    mut system: ParticleSystem<R>,
    gravity: Vec3<R>,
    h: R,
    steps: u64,
    exact: [f64; 3],
) -> Outcome {
    let mut rng = Pcg32::new(1, 1);
    for _ in 0..steps {
        system.step(h, gravity, &mut rng);
    }
    let observable = system.positions()[BODY].to_f64();
    let error = observable
        .iter()
        .zip(exact)
        .map(|(got, want)| (got - want).powi(2))
        .sum::<f64>()
        .sqrt();
    Outcome {
        error,
        observable,
        steps,
    }
}

/// A 1 kg particle on an anchored spring of stiffness 1 N/m (ω = 1 rad/s), rest length
/// 2 m and the given damping (N·s/m), released from rest stretched by 1 m.
fn oscillator<R: Real>(integrator: Integrator, damping: R) -> ParticleSystem<R> {
    let rest = R::from_int(SPRING_REST_LENGTH);
    single_particle(
        integrator,
        Vec3::new(rest + R::ONE, R::ZERO, R::ZERO),
        Vec3::ZERO,
        vec![ForceDesc::AnchoredSpring {
            particle: 0,
            anchor: Vec3::ZERO,
            spring: SpringDesc {
                stiffness: R::ONE,
                damping,
                rest_length: rest,
            },
        }],
    )
}

/// A 1 kg body in the point gravity GM = 1 m³/s² of the origin, at periapsis of the orbit
/// with eccentricity 0.5 and semi-major axis 1 m.
fn kepler<R: Real>(integrator: Integrator) -> ParticleSystem<R> {
    single_particle(
        integrator,
        Vec3::new(R::from_f64(1.0 - ECCENTRICITY), R::ZERO, R::ZERO),
        Vec3::new(R::ZERO, R::from_f64(periapsis_speed(ECCENTRICITY)), R::ZERO),
        vec![ForceDesc::PointGravity {
            centre: Vec3::ZERO,
            gm: R::ONE,
            softening: R::ZERO,
            group: None,
        }],
    )
}

/// A 1 kg projectile at the origin, launched at 20 m/s and 45° in the x–y plane, under the
/// world gravity and linear drag b = 0.5 kg/s.
fn projectile<R: Real>(integrator: Integrator) -> ParticleSystem<R> {
    let component = R::from_f64(LAUNCH_SPEED * core::f64::consts::FRAC_1_SQRT_2);
    single_particle(
        integrator,
        Vec3::ZERO,
        Vec3::new(component, component, R::ZERO),
        vec![
            ForceDesc::Gravity {
                scale: R::ONE,
                group: None,
            },
            ForceDesc::LinearDrag {
                coefficient: R::from_f64(1.0 / DRAG_TIME_CONSTANT),
                group: None,
            },
        ],
    )
}

/// A system of one 1 kg particle with the given start and forces.
fn single_particle<R: Real>(
    integrator: Integrator,
    position: Vec3<R>,
    velocity: Vec3<R>,
    forces: Vec<ForceDesc<R>>,
) -> ParticleSystem<R> {
    let desc = ParticlesDesc {
        integrator,
        capacity: 1,
        particles: vec![ParticleDesc {
            position,
            velocity,
            mass: R::ONE,
            group: 0,
            lifetime: R::ZERO,
        }],
        forces,
        ..ParticlesDesc::default()
    };
    ParticleSystem::from_desc(&desc).expect("the benchmark problems are valid scenes")
}

/// Runs the pendulum for `steps` steps of `h` and measures its period between the first
/// and the third zero crossing of θ.
fn run_pendulum<R: Real>(integrator: Integrator, h: R, steps: u64) -> Outcome {
    let mut system = single_particle(
        integrator,
        Vec3::new(R::from_f64(PENDULUM_AMPLITUDE), R::ZERO, R::ZERO),
        Vec3::ZERO,
        vec![ForceDesc::User {
            name: "pendulum".to_owned(),
        }],
    );
    system.register_user_force(
        "pendulum",
        Box::new(PendulumForce {
            omega0_squared: R::ONE,
        }),
    );
    let mut rng = Pcg32::new(1, 1);
    let h_seconds = h.to_f64();
    let mut crossings = Vec::with_capacity(3);
    let mut before = angle_state(&system);
    for n in 0..steps {
        system.step(h, Vec3::ZERO, &mut rng);
        let after = angle_state(&system);
        if (before.0 > 0.0) != (after.0 > 0.0) {
            let fraction = hermite_root(before, after, h_seconds);
            crossings.push((n as f64 + fraction) * h_seconds);
            if crossings.len() == 3 {
                break;
            }
        }
        before = after;
    }
    let exact = pendulum_period(PENDULUM_AMPLITUDE, 1.0);
    let (error, period) = match crossings[..] {
        [first, _, third] => ((third - first - exact).abs(), third - first),
        _ => (f64::INFINITY, f64::NAN),
    };
    Outcome {
        error,
        observable: [period, 0.0, 0.0],
        steps,
    }
}

/// (θ, θ') of the pendulum particle, rad and rad/s.
fn angle_state<R: Real>(system: &ParticleSystem<R>) -> (f64, f64) {
    (
        system.positions()[BODY].x.to_f64(),
        system.velocities()[BODY].x.to_f64(),
    )
}

/// Where in [0, 1] the cubic Hermite interpolant of a step crosses zero, given (θ, θ') at
/// both ends and the step h (s): p(s) = h00 θ₀ + h10 h θ₀' + h01 θ₁ + h11 h θ₁', solved by
/// bisection (θ changes sign over the step, so p does too).
fn hermite_root(start: (f64, f64), end: (f64, f64), h: f64) -> f64 {
    let p = |s: f64| {
        let s2 = s * s;
        let s3 = s2 * s;
        (2.0 * s3 - 3.0 * s2 + 1.0) * start.0
            + (s3 - 2.0 * s2 + s) * h * start.1
            + (-2.0 * s3 + 3.0 * s2) * end.0
            + (s3 - s2) * h * end.1
    };
    let (mut lo, mut hi) = (0.0, 1.0);
    let start_positive = start.0 > 0.0;
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if (p(mid) > 0.0) == start_positive {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}
