//! `fixstep bench stability`: the measured stability limits against linear-stability
//! theory.
//!
//! Theory values: `harmonic_oscillator_discrete_amplification.csv` (undamped: ωh < 2 for
//! semi-implicit Euler, Störmer–Verlet, velocity Verlet and leapfrog, ωh < 2√2 for RK4,
//! explicit Euler never stable; implicit Euler, A-stable, at every ωh, derived) and `damped_spring_stability_limits.csv` (ζ = 0.1:
//! `sympEuler_analytic` 1.80997512422418, `fwdEuler_analytic` 0.2), both computed with
//! mpmath in the project's reference folder.

use crate::replay_support::{TempPath, fixstep};
use fixstep::particles::Integrator;
use fixstep_bench::stability::{HIGHEST, is_stable_in};
use fixstep_bench::{Measured, NumberFormat, StabilityConfig, StabilityRow, run_stability};

/// The measured limit of the only row of `rows` for `integrator` in `format`.
fn limit(rows: &[StabilityRow], integrator: Integrator, format: NumberFormat) -> Measured {
    rows.iter()
        .find(|r| r.integrator == integrator && r.format == format)
        .expect("measured")
        .measured
}

fn assert_limit(measured: Measured, theory: f64, what: &str) {
    match measured {
        Measured::Limit(got) => assert!(
            (got - theory).abs() <= 1e-2,
            "{what}: measured {got}, theory {theory}"
        ),
        other => panic!("{what}: measured {other:?}, theory {theory}"),
    }
}

#[test]
fn undamped_limits_match_theory() {
    let formats = if cfg!(debug_assertions) {
        vec![NumberFormat::F64]
    } else {
        vec![NumberFormat::F64, NumberFormat::I32F32]
    };
    let rows = run_stability(&StabilityConfig {
        integrators: Integrator::ALL.to_vec(),
        damping_ratios: vec![0.0],
        formats: formats.clone(),
    });
    for format in formats {
        for integrator in Integrator::ALL {
            let measured = limit(&rows, integrator, format);
            let what = format!("{integrator} in {}", format.name());
            match integrator {
                Integrator::ExplicitEuler => {
                    assert_eq!(measured, Measured::NeverStable, "{what}");
                }
                Integrator::Rk4 => assert_limit(measured, 2.0 * core::f64::consts::SQRT_2, &what),
                Integrator::ImplicitEuler => {
                    assert_eq!(measured, Measured::AtLeast(HIGHEST), "{what}");
                }
                _ => assert_limit(measured, 2.0, &what),
            }
        }
    }
}

/// Explicit Euler grows by (1 + (ωh)²)^{1/2} per step: unstable at every ωh, not only at
/// the bisection's lowest probe.
#[test]
fn undamped_explicit_euler_is_unstable_everywhere() {
    for omega_h in [1e-3, 0.01, 0.1, 0.5, 1.0, 1.9] {
        assert!(
            !is_stable_in(NumberFormat::F64, Integrator::ExplicitEuler, 0.0, omega_h),
            "ωh = {omega_h}"
        );
    }
}

#[test]
fn damped_limits_match_the_reference_table() {
    let rows = run_stability(&StabilityConfig {
        integrators: vec![Integrator::ExplicitEuler, Integrator::SemiImplicitEuler],
        damping_ratios: vec![0.1],
        formats: vec![NumberFormat::F64],
    });
    let f64 = NumberFormat::F64;
    assert_limit(
        limit(&rows, Integrator::SemiImplicitEuler, f64),
        1.80997512422418,
        "semi-implicit Euler, ζ = 0.1",
    );
    assert_limit(
        limit(&rows, Integrator::ExplicitEuler, f64),
        0.2,
        "explicit Euler, ζ = 0.1",
    );
}

#[test]
fn out_naming_a_file_is_refused_with_exit_2() {
    let file = TempPath::with_bytes("stability-out", b"x");
    let run = fixstep(&["bench", "stability", "--out", file.str()]);
    run.assert_error(&[file.str(), "not a directory"]);
}
