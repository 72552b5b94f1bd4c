// ok-det: the Kepler reference solution in f64 for the accuracy benchmark; never inside a tick.
//! The exact Kepler orbit from Kepler's equation, in f64.
//!
//! Reduced two-body problem q'' = −μ q/|q|³ with μ = 1, semi-major axis a = 1 (so the mean
//! motion is n = √(μ/a³) = 1 rad/s and the period 2π s), eccentricity e, starting at
//! periapsis q₀ = (1 − e, 0), p₀ = (0, √((1 + e)/(1 − e))) — the convention of
//! Hairer, Lubich & Wanner, *Geometric Numerical Integration*, §I.2.3, and of
//! `kepler_e0.5_reference.csv` (checked in `tests/tools/bench_accuracy.rs`).

/// The eccentric anomaly E (rad) solving Kepler's equation E − e sin E = M for the mean
/// anomaly M (rad) and eccentricity 0 ≤ e < 1, by Newton's method from E = M + e sin M,
/// to a residual below 10⁻¹⁵.
pub fn eccentric_anomaly(mean_anomaly: f64, eccentricity: f64) -> f64 {
    let mut e_anomaly = mean_anomaly + eccentricity * mean_anomaly.sin();
    for _ in 0..50 {
        let residual = e_anomaly - eccentricity * e_anomaly.sin() - mean_anomaly;
        if residual.abs() < 1e-15 {
            break;
        }
        e_anomaly -= residual / (1.0 - eccentricity * e_anomaly.cos());
    }
    e_anomaly
}

/// Position (m) at time t (s) on the orbit of eccentricity e described above:
/// x = cos E − e, y = √(1 − e²) sin E, with E from Kepler's equation at M = t.
pub fn kepler_position(eccentricity: f64, t: f64) -> [f64; 2] {
    let e_anomaly = eccentric_anomaly(t, eccentricity);
    [
        e_anomaly.cos() - eccentricity,
        (1.0 - eccentricity * eccentricity).sqrt() * e_anomaly.sin(),
    ]
}

/// Speed at periapsis (m/s): |p₀| = √((1 + e)/(1 − e)), along +y.
pub fn periapsis_speed(eccentricity: f64) -> f64 {
    ((1.0 + eccentricity) / (1.0 - eccentricity)).sqrt()
}
