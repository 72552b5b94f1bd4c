//! The `terrain` scene: level geometry at work. Boxes, balls, cylinders and rocks (convex
//! hulls) fall onto a hill (a heightfield) and tumble down it into a bowl (a triangle
//! mesh), over the seams of thousands of triangles.

use fixstep::math::{Real, Vec3};
use fixstep::rigid::convex::ConvexHull;
use fixstep::rigid::{BodyDesc, Grid, HeightField, RigidDesc, Shape, TriMesh};

use super::rigid::ground;

/// Rows and columns of the hill's grid: 33 × 33 samples, 2048 triangles.
const HILL_SAMPLES: u32 = 33;

/// Cells of the bowl along x; along z it has as many as the hill (32), so that their
/// edges meet sample for sample.
const BOWL_CELLS: u32 = 24;

/// How the level rises towards z = ±12 m, in metres, for w = z / 12 m ∈ [−1, 1] given as
/// w = k / 16: 8 w⁴ = 8 k⁴ / 16⁴. The hill's east edge and the bowl's west edge both rise
/// so, and meet.
fn banks<R: Real>(k: i64) -> R {
    R::from_ratio(8 * k.pow(4), 16i64.pow(4))
}

/// The hill: a 24 m × 24 m heightfield centred at x = −7 m (spanning x from −19 to 5 m),
/// falling from 8 m at its west edge as 8 (1 − u)² m, u = c / 32, with bumps of up to
/// 0.25 m, (4 − |r mod 8 − 4|)(4 − |c mod 8 − 4|) / 64 m, that vanish on every eighth row
/// and column, and banks rising towards its sides as u² times the `banks` profile, so
/// that its east edge meets the bowl's west edge.
pub fn hill<R: Real>() -> BodyDesc<R> {
    let n = HILL_SAMPLES;
    let last = i64::from(n - 1);
    let wave = |k: u32| 4 - (i64::from(k % 8) - 4).abs();
    let mut heights = Vec::with_capacity((n * n) as usize);
    for r in 0..n {
        for c in 0..n {
            let c64 = i64::from(c);
            let fall = R::from_ratio(8 * (last - c64).pow(2), last * last);
            let bumps = R::from_ratio(wave(r) * wave(c), 64);
            let bank = banks::<R>(i64::from(r) - last / 2) * R::from_ratio(c64 * c64, last * last);
            heights.push(fall + bumps + bank);
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

/// The bowl: a triangle mesh over 14 m (x) by 24 m (z), 24 × 32 cells of two triangles
/// facing up, placed at x = 5 m beside the hill. With u = x / 14 m ∈ [0, 1] from its west
/// edge and w = z / 12 m ∈ [−1, 1], its surface is
/// y = 10 u² − 12 u (1 − u) + 12 u w² + 8 w⁴ m: along its west edge (u = 0) the hill's
/// east edge, dipping to −1.6 m at u = 3/11, rising to 10 m at the east edge and to 8 m
/// and more at the sides, so that what rolls down the hill stays in.
pub fn bowl<R: Real>() -> BodyDesc<R> {
    let (n, rows) = (i64::from(BOWL_CELLS), i64::from(HILL_SAMPLES - 1));
    let m = rows / 2;
    let mut vertices = Vec::with_capacity(((n + 1) * (rows + 1)) as usize);
    for j in 0..=rows {
        for i in 0..=n {
            // u = i / n and w = (j − m) / m: y = (10 i² − 12 i (n − i)) / n² +
            // 12 i (j − m)² / (n m²) + banks.
            let k = j - m;
            let y = R::from_ratio(10 * i * i - 12 * i * (n - i), n * n)
                + R::from_ratio(12 * i * k * k, n * m * m)
                + banks::<R>(k);
            vertices.push(Vec3::new(
                R::from_ratio(14 * i, n),
                y,
                R::from_ratio(12 * k, m),
            ));
        }
    }
    let (n, rows) = (BOWL_CELLS, HILL_SAMPLES - 1);
    let mut triangles = Vec::with_capacity((2 * n * rows) as usize);
    for j in 0..rows {
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
        Vec3::new(R::from_int(5), R::ZERO, R::ZERO),
    )
    .fixed()
}

/// The rock's points, in centimetres.
const ROCK_CM: [(i64, i64, i64); 12] = [
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

/// A rock: the hull of 12 points on an irregular cuboctahedron about 0.3 m across each
/// way, in centimetres: (±a, ±b, 0), (0, ±a, ±b), (±b, 0, ±a) with a and b varying from
/// corner to corner between 10 and 20 cm.
fn rock<R: Real>() -> ConvexHull<R> {
    let points: Vec<Vec3<R>> = ROCK_CM
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

/// A 3 × 4 lattice of `shape` bodies with friction 0.3, 1.2 m apart along x from x = −17 m and 0.75 m apart
/// along z from `z` (m), 8 m up, over the top of the hill.
fn lattice<R: Real>(shape: Shape<R>, z: R) -> BodyDesc<R> {
    let mut body = BodyDesc::new(shape, Vec3::new(R::from_int(-17), R::from_int(8), z));
    body.material.friction = R::from_ratio(3, 10);
    body.grid = Some(Grid {
        count: (3, 1, 4),
        spacing: Vec3::new(R::from_ratio(6, 5), R::ZERO, R::from_ratio(3, 4)),
    });
    body
}

/// The bodies: the ground plane at y = −8 m (for anything that leaves the level), the hill, the bowl, and 12 each of boxes (30 cm), balls (radius 15 cm),
/// cylinders (radius 15 cm, 30 cm long) and rocks, in four bands 2.7 m apart across z
/// from z = −5.4 m.
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
        let z = R::from_ratio(-54 + 27 * band as i64, 10);
        bodies.push(lattice(shape, z));
    }
    RigidDesc {
        bodies,
        ..RigidDesc::default()
    }
}

/// Samples along each side of the benchmark landing's grid (`bench/peers`): 256, so
/// 255 × 255 cells and 130 050 triangles.
pub const LANDING_SAMPLES: u32 = 256;

/// The landing's height at sample (r, c), as an exact ratio (numerator, denominator) in
/// metres: gentle hills of up to 1 m, w(r) w(c) / 256 with w(k) = 16 − |k mod 32 − 16|, so
/// that every engine builds the same terrain.
pub fn landing_height(r: u32, c: u32) -> (i64, i64) {
    let wave = |k: u32| 16 - (i64::from(k % 32) - 16).abs();
    (wave(r) * wave(c), 256)
}

/// The rock's points, in centimetres (see `rock`), for engines that build it themselves.
pub fn rock_centimetres() -> [(i64, i64, i64); 12] {
    ROCK_CM
}

/// The benchmark landing (not a built-in scene; `bench/peers` builds the same one in
/// Rapier): a 64 m × 64 m terrain of [`LANDING_SAMPLES`]² samples ([`landing_height`]), as
/// a heightfield or, with `as_mesh`, as the triangle mesh of the same triangles; 1000
/// rocks in a 10 × 10 × 10 lattice 1.2 m apart from (−6, 3, −6) m and 1000 balls of radius
/// 0.2 m in the same lattice moved by (0.6, 0.5, 0.6) m.
pub fn landing<R: Real>(as_mesh: bool) -> RigidDesc<R> {
    let n = LANDING_SAMPLES;
    let heights: Vec<R> = (0..n * n)
        .map(|k| {
            let (num, den) = landing_height(k / n, k % n);
            R::from_ratio(num, den)
        })
        .collect();
    let scale = Vec3::new(R::from_int(64), R::ONE, R::from_int(64));
    let field = HeightField::new(n, n, scale, heights).expect("the landing's grid is valid");
    let shape = if as_mesh {
        let mesh = field.mesh().clone();
        Shape::TriMesh { mesh }
    } else {
        Shape::HeightField { field }
    };
    let ground = BodyDesc::new(shape, Vec3::ZERO).fixed();
    let lattice = |shape: Shape<R>, start: Vec3<R>| {
        let mut body = BodyDesc::new(shape, start);
        body.grid = Some(Grid {
            count: (10, 10, 10),
            spacing: Vec3::new(
                R::from_ratio(6, 5),
                R::from_ratio(6, 5),
                R::from_ratio(6, 5),
            ),
        });
        body
    };
    let rocks = lattice(
        Shape::ConvexHull { hull: rock() },
        Vec3::new(R::from_int(-6), R::from_int(3), R::from_int(-6)),
    );
    let balls = lattice(
        Shape::Sphere {
            radius: R::from_ratio(1, 5),
        },
        Vec3::new(
            R::from_ratio(-27, 5),
            R::from_ratio(7, 2),
            R::from_ratio(-27, 5),
        ),
    );
    RigidDesc {
        bodies: vec![ground, rocks, balls],
        ..RigidDesc::default()
    }
}
