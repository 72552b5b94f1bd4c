//! What rollback costs beyond simulating: GGRS saves the state of every predicted frame (a
//! world snapshot and its 128-bit checksum) and loads one on a misprediction, then
//! re-simulates. For `stack` and `showcase`, at tick 120 with bot inputs:
//! - `step`: one tick, restoring the tick-120 state outside the timing;
//! - `save`: a snapshot and its checksum, what GGRS's `SaveGameState` costs;
//! - `load`: restoring a snapshot, what GGRS's `LoadGameState` costs.
//!
//! The ratios save/step and load/step say how much a rollback of k frames costs beyond the
//! k steps it re-simulates.

use std::hint::black_box;

use criterion::{BatchSize, Criterion, criterion_group, criterion_main};
use fixstep_net::{Bot, build_world, checksum128, tick_input};
use fixstep_scenes::builtin_scene;

/// Ticks run before measuring, so that bodies touch and contacts are warm.
const WARM_TICKS: u64 = 120;

fn rollback_cost(c: &mut Criterion) {
    for name in ["stack", "showcase"] {
        let scene = builtin_scene(name).expect("a built-in scene");
        let mut world = build_world(&scene).expect("the scene builds");
        let bot = Bot::new(1, &world);
        let inputs_at = |tick| [bot.input(0, tick), bot.input(1, tick)];
        for tick in 0..WARM_TICKS {
            world.step(&tick_input(&scene, tick, &inputs_at(tick)));
        }
        let state = world.snapshot();
        let input = tick_input(&scene, WARM_TICKS, &inputs_at(WARM_TICKS));

        let mut group = c.benchmark_group(format!("net/{name}"));
        group.bench_function("step", |b| {
            b.iter_batched_ref(
                || {
                    let mut w = build_world(&scene).expect("the scene builds");
                    w.restore(&state);
                    w
                },
                |w| black_box(w.step(black_box(&input))),
                BatchSize::LargeInput,
            )
        });
        group.bench_function("save", |b| {
            b.iter(|| black_box((world.snapshot(), checksum128(&world))))
        });
        group.bench_function("load", |b| b.iter(|| world.restore(black_box(&state))));
        group.finish();
    }
}

criterion_group!(benches, rollback_cost);
criterion_main!(benches);
