// ok-det: benchmark analysis in f64 (slopes of measured errors); never inside a tick.
//! Measured orders of convergence: the slope of log error against log step, over the
//! steps where truncation error, not rounding, makes up the error.
//!
//! # Which steps count
//!
//! A point counts when its rounding error is below [`ROUNDING_FRACTION`] of its total
//! error. The rounding error of a fixed-point run is measured, not guessed: it is the
//! distance between its answer and the f64 run's answer at the same step (both make the
//! same truncation error; f64's own rounding is negligible next to a fixed-point ulp). The
//! rounding of an f64 run is bounded instead, with ε = 2⁻⁵² and n steps, assuming every step
//! loses an ulp of the answer in the same direction: one-step schemes carry such an error
//! forward as a position error, n·ε·max(1, |answer|) in all; Störmer–Verlet's two-step
//! form x_{n+1} = 2x_n − x_{n−1} + h²a turns it into a velocity error δ/h that keeps moving
//! the particle for the remaining steps, n²·ε·max(1, |answer|) in all.
//!
//! Among the points that count, the order is the least-squares slope over the finest
//! [`FIT_POINTS`] consecutive ones (the coarsest steps can still be outside the asymptotic
//! range, as explicit Euler on the Kepler orbit is).
//!
//! # Which orders are trusted
//!
//! A slope is a result only when the data show one power of the step: at least
//! [`MIN_TRUSTED_POINTS`] points, an error that falls at every halving, and slopes between
//! neighbouring points within [`MAX_SLOPE_SPREAD`] of each other. Otherwise the order is
//! [`Distrust`]ed, with the reason (the period of semi-implicit Euler on the 90° pendulum,
//! whose h² term cancels, gives slopes from 3.2 to 5.6 between halvings; RK4 in I32F32
//! reaches the rounding floor after two points).

use super::format::NumberFormat;
use super::problems::Problem;
use super::sweep::AccuracyRow;
use fixstep::particles::Integrator;

/// A point counts when its rounding error is at most this fraction of its error (5 %:
/// then rounding moves the slope between two counted points by at most
/// log₂(1.05/0.95) ≈ 0.14).
pub const ROUNDING_FRACTION: f64 = 0.05;

/// The slope is fitted over at most this many consecutive points (three halvings).
pub const FIT_POINTS: usize = 4;

/// A fit over fewer points than this is not trusted.
pub const MIN_TRUSTED_POINTS: usize = 3;

/// A fit whose slopes between neighbouring points differ by more than this is not trusted:
/// twice the most rounding may move one slope (0.14, see [`ROUNDING_FRACTION`]), and a
/// margin.
pub const MAX_SLOPE_SPREAD: f64 = 0.3;

/// Why a measured slope is not a trustworthy order of convergence.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Distrust {
    /// Fewer than [`MIN_TRUSTED_POINTS`] consecutive steps had an error clear of rounding.
    TooFewPoints(usize),
    /// The error did not fall when the step was halved to 2^−k s: the rounding floor.
    ErrorStopsFalling {
        /// k of the finer step.
        log2_inverse_step: u32,
    },
    /// The slopes between neighbouring points disagree: the error is not one power of the
    /// step there.
    ScatteredSlopes {
        /// The least slope between two neighbouring points.
        least: f64,
        /// The greatest.
        greatest: f64,
    },
}

impl core::fmt::Display for Distrust {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::TooFewPoints(n) => write!(
                f,
                "only {n} steps clear of rounding (at least {MIN_TRUSTED_POINTS} needed)"
            ),
            Self::ErrorStopsFalling { log2_inverse_step } => write!(
                f,
                "the error stops falling at dt = 2^-{log2_inverse_step} s (rounding floor)"
            ),
            Self::ScatteredSlopes { least, greatest } => write!(
                f,
                "slopes between halvings range from {least:.2} to {greatest:.2}, not one power \
                 of dt"
            ),
        }
    }
}

/// A measured order and the steps it was measured over (h = 2^−k s).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeasuredOrder {
    /// Slope of log error against log h.
    pub order: f64,
    /// k of the coarsest step in the fit.
    pub coarsest_log2_inverse_step: u32,
    /// k of the finest step in the fit.
    pub finest_log2_inverse_step: u32,
    /// Why the slope is not a trustworthy order, if it is not.
    pub distrust: Option<Distrust>,
}

