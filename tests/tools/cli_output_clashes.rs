//! An output that is also an input or another output, however spelt, is refused before
//! anything runs: exit 2, one `error:` line naming both, and every file left as it was.

use std::path::Path;

use crate::replay_support::{TempPath, fixstep};

/// A small scene file's text.
const SCENE: &[u8] = b"(name: \"mine\", ticks: 5)";

/// A fresh folder holding `my.ron` (the scene), removed at the end.
fn folder_with_scene() -> TempPath {
    let folder = TempPath::new("clashes");
    std::fs::create_dir(folder.path()).expect("create the folder");
    std::fs::write(folder.path().join("my.ron"), SCENE).expect("write the scene");
    folder
}

/// Runs `fixstep` in `folder` with `args`, and checks the refusal: exit 2, one error line
/// holding `parts`, the scene unchanged and no other file in the folder than `keep`.
fn assert_refused_in(folder: &Path, args: &[&str], parts: &[&str], keep: &[&str]) {
    let output = std::process::Command::new(env!("CARGO_BIN_EXE_fixstep"))
        .args(args)
        .current_dir(folder)
        .output()
        .expect("the fixstep binary runs");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{args:?}: {stderr}");
    let lines: Vec<&str> = stderr.lines().collect();
    assert_eq!(lines.len(), 1, "{args:?}: {stderr}");
    assert!(lines[0].starts_with("error: "), "{}", lines[0]);
    for part in parts {
        assert!(lines[0].contains(part), "{part:?} not in {:?}", lines[0]);
    }
    assert_eq!(
        std::fs::read(folder.join("my.ron")).expect("the scene is still there"),
        SCENE,
        "{args:?}"
    );
    let mut names: Vec<String> = std::fs::read_dir(folder)
        .expect("readable")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    let mut expected: Vec<String> = keep.iter().map(|s| (*s).to_owned()).collect();
    expected.push("my.ron".to_owned());
    expected.sort();
    assert_eq!(names, expected, "{args:?}: nothing written");
}

#[test]
fn recording_over_the_scene_file_is_refused() {
    let folder = folder_with_scene();
    assert_refused_in(
        folder.path(),
        &["run", "my.ron", "--record", "my.ron"],
        &["--record my.ron is also the scene file my.ron"],
        &[],
    );
}

#[test]
fn every_output_over_the_scene_file_is_refused() {
    let folder = folder_with_scene();
    for option in ["--metrics", "--bodies", "--events", "--snapshot"] {
        assert_refused_in(
            folder.path(),
            &["run", "my.ron", option, "./my.ron"],
            &[&format!("{option} ./my.ron is also the scene file my.ron")],
            &[],
        );
    }
}

#[test]
fn two_spellings_of_one_output_are_refused() {
    let folder = folder_with_scene();
    assert_refused_in(
        folder.path(),
        &["run", "my.ron", "--record", "x", "--metrics", "./x"],
        &["--metrics ./x is also --record x"],
        &[],
    );
    // Through a folder and back.
    std::fs::create_dir(folder.path().join("sub")).expect("create sub");
    assert_refused_in(
        folder.path(),
        &[
            "run",
            "my.ron",
            "--bodies",
            "out.csv",
            "--events",
            "sub/../out.csv",
        ],
        &["--events sub/../out.csv is also --bodies out.csv"],
        &["sub"],
    );
}

#[cfg(unix)]
#[test]
fn a_hard_link_to_the_scene_is_refused() {
    let folder = folder_with_scene();
    std::fs::hard_link(folder.path().join("my.ron"), folder.path().join("link.ron"))
        .expect("hard link");
    assert_refused_in(
        folder.path(),
        &["run", "my.ron", "--record", "link.ron"],
        &["--record link.ron is also the scene file my.ron"],
        &["link.ron"],
    );
    assert_eq!(
        std::fs::read(folder.path().join("link.ron")).expect("the link"),
        SCENE
    );
}

#[cfg(unix)]
#[test]
fn a_symbolic_link_to_the_scene_is_refused() {
    let folder = folder_with_scene();
    std::os::unix::fs::symlink("my.ron", folder.path().join("link.ron")).expect("symlink");
    // The link as the output, and as the scene.
    assert_refused_in(
        folder.path(),
        &["run", "my.ron", "--metrics", "link.ron"],
        &["--metrics link.ron is also the scene file my.ron"],
        &["link.ron"],
    );
    assert_refused_in(
        folder.path(),
        &["run", "link.ron", "--record", "my.ron"],
        &["--record my.ron is also the scene file link.ron"],
        &["link.ron"],
    );
}

#[test]
fn the_snapshot_resumed_from_is_not_an_output() {
    let folder = folder_with_scene();
    let save = fixstep(&[
        "run",
        "fountain",
        "--ticks",
        "3",
        "--snapshot",
        folder.path().join("s.snapshot").to_str().expect("UTF-8"),
    ]);
    assert_eq!(save.code, 0, "{save:?}");
    let before = std::fs::read(folder.path().join("s.snapshot")).expect("saved");
    assert_refused_in(
        folder.path(),
        &[
            "run",
            "fountain",
            "--from-snapshot",
            "s.snapshot",
            "--metrics",
            "./s.snapshot",
        ],
        &["--metrics ./s.snapshot is also --from-snapshot s.snapshot"],
        &["s.snapshot"],
    );
    assert_eq!(
        std::fs::read(folder.path().join("s.snapshot")).expect("kept"),
        before
    );
}
