//! Soft bodies in snapshots: a curtain saved mid-run (with its kinematic target moving)
//! continues bit for bit.

use fixstep::math::Fx;
use fixstep::replay::{InputFeed, scene_id};
use fixstep::world::{World, decode_snapshot, encode_snapshot};
use fixstep_scenes::builtin_scene;

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
    let bytes =
        encode_snapshot(&straight.snapshot(), &scene_id(&scene).expect("id")).expect("encodes");
    run_to(&mut straight, &mut feed, 150);

    let mut resumed = scene.build().expect("valid");
    resumed.restore(&decode_snapshot::<Fx>(&bytes).expect("decodes").state);
    let mut feed = InputFeed::new(&scene.script);
    run_to(&mut resumed, &mut feed, 150);
    assert_eq!(resumed.checksum(), straight.checksum());
}
