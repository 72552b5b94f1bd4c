//! Queries against analytic answers computed in `f64`, edge cases, filters, the tree's
//! invariants, and the tree against brute force.

mod convex_shapes;

use super::tree::AabbTree;
use super::*;
use crate::math::{Pcg32, Quat};
use crate::rigid::{BodyDesc, BodyKind, CollisionFilter, Part, RigidDesc, SolverSettings};

type F = Fx;

/// 2⁻²⁰ m: the distance accuracy asked of a ray.
const DISTANCE_TOLERANCE: f64 = 1.0 / 1048576.0; // ok-det: f64 reference
/// The normal accuracy asked of a ray.
const NORMAL_TOLERANCE: f64 = 1e-5; // ok-det: f64 reference

fn v(x: f64, y: f64, z: f64) -> Vec3<F> // ok-det: f64 reference
{
    Vec3::from_f64(x, y, z)
}

fn fx(x: f64) -> F // ok-det: f64 reference
{
    F::from_f64(x)
}

/// A unit quaternion for a rotation of `angle` rad about the normalised `axis`.
fn rotation(axis: [f64; 3], angle: f64) -> Quat<F> // ok-det: f64 reference
{
    let n = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
    let (s, c) = (angle * 0.5).sin_cos();
    Quat::from_f64(c, s * axis[0] / n, s * axis[1] / n, s * axis[2] / n).normalize()
}

fn body(kind: BodyKind, shape: Shape<F>, position: Vec3<F>, orientation: Quat<F>) -> BodyDesc<F> {
    let mut b = BodyDesc::new(shape, position);
    b.kind = kind;
    b.orientation = orientation;
    b
}

fn fixed(shape: Shape<F>, position: Vec3<F>) -> BodyDesc<F> {
    body(BodyKind::Static, shape, position, Quat::IDENTITY)
}

fn system(bodies: Vec<BodyDesc<F>>) -> RigidSystem<F> {
    RigidSystem::from_desc(&RigidDesc {
        bodies,
        solver: SolverSettings {
            sleeping: false,
            ..SolverSettings::default()
        },
        ..RigidDesc::default()
    })
    .expect("a valid scene")
}

fn sphere(r: f64) -> Shape<F> // ok-det: f64 reference
{
    Shape::Sphere { radius: fx(r) }
}

fn cuboid(x: f64, y: f64, z: f64) -> Shape<F> // ok-det: f64 reference
{
    Shape::Box {
        half_extents: v(x, y, z),
    }
}

fn capsule(r: f64, h: f64) -> Shape<F> // ok-det: f64 reference
{
    Shape::Capsule {
        radius: fx(r),
        half_height: fx(h),
    }
}

fn ground() -> Shape<F> {
    Shape::Plane {
        normal: Vec3::Y,
        offset: F::ZERO,
    }
}

// ---- f64 references -------------------------------------------------------------------

type D3 = [f64; 3]; // ok-det: f64 reference

fn sub(a: D3, b: D3) -> D3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: D3, b: D3) -> f64 // ok-det: f64 reference
{
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: D3, b: D3) -> D3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn scale(a: D3, s: f64) -> D3 // ok-det: f64 reference
{
    [a[0] * s, a[1] * s, a[2] * s]
}
fn add(a: D3, b: D3) -> D3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn unit(a: D3) -> D3 {
    scale(a, 1.0 / dot(a, a).sqrt())
}

/// v rotated by the unit quaternion q = [w, x, y, z]: v + 2w(u×v) + 2u×(u×v).
fn rotate(q: [f64; 4], v: D3) -> D3 // ok-det: f64 reference
{
    let u = [q[1], q[2], q[3]];
    let t = scale(cross(u, v), 2.0);
    add(add(v, scale(t, q[0])), cross(u, t))
}

fn inverse_rotate(q: [f64; 4], v: D3) -> D3 // ok-det: f64 reference
{
    rotate([q[0], -q[1], -q[2], -q[3]], v)
}

/// Ray o + t d (d unit) against the ball (c, r), from outside: (t, normal).
fn ref_sphere(o: D3, d: D3, c: D3, r: f64) -> Option<(f64, D3)> // ok-det: f64 reference
{
    let m = sub(o, c);
    let b = dot(m, d);
    let k = dot(m, m) - r * r;
    let disc = b * b - k;
    if disc < 0.0 || b > 0.0 {
        return None;
    }
    let t = -b - disc.sqrt();
    Some((t, unit(add(m, scale(d, t)))))
}

/// Ray in the box frame against |x_k| ≤ h_k from outside: (t, normal).
fn ref_box(o: D3, d: D3, h: D3) -> Option<(f64, D3)> // ok-det: f64 reference
{
    let (mut enter, mut exit, mut axis) = (f64::NEG_INFINITY, f64::INFINITY, 0); // ok-det: f64 reference
    for k in 0..3 {
        let t1 = (-h[k] - o[k]) / d[k];
        let t2 = (h[k] - o[k]) / d[k];
        let (near, far) = if t1 < t2 { (t1, t2) } else { (t2, t1) };
        if near > enter {
            enter = near;
            axis = k;
        }
        exit = exit.min(far);
    }
    if enter > exit || exit < 0.0 {
        return None;
    }
    let mut n = [0.0; 3];
    n[axis] = -d[axis].signum();
    Some((enter, n))
}

