//! The speed-up of stepping on N threads against 1, same binary, same run (issue
//! [parallel]'s benchmark table): `balls`, ten pyramids of 2016 boxes (20,160 boxes),
//! `dam_break` and a 128×128 cloth, each stepped from its start on 1 thread and on N in
//! alternating rounds; prints the median ms per tick at each count, the speed-up, and
//! whether the checksums agree (they must). `scripts/thread-bench.sh` adds `fixstep verify`.
//!
//! Usage: `cargo run --release --example thread_bench [THREADS] [ROUNDS] [CASE ...]`
//! (default 2 threads, 5 rounds, every case).

use std::time::Instant;

use fixstep::math::{Fx, Real};
use fixstep::scene::Scene;
use fixstep::world::{TickInput, World};
use fixstep_scenes::builtin_scene;

/// A case: its name, how many ticks a round steps, and its scene.
struct Case {
    name: &'static str,
    ticks: u32,
    scene: fn() -> Scene<Fx>,
}

/// The built-in scene `name`.
fn builtin(name: &str) -> Scene<Fx> {
    builtin_scene(name).expect("a built-in scene")
}

/// Ten pyramids of base 63 (2016 unit boxes each), 3 m apart along z: 20,160 boxes.
fn pyramids() -> Scene<Fx> {
    let mut scene = Scene::empty("pyramids");
    let mut rigid = fixstep_scenes::rigid::pyramid::<Fx>(63);
    let rows: Vec<_> = rigid.bodies[1..].to_vec();
    for k in 1..10 {
        for row in &rows {
            let mut row = row.clone();
            row.position.z = Fx::from_int(3 * k);
            rigid.bodies.push(row);
        }
    }
    scene.rigid = Some(rigid);
    scene
}

/// A 128×128 XPBD cloth pinned at two corners, falling and swinging (the built-in `cloth`
/// at 128 vertices a side).
fn cloth128() -> Scene<Fx> {
    let mut scene = Scene::empty("cloth128");
    scene.soft = Some(fixstep_scenes::soft::cloth::<Fx>(128));
    scene
}

const CASES: [Case; 4] = [
    Case {
        name: "balls",
        ticks: 100,
        scene: || builtin("balls"),
    },
    Case {
        name: "pyramids20k",
        ticks: 20,
        scene: pyramids,
    },
    Case {
        name: "dam_break",
        ticks: 12,
        scene: || builtin("dam_break"),
    },
    Case {
        name: "cloth128",
        ticks: 3,
        scene: cloth128,
    },
];

/// Steps `world` `ticks` ticks on `threads` threads; returns ms per tick and the checksum.
fn round(scene: &Scene<Fx>, threads: usize, ticks: u32) -> (f64, String) {
    let mut world: World<Fx> = scene.build().expect("the scene builds");
    world.set_threads(threads);
    let empty = TickInput::default();
    let start = Instant::now();
    for _ in 0..ticks {
        std::hint::black_box(world.step(&empty));
    }
    let ms = start.elapsed().as_secs_f64() * 1e3 / f64::from(ticks);
    (ms, format!("{:?}", world.checksum()))
}

/// The median of `values`.
fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let threads: usize = args.first().and_then(|s| s.parse().ok()).unwrap_or(2);
    let rounds: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(5);
    let only: Vec<&str> = args.iter().skip(2).map(String::as_str).collect();
    println!(
        "| case | ms/tick, 1 thread | ms/tick, {threads} threads | speed-up | same checksum |"
    );
    println!("|---|---|---|---|---|");
    for case in CASES
        .iter()
        .filter(|c| only.is_empty() || only.contains(&c.name))
    {
        let scene = (case.scene)();
        let (mut one, mut many) = (Vec::new(), Vec::new());
        let mut same = true;
        for _ in 0..rounds {
            let (a, sum_a) = round(&scene, 1, case.ticks);
            let (b, sum_b) = round(&scene, threads, case.ticks);
            same &= sum_a == sum_b;
            one.push(a);
            many.push(b);
        }
        let (one, many) = (median(&mut one), median(&mut many));
        println!(
            "| {} | {one:.2} | {many:.2} | {:.2}× | {} |",
            case.name,
            one / many,
            if same { "yes" } else { "NO" }
        );
        if !same {
            std::process::exit(1);
        }
    }
}
