//! Scene files: every file in `scenes/` loads and builds, the built-in ones match the
//! built-in scenes, and malformed files are refused with one line naming the file.
//!
//! `FIXSTEP_BLESS=1 cargo test --test tools cli_scene_files::` rewrites
//! `scenes/<builtin>.ron` from the built-in scenes (scripts/rerecord.sh does this).

use std::path::{Path, PathBuf};

use crate::replay_support::{TempPath, fixstep};
use fixstep::math::Fx;
use fixstep::replay::write_atomic;
use fixstep::scene::{Scene, Simulation, load_scene_file};
use fixstep_scenes::{BUILTIN_SCENES, builtin_scene};
use ron::extensions::Extensions;
use ron::ser::PrettyConfig;

fn scenes_dir() -> PathBuf {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../..")).join("scenes")
}

/// The RON text of a built-in scene file.
fn builtin_file_text(name: &str, scene: &Scene<Fx>) -> String {
    let options = ron::Options::default().with_default_extension(Extensions::IMPLICIT_SOME);
    let body = options
        .to_string_pretty(scene, PrettyConfig::new())
        .expect("scenes serialise");
    format!(
        "// The built-in scene `{name}`, written by `FIXSTEP_BLESS=1 cargo test --test \
         tools cli_scene_files::`.\n// Run it with `fixstep run scenes/{name}.ron`.\n{}\n",
        compact_vectors(&body)
    )
}

/// Puts each `(x: .., y: .., z: ..)` vector that the pretty printer spread over five lines
/// on one line.
fn compact_vectors(text: &str) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::with_capacity(lines.len());
    let mut i = 0;
    while i < lines.len() {
        let window = lines.get(i..i + 5);
        if let Some([open, x, y, z, close]) = window
            && open.ends_with('(')
            && x.trim_start().starts_with("x: ")
            && y.trim_start().starts_with("y: ")
            && z.trim_start().starts_with("z: ")
            && close.trim_start().starts_with(')')
        {
            let components = [x, y, z].map(|c| c.trim().trim_end_matches(','));
            out.push(format!(
                "{open}{}{}",
                components.join(", "),
                close.trim_start()
            ));
            i += 5;
        } else {
            out.push(lines[i].to_owned());
            i += 1;
        }
    }
    out.join("\n")
}

#[test]
fn builtin_scene_files_match_the_builtins() {
    let bless = std::env::var_os("FIXSTEP_BLESS").is_some();
    for (name, _) in BUILTIN_SCENES {
        let scene = builtin_scene::<Fx>(name).expect("built in");
        let path = scenes_dir().join(format!("{name}.ron"));
        if bless {
            write_atomic(&path, builtin_file_text(name, &scene).as_bytes())
                .expect("write scene file");
        }
        let loaded = load_scene_file::<Fx>(&path).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(
            loaded, scene,
            "{name}.ron differs from the built-in scene; regenerate it with \
             FIXSTEP_BLESS=1 cargo test --test tools cli_scene_files::"
        );
    }
}

/// The hand-written skeletons: every field of a scene section, commented.
const SKELETONS: [&str; 5] = ["particles", "rigid", "joints", "soft", "fluid"];

#[test]
fn every_scene_file_loads_builds_and_steps() {
    let mut count = 0;
    for entry in std::fs::read_dir(scenes_dir()).expect("scenes/ exists") {
        let path = entry.expect("readable entry").path();
        assert_eq!(
            path.extension().and_then(|e| e.to_str()),
            Some("ron"),
            "only scene files belong in scenes/: {}",
            path.display()
        );
        let scene = load_scene_file::<Fx>(&path).unwrap_or_else(|e| panic!("{e}"));
        let mut simulation =
            Simulation::new(&scene).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        for _ in 0..2 {
            simulation.step();
        }
        count += 1;
    }
    assert_eq!(
        count,
        BUILTIN_SCENES.len() + SKELETONS.len() + 3,
        "the built-in scenes, the skeletons, tiny.ron, rain.ron and dam_break_adaptive.ron"
    );
}

