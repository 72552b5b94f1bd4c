//! `fixstep rerecord`: record replays again with this build and rewrite them in place.

use std::path::Path;

use super::output::{eprint_line, print_line};
use super::output_file::OutputFile;
use super::status::Status;
use fixstep::replay::{Replay, StateVersionCheck, rerecord};
use fixstep::world::STATE_VERSION;
use fixstep::world::checksum::hex;

/// Re-records every file, reporting each; the status is the most severe of them.
pub fn rerecord_files(files: &[impl AsRef<Path>]) -> Result<Status, String> {
    let mut status = Status::Ok;
    for file in files {
        status = status.max(rerecord_file(file.as_ref())?);
    }
    Ok(status)
}

/// Re-records one file: `rerecorded FILE TICKS CHECKSUM`, noting what changed, or an
/// error on stderr.
fn rerecord_file(path: &Path) -> Result<Status, String> {
    let name = path.display();
    let result = Replay::read_with(path, StateVersionCheck::CurrentOrOlder)
        .map_err(|e| e.to_string())
        .and_then(|old| {
            let new = rerecord(&old).map_err(|e| format!("{name}: scene section: {e}"))?;
            let bytes = new
                .to_bytes()
                .map_err(|e| format!("{name}: cannot encode the replay: {e}"))?;
            OutputFile::write(path, &bytes)?;
            Ok((old, new))
        });
    match result {
        Ok((old, new)) => {
            let mut line = format!(
                "rerecorded {name} {} {}",
                new.ticks(),
                hex(new.final_checksum())
            );
            if old.state_version() != STATE_VERSION {
                line += &format!(
                    " (state version {} -> {STATE_VERSION})",
                    old.state_version()
                );
            }
            if old.final_checksum() != new.final_checksum() {
                line += &format!(" (was {})", hex(old.final_checksum()));
            }
            print_line(&line)?;
            Ok(Status::Ok)
        }
        Err(message) => {
            eprint_line(&format!("error: {message}"));
            Ok(Status::Invalid)
        }
    }
}