/// Ray in the capsule frame (axis y) from outside: (t, normal).
fn ref_capsule(o: D3, d: D3, r: f64, h: f64) -> Option<(f64, D3)> // ok-det: f64 reference
{
    let mut best: Option<(f64, D3)> = None; // ok-det: f64 reference
    let a = d[0] * d[0] + d[2] * d[2];
    let b = o[0] * d[0] + o[2] * d[2];
    let k = o[0] * o[0] + o[2] * o[2] - r * r;
    let disc = b * b - a * k;
    if a > 0.0 && disc >= 0.0 {
        let t = (-b - disc.sqrt()) / a;
        let p = add(o, scale(d, t));
        if t >= 0.0 && p[1].abs() <= h {
            best = Some((t, unit([p[0], 0.0, p[2]])));
        }
    }
    for end in [-h, h] {
        if let Some(hit) = ref_sphere(o, d, [0.0, end, 0.0], r)
            && best.is_none_or(|b| hit.0 < b.0)
        {
            best = Some(hit);
        }
    }
    best
}

fn assert_hit(hit: Option<RayHit<F>>, expected: (f64, D3), what: &str) // ok-det: f64 reference
{
    let hit = hit.unwrap_or_else(|| panic!("{what}: no hit, expected {expected:?}"));
    let t = hit.distance.to_f64();
    assert!(
        (t - expected.0).abs() <= DISTANCE_TOLERANCE,
        "{what}: distance {t}, expected {}",
        expected.0
    );
    let n = hit.normal.to_f64();
    for k in 0..3 {
        assert!(
            (n[k] - expected.1[k]).abs() <= NORMAL_TOLERANCE,
            "{what}: normal {n:?}, expected {:?}",
            expected.1
        );
    }
}

/// Random ray origins around the scene aimed at points near `target`.
fn random_rays(rng: &mut Pcg32, target: D3, count: usize) -> Vec<(D3, D3)> {
    (0..count)
        .map(|_| {
            let o: Vec3<F> = rng.unit_vector();
            let o = add(scale(o.to_f64(), 6.0), target);
            let aim = [
                target[0] + rng.range::<F>(fx(-1.5), fx(1.5)).to_f64(),
                target[1] + rng.range::<F>(fx(-1.5), fx(1.5)).to_f64(),
                target[2] + rng.range::<F>(fx(-1.5), fx(1.5)).to_f64(),
            ];
            (o, unit(sub(aim, o)))
        })
        .collect()
}

/// The ray as the engine sees it: origin and direction rounded to the format, the
/// direction renormalised in f64 (the engine's normalisation is within ulps of it).
fn rounded(o: D3, d: D3) -> (Vec3<F>, Vec3<F>, D3, D3) {
    let (of, df) = (v(o[0], o[1], o[2]), v(d[0], d[1], d[2]));
    (of, df, of.to_f64(), unit(df.to_f64()))
}

// ---- rays against analytic answers ------------------------------------------------------

#[test]
fn rays_against_a_sphere_match_the_analytic_distance_and_normal() {
    let centre = v(1.25, -0.5, 2.0);
    let sys = system(vec![fixed(sphere(0.75), centre)]);
    let c = centre.to_f64();
    let mut rng = Pcg32::new(1, 1);
    let mut hits = 0;
    for (o, d) in random_rays(&mut rng, c, 300) {
        let (of, df, o, d) = rounded(o, d);
        let got = sys.cast_ray(of, df, fx(100.0), &QueryFilter::new());
        match ref_sphere(o, d, c, 0.75) {
            Some(expected) => {
                hits += 1;
                assert_hit(got, expected, "sphere");
            }
            None => assert!(got.is_none(), "sphere: {got:?} for a miss"),
        }
    }
    assert!(hits > 50, "only {hits} of the rays hit");
}

#[test]
fn rays_against_a_rotated_box_match_the_slab_answer() {
    let q = rotation([1.0, 2.0, -0.5], 0.7);
    let centre = v(-1.0, 0.5, 0.25);
    let half = [0.5, 1.25, 0.75];
    let sys = system(vec![body(
        BodyKind::Static,
        cuboid(half[0], half[1], half[2]),
        centre,
        q,
    )]);
    let h = sys.handles().next().unwrap();
    let qf = sys.orientation(h).unwrap().to_f64();
    let c = sys.position(h).unwrap().to_f64();
    let mut rng = Pcg32::new(2, 1);
    let mut hits = 0;
    for (o, d) in random_rays(&mut rng, c, 300) {
        let (of, df, o, d) = rounded(o, d);
        let got = sys.cast_ray(of, df, fx(100.0), &QueryFilter::new());
        let local = ref_box(inverse_rotate(qf, sub(o, c)), inverse_rotate(qf, d), half);
        match local {
            Some((t, n)) => {
                hits += 1;
                assert_hit(got, (t, rotate(qf, n)), "box");
            }
            None => assert!(got.is_none(), "box: {got:?} for a miss"),
        }
    }
    assert!(hits > 50, "only {hits} of the rays hit");
}

#[test]
fn rays_against_a_capsule_match_the_analytic_answer() {
    let q = rotation([0.3, 0.0, 1.0], 1.1);
    let (r, hh) = (0.4, 0.9);
    let sys = system(vec![body(
        BodyKind::Static,
        capsule(r, hh),
        v(0.5, 1.0, -0.5),
        q,
    )]);
    let h = sys.handles().next().unwrap();
    let qf = sys.orientation(h).unwrap().to_f64();
    let c = sys.position(h).unwrap().to_f64();
    let mut rng = Pcg32::new(3, 1);
    let mut hits = 0;
    for (o, d) in random_rays(&mut rng, c, 300) {
        let (of, df, o, d) = rounded(o, d);
        let got = sys.cast_ray(of, df, fx(100.0), &QueryFilter::new());
        let local = ref_capsule(inverse_rotate(qf, sub(o, c)), inverse_rotate(qf, d), r, hh);
        match local {
            Some((t, n)) => {
                hits += 1;
                assert_hit(got, (t, rotate(qf, n)), "capsule");
            }
            None => assert!(got.is_none(), "capsule: {got:?} for a miss"),
        }
    }
    assert!(hits > 50, "only {hits} of the rays hit");
}

