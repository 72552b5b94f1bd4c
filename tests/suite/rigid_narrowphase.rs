//! The narrowphase against geometry worked out by hand: every expected normal, separation
//! and point below comes from the shapes' dimensions and placements (distances between
//! centres, depths of corners below faces, lengths of overlaps), not from running the code.
//!
//! I32F32 rounds each operation to about 2⁻³³ m; a manifold takes a few dozen operations
//! and a rotation from `sin_cos` adds a few 10⁻¹⁰, so positions, normals and separations
//! of order 1 m agree with the geometry to well within [`TOL`] = 10⁻⁶.

use fixstep::math::{Fx, Quat, Real, Vec3};
use fixstep::rigid::narrowphase::collide;
use fixstep::rigid::{Manifold, Part, Shape, Transform};

/// Agreement with the geometry, m (and for unit normals).
const TOL: f64 = 1e-6;

/// The speculative margin used throughout, m.
const MARGIN: f64 = 0.02;

fn real<R: Real>(x: f64) -> R {
    R::from_f64(x)
}

fn vec<R: Real>(v: [f64; 3]) -> Vec3<R> {
    Vec3::from_f64(v[0], v[1], v[2])
}

/// A placement at `position` turned by `degrees` about the unit `axis`.
fn pose<R: Real>(position: [f64; 3], axis: [f64; 3], degrees: f64) -> Transform<R> {
    let angle = real::<R>(degrees.to_radians());
    Transform::from_pose(vec(position), Quat::from_axis_angle(vec(axis), angle))
}

/// A placement at `position`, not turned.
fn at<R: Real>(position: [f64; 3]) -> Transform<R> {
    Transform {
        translation: vec(position),
        ..Transform::IDENTITY
    }
}

fn sphere<R: Real>(radius: f64) -> Shape<R> {
    Shape::Sphere {
        radius: real(radius),
    }
}

fn cuboid<R: Real>(half: [f64; 3]) -> Shape<R> {
    Shape::Box {
        half_extents: vec(half),
    }
}

fn capsule<R: Real>(radius: f64, half_height: f64) -> Shape<R> {
    Shape::Capsule {
        radius: real(radius),
        half_height: real(half_height),
    }
}

fn ground<R: Real>() -> Shape<R> {
    Shape::Plane {
        normal: Vec3::Y,
        offset: R::ZERO,
    }
}

fn run<R: Real>(a: &Shape<R>, xa: &Transform<R>, b: &Shape<R>, xb: &Transform<R>) -> Manifold<R> {
    collide(a, xa, b, xb, real(MARGIN))
}

fn close(a: [f64; 3], b: [f64; 3], tol: f64) -> bool {
    (0..3).all(|k| (a[k] - b[k]).abs() <= tol)
}

/// Asserts the manifold's normal and that its points are, in any order, exactly the
/// expected (point, separation) pairs, and that their ids are distinct.
fn expect<R: Real>(m: &Manifold<R>, normal: [f64; 3], points: &[([f64; 3], f64)]) {
    assert_eq!(
        m.count,
        points.len(),
        "point count: got {:?}",
        m.points()
            .iter()
            .map(|p| (p.point.to_f64(), p.separation.to_f64()))
            .collect::<Vec<_>>()
    );
    assert!(
        close(m.normal.to_f64(), normal, TOL),
        "normal {:?}, expected {normal:?}",
        m.normal.to_f64()
    );
    let mut used = vec![false; points.len()];
    for p in m.points() {
        let (got, sep) = (p.point.to_f64(), p.separation.to_f64());
        let found = points
            .iter()
            .enumerate()
            .position(|(i, (q, s))| !used[i] && close(got, *q, TOL) && (sep - s).abs() <= TOL);
        match found {
            Some(i) => used[i] = true,
            None => panic!("unexpected point {got:?} separation {sep}; expected {points:?}"),
        }
    }
    assert_distinct_ids(m);
}

fn assert_distinct_ids<R: Real>(m: &Manifold<R>) {
    let mut ids: Vec<u32> = m.points().iter().map(|p| p.id).collect();
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids.len(), m.count, "ids not distinct: {:?}", m.points());
}

fn sorted_ids<R: Real>(m: &Manifold<R>) -> Vec<u32> {
    let mut ids: Vec<u32> = m.points().iter().map(|p| p.id).collect();
    ids.sort_unstable();
    ids
}

/// Swapping A and B reverses the normal and gives the same points and separations.
fn assert_swap<R: Real>(a: &Shape<R>, xa: &Transform<R>, b: &Shape<R>, xb: &Transform<R>) {
    let ab = run(a, xa, b, xb);
    let ba = run(b, xb, a, xa);
    assert_eq!(ab.count, ba.count, "swapped count");
    assert!(
        close(ab.normal.to_f64(), (-ba.normal).to_f64(), TOL),
        "swapped normal {:?} vs {:?}",
        ab.normal.to_f64(),
        ba.normal.to_f64()
    );
    let points: Vec<([f64; 3], f64)> = ab
        .points()
        .iter()
        .map(|p| (p.point.to_f64(), p.separation.to_f64()))
        .collect();
    expect(&ba, (-ab.normal).to_f64(), &points);
}

/// Moving B by a small translation keeps the same set of ids.
fn assert_ids_stable<R: Real>(a: &Shape<R>, xa: &Transform<R>, b: &Shape<R>, xb: &Transform<R>) {
    let before = run(a, xa, b, xb);
    assert!(before.count > 0);
    for nudge in [[1e-4, 0.0, 0.0], [0.0, -1e-4, 0.0], [-3e-5, 2e-5, 7e-5]] {
        let moved = Transform {
            translation: xb.translation + vec(nudge),
            ..*xb
        };
        let after = run(a, xa, b, &moved);
        assert_eq!(sorted_ids(&before), sorted_ids(&after), "nudge {nudge:?}");
    }
}

const S2: f64 = std::f64::consts::SQRT_2;

// ---------------------------------------------------------------- sphere–sphere

#[test]
fn sphere_sphere_separated_within_and_overlapping() {
    let (a, b) = (sphere::<Fx>(0.5), sphere::<Fx>(0.25));
    let far = run(&a, &at([0.0; 3]), &b, &at([0.0, 0.0, 0.8]));
    assert_eq!(far.count, 0, "0.05 m apart, beyond the 0.02 margin");

    let near = run(&a, &at([0.0; 3]), &b, &at([0.0, 0.0, 0.76]));
    expect(&near, [0.0, 0.0, 1.0], &[([0.0, 0.0, 0.505], 0.01)]);

    // Overlap along a diagonal: centres 0.6 apart along (3, 4, 0)/5, depth 0.15.
    let m = run(&a, &at([1.0, 2.0, 3.0]), &b, &at([1.36, 2.48, 3.0]));
    let n = [0.6, 0.8, 0.0];
    // Midway between the surfaces: A's surface at 0.5, B's at 0.35 along n.
    let mid = 0.425;
    expect(&m, n, &[([1.0 + n[0] * mid, 2.0 + n[1] * mid, 3.0], -0.15)]);
    assert_eq!(m.points[0].id, 0);
    assert_swap(&a, &at([1.0, 2.0, 3.0]), &b, &at([1.36, 2.48, 3.0]));
}

