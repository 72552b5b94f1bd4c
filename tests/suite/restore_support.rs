//! A check shared by the scene tests: a built-in scene restored mid-run, from a snapshot in
//! memory and from its encoded bytes, continues with the uninterrupted run's checksums.

use fixstep::math::Fx;
use fixstep::world::{TickInput, World};

/// Runs built-in scene `name` for `ticks` ticks uninterrupted; runs it again to tick `at`,
/// snapshots it, steps on 5 ticks, restores the snapshot (and decodes its bytes into a
/// fresh world), and checks that both continue with the uninterrupted run's checksums to
/// `ticks`. Returns the uninterrupted world, for the caller's own checks.
pub fn restored_mid_run_continues(name: &str, ticks: u64, at: u64) -> World<Fx> {
    let scene = fixstep_scenes::builtin_scene::<Fx>(name).expect("built in");
    let mut reference = scene.build().expect("builds");
    let mut uninterrupted = Vec::new();
    for _ in 0..ticks {
        reference.step(&TickInput::default());
        uninterrupted.push(reference.checksum());
    }
    let mut world = scene.build().expect("builds");
    for _ in 0..at {
        world.step(&TickInput::default());
    }
    let snapshot = world.snapshot();
    let bytes = fixstep::codec::encode(&snapshot).expect("encodes");
    for _ in 0..5 {
        world.step(&TickInput::default());
    }
    world.restore(&snapshot);
    let mut fresh: World<Fx> =
        World::from_state(fixstep::codec::decode_exact(&bytes).expect("decodes"));
    for tick in at..ticks {
        world.step(&TickInput::default());
        fresh.step(&TickInput::default());
        let expected = &uninterrupted[tick as usize];
        assert_eq!(&world.checksum(), expected, "{name} restored, tick {tick}");
        assert_eq!(&fresh.checksum(), expected, "{name} decoded, tick {tick}");
    }
    reference
}