#[test]
fn rays_against_a_compound_hit_its_nearest_part() {
    // Two balls of radius 0.5 at x = ±1 and a flat box between them, all on one body.
    let part = |shape: Shape<F>, translation: Vec3<F>| Part {
        rotation: Quat::IDENTITY,
        translation,
        shape,
    };
    let compound = Shape::Compound {
        parts: vec![
            part(sphere(0.5), v(-1.0, 0.0, 0.0)),
            part(sphere(0.5), v(1.0, 0.0, 0.0)),
            part(cuboid(1.0, 0.1, 0.1), Vec3::ZERO),
        ],
    };
    let q = rotation([0.0, 1.0, 0.0], 0.4);
    let sys = system(vec![body(BodyKind::Static, compound, v(0.0, 2.0, 0.0), q)]);
    let h = sys.handles().next().unwrap();
    let qf = sys.orientation(h).unwrap().to_f64();
    let c = sys.position(h).unwrap().to_f64();
    let Some(Shape::Compound { parts }) = sys.shape(h) else {
        panic!("a compound")
    };
    let parts: Vec<(D3, Shape<F>)> = parts
        .iter()
        .map(|p| (p.translation.to_f64(), p.shape.clone()))
        .collect();
    let mut rng = Pcg32::new(4, 1);
    let mut hits = 0;
    for (o, d) in random_rays(&mut rng, c, 300) {
        let (of, df, o, d) = rounded(o, d);
        let got = sys.cast_ray(of, df, fx(100.0), &QueryFilter::new());
        let (lo, ld) = (inverse_rotate(qf, sub(o, c)), inverse_rotate(qf, d));
        let mut best: Option<(f64, D3)> = None; // ok-det: f64 reference
        for (t, shape) in &parts {
            let hit = match shape {
                Shape::Sphere { radius } => ref_sphere(lo, ld, *t, radius.to_f64()),
                Shape::Box { half_extents } => ref_box(sub(lo, *t), ld, half_extents.to_f64()),
                _ => unreachable!(),
            };
            if let Some(hit) = hit
                && best.is_none_or(|b| hit.0 < b.0)
            {
                best = Some(hit);
            }
        }
        match best {
            Some((t, n)) => {
                hits += 1;
                assert_hit(got, (t, rotate(qf, n)), "compound");
            }
            None => assert!(got.is_none(), "compound: {got:?} for a miss"),
        }
    }
    assert!(hits > 50, "only {hits} of the rays hit");
}

#[test]
fn a_plane_is_a_solid_half_space() {
    let sys = system(vec![fixed(
        Shape::Plane {
            normal: v(0.6, 0.8, 0.0),
            offset: fx(0.5),
        },
        Vec3::ZERO,
    )]);
    let f = QueryFilter::new();
    // From above, straight down: s = n·o − c = 0.8·3 − 0.5 = 1.9; t = s / 0.8.
    let hit = sys.cast_ray(v(0.0, 3.0, 0.0), v(0.0, -2.0, 0.0), fx(10.0), &f);
    assert_hit(hit, (1.9 / 0.8, [0.6, 0.8, 0.0]), "plane");
    // Below the plane: inside, distance 0.
    let inside = sys
        .cast_ray(v(0.0, -1.0, 0.0), v(1.0, 0.0, 0.0), fx(10.0), &f)
        .unwrap();
    assert_eq!(inside.distance, F::ZERO);
    assert_eq!(inside.point, v(0.0, -1.0, 0.0));
    assert_eq!(inside.normal, -Vec3::X);
    // Away from it, or too short: no hit.
    assert!(
        sys.cast_ray(v(0.0, 3.0, 0.0), Vec3::Y, fx(10.0), &f)
            .is_none()
    );
    assert!(
        sys.cast_ray(v(0.0, 3.0, 0.0), -Vec3::Y, fx(2.0), &f)
            .is_none()
    );
}

// ---- edge cases -------------------------------------------------------------------------

#[test]
fn a_zero_direction_or_a_negative_distance_finds_nothing() {
    let sys = system(vec![fixed(sphere(1.0), Vec3::ZERO)]);
    let f = QueryFilter::new();
    assert!(
        sys.cast_ray(v(0.0, 0.0, -5.0), Vec3::ZERO, fx(10.0), &f)
            .is_none()
    );
    assert!(
        sys.cast_ray_all(v(0.0, 0.0, -5.0), Vec3::ZERO, fx(10.0), &f)
            .is_empty()
    );
    assert!(
        sys.cast_ray(v(0.0, 0.0, -5.0), Vec3::Z, fx(-1.0), &f)
            .is_none()
    );
    assert!(
        sys.cast_shape(
            &sphere(0.1),
            v(0.0, 0.0, -5.0),
            Quat::IDENTITY,
            Vec3::ZERO,
            fx(10.0),
            &f
        )
        .is_none()
    );
}

#[test]
fn a_ray_starting_inside_hits_at_its_origin_facing_back() {
    for shape in [sphere(1.0), cuboid(1.0, 0.5, 2.0), capsule(0.5, 1.0)] {
        let sys = system(vec![fixed(shape.clone(), Vec3::ZERO)]);
        let o = v(0.1, 0.2, -0.3);
        let hit = sys
            .cast_ray(o, v(0.0, 0.0, 3.0), fx(10.0), &QueryFilter::new())
            .unwrap_or_else(|| panic!("{shape:?}: no hit from inside"));
        assert_eq!(hit.distance, F::ZERO, "{shape:?}");
        assert_eq!(hit.point, o, "{shape:?}");
        assert_eq!(hit.normal, -Vec3::Z, "{shape:?}");
    }
}

