//! Rays and closest points against cylinders, cones and convex hulls, against analytic
//! answers in `f64`, and hulls against the boxes they equal.

use super::*;
use crate::rigid::convex::gjk;

fn cylinder(r: f64, h: f64) -> Shape<F> // ok-det: f64 reference
{
    Shape::Cylinder {
        radius: fx(r),
        half_height: fx(h),
    }
}

fn cone(r: f64, h: f64) -> Shape<F> // ok-det: f64 reference
{
    Shape::Cone {
        radius: fx(r),
        half_height: fx(h),
    }
}

/// A hull built by hand (the construction is not needed): `rings` lists each face's
/// vertex indices counter-clockwise seen from outside ([`gjk::tests::hand_hull`]).
pub(super) fn hand_hull(vertices: Vec<Vec3<F>>, rings: &[&[u16]]) -> Shape<F> {
    Shape::ConvexHull {
        hull: gjk::tests::hand_hull(&vertices, rings),
    }
}

/// The box |x_k| ≤ h_k as a hull, faces in the order −x, +x, −y, +y, −z, +z
/// ([`gjk::tests::cube_hull`]).
pub(super) fn cube_hull(h: Vec3<F>) -> Shape<F> {
    Shape::ConvexHull {
        hull: gjk::tests::cube_hull(h),
    }
}

/// The tetrahedron with vertices (0,0,0), (1,0,0), (0,1,0), (0,0,1), scaled by `s`.
pub(super) fn tetra_hull(s: f64) -> Shape<F> // ok-det: f64 reference
{
    let vertices = vec![
        v(0.0, 0.0, 0.0),
        v(s, 0.0, 0.0),
        v(0.0, s, 0.0),
        v(0.0, 0.0, s),
    ];
    hand_hull(vertices, &[&[0, 2, 1], &[0, 1, 3], &[0, 3, 2], &[1, 2, 3]])
}

/// Ray in the cylinder frame from outside: the first boundary point, (t, normal).
fn ref_cylinder(o: D3, d: D3, r: f64, h: f64) -> Option<(f64, D3)> // ok-det: f64 reference
{
    let mut best: Option<(f64, D3)> = None; // ok-det: f64 reference
    let mut offer = |t: f64, n: D3| // ok-det: f64 reference
    {
        if t >= 0.0 && best.is_none_or(|b| t < b.0) {
            best = Some((t, n));
        }
    };
    let a = d[0] * d[0] + d[2] * d[2];
    let b = o[0] * d[0] + o[2] * d[2];
    let k = o[0] * o[0] + o[2] * o[2] - r * r;
    let disc = b * b - a * k;
    if a > 0.0 && disc >= 0.0 {
        let t = (-b - disc.sqrt()) / a;
        let p = add(o, scale(d, t));
        if p[1].abs() <= h {
            offer(t, unit([p[0], 0.0, p[2]]));
        }
    }
    for (level, n) in [(h, 1.0), (-h, -1.0)] {
        let t = (level - o[1]) / d[1];
        let p = add(o, scale(d, t));
        if d[1] * n < 0.0 && p[0] * p[0] + p[2] * p[2] <= r * r {
            offer(t, [0.0, n, 0.0]);
        }
    }
    best
}

/// Ray in the cone frame from outside: the first boundary point, (t, normal).
fn ref_cone(o: D3, d: D3, r: f64, h: f64) -> Option<(f64, D3)> // ok-det: f64 reference
{
    let mut best: Option<(f64, D3)> = None; // ok-det: f64 reference
    let mut offer = |t: f64, n: D3| // ok-det: f64 reference
    {
        if t >= 0.0 && best.is_none_or(|b| t < b.0) {
            best = Some((t, n));
        }
    };
    // (2h)²(x² + z²) = r²(h − y)² along the ray.
    let (hh, w) = (2.0 * h, h - o[1]);
    let a = hh * hh * (d[0] * d[0] + d[2] * d[2]) - r * r * d[1] * d[1];
    let b = hh * hh * (o[0] * d[0] + o[2] * d[2]) + r * r * w * d[1];
    let c = hh * hh * (o[0] * o[0] + o[2] * o[2]) - r * r * w * w;
    let disc = b * b - a * c;
    if disc >= 0.0 && a != 0.0 {
        for t in [(-b - disc.sqrt()) / a, (-b + disc.sqrt()) / a] {
            let p = add(o, scale(d, t));
            if p[1].abs() <= h {
                let e = unit([p[0], 0.0, p[2]]);
                offer(t, unit([hh * e[0], r, hh * e[2]]));
            }
        }
    }
    let t = (-h - o[1]) / d[1];
    let p = add(o, scale(d, t));
    if d[1] > 0.0 && p[0] * p[0] + p[2] * p[2] <= r * r {
        offer(t, [0.0, -1.0, 0.0]);
    }
    best
}

