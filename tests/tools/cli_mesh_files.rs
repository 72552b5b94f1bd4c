//! Scenes that read mesh files: a mesh named relative to its scene file runs; a bad mesh
//! file is refused with exit code 2 and a message naming the file and the line; a replay
//! embeds the mesh, so it verifies without the file.

use std::path::Path;

use crate::replay_support::{TempPath, fixstep};

/// A directory holding `level.ron` (a static `TriMesh(file: "level.obj")` and a ball above
/// it) and `level.obj` with `obj` as its text.
fn level(obj: &str) -> TempPath {
    let dir = TempPath::new("level");
    std::fs::create_dir_all(dir.path()).expect("a temporary directory");
    let scene = r#"(
        name: "level",
        ticks: 30,
        rigid: (bodies: [
            (kind: Static, shape: TriMesh(file: "level.obj")),
            (shape: Sphere(radius: 0.25), position: (x: 0.3, y: 1.0, z: 0.3)),
        ]),
    )"#;
    std::fs::write(dir.path().join("level.ron"), scene).expect("write the scene");
    std::fs::write(dir.path().join("level.obj"), obj).expect("write the mesh");
    dir
}

fn scene_of(dir: &TempPath) -> String {
    dir.path().join("level.ron").display().to_string()
}

/// A unit square at y = 0 in two triangles facing up, with the lines of its records:
/// vertices on lines 2–5, faces on lines 6–7.
const SQUARE: &str = "# a square\nv 0 0 0\nv 0 0 1\nv 1 0 1\nv 1 0 0\nf 1 2 3\nf 1 3 4\n";

#[test]
fn a_mesh_file_named_beside_its_scene_runs_and_its_replay_stands_alone() {
    let dir = level(SQUARE);
    let replay = TempPath::new("level.replay");
    let run = fixstep(&["run", &scene_of(&dir), "--record", replay.str()]);
    assert_eq!(run.code, 0, "{run:?}");
    std::fs::remove_file(dir.path().join("level.obj")).expect("remove the mesh file");
    let verify = fixstep(&["verify", replay.str()]);
    assert_eq!(verify.code, 0, "the replay carries the mesh: {verify:?}");
    let info = fixstep(&["info", replay.str()]);
    assert!(
        info.stdout
            .contains("1 triangle mesh (2 triangles, 4 vertices, 4 active edges)"),
        "{}",
        info.stdout
    );
}

#[test]
fn the_example_level_reads_its_mesh_beside_it() {
    let root = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."));
    let run = fixstep(&[
        "run",
        root.join("docs/scenes/level.ron").to_str().expect("UTF-8"),
        "--ticks",
        "5",
    ]);
    assert_eq!(run.code, 0, "{run:?}");
}

#[test]
fn bad_mesh_files_are_refused_naming_the_file_and_the_line() {
    for (obj, parts) in [
        ("", vec!["level.obj", "no triangles"]),
        (
            "v 0 0 0\nv 0 0 1\nv 0 0 2\nf 1 2 3\n",
            vec!["level.obj", "line 4", "degenerate"],
        ),
        (
            "v 0 0 0\nv 0 0 1\nv 1 0 0\nv 1 1 0\nv 1 -1 0\nf 1 2 3\nf 3 2 4\nf 2 3 5\n",
            vec!["level.obj", "line 8", "non-manifold"],
        ),
        (
            "v 0 0 0\nv 0 0 1\nv 1 0 0\nf 1 2 7\n",
            vec!["level.obj", "line 4"],
        ),
        (
            "v 0 0 0\nv 0 nan 1\nv 1 0 0\nf 1 2 3\n",
            vec!["level.obj", "line 2"],
        ),
    ] {
        let dir = level(obj);
        let run = fixstep(&["run", &scene_of(&dir)]);
        run.assert_error(&parts);
    }
}

#[test]
fn a_mesh_file_past_the_triangle_limit_is_refused_at_the_line_that_passes_it() {
    // 10⁷ triangles, past the documented limit of 2²² = 4 194 304: three vertices, then
    // the same face again and again. The limit is passed on line 3 + 4 194 305.
    let mut obj = String::from("v 0 0 0\nv 0 0 1\nv 1 0 0\n");
    obj.reserve(8 * 10_000_000);
    for _ in 0..10_000_000 {
        obj.push_str("f 1 2 3\n");
    }
    let dir = level(&obj);
    let run = fixstep(&["run", &scene_of(&dir)]);
    run.assert_error(&["level.obj", "line 4194308", "4194304"]);
}