#[test]
fn every_skeleton_runs_60_ticks_quietly() {
    for name in SKELETONS {
        let file = scenes_dir().join(format!("{name}.ron"));
        let run = fixstep(&["run", file.to_str().expect("UTF-8"), "--ticks", "60"]);
        assert_eq!(run.code, 0, "{name}: {run:?}");
        assert_eq!(run.stderr, "", "{name}: no warning");
        let text = std::fs::read_to_string(&file).expect("readable");
        assert!(
            text.contains(&format!("fixstep run scenes/{name}.ron")),
            "{name}.ron says how to run it"
        );
    }
}

#[test]
fn a_scene_file_runs_like_its_builtin() {
    let (name, _) = BUILTIN_SCENES[1];
    let file = scenes_dir().join(format!("{name}.ron"));
    let from_file = fixstep(&["run", file.to_str().expect("UTF-8"), "--ticks", "40"]);
    let builtin = fixstep(&["run", name, "--ticks", "40"]);
    assert_eq!(from_file.code, 0, "{from_file:?}");
    assert_eq!(
        from_file.stdout.lines().last(),
        builtin.stdout.lines().last()
    );
}

/// `fixstep run` on a file holding `text` fails with one line naming it and `parts`.
fn assert_scene_rejected(text: &[u8], parts: &[&str]) {
    let file = TempPath::with_bytes("scene.ron", text);
    let mut all = vec![file.str()];
    all.extend_from_slice(parts);
    fixstep(&["run", file.str()]).assert_error(&all);
}

#[test]
fn ron_syntax_error_names_line_and_column() {
    assert_scene_rejected(
        b"(\n    name: \"broken\",\n    tick_rate: 60\n    substeps: 2,\n)\n",
        &["line 4, column"],
    );
}

#[test]
fn unknown_field() {
    assert_scene_rejected(b"(name: \"x\", bogus_field: 3)", &["bogus_field"]);
}

#[test]
fn joint_errors_name_the_field() {
    let bodies = "rigid: (bodies: [(kind: Static, shape: Sphere(radius: 0.1)), (shape: Sphere(radius: 0.5), position: (x: 1.0, y: 0.0, z: 0.0))])";
    let with = |joints: &str| format!("(name: \"x\", {bodies}, joints: (list: [{joints}]))");
    assert_scene_rejected(
        b"(name: \"x\", joints: (list: []))",
        &["joints", "no `rigid` section"],
    );
    assert_scene_rejected(
        with("(kind: Ball, bodies: (0, 7), anchor: (x: 0.0, y: 0.0, z: 0.0))").as_bytes(),
        &[
            "joints.list[0].bodies.1",
            "names body 7, but the scene has 2 rigid bodies",
        ],
    );
    assert_scene_rejected(
        with("(kind: Ball, bodies: (1, 1), anchor: (x: 0.0, y: 0.0, z: 0.0))").as_bytes(),
        &["joints.list[0].bodies", "joins body 1 to itself"],
    );
    assert_scene_rejected(
        with("(kind: Hinge(limits: (lower: 1.0, upper: -1.0)), bodies: (0, 1), anchor: (x: 0.0, y: 0.0, z: 0.0))").as_bytes(),
        &["joints.list[0].kind.Hinge.limits.upper", "must be 1 to"],
    );
    assert_scene_rejected(
        with("(kind: Slider(), bodies: (0, 1), anchor: (x: 0.0, y: 0.0, z: 0.0), axis: (x: 0.0, y: 2.0, z: 0.0))").as_bytes(),
        &["joints.list[0].axis", "must have length 1"],
    );
    assert_scene_rejected(
        with("(kind: Rope(max_length: 0.0), bodies: (0, 1), anchor: (x: 0.0, y: 0.0, z: 0.0))")
            .as_bytes(),
        &["joints.list[0].kind.Rope.max_length", "must be 0.001 to"],
    );
    assert_scene_rejected(
        format!("(name: \"x\", {bodies}, joints: (list: [], iterations: 0))").as_bytes(),
        &["joints.iterations", "must be 1 to 8"],
    );
    assert_scene_rejected(
        with("(kind: Ball, bodies: (0, 1), anchor: (x: 0.0, y: 0.0, z: 0.0), grid: (count: (3, 1, 1), stride_b: (1, 0, 0)))").as_bytes(),
        &["joints.list[0] (copy (1, 0, 0)).bodies.1", "names body 2"],
    );
}