#[test]
fn tiny_and_huge_directions_are_normalised_precisely() {
    let sys = system(vec![fixed(sphere(1.0), Vec3::ZERO)]);
    let f = QueryFilter::new();
    let expected = sys.cast_ray(v(0.0, 0.0, -5.0), Vec3::Z, fx(10.0), &f);
    for scale in [F::EPSILON, fx(1e-6), fx(1e6), F::MAX] {
        let got = sys.cast_ray(v(0.0, 0.0, -5.0), Vec3::Z * scale, fx(10.0), &f);
        assert_eq!(got, expected, "direction scaled by {scale}");
    }
}

#[test]
fn grazing_rays_hit_at_the_touching_distance_or_miss() {
    let sys = system(vec![
        fixed(cuboid(1.0, 1.0, 1.0), Vec3::ZERO),
        fixed(sphere(1.0), v(10.0, 0.0, 0.0)),
    ]);
    let f = QueryFilter::new();
    // Along the box's top edge (y = 1, z = 1): touching, so a hit at x = −1.
    let edge = sys
        .cast_ray(v(-5.0, 1.0, 1.0), Vec3::X, fx(6.0), &f)
        .unwrap();
    assert_eq!(edge.distance, fx(4.0));
    // Tangent to the sphere (y = 1 over its centre): a hit at the tangent point or a miss.
    if let Some(hit) = sys.cast_ray(v(7.0, 1.0, 0.0), Vec3::X, fx(10.0), &f) {
        assert!((hit.distance.to_f64() - 3.0).abs() < 1e-3, "{hit:?}");
    }
    // Just past the edge: a miss.
    let past = F::ONE + F::EPSILON;
    assert!(
        sys.cast_ray(Vec3::new(fx(-5.0), past, F::ONE), Vec3::X, fx(6.0), &f)
            .is_none()
    );
}

#[test]
fn huge_values_saturate_without_panicking() {
    let sys = system(vec![
        fixed(sphere(1.0), Vec3::ZERO),
        fixed(cuboid(1.0, 2.0, 3.0), v(5.0, 0.0, 0.0)),
        fixed(capsule(1.0, 2.0), v(-5.0, 0.0, 0.0)),
        fixed(ground(), v(0.0, -10.0, 0.0)),
    ]);
    let f = QueryFilter::new();
    let big = F::MAX;
    for o in [
        Vec3::splat(big),
        Vec3::splat(-big),
        Vec3::new(big, F::ZERO, -big),
    ] {
        for d in [
            Vec3::X,
            -Vec3::Y,
            Vec3::splat(big),
            Vec3::new(F::ONE, -big, F::EPSILON),
        ] {
            let _ = sys.cast_ray(o, d, big, &f);
            let _ = sys.cast_ray_all(o, d, big, &f);
            let _ = sys.cast_shape(&sphere(1.0), o, Quat::IDENTITY, d, big, &f);
            let _ = sys.cast_shape(&cuboid(1.0, 1.0, 1.0), o, Quat::IDENTITY, d, big, &f);
            let _ = sys.project_point(o, big, &f);
            let _ = sys.overlap(&sphere(1.0), o, Quat::IDENTITY, &f);
        }
    }
    // A far ray along −y still finds the plane.
    let hit = sys.cast_ray(v(0.0, 1e6, 50.0), -Vec3::Y, big, &f).unwrap();
    assert_eq!(hit.body, sys.handles().nth(3).unwrap());
    assert!(
        (hit.distance.to_f64() - (1e6 + 10.0)).abs() < 1e-3,
        "{hit:?}"
    );
}

// ---- filters ----------------------------------------------------------------------------

#[test]
fn filters_skip_masked_excluded_and_sensor_bodies() {
    let mut near = fixed(sphere(0.5), v(0.0, 0.0, 2.0));
    near.filter = CollisionFilter::new(0b01, u32::MAX);
    let mut sensor = fixed(sphere(0.5), v(0.0, 0.0, 4.0));
    sensor.sensor = true;
    let far = fixed(sphere(0.5), v(0.0, 0.0, 6.0));
    let sys = system(vec![near, sensor, far]);
    let h: Vec<Handle> = sys.handles().collect();
    let ray = |f: &QueryFilter| {
        sys.cast_ray(Vec3::ZERO, Vec3::Z, fx(10.0), f)
            .map(|h| h.body)
    };
    assert_eq!(ray(&QueryFilter::new()), Some(h[0]));
    assert_eq!(ray(&QueryFilter::new().with_mask(0b10)), Some(h[2]));
    assert_eq!(ray(&QueryFilter::new().excluding(h[0])), Some(h[2]));
    assert_eq!(
        ray(&QueryFilter::new().excluding(h[0]).with_sensors()),
        Some(h[1])
    );
    let all: Vec<Handle> = sys
        .cast_ray_all(
            Vec3::ZERO,
            Vec3::Z,
            fx(10.0),
            &QueryFilter::new().with_sensors(),
        )
        .iter()
        .map(|h| h.body)
        .collect();
    assert_eq!(all, h);
    let big = sphere(10.0);
    assert_eq!(
        sys.overlap(
            &big,
            Vec3::ZERO,
            Quat::IDENTITY,
            &QueryFilter::new().with_mask(0b10)
        ),
        vec![h[2]]
    );
    let p = sys
        .project_point(v(0.0, 0.0, 3.0), fx(10.0), &QueryFilter::new())
        .unwrap();
    assert_eq!(p.body, h[0]);
}

// ---- shape casts ------------------------------------------------------------------------

/// The cast's distance must be the analytic one within 2⁻¹⁹ m (the advancement stops
/// within 2⁻²⁰ m of touching, plus rounding).
fn assert_cast(
    hit: Option<RayHit<F>>,
    distance: f64, // ok-det: f64 reference
    normal: D3,
    what: &str,
) {
    let hit = hit.unwrap_or_else(|| panic!("{what}: no hit"));
    let t = hit.distance.to_f64();
    assert!(
        (t - distance).abs() <= 2.0 * DISTANCE_TOLERANCE,
        "{what}: distance {t}, expected {distance}"
    );
    let n = hit.normal.to_f64();
    for k in 0..3 {
        assert!(
            (n[k] - normal[k]).abs() <= 1e-4,
            "{what}: normal {n:?}, expected {normal:?}"
        );
    }
}

