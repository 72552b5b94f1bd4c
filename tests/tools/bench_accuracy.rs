//! `fixstep bench accuracy`: the reference solutions against the tabulated reference data,
//! the orders of convergence the sweep measures, and the command's files and errors.
//!
//! Reference values are copied from the project's reference folder
//! (`/work/shared/reference/`, each file computed with mpmath to 30 digits), with the file and
//! column named at each constant. The expected orders come from the schemes' theory, not from
//! this benchmark's output.

use crate::replay_support::{TempPath, fixstep};
use fixstep::particles::Integrator;
use fixstep_bench::elliptic::pendulum_period;
use fixstep_bench::exact::{damped_displacement, harmonic_displacement, projectile_position};
use fixstep_bench::kepler_equation::kepler_position;
use fixstep_bench::{
    AccuracyConfig, AccuracyRow, Distrust, NumberFormat, OrderRow, Problem, measured_orders,
    run_accuracy,
};

/// `damped_oscillator_reference.csv`, columns `t` and `zeta=0.1` (ω₀ = 1, x(0) = 1, v(0) = 0).
const DAMPED_ZETA_0_1: [(f64, f64); 6] = [
    (0.5, 0.88154640269708),
    (1.0, 0.5689718909461),
    (2.0, -0.258070263439546),
    (5.0, 0.098550667618586),
    (10.0, -0.336851680590413),
    (20.0, 0.0791160236189625),
];

/// `damped_oscillator_reference.csv`, columns `t` and `zeta=0` (the harmonic oscillator).
const UNDAMPED: [(f64, f64); 3] = [
    (2.0, -0.416146836547142),
    (7.5, 0.346635317835026),
    (10.0, -0.839071529076452),
];

/// `projectile_linear_drag_reference.csv` (g = 9.81, τ = 2 s, 20 m/s at 45°): t, x, y. The
/// last two rows are the apex and the landing.
const PROJECTILE: [(f64, f64, f64); 5] = [
    (0.25, 3.32348947971424, 3.02931102229472),
    (1.0, 11.1289935482478, 6.94873046112403),
    (2.0, 17.8790693470041, 3.44348007543673),
    (1.08558094517309, 11.8475917654583, 6.98517310316594),
    (2.41037751131241, 19.8093012920359, 0.0),
];

/// `kepler_e0.5_reference.csv` (e = 0.5, μ = 1): t, x, y (rows `pi/4`, `pi`, `10`, `100`).
const KEPLER: [(f64, f64, f64); 4] = [
    (
        core::f64::consts::FRAC_PI_4,
        -0.195804996790714,
        0.824984272587591,
    ),
    (core::f64::consts::PI, -1.5, 0.0),
    (10.0, -1.42617025159879, -0.326583065681721),
    (100.0, 0.0958041308370719, -0.695530788864239),
];

/// `pendulum_period_vs_amplitude.csv`: θ₀ in degrees, `T_over_T0_exact`.
const PENDULUM: [(f64, f64); 6] = [
    (1.0, 1.00001903892101),
    (10.0, 1.00190718814322),
    (45.0, 1.0399733431968),
    (90.0, 1.1803405990161),
    (150.0, 1.76220372950376),
    (179.0, 3.90106516038909),
];

#[test]
fn closed_forms_match_the_reference_tables() {
    for (t, x) in UNDAMPED {
        assert!(
            (harmonic_displacement(1.0, 1.0, t) - x).abs() < 1e-13,
            "t = {t}"
        );
    }
    for (t, x) in DAMPED_ZETA_0_1 {
        assert!(
            (damped_displacement(1.0, 1.0, 0.1, t) - x).abs() < 1e-13,
            "t = {t}"
        );
    }
    let v0 = 20.0 * core::f64::consts::FRAC_1_SQRT_2;
    for (t, x, y) in PROJECTILE {
        let [px, py] = projectile_position([v0, v0], 9.81, 2.0, t);
        assert!((px - x).abs() < 1e-11 && (py - y).abs() < 1e-11, "t = {t}");
    }
}

#[test]
fn kepler_equation_matches_the_reference_orbit() {
    for (t, x, y) in KEPLER {
        let [px, py] = kepler_position(0.5, t);
        assert!(
            (px - x).abs() < 1e-12 && (py - y).abs() < 1e-12,
            "t = {t}: ({px}, {py})"
        );
    }
}

#[test]
fn elliptic_integral_period_matches_the_reference_table() {
    for (degrees, ratio) in PENDULUM {
        let period = pendulum_period(degrees.to_radians(), 1.0);
        let got = period / core::f64::consts::TAU;
        assert!((got - ratio).abs() < 1e-12 * ratio, "{degrees}°: {got}");
    }
}

/// The measured f64 orders of one problem, in `Integrator::ALL` order.
fn f64_orders(orders: &[OrderRow], problem: Problem) -> Vec<f64> {
    Integrator::ALL
        .iter()
        .map(|&integrator| {
            let row = orders
                .iter()
                .find(|o| (o.problem, o.integrator) == (problem, integrator))
                .expect("every integrator is measured");
            row.measured
                .unwrap_or_else(|| panic!("{problem:?} {integrator}: no order"))
                .order
        })
        .collect()
}

