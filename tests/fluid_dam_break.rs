//! The dam break against Martin & Moyce (1952): the surge front Z = x/a against
//! T = t √(2g/a), as is and with the customary +0.175 shift in T for the gate's opening.
//! The measured table is `tests/data/martin_moyce_1952_n2_a2.25in_surge_front.csv`.
//!
//! Each run also checks, at every step, that the particle count is conserved, that no
//! particle has passed the floor or a wall, that nothing saturated, and that the mean
//! density error (compression) stays within the solver's bound: 1 % for WCSPH, 0.1 % for
//! DFSPH.

use fixstep::fluid::{FluidSolver, FluidSystem, presets};
use fixstep::math::saturation::count_saturations;
use fixstep::math::{Fx, Real, Vec3};

const TABLE: &str = include_str!("data/martin_moyce_1952_n2_a2.25in_surge_front.csv");

/// (T, Z) rows of the measured table.
fn measured() -> Vec<(f64, f64)> {
    TABLE
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('T'))
        .map(|l| {
            let (t, z) = l.split_once(',').expect("two columns");
            (t.parse().expect("T"), z.parse().expect("Z"))
        })
        .collect()
}

/// Runs the dam break and returns the simulated (T, Z) every step of `1/rate` s up to
/// T = 3.5, and the largest mean density error seen; the particle count and the walls are
/// checked at every step.
fn simulate<R: Real>(
    per_width: u32,
    layers: u32,
    solver: FluidSolver,
    rate: i64,
    substeps: u32,
) -> (Vec<(f64, f64)>, f64) {
    let mut desc = presets::dam_break::<R>(per_width, layers, solver);
    desc.substeps = substeps;

    let dt = R::from_ratio(1, rate);
    let mut fluid = FluidSystem::from_desc(&desc, dt).expect("dam break builds");
    let count = fluid.len();
    let gravity = Vec3::new(R::ZERO, R::from_f64(-9.81), R::ZERO);
    let a = presets::dam_break_width::<R>().to_f64();
    let scale = (2.0 * 9.81 / a).sqrt();
    let mut curve = vec![(0.0, fluid.metrics(gravity).front_x / a)];
    let tank = fluid.settings().tank;
    let mut tick = 0;
    let mut worst_density_error: f64 = 0.0;
    while (tick as f64 / rate as f64) * scale < 3.5 {
        fluid.step(dt, gravity);
        tick += 1;
        assert_eq!(fluid.len(), count, "particle count conserved");
        for p in fluid.positions() {
            assert!(p.x >= tank.min.x && p.x <= tank.max.x, "x inside the walls");
            assert!(p.y >= tank.min.y, "above the floor");
            assert!(p.z >= tank.min.z && p.z <= tank.max.z, "z inside the walls");
        }
        let m = fluid.metrics(gravity);
        curve.push((tick as f64 / rate as f64 * scale, m.front_x / a));
        worst_density_error = worst_density_error.max(m.density_error_avg);
    }
    (curve, worst_density_error)
}

/// RMS of (Z_sim − Z)/Z over the measured points, the simulated curve interpolated
/// linearly at T − shift.
fn rms_relative_error(curve: &[(f64, f64)], shift: f64) -> f64 {
    let table = measured();
    let mut sum = 0.0;
    for &(t, z) in &table {
        let ts = t - shift;
        let k = curve
            .partition_point(|p| p.0 < ts)
            .clamp(1, curve.len() - 1);
        let (t0, z0) = curve[k - 1];
        let (t1, z1) = curve[k];
        let zs = if ts <= t0 {
            z0
        } else {
            z0 + (z1 - z0) * (ts - t0) / (t1 - t0)
        };
        sum += ((zs - z) / z).powi(2);
    }
    (sum / table.len() as f64).sqrt()
}

/// Runs the dam break and checks the front and the density error.
fn check(solver: FluidSolver, rate: i64, substeps: u32, density_bound: f64) {
    let ((curve, density_error), saturations) =
        count_saturations(|| simulate::<Fx>(10, 3, solver, rate, substeps));
    let plain = rms_relative_error(&curve, 0.0);
    let shifted = rms_relative_error(&curve, 0.175);
    eprintln!(
        "{solver:?}: RMS relative error {plain:.4}, shifted {shifted:.4}; worst mean density \
         error {density_error:.5}"
    );
    assert_eq!(saturations, 0, "saturations");
    assert!(plain <= 0.10, "RMS relative error {plain}");
    assert!(
        shifted <= 0.05,
        "RMS relative error with the +0.175 shift {shifted}"
    );
    assert!(
        density_error <= density_bound,
        "mean density error {density_error}"
    );
}

/// DFSPH at 10 particles across a, 3 deep, Δt = 1 ms.
#[test]
fn dfsph_dam_break_front_follows_martin_and_moyce() {
    check(FluidSolver::Dfsph, 1000, 1, 0.001);
}

/// WCSPH at 10 particles across a, 3 deep, c = 20 m/s, Δt = 0.1 ms.
#[test]
fn wcsph_dam_break_front_follows_martin_and_moyce() {
    check(FluidSolver::Wcsph, 1000, 10, 0.01);
}