#[test]
fn sphere_sphere_coincident_centres_push_along_y() {
    let (a, b) = (sphere::<Fx>(0.5), sphere::<Fx>(0.25));
    let m = run(&a, &at([2.0, 1.0, 0.0]), &b, &at([2.0, 1.0, 0.0]));
    // Separation −(0.5 + 0.25); A's surface at +0.5 along y, B's at −0.25.
    expect(&m, [0.0, 1.0, 0.0], &[([2.0, 1.125, 0.0], -0.75)]);
}

// ---------------------------------------------------------------- sphere–box

#[test]
fn sphere_on_box_face_edge_and_corner() {
    let s = sphere::<Fx>(0.5);
    let b = cuboid::<Fx>([1.0, 0.5, 2.0]);
    let xb = at([0.0, 0.0, 0.0]);
    // Above the top face y = 0.5, 0.1 deep: normal from sphere down to box.
    let m = run(&s, &at([0.3, 0.9, -1.0]), &b, &xb);
    expect(&m, [0.0, -1.0, 0.0], &[([0.3, 0.45, -1.0], -0.1)]);
    // Beyond the margin.
    assert_eq!(run(&s, &at([0.3, 1.03, -1.0]), &b, &xb).count, 0);
    // Within the margin.
    let m = run(&s, &at([0.3, 1.01, -1.0]), &b, &xb);
    expect(&m, [0.0, -1.0, 0.0], &[([0.3, 0.505, -1.0], 0.01)]);
    // Off the edge x = 1, y = 0.5, along (1, 1, 0)/√2 at distance 0.45.
    let e = 0.45 / S2;
    let m = run(&s, &at([1.0 + e, 0.5 + e, 0.0]), &b, &xb);
    let along = 0.5 - 0.05 / 2.0; // from the sphere's centre to the midpoint, inwards
    expect(
        &m,
        [-1.0 / S2, -1.0 / S2, 0.0],
        &[([1.0 + e - along / S2, 0.5 + e - along / S2, 0.0], -0.05)],
    );
    // Off the corner (1, 0.5, 2), along (1, 1, 1)/√3 at distance 0.51: separation 0.01.
    let c = 0.51 / 3f64.sqrt();
    let m = run(&s, &at([1.0 + c, 0.5 + c, 2.0 + c]), &b, &xb);
    let n = -1.0 / 3f64.sqrt();
    let k = 0.005 / 3f64.sqrt();
    expect(&m, [n, n, n], &[([1.0 + k, 0.5 + k, 2.0 + k], 0.01)]);
    assert_swap(&s, &at([1.0 + e, 0.5 + e, 0.0]), &b, &xb);
}

#[test]
fn sphere_centre_inside_box_leaves_through_the_nearest_face() {
    let s = sphere::<Fx>(0.2);
    let b = cuboid::<Fx>([1.0, 0.5, 2.0]);
    // Centre 0.1 below the top face: the nearest face (x: 0.7, y: 0.1, z: 1.5 away).
    let m = run(&s, &at([0.3, 0.4, 0.5]), &b, &at([0.0; 3]));
    // Separation −(0.1 + 0.2); box surface at y = 0.5, sphere surface at 0.4 − 0.2.
    expect(&m, [0.0, -1.0, 0.0], &[([0.3, 0.35, 0.5], -0.3)]);
    // Centre exactly at the box's centre of a cube: x (lowest axis) wins the tie, +x.
    let cube = cuboid::<Fx>([1.0, 1.0, 1.0]);
    let m = run(&s, &at([0.0; 3]), &cube, &at([0.0; 3]));
    expect(&m, [-1.0, 0.0, 0.0], &[([0.4, 0.0, 0.0], -1.2)]);
}

#[test]
fn sphere_against_a_turned_box() {
    // A unit cube turned 45° about y: its edge x = √2 (z = 0) faces +x.
    let s = sphere::<Fx>(0.5);
    let b = cuboid::<Fx>([1.0, 1.0, 1.0]);
    let xb = pose([0.0; 3], [0.0, 1.0, 0.0], 45.0);
    let m = run(&s, &at([S2 + 0.49, 0.3, 0.0]), &b, &xb);
    expect(&m, [-1.0, 0.0, 0.0], &[([S2 - 0.005, 0.3, 0.0], -0.01)]);
    assert_ids_stable(&b, &xb, &s, &at([S2 + 0.49, 0.3, 0.0]));
}

// ---------------------------------------------------------------- sphere–capsule

#[test]
fn sphere_against_capsule_side_and_end() {
    let s = sphere::<Fx>(0.25);
    let c = capsule::<Fx>(0.5, 1.0);
    let xc = at([0.0; 3]);
    // Beside the middle: centre at x = 0.7, surfaces 0.5 and 0.45 → −0.05.
    let m = run(&s, &at([0.7, 0.3, 0.0]), &c, &xc);
    expect(&m, [-1.0, 0.0, 0.0], &[([0.475, 0.3, 0.0], -0.05)]);
    // Above the top end (0, 1, 0): centre at y = 1.76, separation 0.01.
    let m = run(&s, &at([0.0, 1.76, 0.0]), &c, &xc);
    expect(&m, [0.0, -1.0, 0.0], &[([0.0, 1.505, 0.0], 0.01)]);
    assert_eq!(run(&s, &at([0.0, 1.78, 0.0]), &c, &xc).count, 0);
    // A capsule lying along x (turned 90° about z), sphere beside its end cap at 45°.
    let xc = pose([0.0; 3], [0.0, 0.0, 1.0], 90.0);
    let r = 0.7 / S2;
    let m = run(&c, &xc, &s, &at([1.0 + r, r, 0.0]));
    let mid = 0.5 - 0.05 / 2.0;
    expect(
        &m,
        [1.0 / S2, 1.0 / S2, 0.0],
        &[([1.0 + mid / S2, mid / S2, 0.0], -0.05)],
    );
    assert_swap(&c, &xc, &s, &at([1.0 + r, r, 0.0]));
}

#[test]
fn sphere_centre_on_capsule_axis_gets_a_fixed_normal() {
    let s = sphere::<Fx>(0.25);
    let c = capsule::<Fx>(0.5, 1.0);
    let m = run(&s, &at([0.0, 0.2, 0.0]), &c, &at([0.0; 3]));
    assert_eq!(m.count, 1);
    let n = m.normal.to_f64();
    assert!((n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1.0).abs() < TOL);
    assert!(n[1].abs() < TOL, "perpendicular to the axis: {n:?}");
    assert!((m.points[0].separation.to_f64() + 0.75).abs() < TOL);
    // The same answer every time.
    assert_eq!(m, run(&s, &at([0.0, 0.2, 0.0]), &c, &at([0.0; 3])));
}

// ---------------------------------------------------------------- capsule–capsule

#[test]
fn crossing_capsules_touch_at_one_point() {
    let c = capsule::<Fx>(0.25, 1.0);
    // A along y at the origin; B along x (turned about z), 0.45 away along z.
    let xb = pose([0.2, 0.3, 0.45], [0.0, 0.0, 1.0], 90.0);
    let m = run(&c, &at([0.0; 3]), &c, &xb);
    expect(&m, [0.0, 0.0, 1.0], &[([0.0, 0.3, 0.225], -0.05)]);
    assert_eq!(m.points[0].id, 2 + 4 * 2, "both between their ends");
    assert_eq!(
        run(
            &c,
            &at([0.0; 3]),
            &c,
            &pose([0.2, 0.3, 0.53], [0.0, 0.0, 1.0], 90.0)
        )
        .count,
        0
    );
    assert_swap(&c, &at([0.0; 3]), &c, &xb);
}