/// The f64 orders of the quick sweep against theory, ±0.2.
///
/// * Position-only forces (harmonic, Kepler): the global orders 1, 1, 2, 2, 2, 4, 1.
/// * Velocity-dependent forces (spring damping, linear drag): velocity Verlet evaluates
///   a(x_{n+1}, v_{n+½}) and leapfrog a(x_{n+½}, v_n), each with a velocity O(h) away from
///   the one the scheme needs, which adds an O(h²) local error: they become first order.
///   Störmer–Verlet's reconstructed velocity is O(h²) accurate, so it stays second order.
/// * The pendulum's period: explicit Euler 1, Störmer–Verlet and velocity Verlet 2, RK4 4.
///   Semi-implicit Euler is conjugate to the second-order leapfrog, and the period does not
///   change under conjugation, so both are at least second order for it (at 90° their h²
///   term happens to vanish, and they show a higher order).
/// * Implicit Euler is first order everywhere; without springs or linear drag (Kepler, the
///   pendulum) its step is semi-implicit Euler's, so the pendulum's period is at least second
///   order for it too.
#[test]
fn quick_sweep_measures_the_theoretical_orders_in_f64() {
    let config = AccuracyConfig {
        formats: vec![NumberFormat::F64],
        ..AccuracyConfig::quick()
    };
    let orders = measured_orders(&run_accuracy(&config));
    let check = |problem: Problem, expected: [Option<f64>; 7]| {
        let measured = f64_orders(&orders, problem);
        println!("{problem:?}: {measured:.2?}");
        for ((integrator, want), got) in Integrator::ALL.iter().zip(expected).zip(measured) {
            match want {
                Some(want) => assert!(
                    (got - want).abs() <= 0.2,
                    "{problem:?} {integrator}: order {got:.2}, expected {want}"
                ),
                None => assert!(
                    got >= 1.8,
                    "{problem:?} {integrator}: order {got:.2}, expected at least 2"
                ),
            }
        }
    };
    let position_only = [1.0, 1.0, 2.0, 2.0, 2.0, 4.0, 1.0].map(Some);
    check(Problem::Harmonic, position_only);
    check(Problem::Kepler, position_only);
    let velocity_dependent = [1.0, 1.0, 2.0, 1.0, 1.0, 4.0, 1.0].map(Some);
    check(Problem::Damped, velocity_dependent);
    check(Problem::Projectile, velocity_dependent);
    check(
        Problem::Pendulum,
        [Some(1.0), None, Some(2.0), Some(2.0), None, Some(4.0), None],
    );
}

/// f64 rows of one problem and scheme with these errors at h = 2⁻¹ … s (observables of 0,
/// so that the f64 rounding bound counts every point).
fn synthetic_rows(errors: &[f64]) -> Vec<AccuracyRow> {
    (1u32..)
        .zip(errors)
        .map(|(k, &error)| AccuracyRow {
            problem: Problem::Harmonic,
            integrator: Integrator::VelocityVerlet,
            format: NumberFormat::F64,
            log2_inverse_step: k,
            dt: 0.5f64.powi(k as i32),
            steps: 1 << k,
            error,
            seconds: 0.0,
            observable: [0.0; 3],
        })
        .collect()
}

/// Why the order measured over `errors` is not trusted, or `None`, with the order.
fn verdict(errors: &[f64]) -> (f64, Option<Distrust>) {
    let orders = measured_orders(&synthetic_rows(errors));
    let measured = orders[0].measured.expect("two points at least");
    (measured.order, measured.distrust)
}

#[test]
fn an_order_is_trusted_only_when_the_data_show_one_power_of_the_step() {
    // Halving the step quarters the error: order 2, trusted.
    let (order, distrust) = verdict(&[1e-2, 2.5e-3, 6.25e-4, 1.5625e-4]);
    assert!(
        (order - 2.0).abs() < 1e-9 && distrust.is_none(),
        "{order} {distrust:?}"
    );
    // Two points are a slope, not an order.
    assert_eq!(verdict(&[1e-2, 2.5e-3]).1, Some(Distrust::TooFewPoints(2)));
    // The error stops falling at h = 2⁻³: the rounding floor.
    assert_eq!(
        verdict(&[1e-2, 2.5e-3, 3e-3, 1e-3]).1,
        Some(Distrust::ErrorStopsFalling {
            log2_inverse_step: 3
        })
    );
    // Slopes 1, 3, 5 average to 3 but are no power of h.
    let (order, distrust) = verdict(&[1.0, 0.5, 0.0625, 0.001953125]);
    assert!((order - 3.0).abs() < 0.01, "{order}");
    match distrust {
        Some(Distrust::ScatteredSlopes { least, greatest }) => {
            assert!((least - 1.0).abs() < 1e-9 && (greatest - 5.0).abs() < 1e-9)
        }
        other => panic!("{other:?}"),
    }
    let text = Distrust::ScatteredSlopes {
        least: 1.0,
        greatest: 5.0,
    }
    .to_string();
    assert_eq!(
        text,
        "slopes between halvings range from 1.00 to 5.00, not one power of dt"
    );
}

