//! fixstep beside Rapier 0.36 on identical rigid-body scenes, in one process: the engines
//! take turns (A B A B …) for each scene, every run starts from a freshly built world, and
//! the table gives each engine's median time per step over the rounds and its ratio to
//! fixstep's. Built once per Rapier mode: `--features enhanced-determinism` for Rapier's
//! cross-platform determinism mode. `scripts/peer-bench.sh` builds and runs both.
//!
//! Rigid bodies, the same for every engine: dt = 1/60 s, 4 solver substeps (Rapier's
//! `num_solver_iterations`, its default; fixstep's default), one thread, gravity
//! −9.81 m/s² along y, sleeping off.
//!
//! Fluid (`water`): salva3d 0.11 (DFSPH, f32) beside fixstep's DFSPH, a cube of 20³
//! particles 1 cm apart settling on the floor of a tank of the same footprint lined with
//! two layers of boundary particles, kernel support 2 cm, rest density 1000 kg/m³,
//! dt = 0.005 s (each engine substeps as its own time-step control requires), timed after
//! 20 steps.
//!
//! Usage: `fixstep-peers [ROUNDS] [SCENE …]`.

mod fixstep_side;
mod rapier_side;
mod salva_side;

use std::time::Instant;

/// A scene both engines build: its name and the steps one run takes.
#[derive(Clone, Copy)]
pub struct Scene {
    pub name: &'static str,
    pub steps: u32,
}

/// The fluid scene: a cube of `n`³ particles `spacing` (m) apart in a tank of the same
/// footprint, 1.5 × as high; `steps` timed steps of `dt` (s) after `warm_steps`.
pub struct FluidScene {
    pub n: u32,
    pub spacing: f32,
    pub dt: f32,
    pub warm_steps: u32,
    pub steps: u32,
}

impl FluidScene {
    /// Side of the cube and the tank, m.
    pub fn side(&self) -> f32 {
        self.spacing * self.n as f32
    }

    /// Height of the tank, m.
    pub fn height(&self) -> f32 {
        1.5 * self.side()
    }
}

const WATER: FluidScene = FluidScene {
    n: 20,
    spacing: 0.01,
    dt: 0.005,
    warm_steps: 20,
    steps: 10,
};

/// The scenes of issue #6's benchmark table.
const SCENES: [Scene; 3] = [
    Scene {
        name: "pyramid",
        steps: 500,
    },
    Scene {
        name: "balls",
        steps: 500,
    },
    Scene {
        name: "falling",
        steps: 1000,
    },
];

/// One engine: builds a scene afresh, runs its steps and returns the mean ms per step.
struct Engine {
    name: &'static str,
    run: fn(Scene) -> f64,
}

/// Mean milliseconds per step of `steps` calls of `step` (building excluded).
pub fn time_steps(steps: u32, mut step: impl FnMut()) -> f64 {
    let start = Instant::now();
    for _ in 0..steps {
        step();
    }
    start.elapsed().as_secs_f64() * 1e3 / f64::from(steps)
}

fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
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
    let water = wanted.is_empty() || wanted.iter().any(|w| w == "water");
    if let Some(unknown) = wanted
        .iter()
        .find(|w| *w != "water" && SCENES.iter().all(|s| s.name != *w))
    {
        eprintln!("error: no scene `{unknown}`; the scenes are pyramid, balls, falling, water");
        std::process::exit(2);
    }
    let rapier = if rapier_side::ENHANCED_DETERMINISM {
        "Rapier 0.36 enhanced-determinism"
    } else {
        "Rapier 0.36 default"
    };
    let engines = [
        Engine {
            name: "fixstep I32F32",
            run: fixstep_side::run_fixed,
        },
        Engine {
            name: rapier,
            run: rapier_side::run,
        },
        Engine {
            name: "fixstep f64 (same code)",
            run: fixstep_side::run_f64,
        },
    ];
    println!("| scene | steps | engine | ms/step (median of {rounds}) | vs fixstep I32F32 |");
    println!("|---|---|---|---|---|");
    for scene in scenes {
        let mut times = vec![Vec::new(); engines.len()];
        for _ in 0..rounds {
            for (engine, times) in engines.iter().zip(&mut times) {
                times.push((engine.run)(scene));
            }
        }
        let medians: Vec<f64> = times.iter_mut().map(|t| median(t)).collect();
        for (engine, m) in engines.iter().zip(&medians) {
            println!(
                "| `{}` | {} | {} | {:.3} | {:.2}× |",
                scene.name,
                scene.steps,
                engine.name,
                m,
                m / medians[0]
            );
        }
    }
    if water {
        water_table(rounds);
    }
}

/// The fluid rows: fixstep I32F32, salva3d, fixstep `f64`, interleaved.
fn water_table(rounds: usize) {
    let scene = &WATER;
    let mut times = [Vec::new(), Vec::new(), Vec::new()];
    let mut counts = (0, 0);
    for _ in 0..rounds {
        times[0].push(fixstep_side::run_fluid_fixed(scene));
        let (ms, fluid, boundary) = salva_side::run(scene);
        times[1].push(ms);
        counts = (fluid, boundary);
        times[2].push(fixstep_side::run_fluid_f64(scene));
    }
    let names = [
        "fixstep I32F32 (DFSPH)",
        "salva3d 0.11 (DFSPH, f32)",
        "fixstep f64 (same code)",
    ];
    let medians: Vec<f64> = times.iter_mut().map(|t| median(t)).collect();
    for (name, m) in names.iter().zip(&medians) {
        println!(
            "| `water` ({} fluid, {} boundary in salva3d) | {} | {} | {:.3} | {:.2}× |",
            counts.0,
            counts.1,
            scene.steps,
            name,
            m,
            m / medians[0]
        );
    }
}