#[test]
fn a_sphere_cast_onto_a_plane_or_a_box_stops_at_the_analytic_distance() {
    let f = QueryFilter::new();
    let plane = system(vec![fixed(ground(), Vec3::ZERO)]);
    // Straight down from y = 5 with radius 0.5: t = 4.5; slanted by 30°: t = 4.5 / cos 30°.
    let hit = plane.cast_shape(
        &sphere(0.5),
        v(0.0, 5.0, 0.0),
        Quat::IDENTITY,
        -Vec3::Y,
        fx(10.0),
        &f,
    );
    assert_cast(hit, 4.5, [0.0, 1.0, 0.0], "sphere onto plane");
    assert!((hit.unwrap().point.y.to_f64()).abs() < 1e-5);
    let slant = v(0.5, -(3.0f64.sqrt()) / 2.0, 0.0);
    let hit = plane.cast_shape(
        &sphere(0.5),
        v(0.0, 5.0, 0.0),
        Quat::IDENTITY,
        slant,
        fx(10.0),
        &f,
    );
    assert_cast(
        hit,
        4.5 / (3.0f64.sqrt() / 2.0),
        [0.0, 1.0, 0.0],
        "slanted sphere onto plane",
    );
    // A box (top face at y = 1) from above and onto its corner region.
    let boxed = system(vec![fixed(cuboid(2.0, 1.0, 2.0), Vec3::ZERO)]);
    let hit = boxed.cast_shape(
        &sphere(0.25),
        v(0.5, 4.0, -0.5),
        Quat::IDENTITY,
        -Vec3::Y,
        fx(10.0),
        &f,
    );
    assert_cast(hit, 2.75, [0.0, 1.0, 0.0], "sphere onto box face");
    // Over the edge x = 2, y = 1, passing 0.1 beyond it in x: touches the edge where
    // (0.1)² + (y − 1)² = 0.25², y = 1 + √(0.0625 − 0.01).
    let hit = boxed.cast_shape(
        &sphere(0.25),
        v(2.1, 4.0, 0.0),
        Quat::IDENTITY,
        -Vec3::Y,
        fx(10.0),
        &f,
    );
    let y = 1.0 + (0.0625f64 - 0.01).sqrt();
    assert_cast(
        hit,
        4.0 - y,
        unit([0.1, y - 1.0, 0.0]),
        "sphere onto box edge",
    );
    // Far past the box: a miss.
    assert!(
        boxed
            .cast_shape(
                &sphere(0.25),
                v(2.3, 4.0, 0.0),
                Quat::IDENTITY,
                -Vec3::Y,
                fx(10.0),
                &f
            )
            .is_none()
    );
}

#[test]
fn boxes_and_capsules_cast_onto_planes_boxes_and_spheres() {
    let f = QueryFilter::new();
    let plane = system(vec![fixed(ground(), Vec3::ZERO)]);
    // A box turned 45° about z: its lowest edge is √2·0.5 below its centre.
    let q = rotation([0.0, 0.0, 1.0], core::f64::consts::FRAC_PI_4); // ok-det: f64 reference
    let hit = plane.cast_shape(
        &cuboid(0.5, 0.5, 0.5),
        v(0.0, 3.0, 0.0),
        q,
        -Vec3::Y,
        fx(10.0),
        &f,
    );
    assert_cast(
        hit,
        3.0 - 0.5 * 2.0f64.sqrt(),
        [0.0, 1.0, 0.0],
        "turned box onto plane",
    );
    // A capsule lying along x (turned 90° about z), radius 0.3, onto a box top at y = 1.
    let lying = rotation([0.0, 0.0, 1.0], core::f64::consts::FRAC_PI_2); // ok-det: f64 reference
    let boxed = system(vec![fixed(cuboid(2.0, 1.0, 2.0), Vec3::ZERO)]);
    let hit = boxed.cast_shape(
        &capsule(0.3, 0.8),
        v(0.0, 3.0, 0.0),
        lying,
        -Vec3::Y,
        fx(10.0),
        &f,
    );
    assert_cast(hit, 2.0 - 0.3, [0.0, 1.0, 0.0], "capsule onto box");
    // A box sideways onto a sphere: face x = −0.5 of the box meets the ball at x = 1.
    let ball = system(vec![fixed(sphere(1.0), Vec3::ZERO)]);
    let hit = ball.cast_shape(
        &cuboid(0.5, 0.5, 0.5),
        v(5.0, 0.0, 0.0),
        Quat::IDENTITY,
        -Vec3::X,
        fx(10.0),
        &f,
    );
    assert_cast(hit, 3.5, [1.0, 0.0, 0.0], "box onto sphere");
    // A sphere onto a capsule's side (analytic): the capsule stands along y at the origin.
    let cap = system(vec![fixed(capsule(0.5, 1.0), Vec3::ZERO)]);
    let hit = cap.cast_shape(
        &sphere(0.25),
        v(3.0, 0.5, 0.0),
        Quat::IDENTITY,
        -Vec3::X,
        fx(10.0),
        &f,
    );
    assert_cast(hit, 2.25, [1.0, 0.0, 0.0], "sphere onto capsule");
    let hit = hit.unwrap();
    assert!((hit.point.x.to_f64() - 0.5).abs() < 1e-5, "{hit:?}");
    // Already overlapping: distance 0.
    let hit = cap.cast_shape(
        &sphere(0.25),
        v(0.6, 0.0, 0.0),
        Quat::IDENTITY,
        Vec3::X,
        fx(10.0),
        &f,
    );
    assert_eq!(hit.unwrap().distance, F::ZERO);
    // Plane and compound cast shapes are not supported.
    assert!(
        cap.cast_shape(
            &ground(),
            v(3.0, 0.0, 0.0),
            Quat::IDENTITY,
            -Vec3::X,
            fx(10.0),
            &f
        )
        .is_none()
    );
}

