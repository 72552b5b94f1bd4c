//! Mass properties against the standard table of moments of inertia, and against an
//! independent slice-by-slice integration for the capsule.
//!
//! Table (m mass, r radius, h half height, H height, L length, (a, b, c) half extents):
//! solid sphere ⅖ m r²; hollow sphere ⅔ m r²; box Iₓ = m (b² + c²)/3; cylinder about its
//! axis ½ m r², across m (3r² + (2h)²)/12; cone about its axis (3/10) m r², across its
//! centre of mass (3/20) m r² + (3/80) m H²; thin rod across m L²/12.

use fixstep::math::{Fx, Mat3, Quat, Real, Vec3};
use fixstep::rigid::convex::ConvexHull;
use fixstep::rigid::{BodyDesc, MassProperties, Part, RigidDesc, Shape};
use fixstep::scene::Scene;

/// Relative agreement: I32F32 rounds each operation to 2⁻³³ absolute, so values of order 1
/// to 100 agree with the formula to about 10⁻⁸ relative.
fn close(got: f64, expected: f64, tolerance: f64) -> bool {
    (got - expected).abs() <= tolerance * expected.abs().max(1e-12)
}

fn diagonal<R: Real>(props: &MassProperties<R>) -> [f64; 3] {
    props.inertia.diagonal().to_f64()
}

fn assert_principal<R: Real>(
    props: MassProperties<R>,
    mass: f64,
    moments: [f64; 3],
    tolerance: f64,
) {
    assert!(
        close(props.mass.to_f64(), mass, tolerance),
        "mass {:?} vs {mass}",
        props.mass.to_f64()
    );
    for (k, (got, expected)) in diagonal(&props).into_iter().zip(moments).enumerate() {
        assert!(
            close(got, expected, tolerance),
            "moment {k}: {got} vs {expected}"
        );
    }
    let m = props.inertia.to_f64();
    for (i, row) in m.iter().enumerate() {
        for (j, &value) in row.iter().enumerate() {
            if i != j {
                assert!(
                    value.abs() <= tolerance * moments[0].abs(),
                    "off-diagonal ({i},{j}) = {value}"
                );
            }
        }
    }
}

fn fx(x: f64) -> Fx {
    Fx::from_f64(x)
}

#[test]
fn the_table_of_solids() {
    let (m, r) = (3.0, 0.5);
    for tolerance in [1e-12, 1e-8] {
        let check = |props_f64: MassProperties<f64>,
                     props_fx: MassProperties<Fx>,
                     mass: f64,
                     moments: [f64; 3]| {
            assert_principal(props_f64, mass, moments, 1e-12);
            assert_principal(props_fx, mass, moments, tolerance.max(1e-8));
        };
        check(
            MassProperties::solid_sphere(m, r),
            MassProperties::solid_sphere(fx(m), fx(r)),
            m,
            [0.3; 3],
        );
        check(
            MassProperties::hollow_sphere(m, r),
            MassProperties::hollow_sphere(fx(m), fx(r)),
            m,
            [0.5; 3],
        );
        let half = [0.5, 1.0, 1.5];
        let box_moments = [
            m * (1.0 + 2.25) / 3.0,
            m * (0.25 + 2.25) / 3.0,
            m * (0.25 + 1.0) / 3.0,
        ];
        check(
            MassProperties::solid_box(m, Vec3::new(half[0], half[1], half[2])),
            MassProperties::solid_box(fx(m), Vec3::new(fx(half[0]), fx(half[1]), fx(half[2]))),
            m,
            box_moments,
        );
        let (cr, ch) = (0.4, 1.2);
        let across = m * (3.0 * cr * cr + (2.0 * ch) * (2.0 * ch)) / 12.0;
        check(
            MassProperties::solid_cylinder(m, cr, ch),
            MassProperties::solid_cylinder(fx(m), fx(cr), fx(ch)),
            m,
            [across, 0.5 * m * cr * cr, across],
        );
        let (kr, kh) = (0.6, 2.0);
        let across = 0.15 * m * kr * kr + 0.0375 * m * kh * kh;
        check(
            MassProperties::solid_cone(m, kr, kh),
            MassProperties::solid_cone(fx(m), fx(kr), fx(kh)),
            m,
            [across, 0.3 * m * kr * kr, across],
        );
        check(
            MassProperties::thin_rod(m, 2.0),
            MassProperties::thin_rod(fx(m), fx(2.0)),
            m,
            [m * 4.0 / 12.0, 0.0, m * 4.0 / 12.0],
        );
    }
    let cone: MassProperties<f64> = MassProperties::solid_cone(1.0, 0.6, 2.0);
    assert_eq!(cone.centre.to_f64(), [0.0, 0.5, 0.0]);
}

