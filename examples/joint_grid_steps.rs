//! Runs the joint-grid benchmark scene (`joint_grid`, 100 × 100 balls on ball joints,
//! sleeping off) and prints the mean time per step, for profiling
//! (`perf record ./target/release/examples/joint_grid_steps 60`). The benchmark figures come
//! from `cargo bench --bench joints`, not from here.
//!
//! Usage: `cargo run --release --example joint_grid_steps [STEPS] [N]` (default 60 steps of
//! a 100 × 100 grid).

use fixstep::math::Fx;
use fixstep::scene::Scene;
use fixstep::world::TickInput;
use fixstep_scenes::joints::joint_grid;

fn main() {
    let mut args = std::env::args().skip(1);
    let steps: u32 = args.next().and_then(|s| s.parse().ok()).unwrap_or(60);
    let n: u32 = args.next().and_then(|s| s.parse().ok()).unwrap_or(100);
    let (mut rigid, joints) = joint_grid::<Fx>(n);
    rigid.solver.sleeping = false;
    let mut scene = Scene::empty("joint_grid");
    scene.rigid = Some(rigid);
    scene.joints = Some(joints);
    let mut world = scene.build().expect("the grid builds");
    let empty = TickInput::default();
    let start = std::time::Instant::now();
    for _ in 0..steps {
        world.step(&empty);
    }
    let contacts = world.rigid().map_or(0, |r| r.contact_count());
    println!(
        "joint_grid {n}x{n}: {:?} per step over {steps} steps, {contacts} contacts at the end",
        start.elapsed() / steps.max(1)
    );
}
