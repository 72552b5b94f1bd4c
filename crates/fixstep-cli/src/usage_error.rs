//! clap's usage errors as one `error:` line: the error, and its tip if it has one (clap
//! prints a usage block after it; a missing subcommand gets the help page and no `error:`
//! line at all).

use clap::CommandFactory;
use clap::error::ErrorKind;

use super::args::Cli;

/// The one line that reports `error`, a usage error in the command line `args` (program name
/// first).
pub fn usage_error_line(error: &clap::Error, args: &[std::ffi::OsString]) -> String {
    if error.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
        return missing_subcommand_line(args);
    }
    let rendered = error.render().to_string();
    let mut lines = rendered.lines().map(str::trim).filter(|l| !l.is_empty());
    let first = lines.next().unwrap_or("error: bad command line");
    let mut line = if first.starts_with("error:") {
        first.to_owned()
    } else {
        format!("error: {first}")
    };
    // A first line ending in `:` (such as a missing required argument's) is followed by
    // what it names, up to the usage block.
    if line.ends_with(':') {
        let named: Vec<&str> = rendered
            .lines()
            .skip(1)
            .map(str::trim)
            .take_while(|l| !l.is_empty() && !l.starts_with("Usage:"))
            .collect();
        if !named.is_empty() {
            line = format!("{line} {}", named.join(", "));
        }
    }
    for tip in lines.filter(|l| l.starts_with("tip:")) {
        line += &format!(" ({tip})");
    }
    line
}

/// `error: `fixstep bench` needs one of: accuracy, stability`: the deepest subcommand the
/// arguments name, and its subcommands.
fn missing_subcommand_line(args: &[std::ffi::OsString]) -> String {
    let mut command = Cli::command();
    let mut path = vec![command.get_name().to_owned()];
    for arg in args.iter().skip(1) {
        let Some(sub) = arg
            .to_str()
            .and_then(|name| command.find_subcommand(name))
            .cloned()
        else {
            break;
        };
        path.push(sub.get_name().to_owned());
        command = sub;
    }
    let names: Vec<&str> = command
        .get_subcommands()
        .filter(|s| !s.is_hide_set())
        .map(|s| s.get_name())
        .filter(|name| *name != "help")
        .collect();
    format!(
        "error: `{}` needs one of: {} (see `{} --help`)",
        path.join(" "),
        names.join(", "),
        path.join(" ")
    )
}
