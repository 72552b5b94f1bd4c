//! Scalar and vector operations on I32F32 beside the same operation in `f32` and `f64`.
//!
//! Each benchmark maps an operation over a 1024-element input array, so the figure is the
//! throughput of a loop, not the latency of one call; per-element times come from dividing
//! by 1024 (criterion reports the elements/s). Results are summarised as ratios in
//! docs/PERFORMANCE.md.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use fixstep::math::rng::Pcg32;
use fixstep::math::{Fx, Quat, Real, Vec3};

const N: usize = 1024;

/// Values uniform in [lo, hi), from a fixed seed.
fn values(lo: f64, hi: f64, seed: u64) -> Vec<f64> {
    let mut rng = Pcg32::new(seed, 1);
    (0..N)
        .map(|_| lo + (hi - lo) * (rng.next_u32() as f64 / 4294967296.0))
        .collect()
}

fn unary<T: Copy>(
    c: &mut Criterion,
    name: &str,
    input: &[f64],
    to: fn(f64) -> T,
    op: fn(T) -> T,
    label: &str,
) {
    let xs: Vec<T> = input.iter().map(|&v| to(v)).collect();
    let mut group = c.benchmark_group(name);
    group.throughput(Throughput::Elements(N as u64));
    group.bench_function(BenchmarkId::from_parameter(label), |b| {
        let mut out = vec![xs[0]; N];
        b.iter(|| {
            for (o, &x) in out.iter_mut().zip(black_box(&xs)) {
                *o = op(x);
            }
            black_box(&out);
        })
    });
    group.finish();
}

fn binary<T: Copy>(
    c: &mut Criterion,
    name: &str,
    a: &[f64],
    b_in: &[f64],
    to: fn(f64) -> T,
    op: fn(T, T) -> T,
    label: &str,
) {
    let xs: Vec<T> = a.iter().map(|&v| to(v)).collect();
    let ys: Vec<T> = b_in.iter().map(|&v| to(v)).collect();
    let mut group = c.benchmark_group(name);
    group.throughput(Throughput::Elements(N as u64));
    group.bench_function(BenchmarkId::from_parameter(label), |b| {
        let mut out = vec![xs[0]; N];
        b.iter(|| {
            for ((o, &x), &y) in out.iter_mut().zip(black_box(&xs)).zip(black_box(&ys)) {
                *o = op(x, y);
            }
            black_box(&out);
        })
    });
    group.finish();
}

fn fx(v: f64) -> Fx {
    Fx::from_f64(v)
}

fn f32_of(v: f64) -> f32 {
    v as f32
}

fn f64_of(v: f64) -> f64 {
    v
}

fn scalar_ops(c: &mut Criterion) {
    let a = values(-100.0, 100.0, 1);
    let b = values(0.5, 100.0, 2);
    let positive = values(0.0, 1000.0, 3);
    let angles = values(-10.0, 10.0, 4);

    binary(c, "mul", &a, &b, fx, |x, y| x * y, "I32F32");
    binary(c, "mul", &a, &b, f32_of, |x, y| x * y, "f32");
    binary(c, "mul", &a, &b, f64_of, |x, y| x * y, "f64");

    binary(c, "div", &a, &b, fx, |x, y| x / y, "I32F32");
    binary(c, "div", &a, &b, f32_of, |x, y| x / y, "f32");
    binary(c, "div", &a, &b, f64_of, |x, y| x / y, "f64");

    unary(c, "sqrt", &positive, fx, Real::sqrt, "I32F32");
    unary(
        c,
        "sqrt",
        &positive,
        fixed_crate,
        |x| x.sqrt(),
        "fixed-crate",
    );
    unary(c, "sqrt", &positive, f32_of, f32::sqrt, "f32");
    unary(c, "sqrt", &positive, f64_of, f64::sqrt, "f64");

    unary(
        c,
        "sin_cos",
        &angles,
        fx,
        |x| {
            let (s, c) = x.sin_cos();
            s + c
        },
        "I32F32",
    );
    unary(
        c,
        "sin_cos",
        &angles,
        f32_of,
        |x| {
            let (s, c) = x.sin_cos();
            s + c
        },
        "f32",
    );
    unary(
        c,
        "sin_cos",
        &angles,
        f64_of,
        |x| {
            let (s, c) = x.sin_cos();
            s + c
        },
        "f64",
    );

    binary(c, "atan2", &a, &angles, fx, Real::atan2, "I32F32");
    binary(c, "atan2", &a, &angles, f32_of, f32::atan2, "f32");
    binary(c, "atan2", &a, &angles, f64_of, f64::atan2, "f64");
}

fn fixed_crate(v: f64) -> fixed::types::I32F32 {
    fixed::types::I32F32::from_num(v)
}

