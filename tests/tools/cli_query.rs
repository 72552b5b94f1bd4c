//! `fixstep query`: rays, casts and overlaps against a simulated scene or replay, one JSON
//! object a line, and its argument errors.

use crate::replay_support::{TempPath, fixstep};

/// A ball of radius ½ m whose centre is 2 m above the ground (body 0v0 the ground, 1v0
/// the ball): it has landed after a second.
const DROP_SCENE: &[u8] = b"(name: \"drop\", rigid: (bodies: [
    (kind: Static, shape: Plane(normal: (x: 0.0, y: 1.0, z: 0.0), offset: 0.0)),
    (shape: Sphere(radius: 0.5), position: (x: 0.0, y: 2.0, z: 0.0)),
]))";

/// The text after `"key":` in a one-line JSON object, up to the next `,"` or `}` (a
/// number or a string) or to the closing `]` (an array).
fn raw<'a>(line: &'a str, key: &str) -> &'a str {
    let start = line
        .find(&format!("\"{key}\":"))
        .unwrap_or_else(|| panic!("no {key} in {line}"))
        + key.len()
        + 3;
    let rest = &line[start..];
    let end = if rest.starts_with('[') {
        rest.find(']').expect("array end") + 1
    } else {
        rest.find([',', '}']).expect("value end")
    };
    &rest[..end]
}

/// A number field.
fn number(line: &str, key: &str) -> f64 {
    raw(line, key)
        .parse()
        .unwrap_or_else(|_| panic!("{key} in {line}"))
}

/// A three-number array field.
fn vector(line: &str, key: &str) -> [f64; 3] {
    let text = raw(line, key);
    let values: Vec<f64> = text[1..text.len() - 1]
        .split(',')
        .map(|v| v.parse().unwrap_or_else(|_| panic!("{key} in {line}")))
        .collect();
    values
        .try_into()
        .unwrap_or_else(|_| panic!("{key} in {line}"))
}

/// Asserts a hit on `body` at `distance`, `point` and `normal` (to a micrometre).
fn assert_hit(stdout: &str, body: &str, distance: f64, point: [f64; 3], normal: [f64; 3]) {
    let lines: Vec<&str> = stdout.lines().collect();
    assert_eq!(lines.len(), 1, "{stdout}");
    let line = lines[0];
    assert!(line.starts_with('{') && line.ends_with('}'), "{line}");
    assert_eq!(raw(line, "body"), format!("\"{body}\""), "{line}");
    let close = |a: f64, b: f64| (a - b).abs() < 1e-6;
    assert!(close(number(line, "distance"), distance), "{line}");
    for (got, want) in [
        (vector(line, "point"), point),
        (vector(line, "normal"), normal),
    ] {
        assert!(got.iter().zip(want).all(|(&g, w)| close(g, w)), "{line}");
    }
}

