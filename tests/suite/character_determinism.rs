//! Characters under rollback and at any speed: snapshot and restore at every tick of
//! `parkour` gives the same bits; random moves in random box mazes never end inside a box
//! nor pass through the maze's walls, up to 50 m/s.

use fixstep::character::CharacterDesc;
use fixstep::math::{Fx, Quat, Real};
use fixstep::rigid::{QueryFilter, Shape};
use fixstep::world::{TickInput, World};
use proptest::prelude::*;

use super::character_support::*;

#[test]
fn parkour_restored_at_every_tick_gives_the_same_bits() {
    let scene = fixstep_scenes::builtin_scene::<Fx>("parkour").expect("built in");
    let input = |tick: u64| scene.script_at(tick).cloned().unwrap_or_default();
    let mut reference = scene.build().expect("builds");
    let mut world = scene.build().expect("builds");
    for tick in 0..scene.ticks {
        let snapshot = world.snapshot();
        world.step(&input(tick));
        // A mispredicted tick (other inputs), then the rollback.
        world.step(&TickInput::default());
        world.restore(&snapshot);
        let bytes = fixstep::codec::encode(&world.snapshot()).expect("encodes");
        let mut decoded: World<Fx> =
            World::from_state(fixstep::codec::decode_exact(&bytes).expect("decodes"));
        world.step(&input(tick));
        decoded.step(&input(tick));
        let report = reference.step(&input(tick));
        assert_eq!(world.checksum(), reference.checksum(), "tick {tick}");
        assert_eq!(
            decoded.checksum(),
            reference.checksum(),
            "decoded, tick {tick}"
        );
        assert_eq!(world.events(), &report.events[..], "tick {tick}");
    }
    let characters = reference.characters().expect("characters").characters();
    assert!(characters.iter().all(|c| c.position.y > Fx::ZERO));
}

/// The shrunk shape of a capsule character, to test for overlap (the skin is 1 cm).
fn inner_capsule() -> Shape<Fx> {
    Shape::Capsule {
        radius: fx(0.295),
        half_height: fx(0.5),
    }
}

/// A maze: a floor, four walls 0.2 m thick around a 10 m × 10 m arena and `boxes` boxes
/// (cell x, cell z, height in tenths, width in tenths) on a 1 m grid.
fn maze(boxes: &[(i32, i32, i32, i32)]) -> Vec<fixstep::rigid::BodyDesc<Fx>> {
    let mut bodies = vec![floor(-20.0, 20.0)];
    for (cx, cz, hx, hz) in [
        (5.1, 0.0, 0.1, 5.2),
        (-5.1, 0.0, 0.1, 5.2),
        (0.0, 5.1, 5.2, 0.1),
        (0.0, -5.1, 5.2, 0.1),
    ] {
        bodies.push(slab(v(cx, 2.0, cz), v(hx, 2.0, hz), 0.0));
    }
    for &(x, z, height, width) in boxes {
        let (h, w) = (f64::from(height) / 10.0, f64::from(width) / 20.0);
        bodies.push(slab(
            v(f64::from(x) + 0.5, h / 2.0, f64::from(z) + 0.5),
            v(w, h / 2.0, w),
            0.0,
        ));
    }
    bodies
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn random_moves_in_a_box_maze_never_end_inside_a_box_or_leave_it(
        boxes in prop::collection::vec((-5i32..5, -5i32..5, 1i32..20, 3i32..10), 0..25),
        moves in prop::collection::vec(([-500i32..500, -500i32..500], any::<bool>(), 1u32..20), 1..12),
    ) {
        let bodies = maze(&boxes);
        // Start at the first free cell along the diagonal.
        let probe = world(bodies.clone(), vec![]);
        let free = (-4..5).map(|k| v(f64::from(k) + 0.5, 1.0, f64::from(k) + 0.5)).find(|p| {
            probe.overlap(&capsule(), *p, Quat::IDENTITY, &QueryFilter::new()).is_empty()
        });
        let Some(start) = free else { return Ok(()); };
        let mut w = world(bodies, vec![CharacterDesc::new(capsule(), start)]);
        for (velocity, jump, ticks) in moves {
            let vel = v(f64::from(velocity[0]) / 10.0, 0.0, f64::from(velocity[1]) / 10.0);
            for k in 0..ticks {
                w.step(&move_input(w.tick(), 0, vel, jump && k == 0));
                let p = character(&w, 0).position;
                let inside = w.overlap(&inner_capsule(), p, Quat::IDENTITY, &QueryFilter::new());
                prop_assert!(inside.is_empty(), "tick {}: inside {inside:?} at {p:?}", w.tick());
                let [x, y, z] = p.to_f64();
                prop_assert!(x.abs() < 5.0 && z.abs() < 5.0 && y > 0.7, "left the maze: {x} {y} {z}");
            }
        }
    }
}

#[test]
fn at_50_m_s_it_never_passes_through_a_thin_wall() {
    for speed in [5.0, 20.0, 50.0, -50.0] {
        let wall = slab(v(0.0, 1.0, 0.0), v(0.05, 1.0, 5.0), 0.0);
        let start = if speed > 0.0 { -1.0 } else { 1.0 };
        let mut w = world(
            vec![floor(-20.0, 20.0), wall],
            vec![CharacterDesc::new(capsule(), v(start, 0.81, 0.0))],
        );
        for _ in 0..60 {
            walk(&mut w, v(speed, 0.0, 0.0));
            let x = pos(&w, 0)[0];
            assert!(x * start > 0.3, "speed {speed}: passed to x = {x}");
        }
    }
}
