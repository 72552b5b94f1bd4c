//! Every fuzz seed and every input a fuzzer once crashed on, run through the same checks as
//! the fuzz targets (`fuzz/src/lib.rs`), in the ordinary test suite. A file under
//! `fuzz/regressions/TARGET/` is a crash that was fixed; this test keeps it fixed.

#[path = "../../fuzz/src/lib.rs"]
mod targets;

use std::path::PathBuf;

/// Every file under `fuzz/KIND/TARGET`, in name order.
fn inputs(kind: &str, target: &str) -> Vec<(PathBuf, Vec<u8>)> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("fuzz")
        .join(kind)
        .join(target);
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut files: Vec<(PathBuf, Vec<u8>)> = entries
        .map(|entry| {
            let path = entry.expect("a directory entry").path();
            let bytes = std::fs::read(&path).expect("readable");
            (path, bytes)
        })
        .collect();
    files.sort();
    files
}

/// Seeds must be accepted (or they would seed nothing); kept crashes must not crash.
fn run_all(target: &str, check: fn(&[u8]) -> bool) {
    let seeds = inputs("seeds", target);
    assert!(!seeds.is_empty(), "no seeds for {target}");
    for (path, bytes) in seeds {
        assert!(
            check(&bytes),
            "{target} refuses its seed {}",
            path.display()
        );
    }
    for (path, bytes) in inputs("regressions", target) {
        let outcome = std::panic::catch_unwind(|| check(&bytes));
        assert!(outcome.is_ok(), "{target} fails on {}", path.display());
    }
}

#[test]
fn replay_decode_inputs() {
    run_all("replay_decode", targets::replay_decode);
}

#[test]
fn mesh_obj_inputs() {
    run_all("mesh_obj", targets::mesh_obj);
}

#[test]
fn scene_ron_inputs() {
    run_all("scene_ron", targets::scene_ron);
}

#[test]
fn snapshot_decode_inputs() {
    run_all("snapshot_decode", targets::snapshot_decode);
}

#[test]
fn world_step_inputs() {
    run_all("world_step", targets::world_step);
}