#[test]
fn rigid_body_errors_name_the_field() {
    assert_scene_rejected(
        b"(name: \"x\", rigid: (bodies: [(shape: Sphere(radius: -1.0))]))",
        &["rigid.bodies[0].shape.Sphere.radius", "must be above 0"],
    );
    assert_scene_rejected(
        b"(name: \"x\", rigid: (bodies: [(shape: Plane(normal: (x: 0.0, y: 1.0, z: 0.0), offset: 0.0))]))",
        &["rigid.bodies[0].shape.Plane", "only be a static body"],
    );
    assert_scene_rejected(
        b"(name: \"x\", rigid: (solver: (substeps: 0)))",
        &["rigid.solver.substeps", "must be 1 to 64"],
    );
    // Lattices whose copies overflow 64 bits: refused, not a panic (found by fuzzing).
    assert_scene_rejected(
        b"(name: \"x\", rigid: (bodies: [(shape: Sphere(radius: 1.0), grid: (count: (4294967295, 4294967295, 4294967295), spacing: (x: 3.0, y: 3.0, z: 3.0)))]))",
        &["rigid.bodies", "more than"],
    );
    assert_scene_rejected(
        b"(name: \"x\", soft: (bodies: [(shape: Lattice(origin: (x: 0.0, y: 0.0, z: 0.0), spacing: 0.1, count: (4294967295, 4294967295, 4294967295)), model: SpringMass(stiffness: 10.0), mass: 1.0)]))",
        &["soft.bodies[0]", "more than"],
    );
}

/// Orientations whose normalised form would not be a rotation in I32F32: |q|² past the
/// range (a component of 50,000) or lost in its precision (a length of 2·10⁻⁵), and zero.
/// Found by fuzzing: a body oriented by (0.99, 0, −2³¹, −0.15) was built with a
/// "normalised" orientation of length about 46,000, and the frames of the joints on it
/// failed the snapshot decoder's checks.
#[test]
fn orientations_of_any_length_are_normalised_and_zero_is_refused() {
    let body = |orientation: &str| {
        format!(
            "(name: \"x\", rigid: (bodies: [(kind: Static, shape: Box(half_extents: (x: 5.0, y: 0.5, z: 5.0))), (shape: Box(half_extents: (x: 0.5, y: 0.2, z: 0.3)), position: (x: 0.0, y: 2.0, z: 0.0), orientation: {orientation}, angular_velocity: (x: 1.0, y: 2.0, z: 0.5))]))"
        )
    };
    let run = |text: String| {
        let file = TempPath::with_bytes("scene.ron", text.as_bytes());
        let run = fixstep(&["run", file.str(), "--ticks", "60"]);
        assert_eq!(run.code, 0, "{run:?}");
        run.stdout.lines().last().map(str::to_owned)
    };
    // A half turn about y given at unit length, 2¹⁶ times longer (its |q|² would saturate
    // I32F32) and 2²⁴ times shorter (its |q|² would round to 0): scaled by powers of two,
    // all three normalise to the same bits and run alike.
    let unit = run(body("(w: 0.0, x: 0.0, y: 1.0, z: 0.0)"));
    assert_eq!(run(body("(w: 0.0, x: 0.0, y: 65536.0, z: 0.0)")), unit);
    assert_eq!(
        run(body(
            "(w: 0.0, x: 0.0, y: 0.000000059604644775390625, z: 0.0)"
        )),
        unit
    );
    assert_scene_rejected(
        body("(w: 0.0, x: 0.0, y: 0.0, z: 0.0)").as_bytes(),
        &["rigid.bodies[1].orientation", "must not be zero"],
    );
    assert_scene_rejected(
        b"(name: \"x\", rigid: (bodies: [(shape: Compound(parts: [(rotation: (w: 0.0, x: 0.0, y: 0.0, z: 0.0), translation: (x: 0.0, y: 0.0, z: 0.0), shape: Sphere(radius: 1.0))]))]))",
        &[
            "rigid.bodies[0].shape.Compound.parts[0].rotation",
            "must not be zero",
        ],
    );
    assert_scene_rejected(
        b"(name: \"x\", soft: (bodies: [], colliders: [(shape: Plane(normal: (x: 0.0, y: 1.0, z: 0.0), offset: 0.0), orientation: (w: 0.0, x: 0.0, y: 0.0, z: 0.0))]))",
        &["soft.colliders[0].orientation", "must not be zero"],
    );
}