// ---- overlap and closest points ---------------------------------------------------------

#[test]
fn overlap_and_closest_point_answer_each_shape() {
    let sys = system(vec![
        fixed(ground(), Vec3::ZERO),
        fixed(sphere(0.5), v(0.0, 2.0, 0.0)),
        fixed(cuboid(0.5, 0.5, 0.5), v(3.0, 2.0, 0.0)),
        fixed(capsule(0.25, 1.0), v(-3.0, 2.0, 0.0)),
    ]);
    let h: Vec<Handle> = sys.handles().collect();
    let f = QueryFilter::new();
    let at = |x: f64, y: f64, r: f64| sys.overlap(&sphere(r), v(x, y, 0.0), Quat::IDENTITY, &f); // ok-det: f64 reference
    assert_eq!(at(0.0, 2.0, 0.1), vec![h[1]]);
    assert_eq!(at(0.0, 0.05, 0.1), vec![h[0]]);
    assert_eq!(at(1.5, 2.0, 0.5), Vec::<Handle>::new());
    assert_eq!(at(1.5, 2.0, 1.2), vec![h[1], h[2]]);
    assert_eq!(at(-3.0, 3.2, 0.1), vec![h[3]]);
    // A wide box over everything, just above the ground.
    let slab = sys.overlap(&cuboid(5.0, 0.6, 1.0), v(0.0, 2.0, 0.0), Quat::IDENTITY, &f);
    assert_eq!(slab, h[1..].to_vec());
    // Closest points.
    let p = sys.project_point(v(0.0, 3.5, 0.0), fx(10.0), &f).unwrap();
    assert_eq!(p.body, h[1]);
    assert!(!p.inside);
    assert!((p.distance.to_f64() - 1.0).abs() < 1e-6 && (p.point.y.to_f64() - 2.5).abs() < 1e-6);
    let p = sys.project_point(v(3.0, 2.0, 0.2), fx(10.0), &f).unwrap();
    assert_eq!((p.body, p.inside, p.distance), (h[2], true, F::ZERO));
    assert_eq!(p.point, v(3.0, 2.0, 0.2));
    let p = sys.project_point(v(-3.0, 3.5, 0.0), fx(10.0), &f).unwrap();
    assert_eq!(p.body, h[3]);
    assert!((p.distance.to_f64() - 0.25).abs() < 1e-6, "{p:?}");
    let p = sys.project_point(v(10.0, 0.5, 0.0), fx(10.0), &f).unwrap();
    assert_eq!(p.body, h[0]);
    assert!((p.point.y.to_f64()).abs() < 1e-9);
    assert!(sys.project_point(v(10.0, 0.5, 0.0), fx(0.25), &f).is_none());
}

// ---- the tree ---------------------------------------------------------------------------

fn random_box(rng: &mut Pcg32, extent: f64) -> Aabb<F> // ok-det: f64 reference
{
    let c = Vec3::new(
        rng.range(fx(-extent), fx(extent)),
        rng.range(fx(-extent), fx(extent)),
        rng.range(fx(-extent), fx(extent)),
    );
    let h = Vec3::new(
        rng.range(fx(0.0), fx(2.0)),
        rng.range(fx(0.0), fx(2.0)),
        rng.range(fx(0.0), fx(2.0)),
    );
    Aabb {
        min: c - h,
        max: c + h,
    }
}

#[test]
fn the_tree_keeps_its_invariants_and_finds_every_overlap() {
    let mut rng = Pcg32::new(7, 3);
    let mut tree = AabbTree::<F>::default();
    let mut leaves: Vec<Option<(u32, Aabb<F>)>> = vec![None; 500];
    let mut stack = Vec::new();
    for round in 0..4000 {
        let slot = rng.below(500) as usize;
        let fat = random_box(&mut rng, 40.0);
        match leaves[slot] {
            None => leaves[slot] = Some((tree.insert(slot as u32, fat), fat)),
            Some((leaf, _)) if rng.below(3) == 0 => {
                tree.remove(leaf);
                leaves[slot] = None;
            }
            Some((leaf, _)) => {
                tree.reinsert(leaf, fat);
                leaves[slot] = Some((leaf, fat));
            }
        }
        if round % 500 == 0 {
            let live = leaves.iter().flatten().count();
            assert_eq!(tree.validate(), live);
            let bound = 2.0 * (live.max(2) as f64).log2() + 2.0; // ok-det: f64 reference
            assert!(
                f64::from(tree.height()) <= bound, // ok-det: f64 reference
                "height {} for {live}",
                tree.height()
            );
            for _ in 0..50 {
                let q = random_box(&mut rng, 40.0);
                let mut found = Vec::new();
                tree.traverse(&mut stack, |aabb, leaf| {
                    let hit = aabb.overlaps(&q);
                    if hit && let Some(slot) = leaf {
                        found.push(slot as usize);
                    }
                    hit
                });
                found.sort_unstable();
                let expected: Vec<usize> = (0..500)
                    .filter(|&s| leaves[s].is_some_and(|(_, b)| b.overlaps(&q)))
                    .collect();
                assert_eq!(found, expected);
            }
        }
    }
}

