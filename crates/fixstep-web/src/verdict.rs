//! A replay's bytes simulated again: `ok`, or the first desync, or why the bytes are no
//! replay (naming the section and the byte offset).

use fixstep::replay::{Replay, VerifyOutcome, verify};
use fixstep::world::checksum::hex;

/// What verifying a replay found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Verdict {
    /// `ok` when every checkpoint matched, `desync` otherwise.
    pub verdict: String,
    /// The ticks simulated (ok), or the tick of the first checkpoint that differs (desync).
    pub tick: u64,
    /// The subsystem whose sub-checksum differs first (`rigid`, `soft`, …; `unknown` when
    /// none does); empty when ok.
    pub subsystem: String,
    /// The first object whose digest differs, such as `2v0` (slot 2, generation 0);
    /// `unknown` when none does; empty when ok.
    pub object: String,
    /// The final checksum (ok) or the recorded one (desync), 16 hex digits.
    pub expected: String,
    /// The checksum this build computed, 16 hex digits.
    pub got: String,
    /// The line `fixstep verify` prints, with `origin` for the file.
    pub line: String,
}

/// Verifies the replay file `bytes`; `origin` names it in the messages. Bad bytes give the
/// message `fixstep verify` prints (`ORIGIN: checksums section: ... at byte 1234`).
pub fn verify_bytes(bytes: &[u8], origin: &str) -> Result<Verdict, String> {
    let replay = Replay::from_bytes(bytes, origin).map_err(|e| e.to_string())?;
    let outcome = verify(&replay).map_err(|e| format!("{origin}: {e}"))?;
    Ok(match outcome {
        VerifyOutcome::Ok { ticks, checksum } => Verdict {
            verdict: "ok".to_owned(),
            tick: ticks,
            subsystem: String::new(),
            object: String::new(),
            expected: hex(checksum),
            got: hex(checksum),
            line: format!("ok {origin} {ticks} {}", hex(checksum)),
        },
        VerifyOutcome::Desync {
            tick,
            expected,
            got,
            part,
            first_differing_id,
        } => {
            let subsystem = part.map_or("unknown", |p| p.name()).to_owned();
            let object = first_differing_id.unwrap_or_else(|| "unknown".to_owned());
            Verdict {
                line: format!(
                    "desync {origin} at tick {tick}: expected {} got {} (subsystem {subsystem}, \
                     first differing id {object})",
                    hex(expected),
                    hex(got)
                ),
                verdict: "desync".to_owned(),
                tick,
                subsystem,
                object,
                expected: hex(expected),
                got: hex(got),
            }
        }
    })
}
