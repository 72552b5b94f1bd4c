//! Broadphase cost: `BroadPhase::find_pairs` on the scenes of the Rapier comparison, in
//! I32F32, with a warm cache (the same boxes as the previous call, as in a resting frame)
//! unless the name says `moving`.
//!
//! - `lattice_4096`: 4096 spheres of radius 0.5 on a 16×16×16 lattice of spacing 1.1 m, all
//!   awake (no pair overlaps; 16 equal lower bounds along every axis).
//! - `lattice_4096_10pct_awake`: the same with 90 % of the bodies asleep;
//!   `lattice_4096_asleep`: all of them asleep (the fixed cost per resting body).
//! - `lattice_4096_moving`: all awake, jittered by ±0.05 m, every sphere drifting with its
//!   own velocity (up to 0.02 m per frame per axis), going back and forth through 32
//!   frames, so every call re-sorts a nearly sorted order (~2 000–9 000 pairs).
//! - `pile_4096`: the spheres packed in a 20×20 m box, 400 per layer at 1 m spacing,
//!   jittered by ±0.05 m (12 702 pairs); also `pile_4096_10pct_awake`.
//! - `pyramid_210`: a 20-box-wide 2D pyramid of unit boxes, all touching their neighbours.
//! - `falling_1000`: 1000 spheres on a 10×10×10 lattice of spacing 1.2 m jittered by
//!   ±0.2 m, next to a brute-force O(n²) pass over the same boxes
//!   (`falling_1000_brute_force`).
//!
//! After criterion's report, the brute-force / broadphase time ratio at n = 1000 is measured
//! again in this run (fastest of 31 rounds each) and printed.

use std::hint::black_box;
use std::time::Instant;

use criterion::{Criterion, criterion_group, criterion_main};
use fixstep::math::{Fx, Pcg32, Vec3};
use fixstep::rigid::Aabb;
use fixstep::rigid::broadphase::BroadPhase;

/// Boxes and flags of one frame.
struct Scene {
    boxes: Vec<Aabb<Fx>>,
    active: Vec<bool>,
    present: Vec<bool>,
}

impl Scene {
    /// The boxes, all present and awake.
    fn new(boxes: Vec<Aabb<Fx>>) -> Self {
        let n = boxes.len();
        Self {
            boxes,
            active: vec![true; n],
            present: vec![true; n],
        }
    }

    /// Puts every body but each `k`-th one to sleep (all of them when `k` is 0).
    fn awake_every(mut self, k: usize) -> Self {
        for (i, a) in self.active.iter_mut().enumerate() {
            *a = k != 0 && i % k == 0;
        }
        self
    }
}

/// The box of a sphere of radius `r` at `c`.
fn sphere(c: [f64; 3], r: f64) -> Aabb<Fx> {
    Aabb {
        min: Vec3::from_f64(c[0] - r, c[1] - r, c[2] - r),
        max: Vec3::from_f64(c[0] + r, c[1] + r, c[2] + r),
    }
}

/// Spheres of radius 0.5 on a `side`³ lattice of spacing `spacing`, each moved by up to
/// ±`jitter` per axis.
fn lattice(side: usize, spacing: f64, jitter: f64, seed: u64) -> Vec<Aabb<Fx>> {
    let mut rng = Pcg32::new(seed, 1);
    let mut out = Vec::new();
    for x in 0..side {
        for y in 0..side {
            for z in 0..side {
                let c = [x, y, z].map(|k| k as f64 * spacing + rng.range(-jitter, jitter));
                out.push(sphere(c, 0.5));
            }
        }
    }
    out
}

/// [`DRIFT_FRAMES`] frames of the 16³ lattice (jittered by ±0.05 m) in which every sphere
/// drifts with its own velocity of up to 0.02 m per frame along each axis.
fn drifting_lattice() -> Vec<Scene> {
    let mut rng = Pcg32::new(5, 5);
    let start: Vec<[f64; 3]> = (0..4096)
        .map(|i| [i / 256, i / 16 % 16, i % 16].map(|k| k as f64 * 1.1 + rng.range(-0.05, 0.05)))
        .collect();
    let velocity: Vec<[f64; 3]> = (0..4096)
        .map(|_| [0; 3].map(|_| rng.range(-0.02, 0.02)))
        .collect();
    (0..DRIFT_FRAMES)
        .map(|f| {
            let boxes = start
                .iter()
                .zip(&velocity)
                .map(|(p, v)| sphere([0, 1, 2].map(|a| p[a] + v[a] * f as f64), 0.5))
                .collect();
            Scene::new(boxes)
        })
        .collect()
}

/// Frames in [`drifting_lattice`].
const DRIFT_FRAMES: usize = 32;

/// The frame to show at step `k` when going back and forth through `n` frames, so that
/// consecutive steps are always neighbouring frames: 0, 1, …, n−1, n−2, …, 1, 0, 1, …
fn ping_pong(k: usize, n: usize) -> usize {
    let period = 2 * (n - 1);
    let phase = k % period;
    if phase < n { phase } else { period - phase }
}

