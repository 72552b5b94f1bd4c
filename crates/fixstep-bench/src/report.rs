// ok-det: benchmark reporting (CSV text and printed tables of f64 results); never inside a tick.
//! The benchmarks' CSV files and printed tables.

use super::format::NumberFormat;
use super::order::OrderRow;
use super::stability::{Measured, StabilityRow, Theory};
use super::sweep::AccuracyRow;

/// `accuracy.csv`: the header and one line per row.
pub fn accuracy_csv(rows: &[AccuracyRow]) -> String {
    let mut csv = format!("{}\n", AccuracyRow::CSV_HEADER);
    for row in rows {
        csv.push_str(&row.csv_row());
        csv.push('\n');
    }
    csv
}

/// The measured orders as a table: one line per problem × integrator, one column per
/// format (in [`NumberFormat::ALL`] order). An order that cannot be trusted
/// ([`Distrust`](super::order::Distrust)) reads `untrusted (n)` and note n, after the
/// table, says why.
pub fn orders_table(orders: &[OrderRow]) -> Vec<String> {
    let mut lines = vec![
        "measured order p (slope of log error vs log dt; in brackets the fitted steps, dt = 2^-k s for k in a..b; - where rounding dominates every step; untrusted (n): see note n)".to_owned(),
        format!(
            "{:<11} {:<18} {:>8} {}",
            "problem",
            "integrator",
            "expected",
            format_columns(|format| format!("{:>15}", format.name()))
        ),
    ];
    let mut notes = Vec::new();
    for group in orders.chunk_by(|a, b| (a.problem, a.integrator) == (b.problem, b.integrator)) {
        let first = group[0];
        let cells = format_columns(|format| {
            let cell = match group.iter().find(|o| o.format == format) {
                Some(OrderRow {
                    measured: Some(m), ..
                }) => {
                    let fit = format!(
                        "{:.2} [{}..{}]",
                        m.order, m.coarsest_log2_inverse_step, m.finest_log2_inverse_step
                    );
                    match m.distrust {
                        None => fit,
                        Some(reason) => {
                            notes.push(format!(
                                "({}) {} {} {}: untrusted: {reason} (the fit gives {fit})",
                                notes.len() + 1,
                                first.problem.name(),
                                first.integrator.name(),
                                format.name()
                            ));
                            format!("untrusted ({})", notes.len())
                        }
                    }
                }
                Some(_) => "-".to_owned(),
                None => String::new(),
            };
            format!("{cell:>15}")
        });
        lines.push(format!(
            "{:<11} {:<18} {:>8} {cells}",
            first.problem.name(),
            first.integrator.name(),
            first.integrator.order()
        ));
    }
    lines.push(
        "expected: the order for forces of position only; with velocity-dependent forces \
         (damped, projectile) VelocityVerlet and Leapfrog are first order, and for the pendulum's \
         period SemiImplicitEuler and Leapfrog at least second order (docs/ACCURACY.md)"
            .to_owned(),
    );
    lines.extend(notes);
    lines
}

/// The error floor of each problem in each format: the smallest error of any integrator
/// at any step, with the integrator and step that reached it.
pub fn floors_table(rows: &[AccuracyRow]) -> Vec<String> {
    let mut lines = vec![
        "error floor (smallest error of any integrator at any step: error integrator dt)"
            .to_owned(),
        format!(
            "{:<11} {}",
            "problem",
            format_columns(|format| format!("{:>32}", format.name()))
        ),
    ];
    let mut problems: Vec<_> = rows.iter().map(|row| row.problem).collect();
    problems.dedup();
    for problem in problems {
        let cells = format_columns(|format| {
            let best = rows
                .iter()
                .filter(|r| r.problem == problem && r.format == format && r.error.is_finite())
                .min_by(|a, b| a.error.total_cmp(&b.error));
            let cell = best.map_or(String::new(), |r| {
                format!(
                    "{:.1e} {} 2^-{}",
                    r.error,
                    r.integrator.name(),
                    r.log2_inverse_step
                )
            });
            format!("{cell:>32}")
        });
        lines.push(format!("{:<11} {cells}", problem.name()));
    }
    lines
}

/// `stability.csv`: a header and one line per row. Limits are numbers, `none` (never
/// stable) or `>=4` (stable over the whole range); an unknown theory value is empty.
pub fn stability_csv(rows: &[StabilityRow]) -> String {
    let mut csv = "integrator,zeta,format,measured_limit,theory_limit\n".to_owned();
    for row in rows {
        csv.push_str(&format!(
            "{},{},{},{},{}\n",
            row.integrator.name(),
            row.damping_ratio,
            row.format.name(),
            measured_text(row.measured),
            theory_text(row.theory)
        ));
    }
    csv
}

/// The stability limits as a table: one line per integrator × ζ, the theory and the
/// measured limit in each format.
pub fn stability_table(rows: &[StabilityRow]) -> Vec<String> {
    let mut formats: Vec<NumberFormat> = rows.iter().map(|row| row.format).collect();
    formats.sort();
    formats.dedup();
    let mut header = format!("{:<18} {:>5} {:>8}", "integrator", "zeta", "theory");
    for format in &formats {
        header.push_str(&format!(" {:>8}", format.name()));
    }
    let mut lines = vec![
        "largest stable omega*h (measured: bisection to 1e-3; theory: linear stability)".to_owned(),
        header,
    ];
    for group in
        rows.chunk_by(|a, b| (a.integrator, a.damping_ratio) == (b.integrator, b.damping_ratio))
    {
        let mut line = format!(
            "{:<18} {:>5} {:>8}",
            group[0].integrator.name(),
            group[0].damping_ratio,
            theory_text(group[0].theory)
        );
        for format in &formats {
            let cell = group
                .iter()
                .find(|row| row.format == *format)
                .map_or(String::new(), |row| measured_text(row.measured));
            line.push_str(&format!(" {cell:>8}"));
        }
        lines.push(line);
    }
    lines
}

/// One cell per format of [`NumberFormat::ALL`], joined by spaces.
fn format_columns(mut cell: impl FnMut(NumberFormat) -> String) -> String {
    NumberFormat::ALL
        .iter()
        .map(|&format| cell(format))
        .collect::<Vec<_>>()
        .join(" ")
}

fn measured_text(measured: Measured) -> String {
    match measured {
        Measured::Limit(limit) => format!("{limit:.3}"),
        Measured::NeverStable => "none".to_owned(),
        Measured::AtLeast(limit) => format!(">={limit}"),
    }
}

fn theory_text(theory: Theory) -> String {
    match theory {
        Theory::Limit(limit) => format!("{limit:.3}"),
        Theory::NeverStable => "none".to_owned(),
        Theory::AlwaysStable => "any".to_owned(),
        Theory::Unknown => String::new(),
    }
}
