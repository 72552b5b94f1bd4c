//! The deterministic quickhull: structure (corners only, merged plane faces, Euler's
//! V − E + F = 2), independence from the order of the points, idempotence through RON and
//! bincode, the refused inputs, and random point clouds.

use fixstep::math::{Fx, Quat, Real, Vec3};
use fixstep::rigid::Shape;
use fixstep::rigid::convex::{ConvexHull, HullError, MAX_HULL_POINTS};
use proptest::prelude::*;

fn v(x: f64, y: f64, z: f64) -> Vec3<Fx> {
    Vec3::from_f64(x, y, z)
}

/// The 8 corners of the box of half extents (a, b, c).
fn box_corners(a: f64, b: f64, c: f64) -> Vec<Vec3<Fx>> {
    let mut corners = Vec::new();
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            for sz in [-1.0, 1.0] {
                corners.push(v(sx * a, sy * b, sz * c));
            }
        }
    }
    corners
}

/// The half extent of the points' bounding box along its longest axis, m: the scale of the
/// construction's tolerance.
fn half_extent(points: &[Vec3<Fx>]) -> f64 {
    (0..3)
        .map(|k| {
            let values = points.iter().map(|p| p.to_f64()[k]);
            let (lo, hi) = values.fold((f64::MAX, f64::MIN), |(lo, hi), x| (lo.min(x), hi.max(x)));
            (hi - lo) / 2.0
        })
        .fold(0.0, f64::max)
}

/// The checks every hull passes: Euler's formula, every face a loop of at least 3 distinct
/// vertices starting at its lowest, unit normals, every vertex in at least 3 faces, every
/// point of `points` inside every face plane within `slack` (m), each edge in exactly two
/// faces in opposite directions, and support points that are the farthest input points.
fn assert_valid(hull: &ConvexHull<Fx>, points: &[Vec3<Fx>], slack: f64) {
    let (nv, ne, nf) = (
        hull.vertices().len() as i64,
        hull.edges().len() as i64,
        hull.faces().len() as i64,
    );
    assert_eq!(nv - ne + nf, 2, "Euler: V {nv} E {ne} F {nf}");
    let mut faces_at = vec![0; hull.vertices().len()];
    let mut directed = Vec::new();
    for face in hull.faces() {
        let loop_ = hull.face_indices(face);
        assert!(loop_.len() >= 3);
        assert_eq!(loop_[0], *loop_.iter().min().expect("not empty"));
        let n = face.normal.to_f64();
        let length = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        assert!((length - 1.0).abs() < 1e-8, "normal length {length}");
        for (k, &a) in loop_.iter().enumerate() {
            faces_at[usize::from(a)] += 1;
            directed.push((a, loop_[(k + 1) % loop_.len()]));
        }
        for p in points {
            let p = p.to_f64();
            let height = n[0] * p[0] + n[1] * p[1] + n[2] * p[2] - face.offset.to_f64();
            assert!(height <= slack, "a point {height} m above a face");
        }
    }
    assert!(faces_at.iter().all(|&k| k >= 3), "{faces_at:?}");
    directed.sort_unstable();
    assert!(directed.windows(2).all(|w| w[0] != w[1]), "an edge twice");
    for &(a, b) in &directed {
        assert!(directed.binary_search(&(b, a)).is_ok(), "edge {a}-{b} once");
        let key = [a.min(b), a.max(b)];
        assert!(hull.edges().binary_search(&key).is_ok());
    }
    let mut sorted = hull.vertices().to_vec();
    sorted.sort_by(|a, b| {
        a.x.total_cmp(&b.x)
            .then(a.y.total_cmp(&b.y))
            .then(a.z.total_cmp(&b.z))
    });
    assert_eq!(sorted, hull.vertices(), "vertices in canonical order");
    for direction in [v(1.0, 0.3, -0.2), v(-0.5, 1.0, 0.7), v(0.1, -0.9, -1.0)] {
        let best = points
            .iter()
            .map(|p| p.dot(direction).to_f64())
            .fold(f64::MIN, f64::max);
        let got = hull.vertices()[hull.support_index(direction)]
            .dot(direction)
            .to_f64();
        assert!(got >= best - 2.0 * slack, "support {got} vs {best}");
    }
}