/// Capsule mass and moments by integrating discs along the axis with Simpson's rule:
/// a slice at height y has radius ρ(y) (r on the cylinder, √(r² − (|y| − h)²) on the caps),
/// mass dm = ρ_density π ρ² dy, axial moment ½ ρ² dm, transverse moment (¼ ρ² + y²) dm.
fn capsule_by_slices(density: f64, r: f64, h: f64) -> (f64, f64, f64) {
    let radius_at = |y: f64| {
        let beyond = y.abs() - h;
        if beyond <= 0.0 {
            r
        } else {
            (r * r - beyond * beyond).max(0.0).sqrt()
        }
    };
    let n = 200_000;
    let (lo, hi) = (-(h + r), h + r);
    let dy = (hi - lo) / n as f64;
    let (mut mass, mut axial, mut across) = (0.0, 0.0, 0.0);
    for k in 0..=n {
        let y = lo + k as f64 * dy;
        let weight = if k == 0 || k == n {
            1.0
        } else if k % 2 == 1 {
            4.0
        } else {
            2.0
        };
        let rho = radius_at(y);
        let dm = density * std::f64::consts::PI * rho * rho * weight * dy / 3.0;
        mass += dm;
        axial += 0.5 * rho * rho * dm;
        across += (0.25 * rho * rho + y * y) * dm;
    }
    (mass, axial, across)
}

#[test]
fn the_capsule_matches_integration_by_slices() {
    for (density, r, h) in [(1000.0, 0.5, 1.0), (7.8, 0.25, 0.0), (2.0, 1.0, 0.1)] {
        let (mass, axial, across) = capsule_by_slices(density, r, h);
        // Simpson's rule on the caps' square-root profile converges slowly near the poles:
        // 10⁻⁶ relative at 2·10⁵ slices.
        let exact: MassProperties<f64> = MassProperties::solid_capsule(density, r, h);
        assert_principal(exact, mass, [across, axial, across], 1e-6);
        let fixed = MassProperties::solid_capsule(fx(density), fx(r), fx(h));
        assert_principal(fixed, mass, [across, axial, across], 1e-6);
    }
}

#[test]
fn a_capsule_without_a_cylinder_is_a_sphere() {
    let capsule = MassProperties::solid_capsule(fx(500.0), fx(0.75), Fx::ZERO);
    let sphere = MassProperties::sphere_from_density(fx(500.0), fx(0.75));
    assert!(close(capsule.mass.to_f64(), sphere.mass.to_f64(), 1e-8));
    for (a, b) in diagonal(&capsule).into_iter().zip(diagonal(&sphere)) {
        assert!(close(a, b, 1e-8), "{a} vs {b}");
    }
}

#[test]
fn two_half_boxes_make_the_whole_box() {
    // Parallel-axis theorem: halves of 1 × 2 × 1 m side by side along x.
    let half = Shape::<Fx>::Box {
        half_extents: Vec3::new(fx(0.25), fx(1.0), fx(0.5)),
    };
    let place = |x: f64| Part {
        rotation: Quat::IDENTITY,
        translation: Vec3::new(fx(x), Fx::ZERO, Fx::ZERO),
        shape: half.clone(),
    };
    let compound = Shape::Compound {
        parts: vec![place(-0.25), place(0.25)],
    };
    let whole = Shape::Box {
        half_extents: Vec3::new(fx(0.5), fx(1.0), fx(0.5)),
    };
    let (a, b) = (
        compound.mass_properties(fx(300.0)),
        whole.mass_properties(fx(300.0)),
    );
    assert!(close(a.mass.to_f64(), b.mass.to_f64(), 1e-9));
    assert_eq!(a.centre, Vec3::ZERO);
    let (ia, ib) = (a.inertia.to_f64(), b.inertia.to_f64());
    for i in 0..3 {
        for j in 0..3 {
            assert!(
                (ia[i][j] - ib[i][j]).abs() < 1e-6,
                "({i},{j}): {} vs {}",
                ia[i][j],
                ib[i][j]
            );
        }
    }
}

