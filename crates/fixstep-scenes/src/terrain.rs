//! The `terrain` scene: level geometry at work. Boxes, balls, cylinders and rocks (convex
//! hulls) fall onto a hill (a heightfield) and tumble down it into a bowl (a triangle
//! mesh), over the seams of thousands of triangles.

use fixstep::math::{Real, Vec3};
use fixstep::rigid::convex::ConvexHull;
use fixstep::rigid::{BodyDesc, Grid, HeightField, RigidDesc, Shape, TriMesh};

use super::rigid::ground;

/// Rows and columns of the hill's grid: 33 × 33 samples, 2048 triangles.
const HILL_SAMPLES: u32 = 33;

/// Cells along each side of the bowl: 24 × 24 squares, 1152 triangles.
const BOWL_CELLS: u32 = 24;

/// The hill: a 24 m × 24 m heightfield centred at x = −7 m (spanning x from −19 to 5 m),
/// falling from 8 m at its west edge to 0 at its east edge as 8 (1 − u)² m, u = c / 32,
/// with bumps of up to 0.25 m, (4 − |r mod 8 − 4|)(4 − |c mod 8 − 4|) / 64 m, that vanish
/// on every eighth row and column, so that the east edge meets the bowl's rim at 0.
pub fn hill<R: Real>() -> BodyDesc<R> {
    let n = HILL_SAMPLES;
    let last = i64::from(n - 1);
    let wave = |k: u32| 4 - (i64::from(k % 8) - 4).abs();
    let mut heights = Vec::with_capacity((n * n) as usize);
    for r in 0..n {
        for c in 0..n {
            let fall = R::from_ratio(8 * (last - i64::from(c)).pow(2), last * last);
            heights.push(fall + R::from_ratio(wave(r) * wave(c), 64));
        }
    }
    let scale = Vec3::new(R::from_int(24), R::ONE, R::from_int(24));
    let field = HeightField::new(n, n, scale, heights).expect("the hill's grid is valid");
    BodyDesc::new(
        Shape::HeightField { field },
        Vec3::new(R::from_int(-7), R::ZERO, R::ZERO),
    )
    .fixed()
}

/// The bowl: a triangle mesh over a 14 m square (1152 triangles facing up) of the surface
/// y = x²/8 + z²/6 m on its west half (x < 0) and y = x²/3 + z²/6 m on its east half,
/// steeper so that what rolls in stays in, placed with its lowest point at
/// (12, −6.125, 0) m: the middle of its west edge, 6.125 m up at x = 5 m, meets the foot of
/// the hill at y = 0.
pub fn bowl<R: Real>() -> BodyDesc<R> {
    let n = BOWL_CELLS;
    let half = i64::from(n / 2);
    // x = 7 d_i / 12 m with d_i = i − 12, so x² = 49 d_i² / 144 m², and likewise z.
    let mut vertices = Vec::with_capacity(((n + 1) * (n + 1)) as usize);
    for j in 0..=n {
        for i in 0..=n {
            let (di, dj) = (i64::from(i) - half, i64::from(j) - half);
            let steepness = if di < 0 { 8 } else { 3 };
            let y =
                R::from_ratio(49 * di * di, 144 * steepness) + R::from_ratio(49 * dj * dj, 144 * 6);
            vertices.push(Vec3::new(
                R::from_ratio(7 * di, half),
                y,
                R::from_ratio(7 * dj, half),
            ));
        }
    }
    let mut triangles = Vec::with_capacity((2 * n * n) as usize);
    for j in 0..n {
        for i in 0..n {
            let v = j * (n + 1) + i;
            let (next_row, diagonal) = (v + n + 1, v + n + 2);
            triangles.push([v, next_row, diagonal]);
            triangles.push([v, diagonal, v + 1]);
        }
    }
    let mesh = TriMesh::new(vertices, triangles).expect("the bowl is a valid mesh");
    BodyDesc::new(
        Shape::TriMesh { mesh },
        Vec3::new(R::from_int(12), R::from_ratio(-49, 8), R::ZERO),
    )
    .fixed()
}

/// A rock: the hull of 12 points on an irregular cuboctahedron about 0.3 m across each
/// way, in centimetres: (±a, ±b, 0), (0, ±a, ±b), (±b, 0, ±a) with a and b varying from
/// corner to corner between 14 and 20 cm.
fn rock<R: Real>() -> ConvexHull<R> {
    const CM: [(i64, i64, i64); 12] = [
        (20, 12, 0),
        (-18, 11, 0),
        (17, -13, 0),
        (-19, -10, 0),
        (0, 19, 12),
        (0, -16, 11),
        (0, 18, -13),
        (0, -17, -10),
        (12, 0, 18),
        (-11, 0, 17),
        (13, 0, -20),
        (-10, 0, -16),
    ];
    let points: Vec<Vec3<R>> = CM
        .iter()
        .map(|&(x, y, z)| {
            Vec3::new(
                R::from_ratio(x, 100),
                R::from_ratio(y, 100),
                R::from_ratio(z, 100),
            )
        })
        .collect();
    ConvexHull::new(&points).expect("the rock's points span a volume")
}

/// A 3 × 4 lattice of `shape` bodies with friction 0.3, 1.2 m apart along x from x = −17 m and 0.9 m apart
/// along z from `z` (m), 8 m up, over the top of the hill.
fn lattice<R: Real>(shape: Shape<R>, z: R) -> BodyDesc<R> {
    let mut body = BodyDesc::new(shape, Vec3::new(R::from_int(-17), R::from_int(8), z));
    body.material.friction = R::from_ratio(3, 10);
    body.grid = Some(Grid {
        count: (3, 1, 4),
        spacing: Vec3::new(R::from_ratio(6, 5), R::ZERO, R::from_ratio(9, 10)),
    });
    body
}

/// The bodies: the ground plane 2 m below the bowl's bottom (for anything that leaves the
/// level, at y = −8 m), the hill, the bowl, and 12 each of boxes (30 cm), balls (radius 15 cm),
/// cylinders (radius 15 cm, 30 cm long) and rocks, in four bands across z.
pub fn terrain<R: Real>() -> RigidDesc<R> {
    let mut floor = ground::<R>();
    floor.position = Vec3::new(R::ZERO, R::from_int(-8), R::ZERO);
    let half = R::from_ratio(3, 20);
    let shapes = [
        Shape::Box {
            half_extents: Vec3::splat(half),
        },
        Shape::Sphere { radius: half },
        Shape::Cylinder {
            radius: half,
            half_height: half,
        },
        Shape::ConvexHull { hull: rock() },
    ];
    let mut bodies = vec![floor, hill(), bowl()];
    for (band, shape) in shapes.into_iter().enumerate() {
        let z = R::from_ratio(-63 + 36 * band as i64, 10);
        bodies.push(lattice(shape, z));
    }
    RigidDesc {
        bodies,
        ..RigidDesc::default()
    }
}
