//! The per-stage timing table `fixstep run` prints.

use fixstep::world::StageTimings;

/// One line per stage that ran: name, total milliseconds, microseconds per run, runs.
pub fn timing_table(timings: &StageTimings) -> Vec<String> {
    let mut lines = vec![format!(
        "{:<14} {:>12} {:>12} {:>10}",
        "stage", "total ms", "µs per run", "runs"
    )];
    for (stage, total, runs) in timings.rows() {
        let seconds = total.as_secs_f64();
        let per_run = if runs == 0 {
            0.0
        } else {
            seconds * 1e6 / runs as f64
        };
        lines.push(format!(
            "{:<14} {:>12.3} {:>12.3} {:>10}",
            stage.name(),
            seconds * 1e3,
            per_run,
            runs
        ));
    }
    lines
}
