//! The check of the fuzz target `cli_args`, shared with the tools' test of its seeds
//! (`tests/tools/cli_args_seeds.rs`): the bytes are a `fixstep` command line, its
//! arguments separated by NUL bytes (any other byte may appear in an argument, as on Unix),
//! and reading it ([`fixstep_cli::read_command_line`]: usage, counts, shapes, and whether
//! outputs clash with inputs) never panics and refuses with exactly one `error: ` line.

use std::ffi::OsString;
use std::os::unix::ffi::OsStringExt;

/// Reads `data` as a command line and checks the answer (module doc).
pub fn check(data: &[u8]) {
    let args: Vec<OsString> = std::iter::once(OsString::from("fixstep"))
        .chain(
            data.split(|&byte| byte == 0)
                .map(|arg| OsString::from_vec(arg.to_vec())),
        )
        .collect();
    if let Err(line) = fixstep_cli::read_command_line(&args) {
        assert!(
            line.starts_with("error: ") && !line.contains('\n'),
            "not one error line for {args:?}: {line:?}"
        );
    }
}
