//! Building meshes: the tables a triangle mesh derives when it is made (face normals,
//! active edges, the bounding-volume tree), over a 224 × 224 grid of 100 352 triangles,
//! and a 256 × 256 heightfield (130 050 triangles). Prints each mesh's memory once.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use fixstep::math::{Fx, Real, Vec3};
use fixstep::rigid::{HeightField, TriMesh};

/// Rolling heights in metres for sample (r, c), rational so that every build agrees:
/// ((r · 7 + c · 13) mod 32) / 64 + r / 256.
fn height<R: Real>(r: u32, c: u32) -> R {
    R::from_ratio(i64::from((r * 7 + c * 13) % 32), 64) + R::from_ratio(i64::from(r), 256)
}

/// The vertices and triangles of an `n` × `n`-cell grid with 0.25 m cells.
fn grid(n: u32) -> (Vec<Vec3<Fx>>, Vec<[u32; 3]>) {
    let mut vertices = Vec::new();
    for r in 0..=n {
        for c in 0..=n {
            vertices.push(Vec3::new(
                Fx::from_ratio(i64::from(c), 4),
                height(r, c),
                Fx::from_ratio(i64::from(r), 4),
            ));
        }
    }
    let mut triangles = Vec::new();
    for r in 0..n {
        for c in 0..n {
            let v = r * (n + 1) + c;
            triangles.push([v, v + n + 1, v + n + 2]);
            triangles.push([v, v + n + 2, v + 1]);
        }
    }
    (vertices, triangles)
}

fn meshes(c: &mut Criterion) {
    let mut group = c.benchmark_group("mesh_build");
    group.sample_size(10);
    let (vertices, triangles) = grid(224);
    let mesh = TriMesh::new(vertices.clone(), triangles.clone()).expect("a valid grid");
    println!(
        "trimesh: {} triangles, {} tree nodes, {} bytes ({:.1} per triangle)",
        triangles.len(),
        mesh.tree_node_count(),
        mesh.heap_bytes(),
        mesh.heap_bytes() as f64 / triangles.len() as f64 // ok-det: reporting
    );
    group.bench_function("trimesh_100k", |b| {
        b.iter(|| TriMesh::new(black_box(vertices.clone()), black_box(triangles.clone())))
    });
    let n = 256u32;
    let heights: Vec<Fx> = (0..n * n).map(|k| height(k / n, k % n)).collect();
    let scale = Vec3::new(Fx::from_int(64), Fx::ONE, Fx::from_int(64));
    let field = HeightField::new(n, n, scale, heights.clone()).expect("a valid grid");
    println!(
        "heightfield: {} triangles, {} bytes",
        field.mesh().triangles().len(),
        field.mesh().heap_bytes()
    );
    group.bench_function("heightfield_256", |b| {
        b.iter(|| HeightField::new(n, n, scale, black_box(heights.clone())))
    });
    group.finish();
}

criterion_group!(benches, meshes);
criterion_main!(benches);
