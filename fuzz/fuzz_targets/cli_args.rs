#![no_main]
//! Fuzz target: the `fixstep` command line, read and checked before any work
//! ([`fixstep_cli::read_command_line`]); see `fuzz/src/cli_args.rs`, whose check the tools'
//! tests also run over the seeds (the engine's test suite, which runs the other targets'
//! seeds, does not depend on the tool crates).

#[path = "../src/cli_args.rs"]
mod cli_args;

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| cli_args::check(data));