/// Random rays at a body of `shape` under a random rotation, against `reference` (in
/// the body frame, from outside); returns the number of hits.
fn check_random_rays(
    shape: Shape<F>,
    seed: u64,
    reference: impl Fn(D3, D3) -> Option<(f64, D3)>, // ok-det: f64 reference
    what: &str,
) -> usize {
    let q = rotation([0.4, -1.0, 0.7], 0.9);
    let sys = system(vec![body(BodyKind::Static, shape, v(0.5, -0.25, 1.0), q)]);
    let h = sys.handles().next().unwrap();
    let qf = sys.orientation(h).unwrap().to_f64();
    let c = sys.position(h).unwrap().to_f64();
    let mut rng = Pcg32::new(seed, 1);
    let mut hits = 0;
    for (o, d) in random_rays(&mut rng, c, 400) {
        let (of, df, o, d) = rounded(o, d);
        let got = sys.cast_ray(of, df, fx(100.0), &QueryFilter::new());
        match reference(inverse_rotate(qf, sub(o, c)), inverse_rotate(qf, d)) {
            Some((t, n)) => {
                hits += 1;
                assert_hit(got, (t, rotate(qf, n)), what);
            }
            None => assert!(got.is_none(), "{what}: {got:?} for a miss"),
        }
    }
    hits
}

#[test]
fn rays_against_a_cylinder_match_the_analytic_answer() {
    let hits = check_random_rays(
        cylinder(0.6, 0.9),
        21,
        |o, d| ref_cylinder(o, d, 0.6, 0.9),
        "cylinder",
    );
    assert!(hits > 100, "only {hits} of the rays hit");
}

#[test]
fn rays_against_a_cone_match_the_analytic_answer() {
    let hits = check_random_rays(cone(0.8, 0.7), 22, |o, d| ref_cone(o, d, 0.8, 0.7), "cone");
    assert!(hits > 50, "only {hits} of the rays hit");
}

/// The ray from `o` along `d` (normalised) against a body of `shape` at the origin.
fn ray_at(shape: Shape<F>, o: Vec3<F>, d: Vec3<F>) -> Option<RayHit<F>> {
    system(vec![fixed(shape, Vec3::ZERO)]).cast_ray(o, d, fx(100.0), &QueryFilter::new())
}

#[test]
fn cylinder_sides_caps_rims_and_axis_rays() {
    let c = || cylinder(1.0, 2.0);
    // Side, cap, and a ray along the axis (parallel to the side).
    let hit = ray_at(c(), v(5.0, 0.5, 0.0), v(-1.0, 0.0, 0.0));
    assert_hit(hit, (4.0, [1.0, 0.0, 0.0]), "side");
    let hit = ray_at(c(), v(0.3, -6.0, 0.2), v(0.0, 1.0, 0.0));
    assert_hit(
        hit,
        (4.0, [0.0, -1.0, 0.0]),
        "axis ray through the lower cap",
    );
    let hit = ray_at(c(), v(0.6, 7.0, -0.6), v(0.0, -1.0, 0.0));
    assert_hit(
        hit,
        (5.0, [0.0, 1.0, 0.0]),
        "axis ray through the upper cap",
    );
    assert!(
        ray_at(c(), v(1.5, 7.0, 0.0), v(0.0, -1.0, 0.0)).is_none(),
        "parallel, outside"
    );
    // Through the rim edge (1, 2, 0) at 45°: the side on ties.
    let hit = ray_at(c(), v(3.0, 4.0, 0.0), v(-1.0, -1.0, 0.0)).unwrap();
    assert!((hit.distance.to_f64() - 8f64.sqrt()).abs() <= DISTANCE_TOLERANCE); // ok-det: f64 reference
    // Grazing the side along z at x = r: touches at t = 5 or misses.
    if let Some(hit) = ray_at(c(), v(1.0, 0.0, -5.0), v(0.0, 0.0, 1.0)) {
        assert!((hit.distance.to_f64() - 5.0).abs() <= DISTANCE_TOLERANCE);
    }
    // Starting inside or on the surface.
    let hit = ray_at(c(), v(0.5, 1.0, 0.0), v(0.0, 0.0, 1.0)).unwrap();
    assert_eq!((hit.distance, hit.normal), (F::ZERO, v(0.0, 0.0, -1.0)));
    let hit = ray_at(c(), v(0.0, 2.0, 0.0), v(1.0, 0.0, 0.0)).unwrap();
    assert_eq!(hit.distance, F::ZERO);
    assert!(
        ray_at(c(), v(0.0, 5.0, 0.0), v(0.0, 1.0, 0.0)).is_none(),
        "moving away"
    );
}

