//! Verify replay files with the engine alone: simulate each again and compare every
//! checkpoint, as `fixstep verify` does, with the same one line per file:
//! `ok FILE TICKS CHECKSUM`, or `desync FILE at tick T: expected E got G`.
//!
//! Run it: `cargo run --release --example verify_replays -- replays/*.replay`
//!
//! The determinism matrix (`scripts/determinism-matrix.sh`) runs it on every target: it
//! links the engine and nothing of the tools (no renderer, plotter or command-line
//! parser), so a target builds in a fraction of the `fixstep` command's time. Exit status
//! 0 when every file verifies, 1 on a desync, 2 when a file cannot be read.

use std::path::Path;
use std::process::ExitCode;

use fixstep::replay::{Replay, VerifyOutcome, verify};
use fixstep::world::checksum::hex;

fn main() -> ExitCode {
    let mut status = 0;
    for path in std::env::args().skip(1) {
        let outcome = Replay::read(Path::new(&path))
            .map_err(|e| e.to_string())
            .and_then(|replay| verify(&replay).map_err(|e| format!("{path}: {e}")));
        match outcome {
            Ok(VerifyOutcome::Ok { ticks, checksum }) => {
                println!("ok {path} {ticks} {}", hex(checksum));
            }
            Ok(VerifyOutcome::Desync {
                tick,
                expected,
                got,
                ..
            }) => {
                println!(
                    "desync {path} at tick {tick}: expected {} got {}",
                    hex(expected),
                    hex(got)
                );
                status = status.max(1);
            }
            Err(error) => {
                eprintln!("error: {error}");
                status = 2;
            }
        }
    }
    ExitCode::from(status)
}
