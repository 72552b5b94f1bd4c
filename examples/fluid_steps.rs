//! Steps the benchmark's fluid (`presets::cube`) or a dam break (`presets::dam_break`) and
//! prints the mean time per step and the solver's iterations, for profiling
//! (`perf record ./target/release/examples/fluid_steps`). The benchmark figures come from
//! `cargo bench --bench fluid`, not from here.
//!
//! Usage: `cargo run --release --example fluid_steps [dfsph|wcsph|dam] [N] [RATE]
//! [SUBSTEPS] [WARM] [STEPS] [fx|f64] [TOLERANCE] [SOUND] [CFL]`: N³ particles, steps of
//! 1/RATE s in SUBSTEPS fluid substeps (at most SUBSTEPS, adaptive, when CFL is given), WARM steps untimed, then STEPS timed (default
//! `dfsph 20 200 3 20 10 fx`: the DFSPH case of the benchmark, 8000 particles at
//! Δt = 5 ms). TOLERANCE sets the DFSPH tolerance on the mean density error (default
//! 0.0005) and SOUND the speed of sound, m/s (default 20; the time-step limit allows one
//! DFSPH substep of 5 ms at 1 cm spacing from SOUND = 4 down). `dam` runs DFSPH on
//! Martin & Moyce's column with N particles across its width, 2N up and N/2 deep (N³
//! particles) instead of the cube: `dam 20 200 9 0 22 fx 0.05` is the peer benchmark's
//! `dam_break` (8000 particles, the whole collapse from the start) at a loose tolerance, and
//! `dam 20 200 9 0 22 fx 0.05 20 0.3` its fastest row (adaptive substeps at CFL 0.3).

use std::time::{Duration, Instant};

use fixstep::fluid::{FluidSolver, FluidSystem};
use fixstep::math::{Fx, Real, Vec3};
use fixstep_scenes::fluid as presets;

/// The command line's settings.
struct Run {
    solver: FluidSolver,
    /// The dam break instead of the cube.
    dam: bool,
    n: u32,
    rate: i64,
    substeps: u32,
    warm: u32,
    steps: u32,
    tolerance: Option<f64>,
    sound: Option<f64>,
    cfl: Option<f64>,
}

fn run<R: Real>(r: &Run) {
    let dt = R::from_ratio(1, r.rate);
    let gravity = Vec3::new(R::ZERO, R::from_f64(-9.81), R::ZERO);
    let mut desc = if r.dam {
        let mut desc = presets::dam_break::<R>(r.n, r.n / 2, r.solver);
        desc.substeps = r.substeps;
        desc
    } else {
        presets::cube::<R>(r.n, r.solver, r.substeps)
    };
    if let Some(tolerance) = r.tolerance {
        desc.max_density_error = R::from_f64(tolerance);
    }
    if let Some(sound) = r.sound {
        desc.speed_of_sound = R::from_f64(sound);
    }
    if let Some(cfl) = r.cfl {
        desc.cfl = R::from_f64(cfl);
    }
    let mut fluid = match FluidSystem::from_desc(&desc, dt) {
        Ok(fluid) => fluid,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(2);
        }
    };
    for _ in 0..r.warm {
        fluid.step(dt, gravity);
    }
    let mut elapsed = Duration::ZERO;
    let mut iterations = 0;
    let mut substeps = 0;
    for _ in 0..r.steps {
        let start = Instant::now();
        fluid.step(dt, gravity);
        elapsed += start.elapsed();
        iterations += fluid.last_iterations();
        substeps += fluid.last_substeps();
    }
    let m = fluid.metrics(gravity);
    println!(
        "{} {:?} {} particles, dt 1/{} s in {:.2} substeps: {:?} per step over {} steps; \
         {:.1} solver iterations per step; mean density error {:.5}, max speed \
         {:.3} m/s",
        R::NAME,
        r.solver,
        fluid.len(),
        r.rate,
        f64::from(substeps) / f64::from(r.steps.max(1)),
        elapsed / r.steps.max(1),
        r.steps,
        f64::from(iterations) / f64::from(r.steps.max(1)),
        m.density_error_avg,
        m.max_speed,
    );
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let arg = |i: usize, default: &str| args.get(i).cloned().unwrap_or_else(|| default.into());
    let number = |i: usize, default: &str| -> u32 {
        arg(i, default).parse().unwrap_or_else(|_| {
            eprintln!("error: argument {} must be a whole number", i + 1);
            std::process::exit(2);
        })
    };
    let decimal = |i: usize| -> Option<f64> {
        args.get(i).map(|a| {
            a.parse().unwrap_or_else(|_| {
                eprintln!("error: argument {} must be a number", i + 1);
                std::process::exit(2);
            })
        })
    };
    let scene = arg(0, "dfsph");
    let solver = match scene.as_str() {
        "wcsph" => FluidSolver::Wcsph,
        _ => FluidSolver::Dfsph,
    };
    let r = Run {
        solver,
        dam: scene == "dam",
        n: number(1, "20"),
        rate: i64::from(number(2, "200")),
        substeps: number(3, "3"),
        warm: number(4, "20"),
        steps: number(5, "10"),
        tolerance: decimal(7),
        sound: decimal(8),
        cfl: decimal(9),
    };
    match arg(6, "fx").as_str() {
        "f64" => run::<f64>(&r),
        _ => run::<Fx>(&r),
    }
}
