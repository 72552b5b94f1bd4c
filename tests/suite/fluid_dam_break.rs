//! The dam break against Martin & Moyce (1952): the surge front Z = x/a against
//! T = t √(2g/a), as is and with the customary +0.175 shift in T for the gate's opening.
//! The measured table is `tests/suite/data/martin_moyce_1952_n2_a2.25in_surge_front.csv`.
//!
//! Each run also checks, at every step, that the particle count is conserved, that no
//! particle has passed the floor or a wall, that nothing saturated, and that the mean
//! density error (compression) stays within the solver's bound: 1 % for WCSPH, 0.1 % for
//! DFSPH.

use fixstep::fluid::{FluidSolver, FluidSystem};
use fixstep::math::saturation::count_saturations;
use fixstep::math::{Fx, Real, Vec3};
use fixstep_scenes::fluid as presets;

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

/// How a run divides its steps.
#[derive(Clone, Copy)]
struct Stepping {
    /// Steps per second.
    rate: i64,
    /// Fluid substeps per step; with a CFL number, the most.
    substeps: u32,
    /// The CFL number of adaptive substeps, 0 for a fixed count.
    cfl: f64,
}

/// What a run found.
struct Run {
    /// (T, Z) after every step.
    curve: Vec<(f64, f64)>,
    /// The largest mean density error seen.
    density_error: f64,
    /// Fluid substeps taken, summed over the steps.
    substeps: u64,
    /// Steps taken.
    steps: u64,
}

/// Runs the dam break and returns the simulated (T, Z) every step of `1/rate` s up to
/// T = 3.5, the largest mean density error seen and the substeps taken; the particle count
/// and the walls are checked at every step.
fn simulate<R: Real>(per_width: u32, layers: u32, solver: FluidSolver, stepping: Stepping) -> Run {
    let Stepping {
        rate,
        substeps,
        cfl,
    } = stepping;
    let mut desc = presets::dam_break::<R>(per_width, layers, solver);
    desc.substeps = substeps;
    desc.cfl = R::from_f64(cfl);

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
    let mut taken = 0;
    while (tick as f64 / rate as f64) * scale < 3.5 {
        fluid.step(dt, gravity);
        taken += u64::from(fluid.last_substeps());
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
    Run {
        curve,
        density_error: worst_density_error,
        substeps: taken,
        steps: tick,
    }
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

/// Runs the dam break and checks the front and the density error; returns the run.
fn check(solver: FluidSolver, stepping: Stepping, density_bound: f64) -> Run {
    let (run, saturations) = count_saturations(|| simulate::<Fx>(10, 3, solver, stepping));
    let (curve, density_error) = (&run.curve, run.density_error);
    let plain = rms_relative_error(curve, 0.0);
    let shifted = rms_relative_error(curve, 0.175);
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
    run
}

/// DFSPH at 10 particles across a, 3 deep, Δt = 1 ms.
#[test]
fn dfsph_dam_break_front_follows_martin_and_moyce() {
    let stepping = Stepping {
        rate: 1000,
        substeps: 1,
        cfl: 0.0,
    };
    check(FluidSolver::Dfsph, stepping, 0.001);
}

/// DFSPH at 10 particles across a, 3 deep, in steps of 5 ms whose substeps adapt to the
/// flow at CFL number 0.12 (no particle travels more than 0.12 H = 1.4 mm in a substep),
/// at most the 5 that the time-step limit asks of a fixed count for the fastest front
/// (u = c/10 = 2 m/s): the front within the same bounds, in fewer substeps. Longer
/// substeps leave more compression that the solver's prediction does not see (measured:
/// a worst mean of 0.12 % here, 0.16 % at CFL 0.2, against 0.08 % at the fixed 5), so the
/// density is held to the weakly compressible bound of 1 %, not DFSPH's 0.1 %.
#[test]
fn dfsph_dam_break_with_adaptive_substeps_follows_martin_and_moyce() {
    let stepping = Stepping {
        rate: 200,
        substeps: 5,
        cfl: 0.12,
    };
    let run = check(FluidSolver::Dfsph, stepping, 0.01);
    let mean = run.substeps as f64 / run.steps as f64;
    eprintln!("{mean:.2} substeps per step over {} steps", run.steps);
    assert!(
        mean <= 4.5,
        "{mean} substeps per step, where the fixed count takes 5"
    );
    assert!(run.substeps >= run.steps, "at least one substep a step");
}

/// WCSPH at 10 particles across a, 3 deep, c = 20 m/s, Δt = 0.1 ms.
#[test]
fn wcsph_dam_break_front_follows_martin_and_moyce() {
    let stepping = Stepping {
        rate: 1000,
        substeps: 10,
        cfl: 0.0,
    };
    check(FluidSolver::Wcsph, stepping, 0.01);
}
