//! Runs a built-in rigid scene with sleeping off and prints the mean time per step, for
//! profiling (`perf record ./target/release/examples/rigid_steps pyramid 300`). The
//! benchmark figures come from `cargo bench --bench rigid`, not from here.
//!
//! Usage: `cargo run --release --example rigid_steps [SCENE] [STEPS] [f64]` (default
//! `pyramid` 500, in I32F32; `f64` runs the same generic code in `f64`, where no vector
//! kernel runs: the structure's cost alone).

use fixstep::math::{Fx, Real};
use fixstep::world::TickInput;
use fixstep_scenes::builtin_scene;

fn main() {
    let name = std::env::args().nth(1).unwrap_or_else(|| "pyramid".into());
    let steps: u32 = std::env::args()
        .nth(2)
        .and_then(|s| s.parse().ok())
        .unwrap_or(500);
    match std::env::args().nth(3).as_deref() {
        None => run::<Fx>(&name, steps),
        Some("f64") => run::<f64>(&name, steps),
        Some(other) => {
            eprintln!("error: the third argument is `f64` or nothing, not `{other}`");
            std::process::exit(2);
        }
    }
}

/// Steps built-in scene `name` in `R` and prints the mean time per step.
fn run<R: Real>(name: &str, steps: u32) {
    let Some(mut scene) = builtin_scene::<R>(name) else {
        eprintln!("error: no built-in scene `{name}`");
        std::process::exit(2);
    };
    if let Some(rigid) = &mut scene.rigid {
        rigid.solver.sleeping = false;
    }
    let mut world = scene.build().expect("built-in scenes build");
    let empty = TickInput::default();
    let start = std::time::Instant::now();
    for _ in 0..steps {
        world.step(&empty);
    }
    let contacts = world.rigid().map_or(0, |r| r.contact_count());
    println!(
        "{name}: {:?} per step over {steps} steps, {contacts} contacts at the end",
        start.elapsed() / steps.max(1)
    );
}
