// ok-det: the pendulum reference period in f64 for the accuracy benchmark; never inside a tick.
//! The exact period of the simple pendulum, from the complete elliptic integral of the
//! first kind computed with the arithmetic–geometric mean.

/// The arithmetic–geometric mean of a, b > 0: iterate a ← (a + b)/2, b ← √(ab) until the
/// two agree to a relative 10⁻¹⁵ (quadratic convergence: a handful of iterations).
fn arithmetic_geometric_mean(mut a: f64, mut b: f64) -> f64 {
    for _ in 0..60 {
        if (a - b).abs() <= 1e-15 * a {
            break;
        }
        (a, b) = ((a + b) / 2.0, (a * b).sqrt());
    }
    a
}

/// The complete elliptic integral of the first kind for modulus k (0 ≤ k < 1):
/// K(k) = ∫₀^{π/2} dφ / √(1 − k² sin² φ) = π / (2 AGM(1, √(1 − k²))).
pub fn complete_elliptic_k(modulus: f64) -> f64 {
    core::f64::consts::FRAC_PI_2 / arithmetic_geometric_mean(1.0, (1.0 - modulus * modulus).sqrt())
}

/// Period (s) of the pendulum θ'' = −ω₀² sin θ released from rest at amplitude θ₀ (rad,
/// 0 ≤ θ₀ < π), with ω₀ = √(g/L) in rad/s: T = 4 K(sin(θ₀/2)) / ω₀.
pub fn pendulum_period(amplitude: f64, omega0: f64) -> f64 {
    4.0 * complete_elliptic_k((amplitude / 2.0).sin()) / omega0
}
