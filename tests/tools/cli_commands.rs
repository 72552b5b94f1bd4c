//! The `fixstep` command line: its contract of commands, outputs and exit codes.

use crate::replay_support::{TempPath, fixstep, fixstep_with_env, sample_bytes};
use fixstep::world::{Metrics, Stage};
use fixstep_scenes::BUILTIN_SCENES;

/// True for `checksum: ` followed by 16 lowercase hex digits.
fn is_checksum_line(line: &str) -> bool {
    line.strip_prefix("checksum: ").is_some_and(|hex| {
        hex.len() == 16
            && hex
                .bytes()
                .all(|b| b.is_ascii_digit() || (b'a'..=b'f').contains(&b))
    })
}

#[test]
fn scenes_lists_every_builtin() {
    let run = fixstep(&["scenes"]);
    assert_eq!(run.code, 0, "{run:?}");
    let expected: Vec<String> = BUILTIN_SCENES
        .iter()
        .map(|(name, description)| format!("{name}  {description}"))
        .collect();
    assert_eq!(run.stdout.lines().collect::<Vec<_>>(), expected);
}

#[test]
fn run_prints_stage_timings_then_the_checksum_last() {
    let run = fixstep(&["run", "fountain", "--ticks", "30"]);
    assert_eq!(run.code, 0, "{run:?}");
    let lines: Vec<&str> = run.stdout.lines().collect();
    let last = lines.last().expect("output");
    assert!(is_checksum_line(last), "{last:?}");
    let table = run.stdout.as_str();
    assert!(
        table.contains("total ms") && table.contains("µs per run"),
        "{table}"
    );
    for stage in [Stage::ApplyInputs, Stage::Particles, Stage::EndTick] {
        let row = lines
            .iter()
            .find(|l| l.starts_with(stage.name()))
            .unwrap_or_else(|| panic!("no row for {}: {table}", stage.name()));
        assert!(row.ends_with(" 30"), "{row}");
    }
    assert!(run.stderr.is_empty(), "{}", run.stderr);
}

#[test]
fn run_is_deterministic_and_seed_accepts_hex() {
    let a = fixstep(&["run", "fountain", "--ticks", "40", "--seed", "0x10"]);
    let b = fixstep(&["run", "fountain", "--ticks", "40", "--seed", "16"]);
    assert_eq!(a.code, 0, "{a:?}");
    assert_eq!(a.stdout.lines().last(), b.stdout.lines().last());
}

#[test]
fn no_arguments_runs_the_showcase() {
    let bare = fixstep::<&str>(&[]);
    assert_eq!(bare.code, 0, "{bare:?}");
    assert!(bare.stdout.starts_with("showcase: "), "{}", bare.stdout);
    let explicit = fixstep(&["run", "showcase"]);
    let mut lines = bare.stdout.lines().rev();
    assert_eq!(lines.next(), Some(fixstep_cli::SHOW_IN_3D));
    let checksum = lines.next().expect("output");
    assert!(is_checksum_line(checksum), "{checksum:?}");
    assert_eq!(Some(checksum), explicit.stdout.lines().last());
}

#[test]
fn metrics_csv_has_the_header_and_a_row_every_k_ticks_and_at_the_end() {
    let csv = TempPath::new("metrics.csv");
    let run = fixstep(&[
        "run",
        "fountain",
        "--ticks",
        "10",
        "--metrics",
        csv.str(),
        "--every",
        "3",
    ]);
    assert_eq!(run.code, 0, "{run:?}");
    let text = std::fs::read_to_string(csv.path()).expect("written");
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some(Metrics::CSV_HEADER));
    let columns = Metrics::CSV_HEADER.split(',').count();
    let ticks: Vec<u64> = lines
        .map(|row| {
            let fields: Vec<&str> = row.split(',').collect();
            assert_eq!(fields.len(), columns, "{row}");
            fields[0].parse().expect("tick column")
        })
        .collect();
    assert_eq!(ticks, [0, 3, 6, 9, 10]);
}

#[test]
fn metrics_every_tick_by_default() {
    let csv = TempPath::new("every.csv");
    let run = fixstep(&["run", "orbits", "--ticks", "4", "--metrics", csv.str()]);
    assert_eq!(run.code, 0, "{run:?}");
    let text = std::fs::read_to_string(csv.path()).expect("written");
    assert_eq!(text.lines().count(), 1 + 5, "{text}");
}

#[test]
fn saturations_are_a_warning_not_an_error() {
    let scene = TempPath::with_bytes(
        "saturating.ron",
        b"(name: \"saturating\", particles: (particles: [(
            position: (x: 2000000000.0, y: 0.0, z: 0.0),
            velocity: (x: 2000000000.0, y: 0.0, z: 0.0),
        )]))",
    );
    let run = fixstep(&["run", scene.str(), "--ticks", "5"]);
    assert_eq!(run.code, 0, "{run:?}");
    let warning = run.stderr.trim_end();
    assert!(
        warning.starts_with("warning: 1 fixed-point saturations (values hit the numeric range)")
            && warning.ends_with(
                "the first at tick 4 (1 that tick), in the particles stage, particle 0v0 \
                 holding a value at the range's edge"
            )
            && warning.lines().count() == 1,
        "{warning:?}"
    );
    assert!(is_checksum_line(run.stdout.lines().last().expect("output")));
}