#[test]
fn capsules_end_to_end_push_along_the_axis() {
    let c = capsule::<Fx>(0.25, 1.0);
    let m = run(&c, &at([0.0; 3]), &c, &at([0.0, 2.49, 0.0]));
    // A's top end at y = 1, B's bottom end at y = 1.49: separation −0.01.
    expect(&m, [0.0, 1.0, 0.0], &[([0.0, 1.245, 0.0], -0.01)]);
    assert_eq!(m.points[0].id, 1, "A's +h end and B's −h end");
}

#[test]
fn parallel_capsules_side_by_side_get_two_points() {
    let c = capsule::<Fx>(0.25, 1.0);
    let short = capsule::<Fx>(0.25, 0.5);
    // B along y, 0.48 away along x, shifted 0.8 up: overlap of A's [−1, 1] with B's
    // [0.3, 1.3] is [0.3, 1].
    let xb = at([0.48, 0.8, 0.0]);
    let m = run(&c, &at([0.0; 3]), &short, &xb);
    expect(
        &m,
        [1.0, 0.0, 0.0],
        &[([0.24, 0.3, 0.0], -0.02), ([0.24, 1.0, 0.0], -0.02)],
    );
    assert_swap(&c, &at([0.0; 3]), &short, &xb);
    assert_ids_stable(&c, &at([0.0; 3]), &short, &xb);
    // Antiparallel (B turned 180° about z) gives the same contact.
    let flipped = pose([0.48, 0.8, 0.0], [0.0, 0.0, 1.0], 180.0);
    let m = run(&c, &at([0.0; 3]), &short, &flipped);
    expect(
        &m,
        [1.0, 0.0, 0.0],
        &[([0.24, 0.3, 0.0], -0.02), ([0.24, 1.0, 0.0], -0.02)],
    );
    // Both lying along x on top of each other (turned about z): B 0.49 above A.
    let lying_a = pose([0.0; 3], [0.0, 0.0, 1.0], 90.0);
    let lying_b = pose([0.5, 0.49, 0.0], [0.0, 0.0, 1.0], 90.0);
    let m = run(&c, &lying_a, &c, &lying_b);
    expect(
        &m,
        [0.0, 1.0, 0.0],
        &[([-0.5, 0.245, 0.0], -0.01), ([1.0, 0.245, 0.0], -0.01)],
    );
}

#[test]
fn slightly_tilted_capsule_lying_on_another_gets_each_end_depth() {
    let c = capsule::<Fx>(0.25, 1.0);
    // A along x; B along x turned by θ = 0.5° about z, centre 0.5 above A's centre: its
    // segment ends are at heights 0.5 ∓ sin θ, so the separations are ∓ sin θ, to second
    // order: the raised point pairs A's axis below B's end with B's closest point to it,
    // which is θ·0.5 along B from the end, lower by about θ²·0.5.
    let xa = pose([0.0; 3], [0.0, 0.0, 1.0], 90.0);
    let xb = pose([0.0, 0.5, 0.0], [0.0, 0.0, 1.0], 90.5);
    let m = run(&c, &xa, &c, &xb);
    assert_eq!(m.count, 2);
    let sin = 0.5f64.to_radians().sin();
    let mut seps: Vec<f64> = m.points().iter().map(|p| p.separation.to_f64()).collect();
    seps.sort_by(f64::total_cmp);
    // The lower end projects on A's axis at cos(0.5°) from A's centre, A's end is at 1:
    // both ends of the overlap are B's ends, at heights 0.5 ∓ sin.
    let second_order = 0.5f64.to_radians().powi(2);
    assert!((seps[0] + sin).abs() < TOL, "{seps:?} vs ∓{sin}");
    assert!((seps[1] - sin).abs() < second_order, "{seps:?} vs ∓{sin}");
    assert!(close(m.normal.to_f64(), [0.0, 1.0, 0.0], TOL));
    assert_distinct_ids(&m);
}

// ---------------------------------------------------------------- capsule–box

#[test]
fn capsule_standing_on_a_box_touches_at_its_end() {
    let c = capsule::<Fx>(0.25, 0.5);
    let b = cuboid::<Fx>([1.0, 0.5, 1.0]);
    // Bottom end at y = 0.74 over the top face y = 0.5: separation −0.01.
    let m = run(&c, &at([0.2, 1.24, 0.1]), &b, &at([0.0; 3]));
    expect(&m, [0.0, -1.0, 0.0], &[([0.2, 0.495, 0.1], -0.01)]);
    assert_eq!(m.points[0].id & 3, 0, "the −h end");
    assert_eq!(run(&c, &at([0.2, 1.28, 0.1]), &b, &at([0.0; 3])).count, 0);
    assert_swap(&c, &at([0.2, 1.24, 0.1]), &b, &at([0.0; 3]));
}

#[test]
fn capsule_lying_on_a_box_gets_two_points() {
    let b = cuboid::<Fx>([1.0, 0.5, 1.0]);
    let xb = at([0.0; 3]);
    // Shorter than the face: both segment ends, core at y = 0.74 (separation −0.01).
    let c = capsule::<Fx>(0.25, 0.6);
    let xc = pose([0.1, 0.74, 0.2], [0.0, 0.0, 1.0], 90.0);
    let m = run(&c, &xc, &b, &xb);
    expect(
        &m,
        [0.0, -1.0, 0.0],
        &[([-0.5, 0.495, 0.2], -0.01), ([0.7, 0.495, 0.2], -0.01)],
    );
    assert_ids_stable(&b, &xb, &c, &xc);
    assert_swap(&c, &xc, &b, &xb);
    // Longer than the face: clipped at the face's sides x = ±1; within the margin.
    let long = capsule::<Fx>(0.25, 2.0);
    let xl = pose([0.3, 0.76, -0.4], [0.0, 0.0, 1.0], 90.0);
    let m = run(&long, &xl, &b, &xb);
    expect(
        &m,
        [0.0, -1.0, 0.0],
        &[([-1.0, 0.505, -0.4], 0.01), ([1.0, 0.505, -0.4], 0.01)],
    );
    assert_ids_stable(&b, &xb, &long, &xl);
    // Lying diagonally on the face (along (1, 0, 1)/√2): clipped where it leaves the
    // face, at x = z = ±1.
    let diagonal = Transform::from_pose(
        vec([0.0, 0.74, 0.0]),
        Quat::from_axis_angle(vec([0.0, 1.0, 0.0]), real(-45f64.to_radians()))
            * Quat::from_axis_angle(vec([0.0, 0.0, 1.0]), real(90f64.to_radians())),
    );
    let m = run(&long, &diagonal, &b, &xb);
    expect(
        &m,
        [0.0, -1.0, 0.0],
        &[([-1.0, 0.495, -1.0], -0.01), ([1.0, 0.495, 1.0], -0.01)],
    );
}

