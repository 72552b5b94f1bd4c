//! The warnings `run`, `render` and `verify` print: a mass ratio the solver cannot hold
//! (named at build, with the body indices), the broadphase's pair cap (named, and the
//! ground still holding the pile), and saturations with their stage. Each is one
//! `warning:` line, and the three commands print the same ones.

use crate::replay_support::{Run, TempPath, fixstep};

/// A 100 t box resting on a 1 kg box on a static ground box: bodies 1 and 2.
const HEAVY_ON_LIGHT: &[u8] = b"(name: \"heavy\", ticks: 120, rigid: (bodies: [
    (kind: Static, shape: Box(half_extents: (x: 5.0, y: 0.5, z: 5.0)), position: (x: 0.0, y: -0.5, z: 0.0)),
    (shape: Box(half_extents: (x: 0.5, y: 0.5, z: 0.5)), position: (x: 0.0, y: 0.5, z: 0.0), density: 1.0),
    (shape: Box(half_extents: (x: 0.5, y: 0.5, z: 0.5)), position: (x: 0.0, y: 1.5, z: 0.0), density: 100000.0),
]))";

/// 0.1 kg, 100 t and 0.1 kg boxes stacked on a static ground box: bodies 1, 2 and 3.
const LIGHT_HEAVY_LIGHT: &[u8] = b"(name: \"sandwich\", ticks: 120, rigid: (bodies: [
    (kind: Static, shape: Box(half_extents: (x: 5.0, y: 0.5, z: 5.0)), position: (x: 0.0, y: -0.5, z: 0.0)),
    (shape: Box(half_extents: (x: 0.5, y: 0.5, z: 0.5)), position: (x: 0.0, y: 0.5, z: 0.0), density: 0.1),
    (shape: Box(half_extents: (x: 0.5, y: 0.5, z: 0.5)), position: (x: 0.0, y: 1.5, z: 0.0), density: 100000.0),
    (shape: Box(half_extents: (x: 0.5, y: 0.5, z: 0.5)), position: (x: 0.0, y: 2.5, z: 0.0), density: 0.1),
]))";

/// 729 unit boxes piled on one spot 2 m above a static ground box whose top is at y = 0.
const PILE: &[u8] = b"(name: \"pile\", ticks: 60, rigid: (bodies: [
    (kind: Static, shape: Box(half_extents: (x: 20.0, y: 0.5, z: 20.0)), position: (x: 0.0, y: -0.5, z: 0.0)),
    (shape: Box(half_extents: (x: 0.5, y: 0.5, z: 0.5)), position: (x: 0.0, y: 2.0, z: 0.0),
     grid: Some((count: (9, 9, 9), spacing: (x: 0.01, y: 0.01, z: 0.01)))),
]))";

/// The cap's warning, up to the tick count.
const CAPPED: &str = "warning: contacts capped at tick 0 (and ";

/// Every line of `run`'s standard error is a warning; returns them.
fn warnings(run: &Run) -> Vec<&str> {
    let lines: Vec<&str> = run.stderr.lines().collect();
    for line in &lines {
        assert!(line.starts_with("warning: "), "{}", run.stderr);
    }
    lines
}

#[test]
fn a_heavy_box_on_a_light_one_is_named_at_build() {
    let scene = TempPath::with_bytes("heavy.ron", HEAVY_ON_LIGHT);
    let run = fixstep(&["run", scene.str()]);
    assert_eq!(run.code, 0, "{run:?}");
    let lines = warnings(&run);
    assert!(
        lines[0].starts_with(
            "warning: rigid.bodies: bodies 1 (1 kg) and 2 (100000 kg) can touch, a mass ratio \
             of 1:100000, past 1:100"
        ),
        "{}",
        run.stderr
    );
}

#[test]
fn a_heavy_box_between_light_ones_names_both_pairs() {
    let scene = TempPath::with_bytes("sandwich.ron", LIGHT_HEAVY_LIGHT);
    let run = fixstep(&["run", scene.str()]);
    assert_eq!(run.code, 0, "{run:?}");
    let lines = warnings(&run);
    assert!(
        lines[0].contains("bodies 1 (0.1 kg) and 2 (100000 kg) can touch"),
        "{}",
        run.stderr
    );
    assert!(
        lines[1].contains("bodies 3 (0.1 kg) and 2 (100000 kg) can touch"),
        "{}",
        run.stderr
    );
}

