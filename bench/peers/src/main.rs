//! fixstep beside Rapier 0.36 and salva3d 0.11 on identical scenes, in one process: the
//! engines take turns (A B A B …) for each scene, every run starts from a freshly built
//! world, and the table gives each engine's median time per step over the rounds, its
//! ratio to fixstep's, and a quality figure computed from the engine's positions in the same
//! way for every engine ([`quality`]). Built once per Rapier mode: `--features
//! enhanced-determinism` for Rapier's cross-platform determinism mode.
//! `scripts/peer-bench.sh` builds and runs both.
//!
//! Everything here also builds for `wasm32-wasip1`, with and without `-C
//! target-feature=+simd128` (fixstep's `simd128` kernels), and runs under Node's WASI
//! (`scripts/wasi-run.mjs`, which passes `FIXSTEP_SIMD` on): `scripts/peer-bench.sh --wasm`
//! builds both with Rapier's enhanced-determinism mode and runs them, what a browser game
//! pays. The clock there is WASI's monotonic `clock_time_get`, behind [`Instant`].
//!
//! Rigid bodies, the same for every engine: dt = 1/60 s, each engine's default solver
//! substeps (Rapier's `num_solver_iterations`, 4; fixstep's, 5 since state version 4), one
//! thread, gravity −9.81 m/s² along y, sleeping off, then `pyramid` and `balls` again with
//! sleeping on. Rapier runs twice: with its default friction model (one friction
//! constraint per manifold plus a twist row, as fixstep solves friction since state version
//! 4) and with Coulomb friction at every contact point.
//!
//! Fluids (`src/scenes.rs`): salva3d 0.11 (DFSPH, f32) beside fixstep's DFSPH, `water` (a
//! cube of 20³ particles 1 cm apart settling in a tank) and `dam_break` (Martin & Moyce's
//! column, 8000 particles), dt = 0.005 s. salva3d takes one substep per step (its CFL
//! control is off in 0.11) and runs twice: with its default tolerance (mean predicted
//! compression 5 %) and with fixstep's (0.05 %). fixstep runs at both tolerances too, with
//! the fixed substep count its time-step limit asks for and, in the dam break, with
//! adaptive substeps (CFL 0.2, and 0.3 at salva3d's tolerance).
//!
//! Scene queries (`queries`, [`queries`]): 100,000 rays and 10,000 sphere overlaps on
//! `balls` and `pyramid` after 300 steps, queries per second of each engine and how often
//! their answers agree. Filters (`filters`): fixstep's `balls` with every body on layer 1
//! (so the collide stage filters pairs) beside the default filter.
//!
//! Characters (`characters`, [`characters`]): 1000 kinematic characters among 10,000 static
//! boxes, fixstep's beside Rapier's `KinematicCharacterController`, ms per tick.
//!
//! Energy (`energy`, [`energy`]): the energy drift of pendulums, a spinning hinge wheel
//! and a touching cradle, fixstep's beside Rapier's (no timing).
//!
//! Usage: `fixstep-peers [ROUNDS] [SCENE …]`, SCENE one of pyramid, balls, falling, water,
//! dam_break, queries, filters, characters, energy; none means every one.

mod characters;
mod energy;
mod fixstep_side;
mod quality;
mod queries;
mod rapier_side;
mod salva_side;
mod scenes;

use scenes::{FIXSTEP_TOLERANCE, FLUID_SCENES, FluidRun, FluidScene, RigidRun, SCENES, Scene};
use std::time::Instant;

/// One rigid-body engine: builds a scene afresh and runs it.
struct Engine {
    name: String,
    run: fn(Scene) -> RigidRun,
}

/// Mean milliseconds per step of `steps` calls of `step` (building excluded).
pub fn time_steps(steps: u32, mut step: impl FnMut()) -> f64 {
    let start = Instant::now();
    for _ in 0..steps {
        step();
    }
    start.elapsed().as_secs_f64() * 1e3 / f64::from(steps)
}

pub fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// The scene's label in the table.
fn label(scene: Scene) -> String {
    if scene.sleeping {
        format!("`{}`, sleeping on", scene.name)
    } else {
        format!("`{}`", scene.name)
    }
}

