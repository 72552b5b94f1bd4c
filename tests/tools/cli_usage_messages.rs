//! A bad command line is one `error:` line and exit 2: a negative or zero count says what
//! the option takes, a command missing its subcommand lists them, and clap's usage errors
//! are one line too.

use crate::replay_support::fixstep;

#[test]
fn a_bad_count_says_what_the_option_takes() {
    for (args, message) in [
        (
            &["run", "stack", "--ticks", "-1"][..],
            "`--ticks` takes a count ≥ 1, not `-1`",
        ),
        (
            &["run", "stack", "--ticks", "0"],
            "`--ticks` takes a count ≥ 1, not `0`",
        ),
        (
            &["run", "stack", "--ticks=-5"],
            "`--ticks` takes a count ≥ 1, not `-5`",
        ),
        (
            &["run", "stack", "--every", "-2"],
            "`--every` takes a count ≥ 1, not `-2`",
        ),
        (
            &["render", "stack", "--ticks", "-1"],
            "`--ticks` takes a count ≥ 1, not `-1`",
        ),
        (
            &["render", "stack", "--every", "0"],
            "`--every` takes a count ≥ 1, not `0`",
        ),
        (
            &["query", "stack", "--tick", "-3", "--ray", "0,1,0,0,-1,0"],
            "`--tick` takes a count ≥ 0, not `-3`",
        ),
        (
            &["run", "stack", "--ticks", "many"],
            "`--ticks` takes a count ≥ 1, not `many`",
        ),
    ] {
        fixstep(args).assert_error(&[message]);
    }
}

#[cfg(feature = "net")]
#[test]
fn a_bad_peer_count_says_what_the_option_takes() {
    let base = ["peer", "--local-port", "0", "--remote", "127.0.0.1:9"];
    let mut ticks = base.to_vec();
    ticks.extend(["--ticks", "-1"]);
    fixstep(&ticks).assert_error(&["`--ticks` takes a count ≥ 1, not `-1`"]);
    let mut every = base.to_vec();
    every.extend(["--desync-every", "-1"]);
    fixstep(&every).assert_error(&["`--desync-every` takes a count from 1 to 4294967295"]);
}

#[test]
fn bench_alone_names_its_benchmarks() {
    fixstep(&["bench"]).assert_error(&["`fixstep bench` needs one of: accuracy, stability"]);
}

#[test]
fn usage_errors_are_one_line() {
    for (args, part) in [
        (&["bogus"][..], "unrecognized subcommand 'bogus'"),
        (
            &["run", "stack", "--frobnicate"],
            "unexpected argument '--frobnicate'",
        ),
        (
            &["run", "stack", "--tickz", "3"],
            "a similar argument exists: '--ticks'",
        ),
        (&["verify"], "required"),
        (&["scenes", "extra"], "unexpected argument 'extra'"),
        (&["run", "stack", "--seed", "0xZZ"], "0xZZ"),
    ] {
        let run = fixstep(args);
        run.assert_error(&[part]);
        assert!(run.stdout.is_empty(), "{args:?}: {}", run.stdout);
    }
}
