//! Extreme values in valid scenes: the run completes, nothing panics, and the world reports
//! what went wrong (saturation, divergence) in its metrics and as `fixstep run` warnings.
//! A stable scene gets neither.
//!
//! Expected behaviour comes from stability theory: semi-implicit Euler on a spring is stable
//! only for ωh < 2 (ω = √(k/m)); explicit Euler multiplies the energy by 1 + (ωh)² per step.

use crate::replay_support::{TempPath, fixstep};
use fixstep::math::Fx;
use fixstep::replay::InputFeed;
use fixstep::scene::{Scene, parse_scene};
use fixstep::world::{Metrics, World};
use fixstep_scenes::builtin_scene;

/// A one-particle scene: a 1 kg bob on an anchored spring of stiffness `k` (N/m) and rest
/// length 0 (so F = −k x exactly, a linear oscillator), stepped at `tick_rate` Hz with
/// `integrator`, released 1 m from the anchor.
fn spring_scene(integrator: &str, k: &str, tick_rate: u32) -> String {
    format!(
        "(name: \"spring\", tick_rate: {tick_rate}, ticks: 600, gravity: (x: 0.0, y: 0.0, z: 0.0),
          particles: (integrator: {integrator},
            particles: [(position: (x: 1.0, y: 0.0, z: 0.0))],
            forces: [AnchoredSpring(particle: 0, anchor: (x: 0.0, y: 0.0, z: 0.0),
                       spring: (stiffness: {k}, rest_length: 0.0))]))"
    )
}

fn world_of(ron: &str) -> (Scene<Fx>, World<Fx>) {
    let scene: Scene<Fx> = parse_scene(ron, "test.ron").expect("valid scene");
    let world = scene.build().expect("builds");
    (scene, world)
}

/// Runs `ticks` ticks with the divergence check on every tick.
fn run_checked(ron: &str, ticks: u64) -> World<Fx> {
    let (scene, mut world) = world_of(ron);
    world.enable_divergence_check(1);
    let mut feed = InputFeed::new(&scene.script);
    for tick in 0..ticks {
        world.step(feed.at(tick));
    }
    world
}

#[test]
fn semi_implicit_euler_past_its_limit_is_reported_as_divergent() {
    // ω = 150 rad/s at 60 Hz: ωh = 2.5 > 2.
    let world = run_checked(&spring_scene("SemiImplicitEuler", "22500.0", 60), 300);
    let divergence = world.divergence().expect("diverges");
    assert!(divergence.energy_scale > 1e4 * divergence.reference);
    assert!(world.metrics().diverged);
}

#[test]
fn semi_implicit_euler_within_its_limit_is_not_reported() {
    // ω = 90 rad/s at 60 Hz: ωh = 1.5 < 2, energy bounded.
    let world = run_checked(&spring_scene("SemiImplicitEuler", "8100.0", 60), 600);
    assert_eq!(world.divergence(), None);
    assert!(!world.metrics().diverged);
    assert_eq!(world.saturations_total(), 0);
}

#[test]
fn explicit_euler_is_caught_before_the_numeric_range() {
    // ωh = 0.5: the energy (450 J at tick 0, the reference) grows by 1.25 per step, past
    // 10⁴-fold after ln(10⁴)/ln(1.25) ≈ 41.3 steps, so at tick 42, long before it saturates
    // (2³¹ J would take ≈ 68 steps).
    let world = run_checked(&spring_scene("ExplicitEuler", "900.0", 60), 60);
    let divergence = world.divergence().expect("diverges");
    assert_eq!(divergence.tick, 42, "{divergence:?}");
    assert!(
        (divergence.reference - 450.0).abs() < 1e-6,
        "{divergence:?}"
    );
    assert_eq!(world.saturations_total(), 0);
}

#[test]
fn builtin_scenes_never_report_divergence() {
    for (name, _) in fixstep_scenes::BUILTIN_SCENES {
        let scene: Scene<Fx> = builtin_scene(name).expect("built in");
        let mut world = scene.build().expect("builds");
        world.enable_divergence_check(1);
        let mut feed = InputFeed::new(&scene.script);
        for tick in 0..scene.ticks {
            world.step(feed.at(tick));
        }
        assert_eq!(world.divergence(), None, "{name}");
        assert_eq!(world.saturations_total(), 0, "{name}");
    }
}