/// The quality figure with its unit.
fn quality_text(scene: Scene, value: Option<f64>) -> String {
    let what = match scene.name {
        "pyramid" => "max drift",
        "balls" => "deepest overlap",
        "falling" => "max free-fall error",
        "hills" | "hills_mesh" => "lowest centre",
        _ => "",
    };
    value.map_or_else(|| "—".into(), |v| format!("{what} {v:.4} m"))
}

fn main() {
    let mut args = std::env::args().skip(1);
    let rounds: usize = match args.next().map(|a| a.parse()) {
        None => 5,
        Some(Ok(n)) if n > 0 => n,
        Some(_) => {
            eprintln!("error: ROUNDS must be a positive whole number");
            std::process::exit(2);
        }
    };
    let wanted: Vec<String> = args.collect();
    let scenes: Vec<Scene> = SCENES
        .into_iter()
        .filter(|s| wanted.is_empty() || wanted.iter().any(|w| w == s.name))
        .collect();
    let fluids: Vec<&FluidScene> = FLUID_SCENES
        .iter()
        .filter(|s| wanted.is_empty() || wanted.iter().any(|w| w == s.name))
        .collect();
    let other = |name: &str| wanted.is_empty() || wanted.iter().any(|w| w == name);
    if let Some(unknown) = wanted.iter().find(|w| {
        SCENES.iter().all(|s| s.name != *w)
            && FLUID_SCENES.iter().all(|s| s.name != *w)
            && !OTHER_BENCHES.contains(&w.as_str())
    }) {
        eprintln!(
            "error: no scene `{unknown}`; the scenes are pyramid, balls, falling, hills, hills_mesh, water, dam_break, queries, filters, characters, energy"
        );
        std::process::exit(2);
    }
    let rapier = if rapier_side::ENHANCED_DETERMINISM {
        "Rapier 0.36 enhanced-determinism"
    } else {
        "Rapier 0.36 default"
    };
    let engines = [
        Engine {
            name: "fixstep I32F32".into(),
            run: fixstep_side::run_fixed,
        },
        Engine {
            name: format!("{rapier}, its default friction (per manifold)"),
            run: rapier_side::run_simplified,
        },
        Engine {
            name: format!("{rapier}, Coulomb friction (per point, as fixstep)"),
            run: rapier_side::run_coulomb,
        },
        Engine {
            name: "fixstep f64 (same code)".into(),
            run: fixstep_side::run_f64,
        },
    ];
    if !scenes.is_empty() {
        println!(
            "| scene | steps | engine | ms/step (median of {rounds}) | vs fixstep I32F32 | quality |"
        );
        println!("|---|---|---|---|---|---|");
    }
    for scene in scenes {
        let mut times = vec![Vec::new(); engines.len()];
        let mut qualities = vec![None; engines.len()];
        for _ in 0..rounds {
            for ((engine, times), q) in engines.iter().zip(&mut times).zip(&mut qualities) {
                let run = (engine.run)(scene);
                times.push(run.ms);
                *q = quality::rigid(scene, &run);
            }
        }
        let medians: Vec<f64> = times.iter_mut().map(|t| median(t)).collect();
        for ((engine, m), q) in engines.iter().zip(&medians).zip(&qualities) {
            println!(
                "| {} | {} | {} | {:.3} | {:.2}× | {} |",
                label(scene),
                scene.steps,
                engine.name,
                m,
                m / medians[0],
                quality_text(scene, *q)
            );
        }
    }
    if other("filters") {
        filter_table(rounds);
    }
    if other("queries") {
        queries::table(rounds, rapier);
    }
    if other("characters") {
        characters::table(rounds, rapier);
    }
    if other("energy") {
        energy::table(rapier);
    }
    for scene in fluids {
        fluid_table(scene, rounds);
    }
}

/// The benches that are not a scene of their own.
const OTHER_BENCHES: [&str; 4] = ["queries", "filters", "characters", "energy"];

