//! Runs a built-in rigid scene with sleeping off and prints the mean time per step, for
//! profiling (`perf record ./target/release/examples/rigid_steps pyramid 300`). The
//! benchmark figures come from `cargo bench --bench rigid`, not from here.
//!
//! Usage: `cargo run --release --example rigid_steps [SCENE] [STEPS]` (default `pyramid`
//! 500).

use fixstep::math::Fx;
use fixstep::world::TickInput;
use fixstep_scenes::builtin_scene;

fn main() {
    let name = std::env::args().nth(1).unwrap_or_else(|| "pyramid".into());
    let steps: u32 = std::env::args()
        .nth(2)
        .and_then(|s| s.parse().ok())
        .unwrap_or(500);
    let Some(mut scene) = builtin_scene::<Fx>(&name) else {
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