#[test]
fn run_warns_about_a_stiff_spring_at_a_large_step() {
    let scene = TempPath::with_bytes(
        "stiff.ron",
        spring_scene("SemiImplicitEuler", "1000000.0", 30).as_bytes(),
    );
    let run = fixstep(&["run", scene.str(), "--ticks", "200"]);
    assert_eq!(run.code, 0, "{run:?}");
    assert!(
        run.stderr
            .contains("warning: the simulation diverged at tick"),
        "{}",
        run.stderr
    );
    assert!(
        run.stderr.contains("fixed-point saturations"),
        "{}",
        run.stderr
    );
    assert!(!run.stderr.contains("panicked"), "{}", run.stderr);
}

#[test]
fn metrics_mark_the_divergence() {
    let scene = TempPath::with_bytes(
        "unstable.ron",
        spring_scene("ExplicitEuler", "900.0", 60).as_bytes(),
    );
    let csv = TempPath::new("unstable.csv");
    let run = fixstep(&["run", scene.str(), "--ticks", "60", "--metrics", csv.str()]);
    assert_eq!(run.code, 0, "{run:?}");
    let text = std::fs::read_to_string(csv.path()).expect("metrics written");
    let column = Metrics::CSV_HEADER
        .split(',')
        .position(|name| name == "diverged")
        .expect("a diverged column");
    let diverged = |row: &str| row.split(',').nth(column).map(str::to_owned);
    let rows: Vec<&str> = text.lines().skip(1).collect();
    assert_eq!(
        diverged(rows.first().expect("rows")).as_deref(),
        Some("0"),
        "{text}"
    );
    assert_eq!(
        diverged(rows.last().expect("rows")).as_deref(),
        Some("1"),
        "{text}"
    );
}

#[test]
fn positions_and_forces_at_the_numeric_range_saturate_without_a_panic() {
    let ron = "(name: \"edge\", ticks: 100, gravity: (x: 0.0, y: -1000000000.0, z: 0.0),
      particles: (particles: [
          (position: (x: 2147483000.0, y: -2147483000.0, z: 0.0),
           velocity: (x: 1000000000.0, y: -1000000000.0, z: 0.0)),
          (position: (x: 0.0, y: 0.0, z: 0.0), mass: 0.000001),
          (position: (x: 0.0, y: 0.0, z: 0.0), mass: 1000000.0)],
        forces: [Gravity(), QuadraticDrag(coefficient: 1000000.0),
                 Spring(first: 1, second: 2, spring: (stiffness: 1000000000.0, rest_length: 0.0)),
                 PointGravity(centre: (x: 0.0, y: 0.0, z: 0.0), gm: 1000000000.0, softening: 0.0)]))";
    let scene = TempPath::with_bytes("edge.ron", ron.as_bytes());
    let run = fixstep(&["run", scene.str()]);
    assert_eq!(run.code, 0, "{run:?}");
    assert!(
        run.stderr.contains("fixed-point saturations"),
        "{}",
        run.stderr
    );
    let again = fixstep(&["run", scene.str()]);
    assert_eq!(run.stdout.lines().last(), again.stdout.lines().last());
}

#[test]
fn coincident_particles_on_a_zero_length_spring_stay_finite() {
    let ron = "(name: \"coincident\", ticks: 60,
      particles: (particles: [(position: (x: 1.0, y: 1.0, z: 1.0)), (position: (x: 1.0, y: 1.0, z: 1.0))],
        forces: [Spring(first: 0, second: 1, spring: (stiffness: 100.0, damping: 1.0, rest_length: 0.0)),
                 PointGravity(centre: (x: 0.0, y: 0.0, z: 0.0), gm: 1.0, softening: 0.0)]))";
    let world = run_checked(ron, 60);
    assert_eq!(world.saturations_total(), 0);
    assert_eq!(world.divergence(), None);
}