/// fixstep's `balls` (500 steps, sleeping off) with the default filter and with every body
/// on layer 1 interacting with every layer, interleaved: the cost of the collide stage's
/// filtering (contact events are always computed, so both rows include them). The
/// positions must come out the same.
fn filter_table(rounds: usize) {
    let scene = SCENES[1];
    assert_eq!(scene.name, "balls");
    let runs = [
        Engine {
            name: "fixstep I32F32, the default filter".into(),
            run: fixstep_side::run_fixed,
        },
        Engine {
            name: "fixstep I32F32, every body on layer 1 (the collide stage filters pairs)".into(),
            run: fixstep_side::run_filtered,
        },
    ];
    let mut times = vec![Vec::new(); runs.len()];
    let mut ends = vec![Vec::new(); runs.len()];
    for _ in 0..rounds {
        for ((engine, times), end) in runs.iter().zip(&mut times).zip(&mut ends) {
            let result = (engine.run)(scene);
            times.push(result.ms);
            *end = result.end;
        }
    }
    let same = ends[0] == ends[1];
    let medians: Vec<f64> = times.iter_mut().map(|t| median(t)).collect();
    println!();
    println!(
        "| scene | steps | engine | ms/step (median of {rounds}) | vs default filter | positions |"
    );
    println!("|---|---|---|---|---|---|");
    for (engine, m) in runs.iter().zip(&medians) {
        println!(
            "| {} | {} | {} | {m:.3} | {:+.1} % | {} |",
            label(scene),
            scene.steps,
            engine.name,
            100.0 * (m / medians[0] - 1.0),
            if same { "the same bits" } else { "DIFFERENT" }
        );
    }
}

/// The rows of `scene`: fixstep I32F32 with each of its settings, salva3d at its
/// tolerance and at fixstep's, fixstep `f64` with the first settings, interleaved; ratios
/// to the first row.
fn fluid_table(scene: &FluidScene, rounds: usize) {
    let fixstep = scene.fixstep;
    let mut names: Vec<String> = fixstep
        .iter()
        .map(|f| format!("fixstep I32F32 (DFSPH, {})", f.label()))
        .collect();
    names.push("salva3d 0.11 (DFSPH, f32, one substep, its default tolerance 5 %)".into());
    names.push("salva3d 0.11 (DFSPH, f32, one substep, fixstep's tolerance 0.05 %)".into());
    names.push(format!("fixstep f64 (same code, {})", fixstep[0].label()));
    let mut times = vec![Vec::new(); names.len()];
    let mut quality = vec![String::new(); names.len()];
    let mut counts = (0, 0);
    let elapsed = f64::from(scene.warm_steps + scene.steps) * f64::from(scene.dt);
    let mut record = |k: usize, run: FluidRun, times: &mut [Vec<f64>]| {
        times[k].push(run.ms);
        let compression = 100.0 * quality::mean_compression(scene, &run.positions);
        quality[k] = if scene.name == "dam_break" {
            let (t, z, error, shifted) = quality::dam_front(scene, &run.positions, elapsed);
            format!(
                "front Z {z:.2} at T {t:.2}: {:+.1} % against Martin & Moyce ({:+.1} % shifted); mean compression {compression:.3} %",
                100.0 * error,
                100.0 * shifted
            )
        } else {
            format!("mean compression {compression:.3} %")
        };
    };
    let salva = fixstep.len();
    for _ in 0..rounds {
        for (k, &settings) in fixstep.iter().enumerate() {
            record(
                k,
                fixstep_side::run_fluid_fixed(scene, settings),
                &mut times,
            );
        }
        let (run, fluid, boundary) = salva_side::run(scene, None);
        counts = (fluid, boundary);
        record(salva, run, &mut times);
        let (run, _, _) = salva_side::run(scene, Some(FIXSTEP_TOLERANCE));
        record(salva + 1, run, &mut times);
        let run = fixstep_side::run_fluid_f64(scene, fixstep[0]);
        record(salva + 2, run, &mut times);
    }
    let medians: Vec<f64> = times.iter_mut().map(|t| median(t)).collect();
    for ((name, m), q) in names.iter().zip(&medians).zip(&quality) {
        println!(
            "| `{}` ({} fluid, {} boundary) | {} | {} | {:.3} | {:.2}× | {} |",
            scene.name,
            counts.0,
            counts.1,
            scene.steps,
            name,
            m,
            m / medians[0],
            q
        );
    }
}
