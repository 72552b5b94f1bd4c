//! The `fixstep` binary: see [`fixstep_cli`].

fn main() {
    std::process::exit(fixstep_cli::main())
}
