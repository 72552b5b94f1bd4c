//! The `fixstep` binary: see [`fixstep::cli`].

fn main() {
    std::process::exit(fixstep::cli::main())
}