#[test]
fn an_offset_part_moves_the_centre_but_not_the_central_inertia() {
    let ball = Shape::<Fx>::Sphere { radius: fx(0.5) };
    let offset = Vec3::new(fx(2.0), fx(-1.0), fx(0.5));
    let moved = Shape::Compound {
        parts: vec![Part {
            rotation: Quat::IDENTITY,
            translation: offset,
            shape: ball.clone(),
        }],
    };
    let (a, b) = (
        moved.mass_properties(fx(10.0)),
        ball.mass_properties(fx(10.0)),
    );
    // c = (m c)/m: a product and a division, a few ulp (2⁻³² m) each.
    assert!(
        (a.centre - offset).length().to_f64() < 1e-8,
        "{:?}",
        a.centre
    );
    let (ia, ib) = (a.inertia.to_f64(), b.inertia.to_f64());
    for i in 0..3 {
        for j in 0..3 {
            assert!((ia[i][j] - ib[i][j]).abs() < 1e-8, "({i},{j})");
        }
    }
    // About the body origin instead: I + m (|d|² E − d dᵀ).
    let about_origin = b.inertia_about(offset).to_f64();
    let (m, d) = (b.mass.to_f64(), offset.to_f64());
    let central = b.inertia.to_f64();
    let d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    for i in 0..3 {
        for j in 0..3 {
            let expected = central[i][j] + m * (if i == j { d2 } else { 0.0 } - d[i] * d[j]);
            assert!((about_origin[i][j] - expected).abs() < 1e-6, "({i},{j})");
        }
    }
}

#[test]
fn a_rotated_box_has_the_rotated_tensor() {
    // A box turned 90° about z swaps its x and y moments.
    let turned = Part {
        rotation: Quat::from_axis_angle(Vec3::Z, Fx::FRAC_PI_2),
        translation: Vec3::ZERO,
        shape: Shape::Box {
            half_extents: Vec3::new(fx(0.5), fx(1.5), fx(0.25)),
        },
    };
    let straight = turned.shape.mass_properties(fx(100.0));
    let rotated = Shape::Compound {
        parts: vec![turned],
    }
    .mass_properties(fx(100.0));
    let (s, r) = (diagonal(&straight), diagonal(&rotated));
    assert!(
        close(r[0], s[1], 1e-7) && close(r[1], s[0], 1e-7) && close(r[2], s[2], 1e-7),
        "{r:?} vs {s:?}"
    );
}

#[test]
fn planes_and_empty_compounds_have_no_mass() {
    let plane = Shape::<Fx>::Plane {
        normal: Vec3::Y,
        offset: Fx::ZERO,
    };
    assert_eq!(plane.mass_properties(fx(1000.0)), MassProperties::ZERO);
    let empty = Shape::<Fx>::Compound { parts: Vec::new() };
    assert_eq!(empty.mass_properties(fx(1000.0)), MassProperties::ZERO);
}

#[test]
fn a_thin_rod_has_a_safe_inverse() {
    let rod = MassProperties::thin_rod(fx(2.0), fx(3.0));
    let inverse = rod.inertia.safe_inverse_symmetric();
    let expected = 12.0 / (2.0 * 9.0);
    let d = inverse.diagonal().to_f64();
    assert!(
        close(d[0], 1.0 / (2.0 * 9.0 / 12.0), 1e-7) && d[1] == 0.0,
        "{d:?} vs {expected}"
    );
    assert_eq!(Mat3::<Fx>::ZERO.safe_inverse_symmetric(), Mat3::ZERO);
}

/// Relative agreement within `relative`, or within `ulps` units of 2⁻³² (I32F32's
/// resolution) where the value itself is that small (a 1 cm hull's inertia is ~10⁻⁹ kg·m²).
fn near(got: f64, expected: f64, relative: f64, ulps: f64) -> bool {
    (got - expected).abs() <= (relative * expected.abs()).max(ulps * 2f64.powi(-32))
}

fn assert_same_props<R: Real>(
    got: &MassProperties<R>,
    expected: &MassProperties<f64>,
    relative: f64,
    ulps: f64,
) {
    assert!(
        near(got.mass.to_f64(), expected.mass, relative, ulps),
        "mass {} vs {}",
        got.mass.to_f64(),
        expected.mass
    );
    let scale = expected.centre.length().max(1.0);
    for (g, e) in got
        .centre
        .to_f64()
        .into_iter()
        .zip(expected.centre.to_f64())
    {
        assert!(
            near(g, e, 0.0, ulps) || (g - e).abs() <= relative * scale,
            "centre {g} vs {e}"
        );
    }
    let (gi, ei) = (got.inertia.to_f64(), expected.inertia.to_f64());
    let largest = ei.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    for i in 0..3 {
        for j in 0..3 {
            assert!(
                (gi[i][j] - ei[i][j]).abs() <= (relative * largest).max(ulps * 2f64.powi(-32)),
                "inertia ({i},{j}): {} vs {}",
                gi[i][j],
                ei[i][j]
            );
        }
    }
}

