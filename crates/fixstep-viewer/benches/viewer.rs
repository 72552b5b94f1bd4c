//! The viewer's cost per frame on `pyramid` (210 boxes and the ground) at 640x480, iso
//! view, one thread: extracting the draw list, rasterising, PNG encoding and adding a GIF
//! frame (two frames, the picture and a blank one, per sample). The baseline in the same
//! run is one `pyramid` tick (the mean of its first 60, awake) in I32F32 and in `f64`;
//! extraction is also measured from both formats.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use fixstep::math::{Fx, Real};
use fixstep::world::{TickInput, World};
use fixstep_scenes::builtin_scene;
use fixstep_viewer::gif::GifWriter;
use fixstep_viewer::{BodyColours, Film, Look, Projection, View, capture, encode_png, rasterise};

/// Ticks per sample of the `tick` baseline.
const TICKS: u64 = 60;

fn world<R: Real>() -> World<R> {
    builtin_scene::<R>("pyramid")
        .expect("a built-in scene")
        .build()
        .expect("the scene builds")
}

fn bench_format<R: Real>(c: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>) {
    let empty = TickInput::default();
    // The mean of the first 60 ticks from the start, while the pyramid is awake.
    c.bench_function(BenchmarkId::new("tick", R::NAME), |b| {
        b.iter_custom(|iterations| {
            let mut total = Duration::ZERO;
            for _ in 0..iterations {
                let mut stepped = world::<R>();
                let start = Instant::now();
                for _ in 0..TICKS {
                    black_box(stepped.step(&empty));
                }
                total += start.elapsed() / TICKS as u32;
            }
            total
        })
    });
    let fresh = world::<R>();
    c.bench_function(BenchmarkId::new("capture", R::NAME), |b| {
        b.iter(|| black_box(capture(&fresh, BodyColours::Palette)))
    });
}

fn viewer(c: &mut Criterion) {
    let mut group = c.benchmark_group("viewer_pyramid");
    group.sample_size(20);
    bench_format::<Fx>(&mut group);
    bench_format::<f64>(&mut group);

    let film = Film::from_frames(vec![capture(&world::<Fx>(), BodyColours::Palette)], 60);
    let projection = Projection::fit(View::Iso, &film.bounds, 640, 480);
    let look = Look {
        palette: film.palette,
        bounds: film.bounds,
        flat: false,
    };
    let frame = &film.frames[0];
    group.bench_function("rasterise", |b| {
        b.iter(|| black_box(rasterise(frame, &projection, &look)))
    });
    let pixmap = rasterise(frame, &projection, &look).expect("draws");
    group.bench_function("encode_png", |b| b.iter(|| black_box(encode_png(&pixmap))));
    // Two frames per iteration, the picture then a blank one, so each stores (nearly)
    // the whole picture; the figure is for two frames.
    let blank = tiny_skia::Pixmap::new(640, 480).expect("a pixmap");
    let mut gif = GifWriter::new(std::io::sink(), 640, 480, 1.0 / 60.0).expect("a GIF");
    group.bench_function("gif_two_frames", |b| {
        b.iter(|| {
            gif.push(&pixmap).expect("a frame");
            gif.push(&blank).expect("a frame");
        })
    });
    group.finish();
}

criterion_group!(benches, viewer);
criterion_main!(benches);
