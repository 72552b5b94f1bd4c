//! What floats: the submerged part of a column, a sphere and a box under a surface, and
//! the float force generator built on it.
//!
//! Buoyancy is Archimedes' force, the weight of the water displaced, F = −ρ V_sub g
//! (N, opposite gravity g in m/s², ρ in kg/m³, V_sub the submerged volume in m³), acting at
//! the centre of the submerged volume; drag is linear, F = −k m f v (k the drag rate in
//! 1/s, m the mass in kg, f = V_sub / V the submerged fraction, v the velocity in m/s).
//! Explicit drag is stable while k h < 2 for a step of h seconds.

use crate::math::{Real, Vec3};

/// The fraction (0 to 1) of a vertical column of `height` (m) centred at `y` (m) that lies
/// below the surface at `surface` (m): (surface − (y − height/2)) / height, clamped.
pub fn column_fraction<R: Real>(y: R, height: R, surface: R) -> R {
    let bottom = y - height * R::HALF;
    ((surface - bottom) / height).clamp(R::ZERO, R::ONE)
}

/// The volume (m³) of a sphere of `radius` r (m) centred at `y` (m) below the surface at
/// `surface` (m): the cap of depth d = surface − (y − r), clamped to 0 … 2r,
/// V = π d² (3r − d) / 3.
pub fn sphere_submerged_volume<R: Real>(y: R, radius: R, surface: R) -> R {
    let d = (surface - (y - radius)).clamp(R::ZERO, radius * R::TWO);
    R::PI * d * d * (radius * R::from_int(3) - d) / R::from_int(3)
}

/// The volume (m³) of a box of world-frame vertical half extent `half_height` (m) and
/// volume `volume` (m³), centred at `y` (m), below the surface at `surface` (m), taken as
/// a horizontal slab: volume · (surface − (y − half_height)) / (2 half_height), clamped to
/// 0 … volume.
pub fn slab_submerged_volume<R: Real>(y: R, half_height: R, volume: R, surface: R) -> R {
    volume * column_fraction(y, half_height * R::TWO, surface)
}

/// The float force generator: buoyancy −ρ V_sub g plus linear drag −k m f v on a body of
/// mass `mass` (kg) and volume `volume` (m³) moving at `velocity` (m/s) with `submerged`
/// m³ under water (N).
pub fn float_force<R: Real>(
    gravity: Vec3<R>,
    density: R,
    submerged: R,
    volume: R,
    mass: R,
    drag: R,
    velocity: Vec3<R>,
) -> Vec3<R> {
    let fraction = (submerged / volume).clamp(R::ZERO, R::ONE);
    gravity * -(density * submerged) - velocity * (drag * mass * fraction)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Fx;

    #[test]
    fn a_column_is_submerged_by_the_depth_of_its_bottom() {
        assert_eq!(
            column_fraction(Fx::from_f64(1.0), Fx::from_f64(0.5), Fx::from_f64(0.0)),
            Fx::ZERO
        );
        assert_eq!(
            column_fraction(Fx::from_f64(-1.0), Fx::from_f64(0.5), Fx::from_f64(0.0)),
            Fx::ONE
        );
        let half =
            column_fraction(Fx::from_f64(0.0), Fx::from_f64(0.5), Fx::from_f64(0.0)).to_f64();
        assert!((half - 0.5).abs() < 1e-9);
    }

    #[test]
    fn a_sphere_cap_gives_half_and_whole_volumes() {
        let r = 0.5;
        let whole = 4.0 / 3.0 * std::f64::consts::PI * r * r * r; // ok-det: test reference
        let full = sphere_submerged_volume(Fx::from_f64(-2.0), Fx::from_f64(r), Fx::from_f64(0.0))
            .to_f64();
        let half =
            sphere_submerged_volume(Fx::from_f64(0.0), Fx::from_f64(r), Fx::from_f64(0.0)).to_f64();
        assert!((full - whole).abs() < 1e-6 * whole, "{full} vs {whole}");
        assert!(
            (half - whole / 2.0).abs() < 1e-6 * whole,
            "{half} vs {}",
            whole / 2.0
        );
        assert_eq!(
            sphere_submerged_volume(Fx::from_f64(2.0), Fx::from_f64(r), Fx::from_f64(0.0)),
            Fx::ZERO
        );
    }

    #[test]
    fn a_floating_body_feels_its_displaced_weight_and_drag() {
        let g = Vec3::new(Fx::ZERO, Fx::from_f64(-10.0), Fx::ZERO);
        let v = Vec3::new(Fx::from_f64(1.0), Fx::ZERO, Fx::ZERO);
        let f = float_force(
            g,
            Fx::from_f64(1000.0),
            Fx::from_f64(0.001),
            Fx::from_f64(0.002),
            Fx::from_f64(2.0),
            Fx::from_f64(3.0),
            v,
        );
        assert!((f.y.to_f64() - 10.0).abs() < 1e-6);
        assert!((f.x.to_f64() + 3.0).abs() < 1e-6, "drag −k m f v = −3 N");
    }
}