/// A compound part's rotation is normalised like a body's orientation: parts turned by
/// (2, 0, 2, 0) and by (½, 0, ½, 0), a quarter turn about y either way, run alike
/// (unnormalised, the rotation scaled the part's inertia and collision shape, and the
/// two ran apart).
#[test]
fn a_compound_parts_rotation_is_normalised() {
    let run = |s: &str| {
        let text = format!(
            "(name: \"x\", rigid: (bodies: [(kind: Static, shape: Box(half_extents: (x: 5.0, y: 0.5, z: 5.0))), (shape: Compound(parts: [(rotation: (w: {s}, x: 0.0, y: {s}, z: 0.0), translation: (x: 0.3, y: 0.0, z: 0.0), shape: Box(half_extents: (x: 0.5, y: 0.1, z: 0.2))), (rotation: (w: 1.0, x: 0.0, y: 0.0, z: 0.0), translation: (x: -0.3, y: 0.0, z: 0.0), shape: Sphere(radius: 0.2))]), position: (x: 0.0, y: 1.0, z: 0.0), angular_velocity: (x: 1.0, y: 2.0, z: 0.5))]))"
        );
        let file = TempPath::with_bytes("scene.ron", text.as_bytes());
        let run = fixstep(&["run", file.str(), "--ticks", "60"]);
        assert_eq!(run.code, 0, "{run:?}");
        run.stdout.lines().last().map(str::to_owned)
    };
    assert_eq!(run("2.0"), run("0.5"));
}

#[test]
fn zero_tick_rate_names_the_field() {
    assert_scene_rejected(b"(name: \"x\", tick_rate: 0)", &["tick_rate"]);
}

#[test]
fn unregistered_user_force_names_the_field() {
    assert_scene_rejected(
        b"(name: \"x\", particles: (forces: [Gravity(), User(name: \"wind\")]))",
        &[
            "particles.forces[1].name",
            "no user force is registered as `wind`",
        ],
    );
}

#[test]
fn invalid_utf8() {
    assert_scene_rejected(b"(name: \"\xff\xfe\")", &["not valid UTF-8"]);
}

#[test]
fn a_directory() {
    let dir = TempPath::new("dir.ron");
    std::fs::create_dir(dir.path()).expect("create");
    fixstep(&["run", dir.str()]).assert_error(&[dir.str(), "is a directory"]);
}

#[test]
fn a_missing_file() {
    let missing = TempPath::new("missing.ron");
    fixstep(&["run", missing.str()]).assert_error(&[missing.str(), "cannot read"]);
}

#[test]
fn a_breaking_joint_is_reported_on_stderr() {
    let text = b"(name: \"breaks\", ticks: 3, rigid: (bodies: [(kind: Static, shape: Sphere(radius: 0.1)), (shape: Box(half_extents: (x: 0.25, y: 0.25, z: 0.25)), position: (x: 0.0, y: -0.25, z: 0.0), density: 800.0)]), joints: (list: [(kind: Ball, bodies: (0, 1), anchor: (x: 0.0, y: 0.0, z: 0.0), break_force: 600.0)]))";
    let file = TempPath::with_bytes("breaks.ron", text);
    let out = fixstep(&["run", file.str()]);
    assert_eq!(out.code, 0, "{out:?}");
    assert!(out.stderr.contains("tick 1: joint 0v0 broke ("), "{out:?}");
}