/// A coarser ulp cannot give a smaller error floor: for every problem the best I32F32 error
/// (ulp 2⁻³²) is below the best I48F16 error (ulp 2⁻¹⁶). Four halvings of the harmonic
/// and projectile problems keep this fast.
#[test]
fn finer_fixed_point_formats_reach_lower_errors() {
    let config = AccuracyConfig {
        problems: vec![Problem::Harmonic, Problem::Projectile],
        formats: vec![NumberFormat::I32F32, NumberFormat::I48F16],
        halvings: 4,
        ..AccuracyConfig::quick()
    };
    let rows = run_accuracy(&config);
    for problem in [Problem::Harmonic, Problem::Projectile] {
        let best = |format: NumberFormat| {
            rows.iter()
                .filter(|r| r.problem == problem && r.format == format)
                .map(|r| r.error)
                .fold(f64::INFINITY, f64::min)
        };
        let (fine, coarse) = (best(NumberFormat::I32F32), best(NumberFormat::I48F16));
        assert!(
            fine < coarse,
            "{problem:?}: I32F32 {fine:e}, I48F16 {coarse:e}"
        );
    }
}

#[test]
fn command_writes_the_csv_and_the_svg_and_prints_the_orders() {
    let dir = TempPath::new("bench-accuracy");
    let run = fixstep(&["bench", "accuracy", "--quick", "--out", dir.str()]);
    assert_eq!(run.code, 0, "{run:?}");
    let csv = std::fs::read_to_string(dir.path().join("accuracy.csv")).expect("accuracy.csv");
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some("problem,integrator,format,dt,steps,error,seconds")
    );
    assert_eq!(
        AccuracyRow::CSV_HEADER,
        "problem,integrator,format,dt,steps,error,seconds"
    );
    let rows: Vec<Vec<&str>> = lines.map(|line| line.split(',').collect()).collect();
    let halvings = AccuracyConfig::quick().halvings as usize;
    assert!(halvings >= 6);
    assert_eq!(rows.len(), 5 * 7 * 4 * (halvings + 1));
    for row in &rows {
        assert_eq!(row.len(), 7, "{row:?}");
        let dt: f64 = row[3].parse().expect("dt");
        let steps: u64 = row[4].parse().expect("steps");
        let seconds: f64 = row[6].parse().expect("seconds");
        row[5].parse::<f64>().expect("error");
        assert!(dt > 0.0 && steps > 0 && seconds >= 0.0, "{row:?}");
    }
    let svg = std::fs::read_to_string(dir.path().join("work-precision.svg")).expect("svg");
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    for problem in Problem::ALL {
        assert!(svg.contains(problem.title()), "{} panel", problem.name());
    }
    assert!(run.stdout.starts_with("measured order p"), "{}", run.stdout);
    for integrator in Integrator::ALL {
        assert!(run.stdout.contains(integrator.name()), "{}", run.stdout);
    }
    // The 90° pendulum's period under semi-implicit Euler falls by 3.2 to 5.6 powers of dt
    // from one halving to the next: flagged with its reason, not printed as an order.
    let row = run
        .stdout
        .lines()
        .find(|line| line.starts_with("pendulum    SemiImplicitEuler"))
        .expect("the pendulum row");
    let f64_cell = row.split_whitespace().nth(3).expect("the f64 cell");
    assert_eq!(f64_cell, "untrusted", "{row}");
    assert!(
        run.stdout.lines().any(|line| line
            .contains("pendulum SemiImplicitEuler f64: untrusted: slopes between halvings")),
        "{}",
        run.stdout
    );
    // A clean order stays a result.
    let row = run
        .stdout
        .lines()
        .find(|line| line.starts_with("harmonic    VelocityVerlet"))
        .expect("the harmonic row");
    assert!(row.contains(" 2.00 ["), "{row}");
    let leftovers: Vec<_> = std::fs::read_dir(dir.path())
        .expect("read the output directory")
        .map(|entry| entry.expect("entry").file_name())
        .filter(|name| name.to_string_lossy().contains(".tmp-"))
        .collect();
    assert!(leftovers.is_empty(), "temporary files left: {leftovers:?}");
}

#[test]
fn out_naming_a_file_is_refused_with_exit_2() {
    let file = TempPath::with_bytes("not-a-dir", b"x");
    let run = fixstep(&["bench", "accuracy", "--quick", "--out", file.str()]);
    run.assert_error(&[file.str(), "not a directory"]);
}

#[test]
fn out_that_cannot_be_created_is_refused_with_exit_2() {
    let file = TempPath::with_bytes("blocker", b"x");
    let below = file.path().join("out");
    let below = below.to_str().expect("UTF-8");
    let run = fixstep(&["bench", "accuracy", "--quick", "--out", below]);
    run.assert_error(&[below, "cannot create"]);
}
