//! The fuzz target `cli_args`'s seeds and kept crashes, through its check
//! (`fuzz/src/cli_args.rs`): every command line is read without a panic and refused, if at
//! all, with one `error:` line.

#[path = "../../fuzz/src/cli_args.rs"]
mod cli_args;

use std::path::Path;

#[test]
fn every_seed_and_kept_crash_reads_with_one_line_at_most() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fuzz");
    let mut count = 0;
    for folder in ["seeds/cli_args", "regressions/cli_args"] {
        let Ok(entries) = std::fs::read_dir(root.join(folder)) else {
            continue;
        };
        for entry in entries {
            let path = entry.expect("a readable folder").path();
            cli_args::check(&std::fs::read(&path).expect("a readable seed"));
            count += 1;
        }
    }
    assert!(count >= 10, "only {count} seeds for cli_args");
}