#[test]
fn a_box_is_eight_corners_six_quadrilaterals_and_twelve_edges() {
    let mut points = box_corners(0.5, 1.0, 1.5);
    // Points on edges, on faces, inside: none is a corner.
    points.extend([
        v(0.0, 1.0, 1.5),
        v(0.5, 0.0, -1.5),
        v(0.5, 0.2, 0.3),
        v(-0.1, -1.0, 0.7),
        v(0.0, 0.0, 0.0),
        v(0.25, 0.5, -0.75),
    ]);
    let hull = ConvexHull::new(&points).expect("a box");
    assert_eq!(hull.vertices(), box_corners(0.5, 1.0, 1.5).as_slice());
    assert_eq!(hull.faces().len(), 6);
    assert!(hull.faces().iter().all(|f| f.count == 4));
    assert_eq!(hull.edges().len(), 12);
    for face in hull.faces() {
        let n = face.normal.to_f64();
        let axis = (0..3).find(|&k| n[k].abs() > 0.5).expect("an axis");
        assert_eq!(n[axis].abs(), 1.0, "{n:?}");
        let half = [0.5, 1.0, 1.5][axis];
        assert_eq!(face.offset.to_f64(), half);
    }
    assert_valid(&hull, &points, 1e-9);
}

#[test]
fn the_order_of_the_points_and_duplicates_do_not_matter() {
    let mut points: Vec<Vec3<Fx>> = (0..60)
        .map(|i| {
            let t = f64::from(i);
            v(
                (t * 1.7).sin() * 2.0,
                (t * 0.9).cos() * 1.5,
                (t * 2.3).sin() * (t * 0.4).cos(),
            )
        })
        .collect();
    let hull = ConvexHull::new(&points).expect("a hull");
    assert_valid(&hull, &points, 1e-7);
    points.reverse();
    points.extend_from_slice(&points.clone()[..10]);
    points.rotate_left(17);
    assert_eq!(ConvexHull::new(&points).expect("a hull"), hull);
}

#[test]
fn a_hull_is_the_hull_of_its_vertices_also_through_ron_and_bincode() {
    let points: Vec<Vec3<Fx>> = (0..200)
        .map(|i| {
            let t = f64::from(i);
            v((t * 0.77).sin(), (t * 1.31).cos(), (t * 0.53).sin() * 0.8)
        })
        .collect();
    let hull = ConvexHull::new(&points).expect("a hull");
    assert_eq!(
        ConvexHull::new(hull.vertices()).expect("its own vertices"),
        hull
    );
    let shape = Shape::ConvexHull { hull: hull.clone() };
    let text = ron::to_string(&shape).expect("ron");
    assert!(text.starts_with("ConvexHull(points:"), "{text}");
    let back: Shape<Fx> = ron::from_str(&text).expect("read back");
    assert_eq!(back, shape);
    let bytes = fixstep::codec::encode(&shape).expect("bincode");
    let back: Shape<Fx> = fixstep::codec::decode_exact(&bytes).expect("decoded");
    assert_eq!(back, shape);
}

#[test]
fn a_rotated_box_still_has_six_plane_faces() {
    // The rotated corners are rounded to 2⁻³² m: not exactly coplanar any more.
    let turn = Quat::from_axis_angle(v(1.0, 2.0, 3.0).normalize_or_zero(), Fx::from_f64(0.7));
    for (size, offset) in [(0.01, 0.0), (1.0, 3.0), (100.0, 99_000.0)] {
        let points: Vec<Vec3<Fx>> = box_corners(size, size * 0.5, size * 2.0)
            .into_iter()
            .map(|p| turn.rotate(p) + v(offset, -offset, 0.5 * offset))
            .collect();
        let hull = ConvexHull::new(&points).expect("a box");
        assert_eq!(
            (
                hull.vertices().len(),
                hull.edges().len(),
                hull.faces().len()
            ),
            (8, 12, 6),
            "size {size}"
        );
        assert_valid(&hull, &points, 1e-9 * (1.0 + offset));
    }
}

