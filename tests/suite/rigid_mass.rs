//! Mass properties against the standard table of moments of inertia, and against an
//! independent slice-by-slice integration for the capsule.
//!
//! Table (m mass, r radius, h half height, H height, L length, (a, b, c) half extents):
//! solid sphere ⅖ m r²; hollow sphere ⅔ m r²; box Iₓ = m (b² + c²)/3; cylinder about its
//! axis ½ m r², across m (3r² + (2h)²)/12; cone about its axis (3/10) m r², across its
//! centre of mass (3/20) m r² + (3/80) m H²; thin rod across m L²/12.

use fixstep::math::{Fx, Mat3, Quat, Real, Vec3};
use fixstep::rigid::{MassProperties, Part, Shape};

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