/// 4096 spheres of radius 0.5 piled in a 20×20 m box: layers of 20×20 at spacing 1 m, each
/// jittered by ±0.05 m, so neighbours touch or overlap about half the time.
fn pile() -> Vec<Aabb<Fx>> {
    let mut rng = Pcg32::new(9, 2);
    (0..4096)
        .map(|i| {
            let (layer, cell) = (i / 400, i % 400);
            let c = [cell % 20, layer, cell / 20].map(|k| k as f64 + 0.5 + rng.range(-0.05, 0.05));
            sphere(c, 0.5)
        })
        .collect()
}

/// A 2D pyramid of unit boxes, 20 at the base: 210 boxes, each touching its neighbours.
fn pyramid() -> Vec<Aabb<Fx>> {
    let mut out = Vec::new();
    for layer in 0..20 {
        for k in 0..20 - layer {
            let x = layer as f64 * 0.5 + k as f64;
            let y = layer as f64;
            out.push(Aabb {
                min: Vec3::from_f64(x, y, 0.0),
                max: Vec3::from_f64(x + 1.0, y + 1.0, 1.0),
            });
        }
    }
    out
}

/// Every pair of overlapping boxes, all awake, by testing all n(n−1)/2 of them.
fn brute_force(boxes: &[Aabb<Fx>], out: &mut Vec<(u32, u32)>) {
    out.clear();
    for a in 0..boxes.len() {
        for b in a + 1..boxes.len() {
            if boxes[a].overlaps(&boxes[b]) {
                out.push((a as u32, b as u32));
            }
        }
    }
}

/// Benchmarks `find_pairs` on `scene`, warm: the cache holds the same frame.
fn bench_scene(
    c: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    name: &str,
    scene: &Scene,
) {
    let mut bp = BroadPhase::new();
    let mut out = Vec::new();
    bp.find_pairs(&scene.boxes, &scene.active, &scene.present, &mut out);
    println!("{name}: {} boxes, {} pairs", scene.boxes.len(), out.len());
    c.bench_function(name, |b| {
        b.iter(|| {
            bp.find_pairs(
                black_box(&scene.boxes),
                &scene.active,
                &scene.present,
                &mut out,
            );
            black_box(out.len())
        })
    });
}

/// The benchmark group `broadphase`, then the ratio at n = 1000.
fn broadphase(c: &mut Criterion) {
    let mut group = c.benchmark_group("broadphase");
    group.sample_size(30);

    bench_scene(
        &mut group,
        "lattice_4096",
        &Scene::new(lattice(16, 1.1, 0.0, 1)),
    );
    bench_scene(
        &mut group,
        "lattice_4096_10pct_awake",
        &Scene::new(lattice(16, 1.1, 0.0, 1)).awake_every(10),
    );
    bench_scene(
        &mut group,
        "lattice_4096_asleep",
        &Scene::new(lattice(16, 1.1, 0.0, 1)).awake_every(0),
    );
    {
        let frames = drifting_lattice();
        let mut bp = BroadPhase::new();
        let mut out = Vec::new();
        let mut k = 0;
        group.bench_function("lattice_4096_moving", |b| {
            b.iter(|| {
                k += 1;
                let s = &frames[ping_pong(k, frames.len())];
                bp.find_pairs(black_box(&s.boxes), &s.active, &s.present, &mut out);
                black_box(out.len())
            })
        });
    }
    bench_scene(&mut group, "pile_4096", &Scene::new(pile()));
    bench_scene(
        &mut group,
        "pile_4096_10pct_awake",
        &Scene::new(pile()).awake_every(10),
    );
    bench_scene(&mut group, "pyramid_210", &Scene::new(pyramid()));

    let falling = Scene::new(lattice(10, 1.2, 0.2, 4));
    bench_scene(&mut group, "falling_1000", &falling);
    let mut out = Vec::new();
    group.bench_function("falling_1000_brute_force", |b| {
        b.iter(|| {
            brute_force(black_box(&falling.boxes), &mut out);
            black_box(out.len())
        })
    });
    group.finish();

    ratio_at_1000(&falling);
}

/// Times the broadphase and the brute force on the same 1000 boxes, alternating, and prints
/// the fastest of each (the least disturbed by other processes) and their ratio.
fn ratio_at_1000(scene: &Scene) {
    let mut bp = BroadPhase::new();
    let (mut fast, mut slow) = (Vec::new(), Vec::new());
    let mut out = Vec::new();
    bp.find_pairs(&scene.boxes, &scene.active, &scene.present, &mut out);
    let mut check = Vec::new();
    brute_force(&scene.boxes, &mut check);
    assert_eq!(out, check, "broadphase and brute force disagree");
    for _ in 0..31 {
        let t = Instant::now();
        for _ in 0..20 {
            bp.find_pairs(
                black_box(&scene.boxes),
                &scene.active,
                &scene.present,
                &mut out,
            );
        }
        fast.push(t.elapsed().as_secs_f64() / 20.0);
        let t = Instant::now();
        brute_force(black_box(&scene.boxes), &mut out);
        slow.push(t.elapsed().as_secs_f64());
    }
    fast.sort_by(f64::total_cmp);
    slow.sort_by(f64::total_cmp);
    let (f, s) = (fast[0], slow[0]);
    println!(
        "broadphase/falling_1000: sweep {:.1} µs, brute force {:.1} µs, brute force / sweep = {:.1}×",
        f * 1e6,
        s * 1e6,
        s / f
    );
}

criterion_group!(benches, broadphase);
criterion_main!(benches);
