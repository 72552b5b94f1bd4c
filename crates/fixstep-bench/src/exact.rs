// ok-det: closed-form reference solutions in f64 for the accuracy benchmark; never inside a tick.
//! Closed-form solutions of the benchmark problems that have one, in f64.
//!
//! They match the tables in the project's reference folder (checked in
//! `tests/tools/bench_accuracy.rs`): `damped_oscillator_reference.csv` and
//! `projectile_linear_drag_reference.csv`, both computed with mpmath from the same formulas.

/// Displacement of the harmonic oscillator x'' = −ω² x released from rest at x₀ (m):
/// x(t) = x₀ cos ωt, with ω in rad/s and t in s.
pub fn harmonic_displacement(x0: f64, omega: f64, t: f64) -> f64 {
    x0 * (omega * t).cos()
}

/// Displacement of the underdamped oscillator x'' + 2ζω₀ x' + ω₀² x = 0 (0 ≤ ζ < 1)
/// released from rest at x₀ (m):
/// x(t) = x₀ e^{−ζω₀t} (cos ω_d t + (ζω₀/ω_d) sin ω_d t), ω_d = ω₀ √(1 − ζ²),
/// with ω₀ in rad/s and t in s.
pub fn damped_displacement(x0: f64, omega0: f64, zeta: f64, t: f64) -> f64 {
    let omega_d = omega0 * (1.0 - zeta * zeta).sqrt();
    let decay = (-zeta * omega0 * t).exp();
    x0 * decay * ((omega_d * t).cos() + zeta * omega0 / omega_d * (omega_d * t).sin())
}

/// Position (m) of a projectile under gravity g (m/s², pointing down −y) and linear drag
/// m dv/dt = m g − b v, with time constant τ = m/b (s), launched from the origin with
/// velocity (v₀ₓ, v₀ᵧ) (m/s):
/// x(t) = v₀ₓ τ (1 − e^{−t/τ}), y(t) = (v₀ᵧ + gτ) τ (1 − e^{−t/τ}) − gτt.
pub fn projectile_position(velocity: [f64; 2], g: f64, tau: f64, t: f64) -> [f64; 2] {
    let spent = tau * (1.0 - (-t / tau).exp());
    [
        velocity[0] * spent,
        (velocity[1] + g * tau) * spent - g * tau * t,
    ]
}
