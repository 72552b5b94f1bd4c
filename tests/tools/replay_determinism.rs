//! Recording is deterministic and re-recording an up-to-date replay changes nothing.

use crate::replay_support::{
    Layout, TempPath, fixstep, rewrite_header, sample_bytes, sample_replay,
};
use fixstep::math::Fx;
use fixstep::replay::{
    DEFAULT_CHECKSUM_EVERY, Replay, StateVersionCheck, VerifyOutcome, record, rerecord, verify,
};
use fixstep::world::STATE_VERSION;
use fixstep_scenes::{BUILTIN_SCENES, builtin_scene};

#[test]
fn recording_twice_gives_identical_bytes() {
    for (name, _) in BUILTIN_SCENES {
        let scene = builtin_scene::<Fx>(name).expect("built in");
        let first = record(&scene, 150, DEFAULT_CHECKSUM_EVERY).expect("builds");
        let second = record(&scene, 150, DEFAULT_CHECKSUM_EVERY).expect("builds");
        assert_eq!(
            first.to_bytes().expect("encodes"),
            second.to_bytes().expect("encodes"),
            "{name}"
        );
    }
    assert_eq!(sample_bytes(), sample_bytes());
}

#[test]
fn recording_twice_from_the_command_line_gives_identical_files() {
    let first = TempPath::new("first.replay");
    let second = TempPath::new("second.replay");
    for file in [&first, &second] {
        let run = fixstep(&["run", "orbits", "--ticks", "100", "--record", file.str()]);
        assert_eq!(run.code, 0, "{run:?}");
    }
    let first = std::fs::read(first.path()).expect("written");
    assert_eq!(first, std::fs::read(second.path()).expect("written"));
    let replay = Replay::from_bytes(&first, "orbits").expect("valid");
    assert_eq!(replay.ticks(), 100);
    assert_eq!(replay.checkpoints().len(), 3);
}

#[test]
fn the_recorded_run_verifies_and_ends_with_the_printed_checksum() {
    let file = TempPath::new("printed.replay");
    let run = fixstep(&["run", "fountain", "--ticks", "75", "--record", file.str()]);
    assert_eq!(run.code, 0, "{run:?}");
    let replay = Replay::read(file.path()).expect("valid");
    let last = run.stdout.lines().last().expect("output");
    assert_eq!(last, format!("checksum: {:016x}", replay.final_checksum()));
    let verified = fixstep(&["verify", file.str()]);
    assert_eq!(verified.code, 0, "{verified:?}");
    assert_eq!(
        verified.stdout,
        format!("ok {} 75 {:016x}\n", file.str(), replay.final_checksum())
    );
}

#[test]
fn inputs_are_recorded_in_canonical_form_and_verify() {
    let replay = sample_replay();
    let ticks: Vec<u64> = replay.inputs().iter().map(|i| i.tick).collect();
    assert_eq!(ticks, [5, 61, 100]);
    assert!(replay.scene().script.is_empty());
    assert_eq!(
        verify(&replay).expect("builds"),
        VerifyOutcome::Ok {
            ticks: 130,
            checksum: replay.final_checksum()
        }
    );
    let checkpoint_ticks: Vec<u64> = replay.checkpoints().iter().map(|c| c.tick).collect();
    assert_eq!(checkpoint_ticks, [0, 60, 120, 130]);
}

#[test]
fn encode_decode_encode_is_identical() {
    let bytes = sample_bytes();
    let decoded = Replay::from_bytes(&bytes, "sample").expect("valid");
    assert_eq!(decoded, sample_replay());
    assert_eq!(decoded.to_bytes().expect("encodes"), bytes);
}

#[test]
fn rerecord_of_an_up_to_date_file_is_byte_identical() {
    let bytes = sample_bytes();
    let file = TempPath::with_bytes("current.replay", &bytes);
    let run = fixstep(&["rerecord", file.str()]);
    assert_eq!(run.code, 0, "{run:?}");
    let replay = Replay::from_bytes(&bytes, "sample").expect("valid");
    assert_eq!(
        run.stdout,
        format!(
            "rerecorded {} 130 {:016x}\n",
            file.str(),
            replay.final_checksum()
        )
    );
    assert_eq!(std::fs::read(file.path()).expect("still there"), bytes);
    assert_eq!(rerecord(&replay).expect("builds"), replay);
}

#[test]
fn rerecord_brings_an_older_state_version_up_to_date() {
    let current = sample_bytes();
    let mut old = current.clone();
    let mut layout = Layout::of(&old);
    layout.header.state_version = STATE_VERSION - 1;
    rewrite_header(&mut old, &layout.header);
    let file = TempPath::with_bytes("old.replay", &old);

    assert_eq!(fixstep(&["verify", file.str()]).code, 2);
    let info = fixstep(&["info", file.str()]);
    assert_eq!(info.code, 0, "{info:?}");
    assert!(info.stdout.contains("fixstep rerecord"), "{}", info.stdout);

    let run = fixstep(&["rerecord", file.str()]);
    assert_eq!(run.code, 0, "{run:?}");
    assert!(
        run.stdout.contains(&format!(
            "(state version {} -> {STATE_VERSION})",
            STATE_VERSION - 1
        )),
        "{}",
        run.stdout
    );
    assert_eq!(std::fs::read(file.path()).expect("rewritten"), current);
    assert!(Replay::read_with(file.path(), StateVersionCheck::Current).is_ok());
}

#[test]
fn rerecord_refuses_a_newer_state_version_and_leaves_the_file() {
    let mut newer = sample_bytes();
    let mut layout = Layout::of(&newer);
    layout.header.state_version = STATE_VERSION + 1;
    rewrite_header(&mut newer, &layout.header);
    let file = TempPath::with_bytes("newer.replay", &newer);
    let run = fixstep(&["rerecord", file.str()]);
    run.assert_error(&[file.str(), "it needs a newer fixstep"]);
    assert_eq!(std::fs::read(file.path()).expect("untouched"), newer);
}

#[test]
fn no_temporary_files_are_left_behind() {
    let dir = TempPath::new("outputs");
    std::fs::create_dir(dir.path()).expect("create");
    let replay = dir.path().join("out.replay");
    let csv = dir.path().join("out.csv");
    let run = fixstep(&[
        "run",
        "fountain",
        "--ticks",
        "10",
        "--record",
        replay.to_str().expect("UTF-8"),
        "--metrics",
        csv.to_str().expect("UTF-8"),
    ]);
    assert_eq!(run.code, 0, "{run:?}");
    let rerun = fixstep(&["rerecord", replay.to_str().expect("UTF-8")]);
    assert_eq!(rerun.code, 0, "{rerun:?}");
    let mut names: Vec<String> = std::fs::read_dir(dir.path())
        .expect("listable")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names, ["out.csv", "out.replay"]);
}

#[test]
fn a_failed_write_leaves_no_file() {
    let dir = TempPath::new("missing-dir");
    let target = dir.path().join("out.replay");
    let run = fixstep(&[
        "run",
        "fountain",
        "--ticks",
        "5",
        "--record",
        target.to_str().expect("UTF-8"),
    ]);
    run.assert_error(&["out.replay", "cannot write"]);
    assert!(!dir.path().exists());
}