#[test]
fn a_pile_past_the_pair_cap_is_named_and_the_ground_holds_it() {
    let scene = TempPath::with_bytes("pile.ron", PILE);
    let bodies = TempPath::new("pile.csv");
    let run = fixstep(&[
        "run",
        scene.str(),
        "--bodies",
        bodies.str(),
        "--every",
        "60",
    ]);
    assert_eq!(run.code, 0, "{run:?}");
    let lines = warnings(&run);
    assert_eq!(lines.len(), 1, "{}", run.stderr);
    assert!(lines[0].starts_with(CAPPED), "{}", run.stderr);
    assert!(
        lines[0].ends_with("bodies may pass through each other"),
        "{}",
        run.stderr
    );
    // At tick 60 the boxes have landed (about tick 40): none is below the ground's top.
    let csv = std::fs::read_to_string(bodies.path()).expect("written");
    let lowest = csv
        .lines()
        .skip(1)
        .map(|row| row.split(',').collect::<Vec<_>>())
        .filter(|fields| fields[0] == "60" && fields[1] != "0v0")
        .map(|fields| fields[3].parse::<f64>().expect("y"))
        .fold(f64::INFINITY, f64::min);
    assert!(lowest > 0.45, "a box fell to {lowest} m");
}

#[test]
fn saturations_name_their_stage() {
    let scene = TempPath::with_bytes(
        "fall.ron",
        b"(name: \"fall\", ticks: 150, gravity: (x: 0.0, y: -1000000000.0, z: 0.0),
          rigid: (bodies: [(shape: Box(half_extents: (x: 0.5, y: 0.5, z: 0.5)), density: 1.0)]))",
    );
    let run = fixstep(&["run", scene.str()]);
    assert_eq!(run.code, 0, "{run:?}");
    let saturations = warnings(&run)
        .into_iter()
        .find(|line| line.contains("fixed-point saturations"))
        .unwrap_or_else(|| panic!("{}", run.stderr));
    assert!(
        saturations.contains("; the first at tick 0 (")
            && saturations.contains("in the rigid stage"),
        "{saturations}"
    );
    assert!(
        saturations.contains("; rigid body 0v0 reached the range's edge at tick "),
        "{saturations}"
    );
}

#[test]
fn render_and_verify_print_the_warnings_run_prints() {
    let scene = TempPath::with_bytes("heavy.ron", HEAVY_ON_LIGHT);
    let replay = TempPath::new("heavy.replay");
    let run = fixstep(&["run", scene.str(), "--record", replay.str()]);
    assert_eq!(run.code, 0, "{run:?}");
    let expected = warnings(&run);
    assert_eq!(expected.len(), 2, "{}", run.stderr);

    let verify = fixstep(&["verify", replay.str()]);
    assert_eq!(verify.code, 0, "{verify:?}");
    let prefixed: Vec<String> = expected
        .iter()
        .map(|line| line.replacen("warning: ", &format!("warning: {}: ", replay.str()), 1))
        .collect();
    assert_eq!(warnings(&verify), prefixed, "{verify:?}");

    let out = TempPath::new("heavy-render");
    let render = fixstep(&["render", scene.str(), "--out", out.str(), "--every", "30"]);
    assert_eq!(render.code, 0, "{render:?}");
    assert_eq!(warnings(&render), expected, "{render:?}");
}

#[test]
fn render_names_the_pair_cap() {
    let scene = TempPath::with_bytes("pile.ron", PILE);
    let out = TempPath::new("pile-render");
    let render = fixstep(&[
        "render",
        scene.str(),
        "--out",
        out.str(),
        "--ticks",
        "3",
        "--every",
        "3",
    ]);
    assert_eq!(render.code, 0, "{render:?}");
    let lines = warnings(&render);
    assert_eq!(
        lines,
        [
            "warning: contacts capped at tick 0 (and 2 later ticks): more than 262144 overlapping \
          pairs of bodies; only contacts with static bodies were kept, so bodies may pass \
          through each other"
        ],
        "{render:?}"
    );
}