fn hull_of<R: Real>(points: &[[f64; 3]]) -> ConvexHull<R> {
    let points: Vec<Vec3<R>> = points
        .iter()
        .map(|p| Vec3::from_f64(p[0], p[1], p[2]))
        .collect();
    ConvexHull::new(&points).expect("a hull")
}

fn box_corner_list(half: [f64; 3], offset: [f64; 3]) -> Vec<[f64; 3]> {
    let mut corners = Vec::new();
    for k in 0..8 {
        let sign = |bit: usize| if k & (1 << bit) == 0 { -1.0 } else { 1.0 };
        corners.push([
            offset[0] + sign(0) * half[0],
            offset[1] + sign(1) * half[1],
            offset[2] + sign(2) * half[2],
        ]);
    }
    corners
}

#[test]
fn cylinder_and_cone_shapes_match_the_table() {
    let pi = std::f64::consts::PI;
    let (density, r, h) = (500.0, 0.4, 1.2);
    let m = density * pi * r * r * 2.0 * h;
    let across = m * (3.0 * r * r + (2.0 * h) * (2.0 * h)) / 12.0;
    let cylinder = Shape::<Fx>::Cylinder {
        radius: fx(r),
        half_height: fx(h),
    };
    let props = cylinder.mass_properties(fx(density));
    assert_principal(props, m, [across, 0.5 * m * r * r, across], 1e-6);
    assert_eq!(props.centre, Vec3::ZERO);

    let (density, r, h) = (800.0, 0.6, 1.0);
    let height = 2.0 * h;
    let m = density * pi * r * r * height / 3.0;
    let across = 0.15 * m * r * r + 0.0375 * m * height * height;
    let cone = Shape::<Fx>::Cone {
        radius: fx(r),
        half_height: fx(h),
    };
    let props = cone.mass_properties(fx(density));
    assert_principal(props, m, [across, 0.3 * m * r * r, across], 1e-6);
    // A quarter of the height above the base at y = −h.
    assert!((props.centre.to_f64()[1] - (-h + height / 4.0)).abs() < 1e-9);
    assert_eq!((props.centre.x, props.centre.z), (Fx::ZERO, Fx::ZERO));
}

#[test]
fn a_box_hull_has_the_box_mass_properties_from_1_cm_to_100_m() {
    // (half extents, offset, density): I32F32 must hold m and I (< 2³¹).
    let cases = [
        ([0.005, 0.0025, 0.004], [0.0, 0.0, 0.0], 8000.0),
        ([0.5, 1.0, 1.5], [3.0, -2.0, 7.0], 1000.0),
        ([50.0, 25.0, 10.0], [-500.0, 200.0, 1000.0], 0.5),
    ];
    for (half, offset, density) in cases {
        let corners = box_corner_list(half, offset);
        let h = Vec3::new(half[0], half[1], half[2]);
        let expected = MassProperties {
            centre: Vec3::new(offset[0], offset[1], offset[2]),
            ..MassProperties::box_from_density(density, h)
        };
        // f64: the volume integrals themselves, at every size.
        let props = hull_of::<f64>(&corners).mass_properties(density);
        assert_same_props(&props, &expected, 1e-12, 0.0);
        // I32F32: 10⁻⁶ relative, or a few ulp of the format for the 1 cm box's inertia
        // (~10⁻¹⁰ kg·m², less than one ulp).
        let props = hull_of::<Fx>(&corners).mass_properties(fx(density));
        assert_same_props(&props, &expected, 1e-6, 4.0);
        let shape = Shape::ConvexHull {
            hull: hull_of::<Fx>(&corners),
        };
        assert_eq!(shape.mass_properties(fx(density)), props);
    }
}

#[test]
fn a_turned_and_moved_cube_has_its_centre_where_it_was_moved() {
    let (a, density) = (0.75, 300.0);
    let turn = Quat::<f64>::from_axis_angle(Vec3::new(0.3, -0.8, 0.52).normalize_or_zero(), 1.1);
    let shift = [12.5, -3.25, 40.0];
    let corners: Vec<[f64; 3]> = box_corner_list([a; 3], [0.0; 3])
        .into_iter()
        .map(|p| {
            let r = turn.rotate(Vec3::new(p[0], p[1], p[2]));
            [r.x + shift[0], r.y + shift[1], r.z + shift[2]]
        })
        .collect();
    let props = hull_of::<Fx>(&corners).mass_properties(fx(density));
    // A cube's tensor is the same about every axis: m (2a²)/3.
    let m = density * 8.0 * a * a * a;
    let expected = MassProperties {
        mass: m,
        centre: Vec3::new(shift[0], shift[1], shift[2]),
        inertia: Mat3::from_diagonal(Vec3::splat(m * 2.0 * a * a / 3.0)),
    };
    assert_same_props(&props, &expected, 1e-6, 4.0);
}