#[test]
fn a_fluid_cfl_number_out_of_range_names_the_field() {
    let fluid = "fluid: (solver: Dfsph, spacing: 0.02, substeps: 4, \
                 tank: (min: (x: 0.0, y: 0.0, z: 0.0), max: (x: 0.2, y: 0.2, z: 0.2)), cfl: ";
    for cfl in ["2.0", "-0.1", "0.001"] {
        let text = format!("(name: \"x\", {fluid}{cfl}))");
        assert_scene_rejected(text.as_bytes(), &["fluid.cfl", "must be 0", "or 0.01 to 1"]);
    }
}

/// The hand-written scene with adaptive fluid substeps records a replay that verifies, and
/// its metrics show the count adapting: one substep at the first tick, more as the front
/// speeds up, never more than the scene's 8.
#[test]
fn adaptive_fluid_substeps_record_verify_and_report() {
    let scene = scenes_dir().join("dam_break_adaptive.ron");
    let scene = scene.to_str().expect("UTF-8");
    let replay = TempPath::new("dam_break_adaptive.replay");
    let metrics = TempPath::new("dam_break_adaptive.csv");
    let run = fixstep(&[
        "run",
        scene,
        "--record",
        replay.str(),
        "--metrics",
        metrics.str(),
    ]);
    assert_eq!(run.code, 0, "{run:?}");
    let verified = fixstep(&["verify", replay.str()]);
    assert_eq!(verified.code, 0, "{verified:?}");
    let text = std::fs::read_to_string(metrics.str()).expect("metrics written");
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().expect("a header").split(',').collect();
    let column = header
        .iter()
        .position(|&c| c == "fluid_substeps")
        .expect("a fluid_substeps column");
    let counts: Vec<u32> = lines
        .map(|l| {
            l.split(',')
                .nth(column)
                .expect("the column")
                .parse()
                .expect("a count")
        })
        .collect();
    assert_eq!(counts[0], 0, "before the first step");
    assert_eq!(counts[1], 1, "the column at rest");
    let most = *counts.iter().max().expect("rows");
    assert!((3..=8).contains(&most), "{counts:?}");
}

#[test]
fn soft_coupling_errors_name_the_field() {
    let rope = |extra: &str, model: &str| {
        format!(
            "(name: \"x\", rigid: Some((bodies: [(kind: Dynamic, shape: Sphere(radius: 0.1))])), \
             soft: Some((bodies: [(shape: Rope(start: (x: 0.0, y: 1.0, z: 0.0), \
             end: (x: 1.0, y: 1.0, z: 0.0), links: 4), model: {model}, mass: 1.0, {extra})])))"
        )
        .into_bytes()
    };
    let xpbd = "Xpbd(stretch_compliance: 0.0)";
    assert_scene_rejected(
        &rope("body_attachments: [(body: 3, vertices: [4])]", xpbd),
        &[
            "soft.bodies[0].body_attachments[0].body",
            "names body 3, but the scene has 1 rigid bodies",
        ],
    );
    assert_scene_rejected(
        &rope("body_attachments: [(body: 0, vertices: [9])]", xpbd),
        &[
            "soft.bodies[0].body_attachments[0].vertices[0]",
            "vertex 9 does not exist",
        ],
    );
    assert_scene_rejected(
        &rope("body_contacts: Some((friction: -1.0))", xpbd),
        &["soft.bodies[0].body_contacts.friction"],
    );
    assert_scene_rejected(
        &rope(
            "body_contacts: Some(())",
            "SpringMass(integrator: SemiImplicitEuler, stiffness: 100.0)",
        ),
        &["soft.bodies[0].body_contacts", "only XPBD bodies"],
    );
}

#[test]
fn particle_collision_errors_name_the_field() {
    let with = |entries: &str| {
        format!("(name: \"x\", particles: Some((collisions: [{entries}])))").into_bytes()
    };
    assert_scene_rejected(
        &with("(group: 0, restitution: 1.5)"),
        &["particles.collisions[0].restitution", "must be 0 to 1"],
    );
    assert_scene_rejected(
        &with("(group: 2, friction: -0.1)"),
        &["particles.collisions[0].friction", "must be ≥ 0"],
    );
    assert_scene_rejected(
        &with("(group: 1), (group: 1)"),
        &[
            "particles.collisions[1].group",
            "group 1 already has an entry",
        ],
    );
}