#[test]
fn info_describes_a_replay() {
    let file = TempPath::with_bytes("info.replay", &sample_bytes());
    let run = fixstep(&["info", file.str()]);
    assert_eq!(run.code, 0, "{run:?}");
    for expected in [
        "format version: 1",
        "scalar: I32F32",
        "scene: scripted",
        "tick rate: 60 Hz",
        "seed: 0x5eed",
        "ticks: 130",
        "input ticks: 3",
        "checkpoints: 4 (every 60 ticks)",
        "final checksum: ",
        "particles: ",
        "rigid bodies: none",
        "joints: none",
        "soft bodies: none",
        "fluid: none",
    ] {
        assert!(
            run.stdout.contains(expected),
            "{expected:?} in {}",
            run.stdout
        );
    }
}

#[test]
fn info_describes_the_fluid_and_its_substeps() {
    let root = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."));
    for (file, line) in [
        (
            "replays/dam_break_adaptive.replay",
            "fluid: Dfsph, spacing 0.01143 m, 1 blocks, 0 emitters, adaptive substeps (CFL 0.2), at most 8\n",
        ),
        (
            "replays/pour.replay",
            "fluid: Dfsph, spacing 0.02 m, 0 blocks, 1 emitters, 10 substeps\n",
        ),
    ] {
        let run = fixstep(&["info", root.join(file).to_str().expect("UTF-8")]);
        assert_eq!(run.code, 0, "{run:?}");
        assert!(run.stdout.contains(line), "{line:?} in {}", run.stdout);
    }
}

#[test]
fn info_describes_the_soft_bodies() {
    let root = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."));
    for (file, line) in [
        (
            "replays/cloth.replay",
            "soft bodies: 1 (32x32 cloth, XPBD), 1024 vertices, 0 colliders, XPBD 40 substeps of 1 iterations\n",
        ),
        (
            "replays/rope.replay",
            "soft bodies: 1 (20-link rope, XPBD), 21 vertices, 0 colliders, XPBD 20 substeps of 1 iterations\n",
        ),
        (
            "replays/jelly.replay",
            "soft bodies: 1 (6x6x6 lattice, spring-mass), 216 vertices, 1 colliders\n",
        ),
    ] {
        let run = fixstep(&["info", root.join(file).to_str().expect("UTF-8")]);
        assert_eq!(run.code, 0, "{run:?}");
        assert!(run.stdout.contains(line), "{line:?} in {}", run.stdout);
    }
}

#[test]
fn info_counts_bodies_and_joints() {
    let root = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."));
    let run = fixstep(&[
        "info",
        root.join("replays/ragdolls.replay")
            .to_str()
            .expect("UTF-8"),
    ]);
    assert_eq!(run.code, 0, "{run:?}");
    assert!(
        run.stdout
            .contains("rigid bodies: 55 (4 sphere, 14 box, 36 capsule, 1 plane)\n"),
        "{}",
        run.stdout
    );
    assert!(
        run.stdout
            .contains("joints: 40 (24 cone-twist, 16 hinge)\n"),
        "{}",
        run.stdout
    );
}

#[test]
fn info_on_a_bad_file_is_one_error_line() {
    let file = TempPath::with_bytes("bad.replay", b"FXSTEPRP");
    fixstep(&["info", file.str()]).assert_error(&[file.str(), "truncated"]);
}

#[test]
fn unknown_scene_is_an_error() {
    let run = fixstep(&["run", "no-such-scene"]);
    run.assert_error(&["unknown scene `no-such-scene`", "showcase"]);
}

#[test]
fn bad_arguments_exit_2() {
    for args in [
        &["bogus"][..],
        &["run", "fountain", "--ticks", "many"],
        &["run", "fountain", "--every", "0"],
        &["run", "fountain", "--seed", "0xZZ"],
        &["run", "fountain", "--frobnicate"],
        &["verify"],
        &["rerecord"],
        &["info"],
        &["scenes", "extra"],
    ] {
        let run = fixstep(args);
        assert_eq!(run.code, 2, "{args:?}: {run:?}");
        assert!(run.stdout.is_empty(), "{args:?}: {}", run.stdout);
        assert!(!run.stderr.contains("panicked"), "{args:?}: {}", run.stderr);
    }
}

#[test]
fn record_and_metrics_to_one_file_is_an_error() {
    let file = TempPath::new("both");
    let run = fixstep(&[
        "run",
        "fountain",
        "--record",
        file.str(),
        "--metrics",
        file.str(),
    ]);
    run.assert_error(&[&format!("--metrics {0} is also --record {0}", file.str())]);
    assert!(!file.path().exists());
}

#[test]
fn help_and_version_exit_0() {
    for args in [&["--help"][..], &["--version"], &["run", "--help"]] {
        let run = fixstep(args);
        assert_eq!(run.code, 0, "{args:?}: {run:?}");
    }
}

