//! Soft bodies in snapshots: a curtain saved mid-run (with its kinematic target moving)
//! continues bit for bit, and a snapshot of layout version 2 (before soft bodies) still
//! reads.

use fixstep::math::Fx;
use fixstep::replay::InputFeed;
use fixstep::scene::builtin_scene;
use fixstep::world::{World, decode_snapshot, encode_snapshot};

/// Steps `world` from its tick to `end` with the scene's script.
fn run_to(world: &mut World<Fx>, feed: &mut InputFeed<'_>, end: u64) {
    while world.tick() < end {
        let tick = world.tick();
        world.step(feed.at(tick));
    }
}

#[test]
fn curtain_continues_bit_for_bit_from_a_snapshot() {
    let scene = builtin_scene::<Fx>("curtain").expect("built in");
    let mut straight = scene.build().expect("valid");
    let mut feed = InputFeed::new(&scene.script);
    run_to(&mut straight, &mut feed, 75);
    let bytes = encode_snapshot(&straight.snapshot()).expect("encodes");
    run_to(&mut straight, &mut feed, 150);

    let mut resumed = scene.build().expect("valid");
    resumed.restore(&decode_snapshot::<Fx>(&bytes).expect("decodes"));
    let mut feed = InputFeed::new(&scene.script);
    run_to(&mut resumed, &mut feed, 150);
    assert_eq!(resumed.checksum(), straight.checksum());
}

#[test]
fn a_layout_2_snapshot_still_reads() {
    let scene = builtin_scene::<Fx>("stack").expect("built in");
    let mut world = scene.build().expect("valid");
    world.step(&Default::default());
    let mut bytes = encode_snapshot(&world.snapshot()).expect("encodes");
    // Layout 2 is layout 3 without the trailing `soft` field (None: one zero byte).
    let hash_at = bytes.len() - 8;
    assert_eq!(bytes[hash_at - 1], 0);
    bytes.remove(hash_at - 1);
    bytes[8..12].copy_from_slice(&2u32.to_le_bytes());
    let at = bytes.len() - 8;
    let mut hasher = fixstep::math::state_hash::StateHasher::new();
    hasher.write_bytes(&bytes[..at]);
    let hash = hasher.finish();
    bytes[at..].copy_from_slice(&hash.to_le_bytes());
    let state = decode_snapshot::<Fx>(&bytes).expect("a layout 2 snapshot reads");
    assert_eq!(state, world.snapshot());
}