/// The measured order of one problem × integrator × format, if at least two consecutive
/// points were free of rounding.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrderRow {
    /// The problem.
    pub problem: Problem,
    /// The scheme.
    pub integrator: Integrator,
    /// The number format.
    pub format: NumberFormat,
    /// The order, or `None` when rounding dominates everywhere.
    pub measured: Option<MeasuredOrder>,
}

/// The measured order of every problem × integrator × format in `rows` (as produced by
/// [`run_accuracy`](super::run_accuracy)), in the rows' order.
pub fn measured_orders(rows: &[AccuracyRow]) -> Vec<OrderRow> {
    rows.chunk_by(|a, b| (a.problem, a.integrator, a.format) == (b.problem, b.integrator, b.format))
        .map(|group| {
            let counted: Vec<bool> = group
                .iter()
                .map(|row| {
                    let rounding = rounding_error(row, rows);
                    row.error.is_finite()
                        && row.error > 0.0
                        && rounding <= ROUNDING_FRACTION * row.error
                })
                .collect();
            OrderRow {
                problem: group[0].problem,
                integrator: group[0].integrator,
                format: group[0].format,
                measured: fit(group, &counted),
            }
        })
        .collect()
}

/// The rounding part of `row`'s error: its distance from the f64 run at the same step, or
/// for f64 itself (or without an f64 run) the bound of the module documentation.
fn rounding_error(row: &AccuracyRow, rows: &[AccuracyRow]) -> f64 {
    let magnitude = row.observable.iter().map(|x| x * x).sum::<f64>().sqrt();
    let steps = row.steps as f64;
    let propagation = match row.integrator {
        Integrator::StormerVerlet => steps * steps,
        _ => steps,
    };
    let bound = propagation * row.format.epsilon() * magnitude.max(1.0);
    if row.format == NumberFormat::F64 {
        return bound;
    }
    rows.iter()
        .find(|r| {
            r.format == NumberFormat::F64
                && (r.problem, r.integrator, r.log2_inverse_step)
                    == (row.problem, row.integrator, row.log2_inverse_step)
        })
        .map_or(bound, |reference| {
            row.observable
                .iter()
                .zip(reference.observable)
                .map(|(a, b)| (a - b).powi(2))
                .sum::<f64>()
                .sqrt()
        })
}

/// The least-squares slope of ln error against ln h over the finest [`FIT_POINTS`] points
/// of the finest run of at least two consecutive counted points, and whether to trust it.
fn fit(group: &[AccuracyRow], counted: &[bool]) -> Option<MeasuredOrder> {
    let finest = counted.windows(2).rposition(|pair| pair[0] && pair[1])? + 1;
    let mut first = finest;
    while first > 0 && counted[first - 1] && finest - (first - 1) < FIT_POINTS {
        first -= 1;
    }
    let points: Vec<(f64, f64)> = group[first..=finest]
        .iter()
        .map(|row| (row.dt.ln(), row.error.ln()))
        .collect();
    let n = points.len() as f64;
    let mean_x = points.iter().map(|p| p.0).sum::<f64>() / n;
    let mean_y = points.iter().map(|p| p.1).sum::<f64>() / n;
    let covariance: f64 = points.iter().map(|p| (p.0 - mean_x) * (p.1 - mean_y)).sum();
    let variance: f64 = points.iter().map(|p| (p.0 - mean_x).powi(2)).sum();
    Some(MeasuredOrder {
        order: covariance / variance,
        coarsest_log2_inverse_step: group[first].log2_inverse_step,
        finest_log2_inverse_step: group[finest].log2_inverse_step,
        distrust: distrust(&group[first..=finest], &points),
    })
}

/// Why the fit over `rows` (ln h, ln error in `points`) is not to be trusted, if it is not;
/// the reasons are tried in the order of [`Distrust`]'s variants.
fn distrust(rows: &[AccuracyRow], points: &[(f64, f64)]) -> Option<Distrust> {
    if points.len() < MIN_TRUSTED_POINTS {
        return Some(Distrust::TooFewPoints(points.len()));
    }
    let slopes: Vec<f64> = points
        .windows(2)
        .map(|p| (p[1].1 - p[0].1) / (p[1].0 - p[0].0))
        .collect();
    if let Some(i) = slopes.iter().position(|&slope| slope <= 0.0) {
        return Some(Distrust::ErrorStopsFalling {
            log2_inverse_step: rows[i + 1].log2_inverse_step,
        });
    }
    let least = slopes.iter().copied().fold(f64::INFINITY, f64::min);
    let greatest = slopes.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    (greatest - least > MAX_SLOPE_SPREAD).then_some(Distrust::ScatteredSlopes { least, greatest })
}