#[test]
fn degenerate_points_are_refused_with_the_reason() {
    let p = |x, y, z| v(x, y, z);
    let cases: [(Vec<Vec3<Fx>>, HullError); 6] = [
        (
            vec![p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0)],
            HullError::TooFewPoints(3),
        ),
        (
            vec![p(0.0, 0.0, 0.0); MAX_HULL_POINTS + 1],
            HullError::TooManyPoints(MAX_HULL_POINTS + 1),
        ),
        (
            vec![p(1.0, 2.0, 3.0); 5],
            HullError::Degenerate("all points coincide"),
        ),
        (
            (0..6)
                .map(|i| p(f64::from(i), 2.0 * f64::from(i), -1.0))
                .collect(),
            HullError::Degenerate("the points lie on one line"),
        ),
        (
            (0..9)
                .map(|i| p(f64::from(i % 3), f64::from(i / 3), 0.5))
                .collect(),
            HullError::Degenerate("the points lie in one plane"),
        ),
        (
            vec![
                p(0.0, 0.0, 0.0),
                p(1.0, 0.0, 0.0),
                p(0.0, 1.0, 0.0),
                p(0.0, 0.0, 100_001.0),
            ],
            HullError::OutOfRange { index: 3 },
        ),
    ];
    for (points, error) in cases {
        assert_eq!(ConvexHull::new(&points), Err(error.clone()));
        assert!(!error.to_string().is_empty());
    }
    // Four distinct points and a duplicate: still a tetrahedron.
    let mut tetra = vec![
        p(0.0, 0.0, 0.0),
        p(1.0, 0.0, 0.0),
        p(0.0, 1.0, 0.0),
        p(0.0, 0.0, 1.0),
    ];
    tetra.push(tetra[2]);
    let hull = ConvexHull::new(&tetra).expect("a tetrahedron");
    assert_eq!((hull.vertices().len(), hull.faces().len()), (4, 4));
    // Nearly flat, but thicker than the tolerance (6·10⁻⁸ of the size): a hull.
    let mut slab: Vec<Vec3<Fx>> = (0..9)
        .map(|i| p(f64::from(i % 3), f64::from(i / 3), 0.0))
        .collect();
    slab.push(p(1.0, 1.0, 1e-6));
    assert!(ConvexHull::new(&slab).is_ok());
    slab.pop();
    slab.push(p(1.0, 1.0, 1e-8));
    assert_eq!(
        ConvexHull::new(&slab),
        Err(HullError::Degenerate("the points lie in one plane"))
    );
}

#[test]
fn a_scene_with_a_flat_hull_is_refused_with_file_line_and_reason() {
    let text = "(name: \"x\", rigid: (bodies: [(shape: ConvexHull(points: [\n\
        (x: 0.0, y: 0.0, z: 0.0), (x: 1.0, y: 0.0, z: 0.0), (x: 0.0, y: 1.0, z: 0.0),\n\
        (x: 1.0, y: 1.0, z: 0.0)]))]))";
    let e = fixstep::scene::parse_scene::<Fx>(text, "x.ron")
        .expect_err("refused")
        .to_string();
    assert!(e.contains("x.ron"), "{e}");
    // ron places the error at the end of the list it could not turn into a hull.
    assert!(e.contains("line 3"), "{e}");
    assert!(
        e.contains("the points span no volume: the points lie in one plane"),
        "{e}"
    );
}

