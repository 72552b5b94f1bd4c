//! `--threads` and `FIXSTEP_THREADS`: the same outputs at any thread count, and a bad count
//! refused.

use crate::replay_support::{fixstep, fixstep_with_env};

fn checksum_line(stdout: &str) -> &str {
    stdout.lines().last().unwrap_or_default()
}

#[test]
fn run_gives_the_same_checksum_at_any_thread_count() {
    // Scenes whose loops split: over 256 contact pairs, and a fluid.
    for (scene, ticks) in [("balls", "40"), ("dam_break", "3")] {
        let one = fixstep(&["run", scene, "--ticks", ticks, "--threads", "1"]);
        assert_eq!(one.code, 0, "{one:?}");
        for threads in ["2", "3", "0"] {
            let many = fixstep(&["run", scene, "--ticks", ticks, "--threads", threads]);
            assert_eq!(many.code, 0, "{many:?}");
            assert_eq!(
                checksum_line(&many.stdout),
                checksum_line(&one.stdout),
                "{scene} on {threads} threads"
            );
        }
        let from_env = fixstep_with_env(
            &["run", scene, "--ticks", ticks],
            &[("FIXSTEP_THREADS", "2")],
        );
        assert_eq!(
            checksum_line(&from_env.stdout),
            checksum_line(&one.stdout),
            "{scene}"
        );
    }
}

#[test]
fn verify_on_threads_prints_in_argument_order() {
    let root = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."));
    let files: Vec<String> = ["tiny", "dam_break", "tank", "cradle"]
        .iter()
        .map(|name| {
            let path = root.join(format!("replays/{name}.replay"));
            path.to_str().expect("UTF-8").to_owned()
        })
        .collect();
    let args = |threads: &'static str| {
        let mut args = vec!["verify", "--threads", threads];
        args.extend(files.iter().map(String::as_str));
        args
    };
    let one = fixstep(&args("1"));
    assert_eq!(one.code, 0, "{one:?}");
    let names: Vec<&str> = one
        .stdout
        .lines()
        .map(|line| line.split(' ').nth(1).unwrap_or_default())
        .collect();
    assert_eq!(names, files, "{one:?}");
    for threads in ["2", "4"] {
        let many = fixstep(&args(threads));
        assert_eq!(many.code, 0, "{many:?}");
        assert_eq!(many.stdout, one.stdout, "{threads} threads");
    }
}

#[test]
fn a_bad_thread_count_is_refused() {
    let run = fixstep(&["run", "stack", "--ticks", "1", "--threads", "two"]);
    assert_eq!(run.code, 2, "{run:?}");
    assert!(run.stderr.contains("not a thread count"), "{}", run.stderr);
    for value in ["-1", "many", "100000"] {
        let run = fixstep_with_env(
            &["run", "stack", "--ticks", "1"],
            &[("FIXSTEP_THREADS", value)],
        );
        assert_eq!(run.code, 2, "{run:?}");
        assert!(run.stdout.is_empty(), "{run:?}");
        assert!(
            run.stderr
                .starts_with("error: environment variable FIXSTEP_THREADS")
                && run.stderr.contains(&format!("`{value}`")),
            "{}",
            run.stderr
        );
    }
}
