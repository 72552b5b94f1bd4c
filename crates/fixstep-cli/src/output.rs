//! Writing to standard output and standard error without panicking.
//!
//! `println!` panics when standard output is closed (`fixstep scenes | head -1`); these
//! return an error instead, which the command reports.

use std::io::Write;
use std::path::Path;

/// Writes `line` and a newline to standard output.
pub fn print_line(line: &str) -> Result<(), String> {
    let mut out = std::io::stdout().lock();
    writeln!(out, "{line}")
        .and_then(|()| out.flush())
        .map_err(|e| format!("cannot write to standard output: {e}"))
}

/// Writes `text` as it is to standard output (help pages); errors are ignored, since the
/// text is all the command had to say.
pub fn print_text(text: &str) {
    let mut out = std::io::stdout().lock();
    let _ = out.write_all(text.as_bytes()).and_then(|()| out.flush());
}

/// Writes `line` and a newline to standard error; errors are ignored, since there is
/// nowhere left to report them.
pub fn eprint_line(line: &str) {
    let _ = writeln!(std::io::stderr().lock(), "{line}");
}

/// The message for a failed write to `path`.
pub fn write_error(path: &Path, error: &std::io::Error) -> String {
    format!("{}: cannot write: {error}", path.display())
}