/// Points on the unit sphere at `rings` latitudes of `segments` points each, plus the poles.
fn latitude_longitude(rings: usize, segments: usize) -> Vec<[f64; 3]> {
    let pi = std::f64::consts::PI;
    let mut points = vec![[0.0, 1.0, 0.0], [0.0, -1.0, 0.0]];
    for i in 1..=rings {
        let polar = pi * i as f64 / (rings + 1) as f64;
        for j in 0..segments {
            // Alternate rings are offset by half a step, which makes the triangles rounder.
            let azimuth = 2.0 * pi * (j as f64 + 0.5 * (i % 2) as f64) / segments as f64;
            points.push([
                polar.sin() * azimuth.cos(),
                polar.cos(),
                polar.sin() * azimuth.sin(),
            ]);
        }
    }
    points
}

#[test]
fn a_finely_sampled_sphere_tends_to_the_sphere() {
    // The inscribed polyhedron misses the caps over its faces: with chords spanning an angle
    // θ, each face lies up to r(1 − cos(θ/2)) ≈ r θ²/8 inside the sphere, so the volume
    // deficit is at most about 3θ²/8 relative and the moment deficit 5θ²/8 (θ = π/16 at 15
    // rings of 32: 1.4% and 2.4%). Measured (I32F32): 52 points −11.3% mass, −19.3%
    // moments; 164 points −3.9%, −6.9%; 482 points −1.44%, −2.54%.
    let (density, radius) = (1000.0, 0.5);
    let exact = MassProperties::<f64>::sphere_from_density(density, radius);
    let mut previous = f64::MAX;
    for (rings, segments, bound) in [(5, 10, 0.15), (9, 18, 0.05), (15, 32, 0.02)] {
        let points: Vec<[f64; 3]> = latitude_longitude(rings, segments)
            .into_iter()
            .map(|p| p.map(|x| x * radius))
            .collect();
        let hull = hull_of::<Fx>(&points);
        assert_eq!(
            hull.vertices().len(),
            points.len(),
            "every point is a corner"
        );
        let props = hull.mass_properties(fx(density));
        let mass_error = 1.0 - props.mass.to_f64() / exact.mass;
        let moments = diagonal(&props);
        let moment_error = moments
            .iter()
            .map(|&i| 1.0 - i / exact.inertia.diagonal().x)
            .fold(0.0f64, f64::max);
        println!(
            "{} points: mass −{mass_error:.5}, moments −{moment_error:.5}",
            points.len()
        );
        assert!(mass_error > 0.0 && mass_error < bound, "{mass_error}");
        assert!(
            moment_error > 0.0 && moment_error < bound * 1.7,
            "{moment_error}"
        );
        assert!(mass_error < previous, "the error shrinks with refinement");
        previous = mass_error;
        assert!(props.centre.length().to_f64() < 1e-6);
    }
}

#[test]
fn a_dynamic_tetrahedron_is_centred_on_its_centre_of_mass() {
    let corners = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ];
    let hull = hull_of::<Fx>(&corners);
    let props = hull.mass_properties(fx(600.0));
    // V = 1/6, centre at the mean of the corners.
    assert!(close(props.mass.to_f64(), 100.0, 1e-8));
    for c in props.centre.to_f64() {
        assert!((c - 0.25).abs() < 1e-9, "{c}");
    }
    let position = Vec3::new(fx(2.0), fx(5.0), fx(-1.0));
    let mut body = BodyDesc::new(Shape::ConvexHull { hull }, position);
    body.density = fx(600.0);
    let mut scene = Scene::empty("tetrahedron");
    scene.rigid = Some(RigidDesc {
        bodies: vec![body],
        ..RigidDesc::default()
    });
    let world = scene.build().expect("builds");
    let rigid = world.rigid().expect("rigid");
    let handle = rigid.handles().next().expect("a body");
    let moved = rigid.position(handle).expect("live") - position;
    for c in moved.to_f64() {
        assert!((c - 0.25).abs() < 1e-9, "{c}");
    }
    let Some(Shape::ConvexHull { hull }) = rigid.shape(handle) else {
        panic!("still a hull");
    };
    assert!(hull.mass_properties(fx(600.0)).centre.length().to_f64() < 1e-8);
}
