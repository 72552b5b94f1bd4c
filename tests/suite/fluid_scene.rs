//! The fluid in a world: bad scene fields are refused with the field named, a snapshot
//! taken mid-run continues with the same checksums, and a snapshot file round-trips.

use fixstep::fluid::{FluidBlock, FluidBox, FluidSolver};
use fixstep::math::{Fx, Real, Vec3};
use fixstep::replay::scene_id;
use fixstep::scene::Scene;
use fixstep::world::{Part, TickInput, decode_snapshot, encode_snapshot};
use fixstep_scenes::builtin_scene;
use fixstep_scenes::fluid as presets;

/// A small dam break at 60 Hz: few particles, so the test is quick.
fn small_scene() -> Scene<Fx> {
    let mut scene = Scene::empty("small");
    scene.fluid = Some(presets::dam_break(4, 2, FluidSolver::Dfsph));
    scene
}

fn error_field(scene: &Scene<Fx>) -> String {
    scene
        .build()
        .map(|_| ())
        .expect_err("the scene is refused")
        .field
}

#[test]
fn bad_fields_are_named() {
    let mut scene = small_scene();
    scene.fluid.as_mut().unwrap().spacing = Fx::ZERO;
    assert_eq!(error_field(&scene), "fluid.spacing");

    let mut scene = small_scene();
    scene.fluid.as_mut().unwrap().substeps = 1;
    assert_eq!(error_field(&scene), "fluid.substeps");

    let mut scene = small_scene();
    scene.fluid.as_mut().unwrap().blocks.push(FluidBlock {
        region: FluidBox {
            min: Vec3::ZERO,
            max: Vec3::splat(Fx::from_int(5)),
        },
        velocity: Vec3::ZERO,
    });
    assert_eq!(error_field(&scene), "fluid.blocks[1].region");

    let mut scene = small_scene();
    let fluid = scene.fluid.as_mut().unwrap();
    fluid.tank.max.x = Fx::from_int(-1);
    assert_eq!(error_field(&scene), "fluid.tank.max.x");

    let mut scene = small_scene();
    let fluid = scene.fluid.as_mut().unwrap();
    fluid.tank.max = Vec3::splat(Fx::from_int(1000));
    assert_eq!(error_field(&scene), "fluid.tank.max.x");

    // 300 spacings along each axis: far below the sites' limit, but 2.7·10⁷ grid cells of
    // half a support (2 spacings), above the 2²⁴ a tank may span.
    let mut scene = small_scene();
    let fluid = scene.fluid.as_mut().unwrap();
    fluid.tank.max = fluid.tank.min + Vec3::splat(fluid.spacing * Fx::from_int(300));
    let error = scene.build().map(|_| ()).expect_err("the scene is refused");
    assert_eq!(error.field, "fluid.tank");
    assert!(
        error
            .to_string()
            .contains("grid cells of half a kernel support; at most 16777216"),
        "{error}"
    );

    let mut scene = small_scene();
    scene.fluid.as_mut().unwrap().speed_of_sound = Fx::MAX;
    assert_eq!(error_field(&scene), "fluid.speed_of_sound");
}

#[test]
fn snapshot_mid_run_continues_with_the_same_checksums() {
    let scene = small_scene();
    let empty = TickInput::default();
    let mut straight = scene.build().expect("builds");
    let mut resumed = scene.build().expect("builds");
    for _ in 0..3 {
        straight.step(&empty);
        resumed.step(&empty);
    }
    let bytes =
        encode_snapshot(&resumed.snapshot(), &scene_id(&scene).expect("id")).expect("encodes");
    let state = decode_snapshot::<Fx>(&bytes).expect("decodes").state;
    let mut restored = fixstep::world::World::from_state(state);
    for _ in 0..3 {
        straight.step(&empty);
        restored.step(&empty);
    }
    let a = straight.checksum();
    assert!(a.parts.iter().any(|(part, _)| *part == Part::Fluid));
    assert_eq!(a, restored.checksum());
}

#[test]
fn builtin_fluid_scenes_build_and_step() {
    for name in ["dam_break", "tank", "pour"] {
        let scene = builtin_scene::<Fx>(name).expect("built in");
        let mut world = scene.build().expect("builds");
        let report = world.step(&TickInput::default());
        assert_eq!(report.saturations, 0, "{name}");
        assert!(world.fluid().is_some(), "{name}");
    }
}
