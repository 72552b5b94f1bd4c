//! `fixstep verify`: simulate each replay again and compare every checkpoint.
//!
//! With more than one thread (`--threads`, `FIXSTEP_THREADS`) and more than one file, the
//! files are verified side by side, one per worker, and each file's lines are printed once
//! all are done, in argument order: the output is the same at any thread count. The
//! largest files start first.

use std::path::Path;

use super::output::{eprint_line, print_line};
use super::progress::Progress;
use super::status::Status;
use super::warnings::{DIVERGENCE_CHECK_EVERY, health_warnings, warning_lines};
use fixstep::parallel::{Pool, map_collect};
use fixstep::replay::{Replay, ReplayError, ReplayErrorKind, VerifyOutcome, verify_reporting};
use fixstep::world::checksum::hex;

/// Verifies every file, reporting each; the status is the most severe of them.
pub fn verify_files(files: &[impl AsRef<Path> + Sync]) -> Result<Status, String> {
    let pool = Pool::process_default();
    let mut status = Status::Ok;
    if pool.threads() == 1 || files.len() == 1 {
        for file in files {
            let report = verify_file(file.as_ref(), true);
            status = status.max(report.print()?);
        }
    } else {
        // The largest files (the longest runs, roughly) start first, so that no long run
        // starts last and keeps one worker busy alone; the reports go back in argument order.
        let size = |i: usize| std::fs::metadata(files[i].as_ref()).map_or(0, |m| m.len());
        let mut order: Vec<usize> = (0..files.len()).collect();
        order.sort_by_key(|&i| (std::cmp::Reverse(size(i)), i));
        let done = pool.run(|| {
            map_collect(order.len(), 1, |k| {
                verify_file(files[order[k]].as_ref(), false)
            })
        });
        let mut reports: Vec<Option<Report>> = (0..files.len()).map(|_| None).collect();
        for (report, &i) in done.into_iter().zip(&order) {
            reports[i] = Some(report);
        }
        for report in reports.into_iter().flatten() {
            status = status.max(report.print()?);
        }
    }
    Ok(status)
}

/// What verifying one file has to say: lines for standard error (warnings, errors) and
/// standard output, and its status.
struct Report {
    warnings: Vec<String>,
    result: Option<String>,
    error: Option<String>,
    status: Status,
}

impl Report {
    /// Prints the report (warnings, then the result line or the error) and returns its
    /// status.
    fn print(self) -> Result<Status, String> {
        for line in &self.warnings {
            eprint_line(line);
        }
        if let Some(line) = &self.result {
            print_line(line)?;
        }
        if let Some(line) = &self.error {
            eprint_line(line);
        }
        Ok(self.status)
    }
}

/// Verifies one file: `ok FILE TICKS CHECKSUM`, a desync line, or an error on stderr; with a
/// progress bar when `progress` (and standard error is a terminal).
fn verify_file(path: &Path, progress: bool) -> Report {
    let name = path.display();
    let outcome = Replay::read(path).and_then(|replay| {
        let mut bar = progress.then(|| Progress::new(replay.ticks()));
        let outcome = verify_reporting(&replay, DIVERGENCE_CHECK_EVERY, |done| {
            if let Some(bar) = &mut bar {
                bar.update(done);
            }
        });
        if let Some(bar) = &mut bar {
            bar.finish();
        }
        outcome
            .map_err(|e| ReplayError::new(name.to_string(), ReplayErrorKind::Scene(e.to_string())))
    });
    let mut report = Report {
        warnings: Vec::new(),
        result: None,
        error: None,
        status: Status::Ok,
    };
    if let Ok((_, world)) = &outcome {
        let about = Some(name.to_string());
        report
            .warnings
            .extend(warning_lines(about.as_deref(), world.warnings()));
        report.warnings.extend(warning_lines(
            about.as_deref(),
            health_warnings(&world.health()),
        ));
    }
    match outcome.map(|(outcome, _)| outcome) {
        Ok(VerifyOutcome::Ok { ticks, checksum }) => {
            report.result = Some(format!("ok {name} {ticks} {}", hex(checksum)));
        }
        Ok(VerifyOutcome::Desync {
            tick,
            expected,
            got,
            part,
            first_differing_id,
        }) => {
            let part = part.map_or("unknown", |p| p.name());
            let id = first_differing_id.unwrap_or_else(|| "unknown".to_owned());
            let altered = if expected == got {
                "; the totals agree, so the recorded checkpoint was altered"
            } else {
                ""
            };
            report.result = Some(format!(
                "desync {name} at tick {tick}: expected {} got {} (subsystem {part}, first \
                 differing id {id}{altered})",
                hex(expected),
                hex(got)
            ));
            report.status = Status::Desync;
        }
        Err(error) => {
            report.error = Some(format!("error: {error}"));
            report.status = Status::Invalid;
        }
    }
    report
}