#[test]
fn cone_sides_bases_and_apexes() {
    let k = || cone(1.0, 1.0);
    // The side at mid height: radius ½ at y = 0, normal (2, 1, 0)/√5.
    let s5 = 5f64.sqrt(); // ok-det: f64 reference
    let hit = ray_at(k(), v(4.0, 0.0, 0.0), v(-1.0, 0.0, 0.0));
    assert_hit(hit, (3.5, [2.0 / s5, 1.0 / s5, 0.0]), "side");
    let hit = ray_at(k(), v(0.2, -4.0, 0.5), v(0.0, 1.0, 0.0));
    assert_hit(hit, (3.0, [0.0, -1.0, 0.0]), "base");
    // Down the axis onto the apex: +y there.
    let hit = ray_at(k(), v(0.0, 3.0, 0.0), v(0.0, -1.0, 0.0));
    assert_hit(hit, (2.0, [0.0, 1.0, 0.0]), "apex");
    // From above the apex, just off the axis: the side.
    let hit = ray_at(k(), v(0.25, 3.0, 0.0), v(0.0, -1.0, 0.0));
    assert_hit(hit, (2.5, [2.0 / s5, 1.0 / s5, 0.0]), "side from above");
    // A steep ray through the upper nappe (above the apex) misses; one below the base too.
    assert!(ray_at(k(), v(-3.0, 4.0, 0.0), v(1.0, 0.0, 0.0)).is_none());
    assert!(ray_at(k(), v(-3.0, -1.5, 0.0), v(1.0, 0.0, 0.0)).is_none());
    // Inside, and on the rim.
    assert_eq!(
        ray_at(k(), v(0.1, 0.0, 0.1), v(1.0, 0.0, 0.0))
            .unwrap()
            .distance,
        F::ZERO
    );
    assert_eq!(
        ray_at(k(), v(1.0, -1.0, 0.0), v(1.0, 0.0, 0.0))
            .unwrap()
            .distance,
        F::ZERO
    );
}

#[test]
fn a_cube_hull_answers_exactly_as_the_box() {
    let half = v(0.5, 1.25, 0.75);
    let q = rotation([1.0, 2.0, -0.5], 0.7);
    let at = v(-1.0, 0.5, 0.25);
    let as_box = system(vec![body(
        BodyKind::Static,
        Shape::Box { half_extents: half },
        at,
        q,
    )]);
    let as_hull = system(vec![body(BodyKind::Static, cube_hull(half), at, q)]);
    let f = QueryFilter::new();
    let mut rng = Pcg32::new(23, 1);
    let mut hits = 0;
    for (o, d) in random_rays(&mut rng, at.to_f64(), 500) {
        let (of, df, _, _) = rounded(o, d);
        let expected = as_box.cast_ray(of, df, fx(100.0), &f);
        hits += usize::from(expected.is_some());
        assert_eq!(as_hull.cast_ray(of, df, fx(100.0), &f), expected);
        assert_eq!(
            as_hull.project_point(of, fx(100.0), &f).map(|p| p.inside),
            as_box.project_point(of, fx(100.0), &f).map(|p| p.inside)
        );
    }
    assert!(hits > 100, "only {hits} of the rays hit");
    // Through an edge and a corner, from inside, and down onto a face.
    let unrotated = |shape| system(vec![fixed(shape, Vec3::ZERO)]);
    let (b, h) = (
        unrotated(Shape::Box { half_extents: half }),
        unrotated(cube_hull(half)),
    );
    for (o, d) in [
        (v(3.0, 3.75, 0.0), v(-1.0, -1.0, 0.0)),
        (v(2.5, 3.25, 2.75), v(-1.0, -1.0, -1.0)),
        (v(0.1, 0.2, 0.3), v(0.0, 1.0, 0.0)),
        (v(0.1, 8.0, 0.3), v(0.0, -1.0, 0.0)),
    ] {
        let hull = h.cast_ray(o, d, fx(100.0), &f);
        assert!(hull.is_some());
        assert_eq!(hull, b.cast_ray(o, d, fx(100.0), &f));
    }
}

