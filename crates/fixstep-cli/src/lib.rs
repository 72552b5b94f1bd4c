//! The `fixstep` command line (one file per subcommand).
//!
//! ```text
//! fixstep                      same as `fixstep run showcase`
//! fixstep scenes               built-in scenes, `NAME  description` per line
//! fixstep run SCENE|FILE.ron [--ticks N] [--seed S] [--record OUT.replay]
//!                            [--metrics OUT.csv] [--bodies OUT.csv] [--events OUT.csv]
//!                            [--every K] [--snapshot OUT.snapshot]
//!                            [--from-snapshot IN.snapshot]
//! fixstep verify FILE.replay...
//! fixstep info FILE.replay
//! fixstep rerecord FILE.replay...
//! fixstep render REPLAY|SCENE [--ticks N] [--out DIR] [--every K]
//!                            [--view iso|front|top] [--size WxH] [--flat]
//! fixstep render REPLAY|SCENE --html PAGE.html [--ticks N] [--web URL]
//! fixstep query SCENE|FILE.ron|FILE.replay [--tick N] [--max D] [--mask M]
//!              (--ray OX,OY,OZ,DX,DY,DZ | --cast SHAPE --from X,Y,Z --dir DX,DY,DZ
//!               | --overlap SHAPE --at X,Y,Z)
//!              SHAPE: sphere:R | box:HX,HY,HZ | capsule:R,H (H: half height)
//! fixstep peer --local-port P --remote ADDR [--remote ADDR...] [--player-index I]
//!              [--scene S] [--ticks T] [--lockstep | --rollback] [--record OUT.replay]
//!              [--bot SEED | --inputs FILE.ron] [--desync-every N] [--timeout SECONDS]
//! fixstep bench accuracy [--out DIR] [--quick]
//! fixstep bench stability [--out DIR]
//! ```
//!
//! Exit status: 0 success; 1 a replay or a peer desynchronised; 2 a bad argument, an unreadable or
//! invalid input, an output that is also an input or another output, or a failed write;
//! 130 or 143 when SIGINT or SIGTERM stopped it (its temporary files removed). Errors are one
//! line on standard error starting with `error: `. Outputs appear only once complete: each is
//! written to a temporary file beside it and renamed into place.

// The modules' documentation is for developers and links to private items (read it with
// `cargo doc --document-private-items`, as the test command builds it).
#![allow(rustdoc::private_intra_doc_links)]

mod args;
mod bench;
mod bodies_csv;
mod count_arg;
mod csv_file;
mod events_csv;
mod file_identity;
mod info;
mod live_page;
mod metrics_csv;
mod output;
mod output_file;
mod output_folder;
#[cfg(feature = "net")]
mod peer;
mod progress;
mod query;
mod query_spec;
mod render;
mod rerecord;
mod run;
mod scene_arg;
mod scenes;
mod status;
mod temporaries;
mod timing_table;
mod usage_error;
mod verify;
mod warnings;

use std::ffi::OsString;

use clap::Parser;

#[cfg(feature = "net")]
pub use args::PeerArgs;
pub use args::{BenchCommand, Cli, Command, QueryArgs, RenderArgs, RunArgs};
pub use status::Status;

/// The last line of a bare `fixstep` (`cargo run --release`): the command that shows the
/// showcase live in 3D in a browser.
pub const SHOW_IN_3D: &str = "see it live in 3D in a browser: ./scripts/web.sh";

/// Runs the command line of this process; returns the exit code.
///
/// A panic would be a bug in fixstep; it is reported as one `error:` line (and the process
/// exits with Rust's panic status, 101), without the default multi-line report.
pub fn main() -> i32 {
    std::panic::set_hook(Box::new(|info| {
        let report = info.to_string().replace('\n', " ");
        output::eprint_line(&format!(
            "error: internal error (a bug in fixstep): {report}"
        ));
    }));
    if let Err(message) = temporaries::remove_on_signal() {
        output::eprint_line(&format!("error: {message}"));
        return Status::Invalid.code();
    }
    main_with_args(std::env::args_os())
}