#[test]
fn capsule_across_a_box_edge_and_deep_in_a_box() {
    let b = cuboid::<Fx>([1.0, 0.5, 1.0]);
    let c = capsule::<Fx>(0.25, 1.0);
    // Along z, beside the edge x = 1, y = 0.5, diagonally at distance 0.24.
    let e = 0.24 / S2;
    let xc = pose([1.0 + e, 0.5 + e, 0.0], [1.0, 0.0, 0.0], 90.0);
    let m = run(&c, &xc, &b, &at([0.0; 3]));
    assert_eq!(m.count, 1);
    assert!(close(m.normal.to_f64(), [-1.0 / S2, -1.0 / S2, 0.0], TOL));
    assert!((m.points[0].separation.to_f64() + 0.01).abs() < TOL);
    // Segment inside the box, lying along x 0.1 below the top face: out through the top.
    let inside = pose([0.0, 0.4, 0.3], [0.0, 0.0, 1.0], 90.0);
    let short = capsule::<Fx>(0.25, 0.5);
    let m = run(&short, &inside, &b, &at([0.0; 3]));
    // Separation −(0.1 + 0.25) at both ends x = ±0.5.
    expect(
        &m,
        [0.0, -1.0, 0.0],
        &[([-0.5, 0.325, 0.3], -0.35), ([0.5, 0.325, 0.3], -0.35)],
    );
    // Standing, its lower end 0.1 inside the top face: one point at that end.
    let m = run(&short, &at([0.0, 0.9, 0.0]), &b, &at([0.0; 3]));
    expect(&m, [0.0, -1.0, 0.0], &[([0.0, 0.325, 0.0], -0.35)]);
}

// ---------------------------------------------------------------- box–box

#[test]
fn box_on_box_face_to_face_gives_the_overlap_corners() {
    let big = cuboid::<Fx>([2.0, 0.5, 2.0]);
    let small = cuboid::<Fx>([0.5, 0.5, 0.5]);
    // Small box 0.01 into the big one's top face, fully inside it in x and z.
    let xs = at([0.3, 0.99, -0.2]);
    let m = run(&big, &at([0.0; 3]), &small, &xs);
    let y = 0.495;
    let corners: Vec<([f64; 3], f64)> = [[-0.2, -0.7], [0.8, -0.7], [0.8, 0.3], [-0.2, 0.3]]
        .iter()
        .map(|&[x, z]| ([x, y, z], -0.01))
        .collect();
    expect(&m, [0.0, 1.0, 0.0], &corners);
    assert_swap(&big, &at([0.0; 3]), &small, &xs);
    assert_ids_stable(&big, &at([0.0; 3]), &small, &xs);
    // Hanging over the corner: the overlap is the rectangle x ∈ [1.5, 2], z ∈ [1.2, 2].
    let over = at([2.0, 1.01, 1.7]);
    let m = run(&big, &at([0.0; 3]), &small, &over);
    let corners: Vec<([f64; 3], f64)> = [[1.5, 1.2], [2.0, 1.2], [2.0, 2.0], [1.5, 2.0]]
        .iter()
        .map(|&[x, z]| ([x, 0.505, z], 0.01))
        .collect();
    expect(&m, [0.0, 1.0, 0.0], &corners);
    assert_ids_stable(&big, &at([0.0; 3]), &small, &over);
    // Beyond the margin.
    assert_eq!(
        run(&big, &at([0.0; 3]), &small, &at([0.3, 1.03, -0.2])).count,
        0
    );
}