/// Ray from outside against the tetrahedron of [`tetra_hull`] (scale `s`): the
/// Cyrus–Beck clip in f64, normal of the entering face.
fn ref_tetra(o: D3, d: D3, s: f64) -> Option<(f64, D3)> // ok-det: f64 reference
{
    let k = 1.0 / 3f64.sqrt(); // ok-det: f64 reference
    let planes = [
        ([0.0, 0.0, -1.0], 0.0),
        ([0.0, -1.0, 0.0], 0.0),
        ([-1.0, 0.0, 0.0], 0.0),
        ([k, k, k], s * k),
    ];
    let (mut enter, mut exit, mut normal) = (f64::NEG_INFINITY, f64::INFINITY, [0.0; 3]); // ok-det: f64 reference
    for (n, c) in planes {
        let (sd, vd) = (dot(n, o) - c, dot(n, d));
        if vd < 0.0 {
            if sd / -vd > enter {
                enter = sd / -vd;
                normal = n;
            }
        } else if vd > 0.0 {
            exit = exit.min(-sd / vd);
        } else if sd > 0.0 {
            return None;
        }
    }
    (enter <= exit && exit >= 0.0).then_some((enter, normal))
}

#[test]
fn rays_against_a_tetrahedron_hull_match_the_clipped_answer() {
    let hits = check_random_rays(
        tetra_hull(1.5),
        24,
        |o, d| ref_tetra(o, d, 1.5),
        "tetrahedron",
    );
    assert!(hits > 50, "only {hits} of the rays hit");
}

/// The closest point of the triangle-shaped (ρ, y) section of a cone to (ρ, y), in 2D.
fn ref_cone_point(rho: f64, y: f64, r: f64, h: f64) -> (f64, f64, f64) // ok-det: f64 reference
{
    let segment = |a: [f64; 2], b: [f64; 2]| // ok-det: f64 reference
    {
        let e = [b[0] - a[0], b[1] - a[1]];
        let u = (((rho - a[0]) * e[0] + (y - a[1]) * e[1]) / (e[0] * e[0] + e[1] * e[1])).clamp(0.0, 1.0);
        let q = [a[0] + u * e[0], a[1] + u * e[1]];
        ((rho - q[0]).hypot(y - q[1]), q[0], q[1])
    };
    let base = segment([0.0, -h], [r, -h]);
    let side = segment([0.0, h], [r, -h]);
    if side.0 < base.0 { side } else { base }
}

#[test]
fn closest_points_of_cylinders_cones_and_hulls() {
    let q = rotation([0.3, 1.0, -0.2], 1.3);
    let at = v(1.0, 2.0, -0.5);
    let (r, hh) = (0.7, 0.9);
    let f = QueryFilter::new();
    let mut rng = Pcg32::new(25, 1);
    let cyl = system(vec![body(BodyKind::Static, cylinder(r, hh), at, q)]);
    let con = system(vec![body(BodyKind::Static, cone(r, hh), at, q)]);
    let half = v(0.5, 0.8, 0.3);
    let bx = system(vec![body(
        BodyKind::Static,
        Shape::Box { half_extents: half },
        at,
        q,
    )]);
    let hull = system(vec![body(BodyKind::Static, cube_hull(half), at, q)]);
    let qf = cyl
        .orientation(cyl.handles().next().unwrap())
        .unwrap()
        .to_f64();
    let c = at.to_f64();
    let (mut outside, mut inside) = (0, 0);
    for _ in 0..400 {
        let p = Vec3::new(
            rng.range(fx(-1.5), fx(1.5)),
            rng.range(fx(-1.5), fx(1.5)),
            rng.range(fx(-1.5), fx(1.5)),
        ) + at;
        let local = inverse_rotate(qf, sub(p.to_f64(), c));
        let rho = local[0].hypot(local[2]);
        let e = if rho > 0.0 {
            [local[0] / rho, 0.0, local[2] / rho]
        } else {
            [1.0, 0.0, 0.0]
        };
        let lifted = |qr: f64, qy: f64| add(c, rotate(qf, [e[0] * qr, qy, e[2] * qr])); // ok-det: f64 reference
        // Cylinder: clamp radially and axially.
        let got = cyl.project_point(p, fx(100.0), &f).unwrap();
        let (qr, qy) = (rho.min(r), local[1].clamp(-hh, hh));
        let dist = (rho - qr).hypot(local[1] - qy);
        check_point(got, dist, lifted(qr, qy), "cylinder");
        // Cone: the triangle in the half-plane.
        let got = con.project_point(p, fx(100.0), &f).unwrap();
        let inside_cone = local[1] >= -hh && rho * 2.0 * hh <= r * (hh - local[1]);
        if inside_cone {
            inside += 1;
            assert!(got.inside, "cone: {got:?} at {local:?}");
        } else {
            outside += 1;
            let (dist, qr, qy) = ref_cone_point(rho, local[1], r, hh);
            check_point(got, dist, lifted(qr, qy), "cone");
        }
        // A cube hull: the box's answer.
        let (got, expected) = (
            hull.project_point(p, fx(100.0), &f).unwrap(),
            bx.project_point(p, fx(100.0), &f).unwrap(),
        );
        assert_eq!(got.inside, expected.inside);
        check_point(
            got,
            expected.distance.to_f64(),
            expected.point.to_f64(),
            "hull",
        );
    }
    assert!(
        outside > 100 && inside > 5,
        "{outside} outside, {inside} inside the cone"
    );
    // A tetrahedron: a face, an edge and a vertex region, and inside.
    let t = system(vec![fixed(tetra_hull(1.0), Vec3::ZERO)]);
    let at = |x: f64, y: f64, z: f64| t.project_point(v(x, y, z), fx(10.0), &f).unwrap(); // ok-det: f64 reference
    let k = 1.0 / 3.0;
    check_point(at(1.0, 1.0, 1.0), 2.0 / 3f64.sqrt(), [k, k, k], "face");
    check_point(at(0.5, -1.0, -1.0), 2f64.sqrt(), [0.5, 0.0, 0.0], "edge");
    check_point(at(-1.0, -2.0, -2.0), 3.0, [0.0, 0.0, 0.0], "vertex");
    check_point(at(2.0, -1.0, 0.0), 2f64.sqrt(), [1.0, 0.0, 0.0], "vertex");
    assert!(at(0.2, 0.2, 0.2).inside);
}