/// A command line read and checked before any work ([`read_command_line`]).
#[derive(Debug)]
pub enum CommandLine {
    /// A command to run.
    Command(Box<Cli>),
    /// `--help` or `--version`: the text to print, and nothing to run.
    Help(String),
}

/// Reads a command line (`args` starts with the program name) and makes every check that
/// comes before any work: its usage (clap's, and the options' own parsers: counts, shapes,
/// sizes), and that no output of `run` or `peer` is one of its inputs or another of its
/// outputs, however the paths are spelt (which reads files' metadata, nothing more). `Err`
/// holds the one line to print, `error: …`. The fuzz target `cli_args` feeds it arbitrary
/// command lines.
pub fn read_command_line(args: &[OsString]) -> Result<CommandLine, String> {
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(error) if error.exit_code() == 0 => {
            return Ok(CommandLine::Help(error.render().to_string()));
        }
        Err(error) => return Err(usage_error::usage_error_line(&error, args)),
    };
    let checked = match &cli.command {
        Some(Command::Run(args)) => run::refuse_clashes(args),
        Some(Command::Render(args)) => live_page::refuse_clashes(args),
        #[cfg(feature = "net")]
        Some(Command::Peer(args)) => peer::refuse_clashes(args),
        _ => Ok(()),
    };
    checked.map_err(|message| format!("error: {message}"))?;
    Ok(CommandLine::Command(Box::new(cli)))
}

/// Runs a command line (`args` starts with the program name); returns the exit code.
pub fn main_with_args(args: impl IntoIterator<Item = impl Into<OsString> + Clone>) -> i32 {
    let args: Vec<OsString> = args.into_iter().map(Into::into).collect();
    let cli = match read_command_line(&args) {
        Ok(CommandLine::Command(cli)) => cli,
        Ok(CommandLine::Help(text)) => {
            output::print_text(&text);
            return 0;
        }
        Err(line) => {
            output::eprint_line(&line);
            return Status::Invalid.code();
        }
    };
    if let Err(message) = fixstep::math::cpu::cap_from_env() {
        output::eprint_line(&format!("error: {message}"));
        return Status::Invalid.code();
    }
    if let Err(message) = fixstep::parallel::threads_from_env() {
        output::eprint_line(&format!("error: {message}"));
        return Status::Invalid.code();
    }
    // `--threads` sets the thread count of every world the command builds.
    let threads = match &cli.command {
        Some(Command::Run(args)) => args.threads,
        Some(Command::Verify { threads, .. }) => *threads,
        Some(Command::Render(args)) => args.threads,
        #[cfg(feature = "net")]
        Some(Command::Peer(args)) => args.threads,
        _ => None,
    };
    if let Some(threads) = threads {
        fixstep::parallel::set_default_threads(threads);
    }
    let result = match cli.command {
        None => run::run(&RunArgs::default()).and_then(|status| {
            output::print_line(SHOW_IN_3D)?;
            Ok(status)
        }),
        Some(Command::Scenes) => scenes::scenes(),
        Some(Command::Run(args)) => run::run(&args),
        Some(Command::Verify { files, .. }) => verify::verify_files(&files),
        Some(Command::Info { file }) => info::info(&file),
        Some(Command::Rerecord { files }) => rerecord::rerecord_files(&files),
        Some(Command::Render(args)) if args.html.is_some() => live_page::write_live_page(&args),
        Some(Command::Render(args)) => render::render(&args),
        Some(Command::Query(args)) => query::query(&args),
        #[cfg(feature = "net")]
        Some(Command::Peer(args)) => peer::peer(&args),
        Some(Command::Bench { benchmark }) => bench::bench(&benchmark),
    };
    match result {
        Ok(status) => status.code(),
        Err(message) => {
            output::eprint_line(&format!("error: {message}"));
            Status::Invalid.code()
        }
    }
}