#[test]
fn equal_boxes_stacked_keep_their_ids_while_jittering() {
    let b = cuboid::<Fx>([0.5, 0.5, 0.5]);
    let xs = at([0.0, 0.999, 0.0]);
    let m = run(&b, &at([0.0; 3]), &b, &xs);
    let corners: Vec<([f64; 3], f64)> = [[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]
        .iter()
        .map(|&[x, z]| ([x, 0.4995, z], -0.001))
        .collect();
    expect(&m, [0.0, 1.0, 0.0], &corners);
    assert_ids_stable(&b, &at([0.0; 3]), &b, &xs);
}

#[test]
fn box_turned_45_degrees_on_a_box_face() {
    let big = cuboid::<Fx>([2.0, 0.5, 2.0]);
    let small = cuboid::<Fx>([0.5, 0.25, 0.5]);
    // Turned 45° about y, 0.02 deep: its bottom corners at radius √2/2 on the axes.
    let xs = pose([0.1, 0.73, 0.2], [0.0, 1.0, 0.0], 45.0);
    let r = 0.5 * S2;
    let y = 0.49;
    let corners = vec![
        ([0.1 + r, y, 0.2], -0.02),
        ([0.1 - r, y, 0.2], -0.02),
        ([0.1, y, 0.2 + r], -0.02),
        ([0.1, y, 0.2 - r], -0.02),
    ];
    let m = run(&small, &xs, &big, &at([0.0; 3]));
    expect(&m, [0.0, -1.0, 0.0], &corners);
    let m = run(&big, &at([0.0; 3]), &small, &xs);
    expect(&m, [0.0, 1.0, 0.0], &corners);
    assert_ids_stable(&big, &at([0.0; 3]), &small, &xs);
}

/// Area of the polygon with these (x, z) vertices taken in angular order about their
/// centroid (shoelace formula).
fn hull_area(points: &[[f64; 2]]) -> f64 {
    let n = points.len() as f64;
    let cx = points.iter().map(|p| p[0]).sum::<f64>() / n;
    let cz = points.iter().map(|p| p[1]).sum::<f64>() / n;
    let mut sorted = points.to_vec();
    sorted.sort_by(|a, b| {
        (a[1] - cz)
            .atan2(a[0] - cx)
            .total_cmp(&(b[1] - cz).atan2(b[0] - cx))
    });
    let mut twice = 0.0;
    for i in 0..sorted.len() {
        let (p, q) = (sorted[i], sorted[(i + 1) % sorted.len()]);
        twice += p[0] * q[1] - q[0] * p[1];
    }
    twice.abs() / 2.0
}

#[test]
fn octagon_overlap_is_reduced_to_four_spread_points() {
    // Equal cubes, the upper one turned 45° about y and 0.01 deep: the overlap of the two
    // squares is an octagon with corners (±0.5, ±(√2/2 − 0.5)) and (±(√2/2 − 0.5), ±0.5).
    let cube = cuboid::<Fx>([0.5, 0.5, 0.5]);
    let xb = pose([0.0, 0.99, 0.0], [0.0, 1.0, 0.0], 45.0);
    let m = run(&cube, &at([0.0; 3]), &cube, &xb);
    assert_eq!(m.count, 4);
    let k = S2 / 2.0 - 0.5;
    let octagon = [
        [0.5, k],
        [0.5, -k],
        [-0.5, k],
        [-0.5, -k],
        [k, 0.5],
        [-k, 0.5],
        [k, -0.5],
        [-k, -0.5],
    ];
    let mut chosen = Vec::new();
    for p in m.points() {
        let [x, y, z] = p.point.to_f64();
        assert!((y - 0.495).abs() < TOL && (p.separation.to_f64() + 0.01).abs() < TOL);
        assert!(
            octagon
                .iter()
                .any(|o| (o[0] - x).abs() < TOL && (o[1] - z).abs() < TOL),
            "({x}, {z}) is an octagon corner"
        );
        chosen.push([x, z]);
    }
    // The best four of the eight corners span half the octagon's area plus the two
    // triangles: compare with every choice of four.
    let mut best: f64 = 0.0;
    for a in 0..8 {
        for b in a + 1..8 {
            for c in b + 1..8 {
                for d in c + 1..8 {
                    let four = [octagon[a], octagon[b], octagon[c], octagon[d]];
                    best = best.max(hull_area(&four));
                }
            }
        }
    }
    let area = hull_area(&chosen);
    assert!(area >= 0.95 * best, "area {area} of the best {best}");
    assert_distinct_ids(&m);
    assert_ids_stable(&cube, &at([0.0; 3]), &cube, &xb);
}

#[test]
fn box_edge_on_a_face_gives_two_points_and_corner_one() {
    let big = cuboid::<Fx>([2.0, 0.5, 2.0]);
    let cube = cuboid::<Fx>([0.5, 0.5, 0.5]);
    // Turned 45° about z: the lowest edge (along z) is √2/2 below the centre.
    let h = 0.5 * S2;
    let xe = pose([0.2, 0.5 + h - 0.01, 0.1], [0.0, 0.0, 1.0], 45.0);
    let m = run(&big, &at([0.0; 3]), &cube, &xe);
    expect(
        &m,
        [0.0, 1.0, 0.0],
        &[([0.2, 0.495, -0.4], -0.01), ([0.2, 0.495, 0.6], -0.01)],
    );
    assert_ids_stable(&big, &at([0.0; 3]), &cube, &xe);
    assert_swap(&big, &at([0.0; 3]), &cube, &xe);
    // A corner down: the diagonal (1, 1, 1) turned onto −y, corner √3/2 below the centre.
    // The rotation taking (1, 1, 1)/√3 to (0, −1, 0): about (1, 1, 1) × (0, −1, 0) =
    // (1, 0, −1) by arccos(−1/√3).
    let k = 0.5 * 3f64.sqrt();
    let angle = (-1.0 / 3f64.sqrt()).acos().to_degrees();
    let xc = pose(
        [-0.3, 0.5 + k - 0.01, 0.4],
        [1.0 / S2, 0.0, -1.0 / S2],
        angle,
    );
    let m = run(&big, &at([0.0; 3]), &cube, &xc);
    expect(&m, [0.0, 1.0, 0.0], &[([-0.3, 0.495, 0.4], -0.01)]);
    assert_ids_stable(&big, &at([0.0; 3]), &cube, &xc);
}

#[test]
fn crossed_box_edges_touch_at_one_point() {
    let bar = cuboid::<Fx>([1.0, 0.5, 0.5]);
    // A: long along x, turned 45° about x, so its top edge (along x) is at y = √2/2.
    // B: long along z... the same bar turned 90° about y then 45° about z: its lowest
    // edge runs along z at y = −√2/2 from its centre.
    let h = 0.5 * S2;
    let xa = pose([0.0; 3], [1.0, 0.0, 0.0], 45.0);
    let turned = Quat::from_axis_angle(vec([0.0, 0.0, 1.0]), real(45f64.to_radians()))
        * Quat::from_axis_angle(vec([0.0, 1.0, 0.0]), real(90f64.to_radians()));
    let xb = Transform::from_pose(vec([0.1, 2.0 * h - 0.01, -0.2]), turned);
    let m = run(&bar, &xa, &bar, &xb);
    // A's edge runs along x at z = 0, B's along z at x = 0.1: they cross at (0.1, ·, 0),
    // 0.01 into each other.
    expect(&m, [0.0, 1.0, 0.0], &[([0.1, h - 0.005, 0.0], -0.01)]);
    assert_swap(&bar, &xa, &bar, &xb);
    assert_ids_stable(&bar, &xa, &bar, &xb);
    // Apart along the edge axis only (the face axes overlap): beyond and within margin.
    let apart = Transform::from_pose(vec([0.1, 2.0 * h + 0.03, -0.2]), turned);
    assert_eq!(run(&bar, &xa, &bar, &apart).count, 0);
    let near = Transform::from_pose(vec([0.1, 2.0 * h + 0.01, -0.2]), turned);
    expect(
        &run(&bar, &xa, &bar, &near),
        [0.0, 1.0, 0.0],
        &[([0.1, h + 0.005, 0.0], 0.01)],
    );
}

#[test]
fn box_box_separated_on_each_kind_of_face_axis() {
    let b = cuboid::<Fx>([0.5, 0.5, 0.5]);
    // A's face axis x.
    assert_eq!(run(&b, &at([0.0; 3]), &b, &at([1.03, 0.2, 0.0])).count, 0);
    // Only B's face axis separates: B turned 45° about z, its centre at distance D along
    // its own x axis n = (1, 1, 0)/√2. Along n, A reaches 0.5·√2 and B 0.5, so the
    // separation is D − 0.5 − √2/2; along A's x, the centres are D/√2 apart and the boxes
    // reach 0.5 + √2/2 together, an overlap for D ≤ 1.7.
    let turned = |distance: f64| {
        let c = distance / S2;
        pose::<Fx>([c, c, 0.0], [0.0, 0.0, 1.0], 45.0)
    };
    assert_eq!(run(&b, &at([0.0; 3]), &b, &turned(1.25)).count, 0);
    // Within the margin: B's face is the reference, A's edge (0.5, 0.5, z) gives its two
    // corners.
    let separation = 1.22 - 0.5 - S2 / 2.0;
    let m = run(&b, &at([0.0; 3]), &b, &turned(1.22));
    let shift = separation / 2.0 / S2;
    expect(
        &m,
        [1.0 / S2, 1.0 / S2, 0.0],
        &[
            ([0.5 + shift, 0.5 + shift, 0.5], separation),
            ([0.5 + shift, 0.5 + shift, -0.5], separation),
        ],
    );
    assert_swap(&b, &at([0.0; 3]), &b, &turned(1.22));
}

// ---------------------------------------------------------------- planes

#[test]
fn spheres_and_capsules_on_a_plane() {
    let g = ground::<Fx>();
    let s = sphere::<Fx>(0.5);
    let m = run(&g, &at([0.0; 3]), &s, &at([1.0, 0.48, 2.0]));
    expect(&m, [0.0, 1.0, 0.0], &[([1.0, -0.01, 2.0], -0.02)]);
    let m = run(&s, &at([1.0, 0.51, 2.0]), &g, &at([0.0; 3]));
    expect(&m, [0.0, -1.0, 0.0], &[([1.0, 0.005, 2.0], 0.01)]);
    assert_eq!(run(&g, &at([0.0; 3]), &s, &at([1.0, 0.53, 2.0])).count, 0);

    let c = capsule::<Fx>(0.25, 1.0);
    // Lying along z, 0.01 deep: both ends.
    let lying = pose([0.5, 0.24, 0.0], [1.0, 0.0, 0.0], 90.0);
    let m = run(&g, &at([0.0; 3]), &c, &lying);
    expect(
        &m,
        [0.0, 1.0, 0.0],
        &[([0.5, -0.005, 1.0], -0.01), ([0.5, -0.005, -1.0], -0.01)],
    );
    assert_ne!(m.points[0].id, m.points[1].id);
    assert_ids_stable(&g, &at([0.0; 3]), &c, &lying);
    assert_swap(&g, &at([0.0; 3]), &c, &lying);
    // Standing: only the lower end (id 0).
    let m = run(&g, &at([0.0; 3]), &c, &at([0.0, 1.24, 0.0]));
    expect(&m, [0.0, 1.0, 0.0], &[([0.0, -0.005, 0.0], -0.01)]);
    assert_eq!(m.points[0].id, 0);
}

#[test]
fn boxes_on_a_plane_face_edge_and_corner() {
    let g = ground::<Fx>();
    let b = cuboid::<Fx>([0.5, 0.25, 1.0]);
    let m = run(&g, &at([0.0; 3]), &b, &at([1.0, 0.24, 0.0]));
    let corners: Vec<([f64; 3], f64)> = [[0.5, -1.0], [1.5, -1.0], [0.5, 1.0], [1.5, 1.0]]
        .iter()
        .map(|&[x, z]| ([x, -0.005, z], -0.01))
        .collect();
    expect(&m, [0.0, 1.0, 0.0], &corners);
    assert_ids_stable(&g, &at([0.0; 3]), &b, &at([1.0, 0.24, 0.0]));
    assert_swap(&g, &at([0.0; 3]), &b, &at([1.0, 0.24, 0.0]));

    let cube = cuboid::<Fx>([0.5, 0.5, 0.5]);
    let h = 0.5 * S2;
    let edge = pose([0.0, h + 0.01, 0.0], [0.0, 0.0, 1.0], 45.0);
    let m = run(&g, &at([0.0; 3]), &cube, &edge);
    expect(
        &m,
        [0.0, 1.0, 0.0],
        &[([0.0, 0.005, -0.5], 0.01), ([0.0, 0.005, 0.5], 0.01)],
    );
    let k = 0.5 * 3f64.sqrt();
    let angle = (-1.0 / 3f64.sqrt()).acos().to_degrees();
    let corner = pose([0.0, k - 0.01, 0.0], [1.0 / S2, 0.0, -1.0 / S2], angle);
    let m = run(&g, &at([0.0; 3]), &cube, &corner);
    expect(&m, [0.0, 1.0, 0.0], &[([0.0, -0.005, 0.0], -0.01)]);
}

#[test]
fn tilted_and_offset_plane() {
    // The plane x·(0, 1, 0) ≤ 0.5 in a body turned 90° about z (its normal becomes −x)
    // and moved to x = 3: the world half-space is x ≥ 2.5, normal −x.
    let wall = Shape::<Fx>::Plane {
        normal: Vec3::Y,
        offset: real(0.5),
    };
    let xw = pose([3.0, 0.0, 0.0], [0.0, 0.0, 1.0], 90.0);
    let s = sphere::<Fx>(0.5);
    let m = run(&wall, &xw, &s, &at([2.01, 1.0, 1.0]));
    // Surface at x = 2.5, sphere reaching 2.51: 0.01 deep.
    expect(&m, [-1.0, 0.0, 0.0], &[([2.505, 1.0, 1.0], -0.01)]);
}

#[test]
fn plane_pairs_and_compounds_are_empty() {
    let g = ground::<Fx>();
    assert_eq!(run(&g, &at([0.0; 3]), &g, &at([0.0; 3])).count, 0);
    let compound = Shape::<Fx>::Compound {
        parts: vec![Part {
            rotation: Quat::IDENTITY,
            translation: Vec3::ZERO,
            shape: sphere(1.0),
        }],
    };
    let s = sphere::<Fx>(1.0);
    assert_eq!(run(&compound, &at([0.0; 3]), &s, &at([0.0; 3])).count, 0);
    assert_eq!(run(&s, &at([0.0; 3]), &compound, &at([0.0; 3])).count, 0);
    assert_eq!(run(&g, &at([0.0; 3]), &compound, &at([0.0; 3])).count, 0);
}

// ---------------------------------------------------------------- f64 agreement

/// Every kind of pair in a general pose, in I32F32 and in f64: same points, normals and
/// separations to 10⁻⁶.
#[test]
fn fixed_point_agrees_with_f64() {
    fn cases<R: Real>() -> Vec<Manifold<R>> {
        let s = sphere::<R>(0.4);
        let b = cuboid::<R>([0.6, 0.3, 0.5]);
        let c = capsule::<R>(0.3, 0.7);
        let g = ground::<R>();
        let tilted = |p: [f64; 3]| pose::<R>(p, [0.36, 0.48, 0.8], 37.0);
        let other = |p: [f64; 3]| pose::<R>(p, [0.0, 0.6, 0.8], -21.0);
        vec![
            run(&s, &tilted([0.0; 3]), &s, &other([0.3, 0.5, 0.2])),
            run(&s, &at([0.4, 0.7, 0.1]), &b, &tilted([0.0; 3])),
            run(&s, &at([0.5, 0.3, -0.2]), &c, &other([0.0; 3])),
            run(&c, &tilted([0.0; 3]), &c, &other([0.5, 0.2, 0.1])),
            run(&c, &other([0.3, 0.8, 0.0]), &b, &tilted([0.0; 3])),
            run(&b, &tilted([0.0; 3]), &b, &other([0.4, 0.6, 0.3])),
            run(
                &b,
                &at([0.0; 3]),
                &b,
                &pose([0.1, 0.58, 0.0], [0.0, 1.0, 0.0], 30.0),
            ),
            run(&g, &at([0.0; 3]), &b, &tilted([0.0, 0.5, 0.0])),
            run(&g, &at([0.0; 3]), &c, &other([0.0, 0.8, 0.0])),
        ]
    }
    let fixed = cases::<Fx>();
    let float = cases::<f64>();
    for (k, (x, f)) in fixed.iter().zip(&float).enumerate() {
        assert!(f.count > 0, "case {k} touches");
        assert_eq!(x.count, f.count, "case {k}");
        assert!(
            close(x.normal.to_f64(), f.normal.to_f64(), TOL),
            "case {k} normal"
        );
        for (p, q) in x.points().iter().zip(f.points()) {
            assert!(
                close(p.point.to_f64(), q.point.to_f64(), TOL),
                "case {k} point"
            );
            assert!(
                (p.separation.to_f64() - q.separation).abs() < TOL,
                "case {k} sep"
            );
            assert_eq!(p.id, q.id, "case {k} id");
        }
    }
}

// ---------------------------------------------------------------- more cases

#[test]
fn capsules_within_the_margin_and_coaxial() {
    let c = capsule::<Fx>(0.25, 1.0);
    let xb = pose([0.2, 0.3, 0.51], [0.0, 0.0, 1.0], 90.0);
    let m = run(&c, &at([0.0; 3]), &c, &xb);
    expect(&m, [0.0, 0.0, 1.0], &[([0.0, 0.3, 0.255], 0.01)]);
    // Same segment: deep, along a fixed direction perpendicular to the axis, two points.
    let m = run(&c, &at([0.0; 3]), &c, &at([0.0; 3]));
    assert_eq!(m.count, 2);
    assert!(m.normal.to_f64()[1].abs() < TOL);
    for p in m.points() {
        assert!((p.separation.to_f64() + 0.5).abs() < TOL);
    }
    assert_eq!(m, run(&c, &at([0.0; 3]), &c, &at([0.0; 3])));
}

#[test]
fn planes_beyond_the_margin_and_coincident_boxes() {
    let g = ground::<Fx>();
    let b = cuboid::<Fx>([0.5, 0.25, 1.0]);
    assert_eq!(run(&g, &at([0.0; 3]), &b, &at([1.0, 0.28, 0.0])).count, 0);
    let c = capsule::<Fx>(0.25, 1.0);
    assert_eq!(run(&g, &at([0.0; 3]), &c, &at([0.0, 1.28, 0.0])).count, 0);
    // Two equal cubes at the same place: A's x face (lowest axis, + side on the tie), one
    // full face of overlap 1 m deep.
    let cube = cuboid::<Fx>([0.5, 0.5, 0.5]);
    let m = run(&cube, &at([0.0; 3]), &cube, &at([0.0; 3]));
    let corners: Vec<([f64; 3], f64)> = [[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]
        .iter()
        .map(|&[y, z]| ([0.0, y, z], -1.0))
        .collect();
    expect(&m, [1.0, 0.0, 0.0], &corners);
}

/// A deterministic sweep of poses for every pair: never a saturation, at most four
/// points, unit normals, separations within the margin, distinct ids, and (except
/// box–box, whose reference face may differ on near ties) the same separations with A and
/// B swapped (except for two spheres or two capsules on the same centre and axis, where
/// nothing tells A from B).
#[test]
fn sweep_of_poses_keeps_the_invariants() {
    use fixstep::math::saturation::count_saturations;
    let shapes = [
        sphere::<Fx>(0.4),
        cuboid([0.6, 0.3, 0.5]),
        capsule(0.3, 0.7),
        cuboid([0.5, 0.5, 0.5]),
        capsule(0.2, 0.0),
        ground(),
    ];
    let turns: Vec<Transform<Fx>> = vec![
        at([0.0; 3]),
        pose([0.0; 3], [0.0, 1.0, 0.0], 45.0),
        pose([0.0; 3], [0.36, 0.48, 0.8], 37.0),
        pose([0.0; 3], [1.0, 0.0, 0.0], 90.0),
        pose([0.0; 3], [0.0, 0.6, -0.8], 123.0),
    ];
    let steps = [-1.1, -0.55, -0.13, 0.0, 0.21, 0.6, 1.05];
    let mut touching = 0;
    for (ia, a) in shapes.iter().enumerate() {
        for b in &shapes[ia..] {
            for ta in &turns {
                for tb in &turns {
                    for &x in &steps {
                        for &y in &steps {
                            for &z in &steps {
                                let xb = Transform {
                                    translation: vec([x, y, z]),
                                    ..*tb
                                };
                                let (m, saturations) = count_saturations(|| run(a, ta, b, &xb));
                                assert_eq!(saturations, 0);
                                check_invariants(&m);
                                let swapped = run(b, &xb, a, ta);
                                check_invariants(&swapped);
                                if m.count == 0 {
                                    continue;
                                }
                                touching += 1;
                                let boxes = matches!(a, Shape::Box { .. })
                                    && matches!(b, Shape::Box { .. });
                                // Two spheres, or two capsules, with the same centre and
                                // axis give no direction that tells A from B: both
                                // orders take the same fixed fallback normal.
                                let symmetric = matches!(
                                    (a, b),
                                    (Shape::Sphere { .. }, Shape::Sphere { .. })
                                        | (Shape::Capsule { .. }, Shape::Capsule { .. })
                                );
                                let same = symmetric
                                    && x == 0.0
                                    && y == 0.0
                                    && z == 0.0
                                    && (ta.rotation.cols[1] == tb.rotation.cols[1]
                                        || matches!(a, Shape::Sphere { .. }));
                                if !boxes && !same {
                                    let points: Vec<([f64; 3], f64)> = m
                                        .points()
                                        .iter()
                                        .map(|p| (p.point.to_f64(), p.separation.to_f64()))
                                        .collect();
                                    expect(&swapped, (-m.normal).to_f64(), &points);
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    assert!(touching > 1000, "the sweep exercises contacts: {touching}");
}

fn check_invariants(m: &Manifold<Fx>) {
    assert!(m.count <= 4);
    if m.count == 0 {
        return;
    }
    let n = m.normal.to_f64();
    let length = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    assert!((length - 1.0).abs() < 1e-6, "normal {n:?}");
    for p in m.points() {
        assert!(p.separation.to_f64() <= MARGIN + 1e-9, "{p:?}");
    }
    assert_distinct_ids(m);
}

// ---------------------------------------------------------------- cylinders, cones, hulls

fn cylinder<R: Real>(radius: f64, half_height: f64) -> Shape<R> {
    Shape::Cylinder {
        radius: real(radius),
        half_height: real(half_height),
    }
}

fn cone<R: Real>(radius: f64, half_height: f64) -> Shape<R> {
    Shape::Cone {
        radius: real(radius),
        half_height: real(half_height),
    }
}

fn hull_cube(half: [f64; 3]) -> Shape<Fx> {
    let points: Vec<Vec3<Fx>> = (0..8)
        .map(|i| {
            let s = |bit: usize, h: f64| if i & bit != 0 { h } else { -h };
            vec([s(1, half[0]), s(2, half[1]), s(4, half[2])])
        })
        .collect();
    Shape::ConvexHull {
        hull: fixstep::rigid::convex::ConvexHull::new(&points).expect("a cube"),
    }
}

/// The floor box: top face at y = 0.
fn floor<R: Real>() -> (Shape<R>, Transform<R>) {
    (cuboid([3.0, 0.5, 3.0]), at([0.0, -0.5, 0.0]))
}

/// A cylinder (r 0.5, h 1) lying along x, 1 cm into the ground plane and into a box's top:
/// two points at the ends of the bottom line, each 1 cm deep, midway (y = −0.005).
#[test]
fn cylinder_lying_on_a_plane_and_on_a_box_gets_two_points() {
    let c = cylinder::<Fx>(0.5, 1.0);
    let xc = pose([0.0, 0.49, 0.0], [0.0, 0.0, 1.0], 90.0);
    let expected = [([-1.0, -0.005, 0.0], -0.01), ([1.0, -0.005, 0.0], -0.01)];
    expect(
        &run(&ground(), &at([0.0; 3]), &c, &xc),
        [0.0, 1.0, 0.0],
        &expected,
    );
    let (f, xf) = floor::<Fx>();
    expect(&run(&f, &xf, &c, &xc), [0.0, 1.0, 0.0], &expected);
    assert_swap(&f, &xf, &c, &xc);
    assert_ids_stable(&f, &xf, &c, &xc);
}

/// The four points of a face contact are on the rim (r from the axis), 1 cm deep, and
/// spread over the cap (two of them a diameter apart).
fn assert_rim_points(m: &Manifold<Fx>, radius: f64, depth: f64) {
    assert_eq!(m.count, 4, "{:?}", m.points());
    assert!(close(m.normal.to_f64(), [0.0, 1.0, 0.0], TOL));
    let mut widest: f64 = 0.0;
    for p in m.points() {
        let q = p.point.to_f64();
        assert!(
            ((q[0] * q[0] + q[2] * q[2]).sqrt() - radius).abs() <= 1e-6,
            "{q:?}"
        );
        assert!((q[1] + depth / 2.0).abs() <= TOL, "{q:?}");
        assert!((p.separation.to_f64() + depth).abs() <= TOL);
        for o in m.points() {
            let r = o.point.to_f64();
            widest = widest.max(((q[0] - r[0]).powi(2) + (q[2] - r[2]).powi(2)).sqrt());
        }
    }
    assert!((widest - 2.0 * radius).abs() <= 1e-6, "widest {widest}");
    assert_distinct_ids(m);
}

#[test]
fn cylinder_standing_on_its_cap_gets_four_spread_points() {
    let c = cylinder::<Fx>(0.5, 1.0);
    let xc = at([0.0, 0.99, 0.0]);
    assert_rim_points(&run(&ground(), &at([0.0; 3]), &c, &xc), 0.5, 0.01);
    let (f, xf) = floor::<Fx>();
    assert_rim_points(&run(&f, &xf, &c, &xc), 0.5, 0.01);
    assert_swap(&f, &xf, &c, &xc);
    assert_ids_stable(&f, &xf, &c, &xc);
}

#[test]
fn cone_on_its_base_gets_four_points_and_on_its_apex_one() {
    let k = cone::<Fx>(0.5, 1.0);
    let (f, xf) = floor::<Fx>();
    let base_down = at([0.0, 0.99, 0.0]);
    assert_rim_points(&run(&f, &xf, &k, &base_down), 0.5, 0.01);
    assert_rim_points(&run(&ground(), &at([0.0; 3]), &k, &base_down), 0.5, 0.01);
    let apex_down = pose([0.0, 0.99, 0.0], [1.0, 0.0, 0.0], 180.0);
    let expected = [([0.0, -0.005, 0.0], -0.01)];
    expect(&run(&f, &xf, &k, &apex_down), [0.0, 1.0, 0.0], &expected);
    expect(
        &run(&ground(), &at([0.0; 3]), &k, &apex_down),
        [0.0, 1.0, 0.0],
        &expected,
    );
    assert_swap(&f, &xf, &k, &base_down);
}

/// A hull cube resting on a box face gives the manifold of the same box on that face: the
/// same normal, four points at the same places and depths.
#[test]
fn hull_cube_on_a_box_matches_box_on_box() {
    let (f, xf) = floor::<Fx>();
    let xb = pose([0.2, 0.49, -0.1], [0.0, 1.0, 0.0], 20.0);
    let as_box = run(&f, &xf, &cuboid([0.5, 0.5, 0.5]), &xb);
    let hull = hull_cube([0.5, 0.5, 0.5]);
    let as_hull = run(&f, &xf, &hull, &xb);
    assert_eq!(as_box.count, 4);
    let points: Vec<([f64; 3], f64)> = as_box
        .points()
        .iter()
        .map(|p| (p.point.to_f64(), p.separation.to_f64()))
        .collect();
    expect(&as_hull, as_box.normal.to_f64(), &points);
    assert_swap(&f, &xf, &hull, &xb);
    assert_ids_stable(&f, &xf, &hull, &xb);
    // On the ground plane too.
    let on_plane = run(&ground(), &at([0.0; 3]), &hull, &xb);
    expect(&on_plane, [0.0, 1.0, 0.0], &points);
}

/// A cylinder lying on another, crossed at right angles: one point between the sides; the
/// two parallel: two points along the common line.
#[test]
fn cylinder_on_cylinder() {
    let c = cylinder::<Fx>(0.5, 1.0);
    let lower = pose([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 90.0);
    let crossed = pose([0.0, 0.99, 0.0], [1.0, 0.0, 0.0], 90.0);
    // Two curved surfaces: EPA and GJK converge on the curvature to about 10⁻⁴.
    let m = run(&c, &lower, &c, &crossed);
    assert_eq!(m.count, 1);
    assert!(
        close(m.normal.to_f64(), [0.0, 1.0, 0.0], 1e-4),
        "{:?}",
        m.normal
    );
    assert!(close(m.points[0].point.to_f64(), [0.0, 0.495, 0.0], 1e-4));
    assert!((m.points[0].separation.to_f64() + 0.01).abs() <= 1e-6);
    let parallel = pose([0.5, 0.99, 0.0], [0.0, 0.0, 1.0], 90.0);
    let m = run(&c, &lower, &c, &parallel);
    assert_eq!(m.count, 2);
    assert!(
        close(m.normal.to_f64(), [0.0, 1.0, 0.0], 1e-4),
        "{:?}",
        m.normal
    );
    for p in m.points() {
        let q = p.point.to_f64();
        assert!(
            (q[0] + 0.5).abs() <= 1e-4 || (q[0] - 1.0).abs() <= 1e-4,
            "{q:?}"
        );
        assert!(close(q, [q[0], 0.495, 0.0], 1e-4), "{q:?}");
        assert!((p.separation.to_f64() + 0.01).abs() <= 1e-6);
    }
    assert_distinct_ids(&m);
}

/// A sphere and a capsule against a hull and a cylinder go through the same path.
#[test]
fn round_shapes_against_new_shapes() {
    let hull = hull_cube([0.5, 0.5, 0.5]);
    let s = sphere::<Fx>(0.25);
    expect(
        &run(&s, &at([0.0, 0.74, 0.1]), &hull, &at([0.0; 3])),
        [0.0, -1.0, 0.0],
        &[([0.0, 0.495, 0.1], -0.01)],
    );
    let c = cylinder::<Fx>(0.5, 1.0);
    let cap = capsule::<Fx>(0.25, 0.5);
    let lying = pose([0.0, 1.24, 0.0], [0.0, 0.0, 1.0], 90.0);
    expect(
        &run(&cap, &lying, &c, &at([0.0; 3])),
        [0.0, -1.0, 0.0],
        &[([-0.5, 0.995, 0.0], -0.01), ([0.5, 0.995, 0.0], -0.01)],
    );
}

/// Cylinders, cones and a hull against every convex shape over a sweep of turned poses:
/// unit normals, at most four points with distinct ids, separations within the margin and
/// above −1 m, and, for shapes of different kinds, the swapped order flips the normal with
/// the same number of points.
#[test]
fn sweep_of_new_shapes_keeps_the_invariants() {
    let shapes: Vec<Shape<Fx>> = vec![
        sphere(0.3),
        capsule(0.2, 0.4),
        cuboid([0.4, 0.3, 0.5]),
        cylinder(0.3, 0.4),
        cone(0.4, 0.5),
        hull_cube([0.3, 0.4, 0.35]),
    ];
    let mut checked = 0;
    for (i, a) in shapes.iter().enumerate() {
        for b in &shapes[3.max(i)..] {
            for k in 0..24 {
                let kf = k as f64;
                let xa = pose([0.0; 3], [0.0, 0.6, 0.8], 15.0 * kf);
                let xb = pose(
                    [
                        0.1 * (kf * 0.7).sin(),
                        0.45 + 0.02 * kf,
                        0.1 * (kf * 1.3).cos(),
                    ],
                    [0.8, 0.0, 0.6],
                    37.0 * kf,
                );
                let m = run(a, &xa, b, &xb);
                let s = run(b, &xb, a, &xa);
                // Shapes of different kinds are always computed in one order and flipped.
                let exact = std::mem::discriminant(a) != std::mem::discriminant(b);
                if exact {
                    assert_eq!(m.count, s.count, "{a:?} {b:?} pose {k}");
                }
                assert!(m.count <= 4);
                if m.count == 0 {
                    continue;
                }
                checked += 1;
                let n = m.normal.to_f64();
                let length = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
                assert!((length - 1.0).abs() <= 1e-6, "{a:?} {b:?} pose {k}: {n:?}");
                if exact {
                    assert!(close(n, (-s.normal).to_f64(), 1e-6));
                }
                for p in m.points() {
                    assert!(p.separation.to_f64() <= MARGIN + TOL);
                    assert!(p.separation.to_f64() >= -1.0, "{a:?} {b:?} pose {k}: {p:?}");
                }
                assert_distinct_ids(&m);
            }
        }
    }
    assert!(checked > 50, "{checked}");
}