/// A scene of `n` random shapes at random poses in a 20 m cube, and a ground plane.
fn random_scene(seed: u64, n: usize, kind: BodyKind) -> RigidSystem<F> {
    let mut rng = Pcg32::new(seed, 5);
    let mut bodies = vec![fixed(ground(), v(0.0, -10.0, 0.0))];
    for _ in 0..n {
        let size = |rng: &mut Pcg32| rng.range(fx(0.1), fx(1.0));
        let shape = match rng.below(7) {
            0 => Shape::Sphere {
                radius: size(&mut rng),
            },
            1 => Shape::Box {
                half_extents: Vec3::new(size(&mut rng), size(&mut rng), size(&mut rng)),
            },
            2 => Shape::Capsule {
                radius: size(&mut rng),
                half_height: size(&mut rng),
            },
            3 => Shape::Cylinder {
                radius: size(&mut rng),
                half_height: size(&mut rng),
            },
            4 => Shape::Cone {
                radius: size(&mut rng),
                half_height: size(&mut rng),
            },
            // A hand-built hull has no mass properties here: static scenes only.
            5 if kind == BodyKind::Static => convex_shapes::tetra_hull(1.0),
            _ => Shape::Compound {
                parts: vec![
                    Part {
                        rotation: Quat::IDENTITY,
                        translation: v(0.5, 0.0, 0.0),
                        shape: Shape::Sphere {
                            radius: size(&mut rng),
                        },
                    },
                    Part {
                        rotation: rotation([1.0, 0.0, 0.0], 0.5),
                        translation: v(-0.5, 0.0, 0.0),
                        shape: Shape::Box {
                            half_extents: Vec3::new(size(&mut rng), size(&mut rng), size(&mut rng)),
                        },
                    },
                ],
            },
        };
        let p = Vec3::new(
            rng.range(fx(-10.0), fx(10.0)),
            rng.range(fx(-9.0), fx(10.0)),
            rng.range(fx(-10.0), fx(10.0)),
        );
        let axis: Vec3<F> = rng.unit_vector();
        let q = Quat::from_axis_angle(axis, rng.range(fx(0.0), fx(3.0)));
        bodies.push(body(kind, shape, p, q));
    }
    system(bodies)
}

/// Runs a batch of every query on `sys` and returns the answers, for comparison.
fn answers(sys: &RigidSystem<F>, seed: u64) -> Vec<String> {
    let mut rng = Pcg32::new(seed, 9);
    let f = QueryFilter::new();
    let mut out = Vec::new();
    let point = |rng: &mut Pcg32| {
        Vec3::new(
            rng.range(fx(-12.0), fx(12.0)),
            rng.range(fx(-12.0), fx(12.0)),
            rng.range(fx(-12.0), fx(12.0)),
        )
    };
    for _ in 0..60 {
        let o = point(&mut rng);
        let d: Vec3<F> = rng.unit_vector();
        out.push(format!("{:?}", sys.cast_ray(o, d, fx(30.0), &f)));
        out.push(format!("{:?}", sys.cast_ray_all(o, d, fx(30.0), &f)));
        let q = Quat::from_axis_angle(rng.unit_vector(), rng.range(fx(0.0), fx(3.0)));
        let shape = match rng.below(3) {
            0 => sphere(0.4),
            1 => cuboid(0.3, 0.5, 0.2),
            _ => capsule(0.2, 0.5),
        };
        out.push(format!(
            "{:?}",
            sys.cast_shape(&shape, o, q, d, fx(30.0), &f)
        ));
        out.push(format!("{:?}", sys.overlap(&sphere(2.0), o, q, &f)));
        out.push(format!("{:?}", sys.overlap(&shape, o, q, &f)));
        out.push(format!("{:?}", sys.project_point(o, fx(3.0), &f)));
    }
    out
}

#[test]
fn the_tree_gives_the_answers_of_brute_force() {
    let mut sys = random_scene(11, 150, BodyKind::Static);
    assert!(!sys.scratch.query.is_current(sys.slot_count()));
    let brute = answers(&sys, 1);
    sys.update_query_index();
    assert!(sys.scratch.query.is_current(sys.slot_count()));
    assert!(sys.scratch.query.tree().validate() == 150);
    assert_eq!(answers(&sys, 1), brute);
    // Every single-body answer (the ray against each body alone) agrees with the nearest.
    let f = QueryFilter::new();
    let mut rng = Pcg32::new(5, 5);
    for _ in 0..40 {
        let o = Vec3::new(
            rng.range(fx(-12.0), fx(12.0)),
            fx(11.0),
            rng.range(fx(-12.0), fx(12.0)),
        );
        let d: Vec3<F> = rng.unit_vector();
        let nearest = sys.cast_ray(o, d, fx(40.0), &f);
        let mut best: Option<RayHit<F>> = None;
        for i in 0..sys.slot_count() {
            let ray = Ray::new(o, unit_direction(d).unwrap(), fx(40.0));
            let probe = BoxProbe::new(&ray, prune_pad());
            if let Some((h, c)) = sys.ray_against(i, &ray, &probe, &f) {
                let hit = ray_hit(&ray, h, c);
                if precedes(hit.distance, hit.body, best.map(|b| (b.distance, b.body))) {
                    best = Some(hit);
                }
            }
        }
        assert_eq!(nearest, best);
    }
}

#[test]
fn the_tree_follows_moving_bodies_and_is_rebuilt_after_a_restore() {
    let mut sys = random_scene(12, 80, BodyKind::Dynamic);
    let g = Vec3::new(F::ZERO, fx(-9.81), F::ZERO);
    let dt = F::from_ratio(1, 60);
    for step in 0..90 {
        sys.step(dt, g);
        if step % 30 == 29 {
            assert!(sys.scratch.query.is_current(sys.slot_count()));
            let tree = answers(&sys, step);
            let brute = sys.clone();
            assert!(!brute.scratch.query.is_current(brute.slot_count()));
            assert_eq!(answers(&brute, step), tree, "step {step}");
            // A restore keeps the buffers but not the tree.
            let mut restored = random_scene(3, 5, BodyKind::Static);
            restored.step(dt, g);
            restored.restore_from(sys.clone());
            assert!(!restored.scratch.query.is_current(restored.slot_count()));
            assert_eq!(answers(&restored, step), tree);
            restored.step(F::ZERO, Vec3::ZERO);
            assert!(restored.scratch.query.is_current(restored.slot_count()));
        }
    }
}

