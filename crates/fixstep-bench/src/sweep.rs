// ok-det: benchmark driver; it times runs with the wall clock and reports errors as f64, never inside a tick.
//! The accuracy sweep: every problem × integrator × number format × step, each run timed.

use std::time::Instant;

use super::format::NumberFormat;
use super::problems::{Outcome, Problem};
use fixstep::math::{Fx, FxI40F24, FxI48F16};
use fixstep::particles::Integrator;

/// How much of the sweep to run.
#[derive(Clone, Debug, PartialEq)]
pub struct AccuracyConfig {
    /// Problems, in report order.
    pub problems: Vec<Problem>,
    /// Integrators, in report order.
    pub integrators: Vec<Integrator>,
    /// Number formats. The rounding estimate of a fixed-point run needs the f64 run at the
    /// same step, so include [`NumberFormat::F64`] to get measured orders for them.
    pub formats: Vec<NumberFormat>,
    /// Halvings of the step after each problem's coarsest one (halvings + 1 steps in all).
    pub halvings: u32,
    /// Runs per point; the reported time is the fastest.
    pub repeats: u32,
}

impl AccuracyConfig {
    /// The number of points the sweep measures: one per problem, integrator, format and
    /// step.
    pub fn points(&self) -> usize {
        self.problems.len()
            * self.integrators.len()
            * self.formats.len()
            * (self.halvings as usize + 1)
    }

    /// Everything, 8 halvings, one run per point: a few seconds in release.
    pub fn quick() -> Self {
        Self {
            halvings: 8,
            repeats: 1,
            ..Self::full()
        }
    }

    /// Everything, 12 halvings (down to 2⁻¹⁴ s, 2⁻¹⁶ s for Kepler and the pendulum, the
    /// finest step I48F16 can represent), fastest of 3 runs per point.
    pub fn full() -> Self {
        Self {
            problems: Problem::ALL.to_vec(),
            integrators: Integrator::ALL.to_vec(),
            formats: NumberFormat::ALL.to_vec(),
            halvings: 12,
            repeats: 3,
        }
    }
}

/// One point of the sweep: one row of `accuracy.csv`.
#[derive(Clone, Debug, PartialEq)]
pub struct AccuracyRow {
    /// The problem.
    pub problem: Problem,
    /// The scheme.
    pub integrator: Integrator,
    /// The number format.
    pub format: NumberFormat,
    /// The step is h = 2^−k s for this k.
    pub log2_inverse_step: u32,
    /// The step h, s.
    pub dt: f64,
    /// Steps taken.
    pub steps: u64,
    /// Error against the exact solution (m, or s for the pendulum).
    pub error: f64,
    /// Wall time of the fastest run, s.
    pub seconds: f64,
    /// The measured quantity (see [`Outcome::observable`]).
    pub observable: [f64; 3],
}

impl AccuracyRow {
    /// The CSV header of `accuracy.csv`.
    pub const CSV_HEADER: &'static str = "problem,integrator,format,dt,steps,error,seconds";

    /// The row as CSV, matching [`Self::CSV_HEADER`].
    pub fn csv_row(&self) -> String {
        format!(
            "{},{},{},{:e},{},{:.6e},{:.6e}",
            self.problem.name(),
            self.integrator.name(),
            self.format.name(),
            self.dt,
            self.steps,
            self.error,
            self.seconds
        )
    }
}

/// Runs the sweep. Rows come grouped by problem, then integrator, then format (in the
/// config's orders), each group from the coarsest step to the finest.
pub fn run_accuracy(config: &AccuracyConfig) -> Vec<AccuracyRow> {
    run_accuracy_with_progress(config, |_| {})
}

/// [`run_accuracy`], calling `on_point` with the number of points measured after each one
/// (of [`AccuracyConfig::points`]), to show progress.
pub fn run_accuracy_with_progress(
    config: &AccuracyConfig,
    mut on_point: impl FnMut(usize),
) -> Vec<AccuracyRow> {
    let mut rows = Vec::new();
    for &problem in &config.problems {
        let coarsest = problem.coarsest_log2_inverse_step();
        for &integrator in &config.integrators {
            for &format in &config.formats {
                for k in coarsest..=coarsest + config.halvings {
                    rows.push(measure(problem, integrator, format, k, config.repeats));
                    on_point(rows.len());
                }
            }
        }
    }
    rows
}

/// Runs one point `repeats` times (at least once) and keeps the fastest time.
fn measure(
    problem: Problem,
    integrator: Integrator,
    format: NumberFormat,
    log2_inverse_step: u32,
    repeats: u32,
) -> AccuracyRow {
    let mut fastest = f64::INFINITY;
    let mut outcome = None;
    for _ in 0..repeats.max(1) {
        let started = Instant::now(); // ok-det: wall time is reported, never simulated
        let result = run_in(format, problem, integrator, log2_inverse_step);
        fastest = fastest.min(started.elapsed().as_secs_f64());
        outcome = Some(result);
    }
    let outcome = outcome.expect("at least one run");
    AccuracyRow {
        problem,
        integrator,
        format,
        log2_inverse_step,
        dt: 1.0 / (1u64 << log2_inverse_step) as f64,
        steps: outcome.steps,
        error: outcome.error,
        seconds: fastest,
        observable: outcome.observable,
    }
}

/// [`Problem::run`] in the scalar type `format` stands for.
fn run_in(
    format: NumberFormat,
    problem: Problem,
    integrator: Integrator,
    log2_inverse_step: u32,
) -> Outcome {
    match format {
        NumberFormat::F64 => problem.run::<f64>(integrator, log2_inverse_step),
        NumberFormat::I32F32 => problem.run::<Fx>(integrator, log2_inverse_step),
        NumberFormat::I40F24 => problem.run::<FxI40F24>(integrator, log2_inverse_step),
        NumberFormat::I48F16 => problem.run::<FxI48F16>(integrator, log2_inverse_step),
    }
}
