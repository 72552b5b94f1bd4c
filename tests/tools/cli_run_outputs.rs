//! `fixstep run`'s per-body and per-event CSV files (`--bodies`, `--events`).

use crate::replay_support::{TempPath, fixstep};

/// The header of `--bodies`.
const BODIES_HEADER: &str = "tick,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz";

/// A ball of radius ½ m whose centre is 2 m above the ground (body 0v0 the ground, 1v0
/// the ball): it lands after about 33 ticks.
const DROP_SCENE: &[u8] = b"(name: \"drop\", rigid: (bodies: [
    (kind: Static, shape: Plane(normal: (x: 0.0, y: 1.0, z: 0.0), offset: 0.0)),
    (shape: Sphere(radius: 0.5), position: (x: 0.0, y: 2.0, z: 0.0)),
]))";

/// The lines of a file `fixstep` wrote.
fn lines_of(path: &TempPath) -> Vec<String> {
    std::fs::read_to_string(path.path())
        .expect("written")
        .lines()
        .map(str::to_owned)
        .collect()
}

#[test]
fn bodies_csv_has_a_row_per_body_every_k_ticks_and_at_the_end() {
    let csv = TempPath::new("bodies.csv");
    let run = fixstep(&[
        "run",
        "stack",
        "--ticks",
        "5",
        "--every",
        "2",
        "--bodies",
        csv.str(),
    ]);
    assert_eq!(run.code, 0, "{run:?}");
    let lines = lines_of(&csv);
    assert_eq!(lines[0], BODIES_HEADER);
    let columns = BODIES_HEADER.split(',').count();
    // The ground and 10 boxes, at ticks 0, 2, 4 and 5 (the last).
    let rows: Vec<(u64, String)> = lines[1..]
        .iter()
        .map(|row| {
            let fields: Vec<&str> = row.split(',').collect();
            assert_eq!(fields.len(), columns, "{row}");
            for field in &fields[2..] {
                let value: f64 = field.parse().unwrap_or_else(|_| panic!("{row}"));
                assert!(value.is_finite(), "{row}");
            }
            (fields[0].parse().expect("tick"), fields[1].to_owned())
        })
        .collect();
    let mut expected = Vec::new();
    for tick in [0, 2, 4, 5] {
        for body in 0..11 {
            expected.push((tick, format!("{body}v0")));
        }
    }
    assert_eq!(rows, expected);
    // At tick 0 the lowest box rests with its centre ½ m up, unrotated and still.
    assert_eq!(lines[2], "0,1v0,0,0.5,0,1,0,0,0,0,0,0,0,0,0");
}

#[test]
fn bodies_csv_of_a_scene_without_rigid_bodies_is_the_header() {
    let csv = TempPath::new("no-bodies.csv");
    let run = fixstep(&["run", "fountain", "--ticks", "3", "--bodies", csv.str()]);
    assert_eq!(run.code, 0, "{run:?}");
    assert_eq!(lines_of(&csv), [BODIES_HEADER]);
}

#[test]
fn events_csv_has_the_contact_of_a_landing() {
    let scene = TempPath::with_bytes("drop.ron", DROP_SCENE);
    let csv = TempPath::new("events.csv");
    let run = fixstep(&["run", scene.str(), "--ticks", "60", "--events", csv.str()]);
    assert_eq!(run.code, 0, "{run:?}");
    let lines = lines_of(&csv);
    assert_eq!(lines[0], "tick,event,a,b");
    let begins: Vec<u64> = lines[1..]
        .iter()
        .filter_map(|row| {
            let fields: Vec<&str> = row.split(',').collect();
            assert_eq!(fields.len(), 4, "{row}");
            (fields[1..] == ["contact_begin", "0v0", "1v0"])
                .then(|| fields[0].parse().expect("tick"))
        })
        .collect();
    assert_eq!(begins.len(), 1, "{lines:?}");
    // Free fall over 1.5 m takes 0.55 s, 33 ticks at 60 Hz.
    assert!((25..40).contains(&begins[0]), "{lines:?}");
}

#[test]
fn events_csv_of_a_quiet_run_is_the_header() {
    let csv = TempPath::new("quiet.csv");
    let run = fixstep(&["run", "falling", "--ticks", "2", "--events", csv.str()]);
    assert_eq!(run.code, 0, "{run:?}");
    assert_eq!(lines_of(&csv), ["tick,event,a,b"]);
}

#[test]
fn two_outputs_to_one_file_are_refused() {
    let file = TempPath::new("same.csv");
    let run = fixstep(&[
        "run",
        "stack",
        "--bodies",
        file.str(),
        "--events",
        file.str(),
    ]);
    run.assert_error(&[&format!("--events {0} is also --bodies {0}", file.str())]);
    assert!(!file.path().exists());
}

#[test]
fn an_unwritable_output_fails_before_the_run() {
    let dir = TempPath::new("missing-dir");
    let file = dir.path().join("bodies.csv");
    let file = file.to_str().expect("UTF-8");
    let run = fixstep(&["run", "stack", "--bodies", file]);
    run.assert_error(&[file, "cannot write"]);
    assert!(run.stdout.is_empty(), "{}", run.stdout);
}
