//! `fixstep verify`: simulate each replay again and compare every checkpoint.

use std::path::Path;

use super::output::{eprint_line, print_line};
use super::progress::Progress;
use super::status::Status;
use super::warnings::{DIVERGENCE_CHECK_EVERY, health_warnings, print_warnings};
use fixstep::replay::{Replay, ReplayError, ReplayErrorKind, VerifyOutcome, verify_reporting};
use fixstep::world::checksum::hex;

/// Verifies every file, reporting each; the status is the most severe of them.
pub fn verify_files(files: &[impl AsRef<Path>]) -> Result<Status, String> {
    let mut status = Status::Ok;
    for file in files {
        status = status.max(verify_file(file.as_ref())?);
    }
    Ok(status)
}

/// Verifies one file: `ok FILE TICKS CHECKSUM`, a desync line, or an error on stderr.
fn verify_file(path: &Path) -> Result<Status, String> {
    let name = path.display();
    let outcome = Replay::read(path).and_then(|replay| {
        let mut progress = Progress::new(replay.ticks());
        let outcome = verify_reporting(&replay, DIVERGENCE_CHECK_EVERY, |done| {
            progress.update(done)
        });
        progress.finish();
        outcome
            .map_err(|e| ReplayError::new(name.to_string(), ReplayErrorKind::Scene(e.to_string())))
    });
    if let Ok((_, world)) = &outcome {
        let about = Some(name.to_string());
        print_warnings(about.as_deref(), world.warnings());
        print_warnings(about.as_deref(), health_warnings(&world.health()));
    }
    match outcome.map(|(outcome, _)| outcome) {
        Ok(VerifyOutcome::Ok { ticks, checksum }) => {
            print_line(&format!("ok {name} {ticks} {}", hex(checksum)))?;
            Ok(Status::Ok)
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
            print_line(&format!(
                "desync {name} at tick {tick}: expected {} got {} (subsystem {part}, first \
                 differing id {id}{altered})",
                hex(expected),
                hex(got)
            ))?;
            Ok(Status::Desync)
        }
        Err(error) => {
            eprint_line(&format!("error: {error}"));
            Ok(Status::Invalid)
        }
    }
}