/// Σ aᵢ·bᵢ + c over 1024 elements: the multiply-add loop of integrators and solvers.
fn multiply_add(c: &mut Criterion) {
    let a = values(-10.0, 10.0, 5);
    let b = values(-10.0, 10.0, 6);
    let mut group = c.benchmark_group("multiply_add");
    group.throughput(Throughput::Elements(N as u64));
    let (ax, bx): (Vec<Fx>, Vec<Fx>) = (
        a.iter().map(|&v| fx(v)).collect(),
        b.iter().map(|&v| fx(v)).collect(),
    );
    group.bench_function("I32F32", |bench| {
        bench.iter(|| {
            let mut acc = Fx::ZERO;
            for (&x, &y) in black_box(&ax).iter().zip(black_box(&bx)) {
                acc += x * y;
            }
            acc
        })
    });
    let (a32, b32): (Vec<f32>, Vec<f32>) = (
        a.iter().map(|&v| v as f32).collect(),
        b.iter().map(|&v| v as f32).collect(),
    );
    group.bench_function("f32", |bench| {
        bench.iter(|| {
            let mut acc = 0.0f32;
            for (&x, &y) in black_box(&a32).iter().zip(black_box(&b32)) {
                acc += x * y;
            }
            acc
        })
    });
    group.bench_function("f64", |bench| {
        bench.iter(|| {
            let mut acc = 0.0f64;
            for (&x, &y) in black_box(&a).iter().zip(black_box(&b)) {
                acc += x * y;
            }
            acc
        })
    });
    group.finish();
}

fn vectors<R: Real>(from: fn(f64) -> R) -> Vec<Vec3<R>> {
    let (x, y, z) = (
        values(-50.0, 50.0, 7),
        values(-50.0, 50.0, 8),
        values(-50.0, 50.0, 9),
    );
    (0..N)
        .map(|i| Vec3::new(from(x[i]), from(y[i]), from(z[i])))
        .collect()
}

fn quats<R: Real>(from: fn(f64) -> R) -> Vec<Quat<R>> {
    vectors(from)
        .into_iter()
        .map(|v| {
            let (axis, _) = v.try_normalize().unwrap_or((Vec3::X, R::ONE));
            Quat::from_axis_angle(axis, from(0.7))
        })
        .collect()
}

fn vector_ops(c: &mut Criterion) {
    fn normalize_bench<R: Real>(c: &mut Criterion, from: fn(f64) -> R, label: &str) {
        let vs = vectors(from);
        let mut group = c.benchmark_group("vec3_normalize");
        group.throughput(Throughput::Elements(N as u64));
        group.bench_function(label, |b| {
            let mut out = vs.clone();
            b.iter(|| {
                for (o, v) in out.iter_mut().zip(black_box(&vs)) {
                    *o = v.normalize_or_zero();
                }
                black_box(&out);
            })
        });
        group.finish();
    }
    fn quat_mul_bench<R: Real>(c: &mut Criterion, from: fn(f64) -> R, label: &str) {
        let qa = quats(from);
        let qb: Vec<Quat<R>> = qa.iter().rev().copied().collect();
        let mut group = c.benchmark_group("quat_mul");
        group.throughput(Throughput::Elements(N as u64));
        group.bench_function(label, |b| {
            let mut out = qa.clone();
            b.iter(|| {
                for ((o, &p), &q) in out.iter_mut().zip(black_box(&qa)).zip(black_box(&qb)) {
                    *o = p * q;
                }
                black_box(&out);
            })
        });
        group.finish();
    }
    normalize_bench(c, fx, "I32F32");
    normalize_bench(c, f64_of, "f64");
    quat_mul_bench(c, fx, "I32F32");
    quat_mul_bench(c, f64_of, "f64");

    // f32 has no `Real` impl (it is never a simulation format), so its baselines are the
    // same formulas written out on arrays.
    let vs: Vec<[f32; 3]> = vectors(f64_of)
        .iter()
        .map(|v| [v.x as f32, v.y as f32, v.z as f32])
        .collect();
    let mut group = c.benchmark_group("vec3_normalize");
    group.throughput(Throughput::Elements(N as u64));
    group.bench_function("f32", |b| {
        let mut out = vs.clone();
        b.iter(|| {
            for (o, v) in out.iter_mut().zip(black_box(&vs)) {
                let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
                let inv = if len == 0.0 { 0.0 } else { 1.0 / len };
                *o = [v[0] * inv, v[1] * inv, v[2] * inv];
            }
            black_box(&out);
        })
    });
    group.finish();
    let qa: Vec<[f32; 4]> = quats(f64_of)
        .iter()
        .map(|q| [q.w as f32, q.x as f32, q.y as f32, q.z as f32])
        .collect();
    let qb: Vec<[f32; 4]> = qa.iter().rev().copied().collect();
    let mut group = c.benchmark_group("quat_mul");
    group.throughput(Throughput::Elements(N as u64));
    group.bench_function("f32", |b| {
        let mut out = qa.clone();
        b.iter(|| {
            for ((o, p), q) in out.iter_mut().zip(black_box(&qa)).zip(black_box(&qb)) {
                *o = [
                    p[0] * q[0] - p[1] * q[1] - p[2] * q[2] - p[3] * q[3],
                    p[0] * q[1] + p[1] * q[0] + p[2] * q[3] - p[3] * q[2],
                    p[0] * q[2] - p[1] * q[3] + p[2] * q[0] + p[3] * q[1],
                    p[0] * q[3] + p[1] * q[2] - p[2] * q[1] + p[3] * q[0],
                ];
            }
            black_box(&out);
        })
    });
    group.finish();
}

criterion_group!(benches, scalar_ops, multiply_add, vector_ops);
criterion_main!(benches);