/// The checksum line of a run.
fn checksum_line(stdout: &str) -> &str {
    stdout.lines().last().unwrap_or_default()
}

#[test]
fn every_simd_cap_gives_the_same_checksums() {
    // Scenes whose stages have kernels: rigid contacts and joints, the fluid, the cloth and
    // the particles. Each cap takes other code on a processor that has the kernels, with
    // the same bits.
    for (scene, ticks) in [
        ("pyramid", "30"),
        ("ragdolls", "30"),
        ("dam_break", "3"),
        ("cloth", "30"),
        ("fountain", "60"),
    ] {
        let args = ["run", scene, "--ticks", ticks];
        let uncapped = fixstep(&args);
        assert_eq!(uncapped.code, 0, "{uncapped:?}");
        assert!(
            is_checksum_line(checksum_line(&uncapped.stdout)),
            "{uncapped:?}"
        );
        // The caps of this machine's architecture (the tools' tests run on x86-64 and
        // aarch64 hosts alike).
        let caps: &[&str] = if cfg!(target_arch = "aarch64") {
            &["avx512", "neon", "scalar"]
        } else {
            &["avx512", "avx2", "scalar"]
        };
        for &cap in caps {
            let capped = fixstep_with_env(&args, &[("FIXSTEP_SIMD", cap)]);
            assert_eq!(capped.code, 0, "{scene}, {cap}: {capped:?}");
            assert_eq!(
                checksum_line(&capped.stdout),
                checksum_line(&uncapped.stdout),
                "{scene}, FIXSTEP_SIMD={cap}"
            );
        }
    }
}

#[test]
fn an_unknown_simd_cap_is_refused() {
    let run = fixstep_with_env(
        &["run", "stack", "--ticks", "1"],
        &[("FIXSTEP_SIMD", "sse9")],
    );
    assert_eq!(run.code, 2, "{run:?}");
    assert!(run.stdout.is_empty(), "{run:?}");
    assert!(
        run.stderr.contains("FIXSTEP_SIMD") && run.stderr.contains("`sse9`"),
        "{}",
        run.stderr
    );
}

#[test]
fn a_simd_cap_of_another_architecture_is_refused() {
    let cap = if cfg!(target_arch = "aarch64") {
        "avx2"
    } else {
        "neon"
    };
    let run = fixstep_with_env(&["run", "stack", "--ticks", "1"], &[("FIXSTEP_SIMD", cap)]);
    assert_eq!(run.code, 2, "{run:?}");
    assert!(run.stdout.is_empty(), "{run:?}");
    assert!(
        run.stderr.starts_with("error: ")
            && run.stderr.contains(&format!("`{cap}` is not available")),
        "{}",
        run.stderr
    );
}

#[test]
fn info_names_the_colliding_particle_groups() {
    let root = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."));
    let run = fixstep(&[
        "info",
        root.join("replays/debris.replay").to_str().expect("UTF-8"),
    ]);
    assert_eq!(run.code, 0, "{run:?}");
    let expected = "colliding with rigid bodies: group 0 (e 0.3, μ 0.4, pushing)";
    assert!(
        run.stdout.contains(expected),
        "{expected:?} in {}",
        run.stdout
    );
}

#[test]
fn info_names_the_rigid_bodies_the_fluid_meets() {
    let root = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."));
    let run = fixstep(&[
        "info",
        root.join("replays/harbour.replay").to_str().expect("UTF-8"),
    ]);
    assert_eq!(run.code, 0, "{run:?}");
    let expected = "meets rigid bodies on layers 0x1 (mask 0x1), two-way";
    assert!(
        run.stdout.contains(expected),
        "{expected:?} in {}",
        run.stdout
    );
}

#[test]
fn info_names_the_soft_bodies_coupled_to_rigid_bodies() {
    let root = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."));
    let run = fixstep(&[
        "info",
        root.join("replays/flag.replay").to_str().expect("UTF-8"),
    ]);
    assert_eq!(run.code, 0, "{run:?}");
    for expected in [
        "13x9 cloth, XPBD, 9 vertices tied to body 1, touching rigid bodies (μ 0.5)",
        "10-link rope, XPBD, 1 vertex tied to body 2",
    ] {
        assert!(
            run.stdout.contains(expected),
            "{expected:?} in {}",
            run.stdout
        );
    }
}

#[test]
fn info_gives_mesh_statistics() {
    let root = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."));
    let run = fixstep(&[
        "info",
        root.join("replays/terrain.replay").to_str().expect("UTF-8"),
    ]);
    assert_eq!(run.code, 0, "{run:?}");
    // The bowl: 24 × 32 cells of 2 triangles on 25 × 33 vertices; the hill: 32 × 32 cells
    // on 33 × 33 samples. Active edges: the boundaries and the convex creases.
    for expected in [
        "1 triangle mesh (1536 triangles, 825 vertices, ",
        "1 heightfield (2048 triangles, 1089 vertices, ",
    ] {
        assert!(
            run.stdout.contains(expected),
            "{expected:?} in {}",
            run.stdout
        );
    }
}