/// A reference distance, m.
type Metres = f64; // ok-det: f64 reference

fn check_point(got: PointProjection<F>, distance: Metres, point: D3, what: &str) {
    if distance == 0.0 {
        assert!(got.inside, "{what}: {got:?}");
        return;
    }
    assert!(!got.inside, "{what}: {got:?}, expected {distance} away");
    assert!(
        (got.distance.to_f64() - distance).abs() <= DISTANCE_TOLERANCE,
        "{what}: {got:?}, expected {distance}"
    );
    let p = got.point.to_f64();
    for k in 0..3 {
        assert!(
            (p[k] - point[k]).abs() <= DISTANCE_TOLERANCE,
            "{what}: {p:?}, expected {point:?}"
        );
    }
}

#[test]
fn cylinders_cones_and_hulls_cast_onto_the_ground_and_overlap_a_box() {
    let sys = system(vec![
        fixed(ground(), Vec3::ZERO),
        fixed(cuboid(0.5, 0.5, 0.5), v(5.0, 1.0, 0.0)),
    ]);
    let f = QueryFilter::new();
    // Dropped from 3 m: the lowest point (−h for the cylinder and the cone, 0 for the
    // tetrahedron) reaches the ground.
    for (shape, bottom) in [
        (cylinder(0.5, 0.75), 0.75),
        (cone(0.5, 0.75), 0.75),
        (tetra_hull(1.0), 0.0),
    ] {
        let hit = sys
            .cast_shape(
                &shape,
                v(0.0, 3.0, 0.0),
                Quat::IDENTITY,
                v(0.0, -1.0, 0.0),
                fx(10.0),
                &f,
            )
            .unwrap_or_else(|| panic!("{shape:?} misses the ground"));
        assert!(
            (hit.distance.to_f64() - (3.0 - bottom)).abs() <= 2.0 * DISTANCE_TOLERANCE,
            "{hit:?}"
        );
        assert!(
            (hit.normal.to_f64()[1] - 1.0).abs() <= NORMAL_TOLERANCE,
            "{hit:?}"
        );
    }
    // Sideways onto the box's −x face at x = 4.5: the cylinder's side (r = 0.5) arrives
    // after 4 m, the normal out of the face.
    let hit = sys
        .cast_shape(
            &cylinder(0.5, 0.25),
            v(0.0, 1.0, 0.0),
            Quat::IDENTITY,
            v(1.0, 0.0, 0.0),
            fx(10.0),
            &f,
        )
        .expect("the cylinder reaches the box");
    assert!(
        (hit.distance.to_f64() - 4.0).abs() <= 2.0 * DISTANCE_TOLERANCE,
        "{hit:?}"
    );
    assert!(
        (hit.normal.to_f64()[0] + 1.0).abs() <= NORMAL_TOLERANCE,
        "{hit:?}"
    );
    // And they overlap what they touch.
    let over = sys.overlap(&cone(0.5, 0.75), v(4.2, 1.0, 0.0), Quat::IDENTITY, &f);
    assert_eq!(over.len(), 1);
}