#[test]
fn a_ray_straight_down_hits_the_ground() {
    let run = fixstep(&["query", "stack", "--ray", "5,10,0,0,-1,0"]);
    assert_eq!(run.code, 0, "{run:?}");
    assert_hit(&run.stdout, "0v0", 10.0, [5.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    assert!(run.stderr.is_empty(), "{}", run.stderr);
}

#[test]
fn a_ray_hits_the_top_of_the_stack_and_its_length_does_not_matter() {
    // The top box (10v0) has its centre at 9.5 m: its top face is 10 m up.
    let run = fixstep(&["query", "stack", "--ray", "0,12,0,0,-4,0"]);
    assert_eq!(run.code, 0, "{run:?}");
    assert_hit(&run.stdout, "10v0", 2.0, [0.0, 10.0, 0.0], [0.0, 1.0, 0.0]);
}

#[test]
fn a_miss_prints_hit_false() {
    for args in [
        &["query", "stack", "--ray", "5,10,0,0,1,0"][..],
        &["query", "stack", "--ray", "5,10,0,0,-1,0", "--max", "9"],
        &["query", "stack", "--ray", "5,10,0,0,-1,0", "--mask", "0"],
    ] {
        let run = fixstep(args);
        assert_eq!(run.code, 0, "{args:?}: {run:?}");
        assert_eq!(run.stdout, "{\"hit\":false}\n", "{args:?}");
    }
}

#[test]
fn a_sphere_cast_stops_a_radius_short() {
    let run = fixstep(&[
        "query",
        "stack",
        "--cast",
        "sphere:0.5",
        "--from",
        "5,10,0",
        "--dir",
        "0,-1,0",
        "--mask",
        "0xffffffff",
    ]);
    assert_eq!(run.code, 0, "{run:?}");
    assert_hit(&run.stdout, "0v0", 9.5, [5.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
}

#[test]
fn overlap_lists_the_bodies_in_ascending_order() {
    // A ball of radius 1 centred 0.9 m up reaches below the ground and into the two
    // lowest boxes.
    let run = fixstep(&["query", "stack", "--overlap", "sphere:1", "--at", "0,0.9,0"]);
    assert_eq!(run.code, 0, "{run:?}");
    assert_eq!(
        run.stdout,
        "{\"body\":\"0v0\"}\n{\"body\":\"1v0\"}\n{\"body\":\"2v0\"}\n"
    );
    let none = fixstep(&["query", "stack", "--overlap", "box:1,1,1", "--at", "5,5,5"]);
    assert_eq!(none.code, 0, "{none:?}");
    assert!(none.stdout.is_empty(), "{}", none.stdout);
}

#[test]
fn a_query_at_a_tick_of_a_scene_file_and_of_its_replay() {
    let scene = TempPath::with_bytes("drop.ron", DROP_SCENE);
    let replay = TempPath::new("drop.replay");
    let record = fixstep(&[
        "run",
        scene.str(),
        "--ticks",
        "90",
        "--record",
        replay.str(),
    ]);
    assert_eq!(record.code, 0, "{record:?}");
    // At tick 0 the ball's top is 2.5 m up; once landed, about 1 m.
    let start = fixstep(&["query", scene.str(), "--ray", "0,10,0,0,-1,0"]);
    assert_hit(&start.stdout, "1v0", 7.5, [0.0, 2.5, 0.0], [0.0, 1.0, 0.0]);
    for input in [scene.str(), replay.str()] {
        let run = fixstep(&["query", input, "--tick", "90", "--ray", "0,10,0,0,-1,0"]);
        assert_eq!(run.code, 0, "{run:?}");
        let distance = number(&run.stdout, "distance");
        assert!((distance - 9.0).abs() < 0.02, "{input}: {}", run.stdout);
    }
}

#[test]
fn bad_arguments_are_one_error_line_naming_the_argument() {
    for (args, parts) in [
        (
            &["--ray", "nan,10,0,0,-1,0"][..],
            &["--ray", "`nan`", "finite"][..],
        ),
        (&["--ray", "0,1e12,0,0,-1,0"], &["--ray", "out of range"]),
        (&["--ray", "0,10,0"], &["--ray", "expected 6"]),
        (&["--ray", "0,10,0,0,0,0"], &["--ray", "direction", "zero"]),
        (
            &["--ray", "0,10,0,0,-1,0", "--mask", "-1"],
            &["--mask", "`-1`"],
        ),
        (
            &["--ray", "0,10,0,0,-1,0", "--mask", "4294967296"],
            &["--mask"],
        ),
        (
            &["--ray", "0,10,0,0,-1,0", "--max", "inf"],
            &["--max", "finite"],
        ),
        (
            &["--cast", "cone:1", "--from", "0,10,0", "--dir", "0,-1,0"],
            &["--cast", "unknown shape kind `cone`"],
        ),
        (
            &["--cast", "sphere:0.5", "--from", "0,10,0"],
            &["--dir", "missing"],
        ),
        (
            &["--cast", "box:1,1", "--from", "0,10,0", "--dir", "0,-1,0"],
            &["--cast", "expected 3"],
        ),
        (&["--overlap", "sphere:0"], &["--at", "missing"]),
        (
            &["--ray", "0,10,0,0,-1,0", "--cast", "sphere:1"],
            &["--ray and --cast", "only one"],
        ),
        (
            &["--ray", "0,10,0,0,-1,0", "--at", "0,0,0"],
            &["--at", "only with --overlap"],
        ),
        (&[], &["--ray, --cast or --overlap"]),
    ] {
        let mut line = vec!["query", "stack"];
        line.extend_from_slice(args);
        let run = fixstep(&line);
        run.assert_error(parts);
        assert!(run.stdout.is_empty(), "{args:?}: {}", run.stdout);
    }
}

#[test]
fn a_bad_input_is_an_error() {
    let run = fixstep(&["query", "no-such-scene", "--ray", "0,10,0,0,-1,0"]);
    run.assert_error(&["unknown scene `no-such-scene`"]);
    let file = TempPath::with_bytes("bad.replay", b"FXSTEPRP");
    fixstep(&["query", file.str(), "--ray", "0,10,0,0,-1,0"]).assert_error(&[file.str()]);
}