/// The cost of keeping the tree current on the `balls` scene (4096 balls dropped into an
/// open box): the step's stages and the index update, timed apart. Run with
/// `cargo test -p fixstep --lib rigid::query::tests::balls -- --ignored --nocapture`.
#[test]
#[ignore]
fn balls_index_cost() {
    use std::time::{Duration, Instant};
    let wall = |c: Vec3<F>, h: Vec3<F>| fixed(Shape::Box { half_extents: h }, c);
    let mut bodies = vec![
        wall(v(0.0, -0.5, 0.0), v(11.0, 0.5, 11.0)),
        wall(v(-10.5, 10.0, 0.0), v(0.5, 10.0, 11.0)),
        wall(v(10.5, 10.0, 0.0), v(0.5, 10.0, 11.0)),
        wall(v(0.0, 10.0, -10.5), v(10.0, 10.0, 0.5)),
        wall(v(0.0, 10.0, 10.5), v(10.0, 10.0, 0.5)),
    ];
    let spacing = F::from_ratio(11, 10);
    let start = -(spacing * F::from_int(15)) * F::HALF;
    let mut ball = BodyDesc::new(sphere(0.5), Vec3::new(start, F::ONE, start));
    ball.grid = Some(crate::rigid::Grid {
        count: (16, 16, 16),
        spacing: Vec3::splat(spacing),
    });
    bodies.push(ball);
    let mut sys = system(bodies);
    let g = Vec3::new(F::ZERO, fx(-9.81), F::ZERO);
    let dt = F::from_ratio(1, 60);
    let (mut stages, mut index) = (Duration::ZERO, Duration::ZERO);
    let ticks = 300;
    for _ in 0..ticks {
        let t0 = Instant::now(); // ok-det: timing report of a test, not simulation
        sys.collide();
        sys.wake_touched();
        sys.solve(dt, g);
        sys.update_sleep(dt);
        let t1 = Instant::now(); // ok-det: timing report of a test, not simulation
        sys.update_query_index();
        index += t1.elapsed();
        stages += t1 - t0;
    }
    let per = |d: Duration| d.as_secs_f64() * 1e3 / f64::from(ticks); // ok-det: f64 reference
    eprintln!(
        "balls, {ticks} steps: stages {:.3} ms/step, index update {:.3} ms/step ({:.2} %)",
        per(stages),
        per(index),
        100.0 * index.as_secs_f64() / stages.as_secs_f64()
    );
    let t0 = Instant::now(); // ok-det: timing report of a test, not simulation
    let f = QueryFilter::new();
    let mut hits = 0;
    let mut rng = Pcg32::new(1, 1);
    for _ in 0..1000 {
        let o = Vec3::new(
            rng.range(fx(-10.0), fx(10.0)),
            fx(30.0),
            rng.range(fx(-10.0), fx(10.0)),
        );
        hits += usize::from(sys.cast_ray(o, -Vec3::Y, fx(100.0), &f).is_some());
    }
    let tree = t0.elapsed();
    let brute = sys.clone();
    let t0 = Instant::now(); // ok-det: timing report of a test, not simulation
    for _ in 0..100 {
        let o = Vec3::new(
            rng.range(fx(-10.0), fx(10.0)),
            fx(30.0),
            rng.range(fx(-10.0), fx(10.0)),
        );
        let _ = brute.cast_ray(o, -Vec3::Y, fx(100.0), &f);
    }
    let slow = t0.elapsed();
    eprintln!(
        "cast_ray: {:.2} µs with the tree ({hits} hits of 1000), {:.2} µs by brute force",
        tree.as_secs_f64() * 1e3,
        slow.as_secs_f64() * 1e4
    );
}

/// The multiplying box probe (boxes grown by the pad) passes every box the exact-quotient
/// test passes unpadded: random boxes and rays, with tiny and zero direction components and
/// far coordinates, at several reaches.
#[test]
fn box_probe_is_never_stricter_than_exact_quotients() {
    use super::ray::{BoxProbe, ray_reaches_box};
    let mut rng = Pcg32::new(11, 3);
    let pad = prune_pad::<F>();
    let mut passed = 0;
    for round in 0..20_000 {
        let scale = [fx(2.0), fx(50.0), fx(5000.0), fx(200_000.0)][round % 4];
        let o = Vec3::new(
            rng.range(-scale, scale),
            rng.range(-scale, scale),
            rng.range(-scale, scale),
        );
        let mut d: Vec3<F> = rng.unit_vector();
        match round % 5 {
            1 => d.x = F::ZERO,
            2 => d.y = F::from_ratio(1, 1 << 12),
            3 => d.z = -F::from_ratio(1, 1 << 9),
            _ => {}
        }
        let Some(d) = unit_direction(d) else { continue };
        let centre = Vec3::new(
            rng.range(-scale, scale),
            rng.range(-scale, scale),
            rng.range(-scale, scale),
        );
        let half = Vec3::new(
            rng.range(fx(0.0), scale),
            rng.range(fx(0.0), scale),
            rng.range(fx(0.0), scale),
        );
        let aabb = Aabb {
            min: centre - half,
            max: centre + half,
        };
        let ray = Ray::new(o, d, scale * fx(4.0));
        let probe = BoxProbe::new(&ray, pad);
        for reach in [ray.max, scale, fx(1.0), F::ZERO] {
            if ray_reaches_box(&aabb, F::ZERO, &ray, reach) {
                passed += 1;
                assert!(probe.reaches(&aabb, reach), "{aabb:?} {ray:?} {reach:?}");
            }
        }
    }
    assert!(passed > 1000, "{passed}");
}
