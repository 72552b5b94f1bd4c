//! The soft benchmark's cloth (`benches/soft.rs`: 64×64, pinned at two corners, falling
//! from horizontal, no bending) stepped a given number of ticks, for `perf stat` and
//! `perf record`: `soft_steps FORMAT TICKS [bending]`, FORMAT `I32F32` or `f64`. The cost
//! of a tick is the difference between two tick counts, so that setup cancels out:
//!
//! ```text
//! perf stat -e instructions:u,cycles:u target/release/examples/soft_steps I32F32 120
//! perf stat -e instructions:u,cycles:u target/release/examples/soft_steps I32F32 20
//! ```
//!
//! It prints a digest of the final vertex positions, the same for every build that gives
//! the same bits.

use fixstep::math::{Fx, Real};
use fixstep::scene::Scene;
use fixstep::soft::SoftModel;
use fixstep::world::{TickInput, World};

/// The benchmark's 64×64 cloth scene in format R, with or without its bending rows.
fn cloth<R: Real>(bending: bool) -> Scene<R> {
    let mut scene = Scene::empty("cloth64");
    let mut soft = fixstep_scenes::soft::cloth::<R>(64);
    if !bending
        && let SoftModel::Xpbd {
            bend_compliance, ..
        } = &mut soft.bodies[0].model
    {
        *bend_compliance = None;
    }
    scene.soft = Some(soft);
    scene
}

/// Steps the cloth `ticks` ticks and prints a digest of the final positions.
fn run<R: Real>(ticks: u32, bending: bool) {
    let mut world: World<R> = cloth::<R>(bending).build().expect("the scene builds");
    let empty = TickInput::default();
    for _ in 0..ticks {
        std::hint::black_box(world.step(&empty));
    }
    let soft = world.soft().expect("the scene has soft bodies");
    let digest = soft.positions().iter().fold(0u64, |hash, p| {
        [p.x, p.y, p.z].iter().fold(hash, |h, c| {
            (h ^ c.canonical_bits()).wrapping_mul(0x0100_0000_01b3)
        })
    });
    println!(
        "{} {ticks} ticks{}: positions digest {digest:016x}",
        R::NAME,
        if bending { " with bending" } else { "" }
    );
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let ticks = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(120);
    let bending = args.get(3).is_some_and(|s| s == "bending");
    match args.get(1).map(String::as_str) {
        Some("f64") => run::<f64>(ticks, bending),
        Some("I32F32") | None => run::<Fx>(ticks, bending),
        Some(other) => {
            eprintln!("error: unknown format `{other}` (I32F32 or f64)");
            std::process::exit(2);
        }
    }
}