/// A random cloud: up to 80 points on a few scales, with exact duplicates and a fraction
/// pushed onto one plane (z = 0.25 s) with sub-tolerance noise.
fn cloud() -> impl Strategy<Value = Vec<Vec3<Fx>>> {
    let point = (-1000i32..=1000, -1000i32..=1000, -1000i32..=1000);
    (
        prop::collection::vec(point, 4..80),
        prop::sample::select(vec![0.01, 1.0, 50.0, 20_000.0]),
        0usize..20,
        0usize..30,
    )
        .prop_map(|(raw, scale, duplicates, flattened)| {
            let mut points: Vec<Vec3<Fx>> = raw
                .iter()
                .enumerate()
                .map(|(k, &(x, y, z))| {
                    let z = if k < flattened {
                        250.0 + f64::from(x % 3) * 1e-6
                    } else {
                        f64::from(z)
                    };
                    v(f64::from(x), f64::from(y), z) * Fx::from_f64(scale / 1000.0)
                })
                .collect();
            for k in 0..duplicates.min(points.len()) {
                points.push(points[k * 7 % points.len()]);
            }
            points
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn random_clouds_give_valid_hulls_or_a_clear_error(points in cloud()) {
        match ConvexHull::new(&points) {
            Ok(hull) => {
                // Dropped points lie within the tolerance ε = 2⁻²⁴ s of the surface; a few ε
                // after the faces are merged and their normals refitted.
                let slack = 16.0 * half_extent(&points) / f64::from(1 << 24) + 1e-9;
                assert_valid(&hull, &points, slack);
                let mut shuffled = points.clone();
                shuffled.reverse();
                shuffled.rotate_left(points.len() / 3);
                prop_assert_eq!(&ConvexHull::new(&shuffled).expect("the same points"), &hull);
                prop_assert_eq!(&ConvexHull::new(hull.vertices()).expect("its vertices"), &hull);
            }
            Err(error) => prop_assert!(matches!(error, HullError::Degenerate(_)), "{error}"),
        }
    }
}

#[test]
fn a_dense_grid_on_a_cube_surface_is_still_eight_corners() {
    // 10 × 10 points on each face (on edges and faces, mostly not corners), far from the
    // origin: 600 points, of which 8 corners.
    let mut points = Vec::new();
    for k in 0..10 {
        for l in 0..10 {
            let (s, t) = (
                f64::from(k) / 9.0 * 2.0 - 1.0,
                f64::from(l) / 9.0 * 2.0 - 1.0,
            );
            for side in [-1.0, 1.0] {
                points.push([side, s, t]);
                points.push([s, side, t]);
                points.push([s, t, side]);
            }
        }
    }
    let points: Vec<Vec3<Fx>> = points
        .iter()
        .map(|p| v(40_000.0 + 3.0 * p[0], -70_000.0 + 3.0 * p[1], 3.0 * p[2]))
        .collect();
    let hull = ConvexHull::new(&points).expect("a cube");
    assert_eq!(
        (
            hull.vertices().len(),
            hull.edges().len(),
            hull.faces().len()
        ),
        (8, 12, 6)
    );
    assert_valid(&hull, &points, 1e-9);
}

#[test]
fn the_largest_hull_keeps_every_point_of_a_sphere() {
    // MAX_HULL_POINTS points of a Fibonacci sphere, every one a corner (about 30 ms with
    // the test profile on the 2-core build machine).
    let n = MAX_HULL_POINTS;
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    let points: Vec<Vec3<Fx>> = (0..n)
        .map(|i| {
            let y = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
            let r = (1.0 - y * y).sqrt();
            let a = golden * i as f64;
            v(r * a.cos() * 2.5, y * 2.5, r * a.sin() * 2.5)
        })
        .collect();
    let start = std::time::Instant::now();
    let hull = ConvexHull::new(&points).expect("a sphere");
    let elapsed = start.elapsed();
    println!("{n} points: {:?}", elapsed);
    assert_eq!(hull.vertices().len(), n);
    assert_eq!(hull.faces().len(), 2 * n - 4, "all triangles");
    assert_valid(&hull, &points, 1e-9);
}
