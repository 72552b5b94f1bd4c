//! Properties of whole runs on the built-in scenes: snapshot/restore at any tick continues
//! exactly like an uninterrupted run, equal seeds and inputs give equal checksums, and a
//! replay survives encode → decode → encode byte for byte.

use fixstep::codec;
use fixstep::math::{Fx, Real, Vec3};
use fixstep::replay::{InputFeed, Replay, VerifyOutcome, record, verify};
use fixstep::scene::Scene;
use fixstep::world::{
    Checksum, Command, Handle, PlayerInput, Target, TickInput, World, WorldState,
};
use fixstep_scenes::{BUILTIN_SCENES, builtin_scene};
use proptest::prelude::*;

/// Ticks per property case: long enough for emitters and orbits to matter, short enough
/// for the debug test profile.
const TICKS: u64 = 150;

fn scene(index: usize) -> Scene<Fx> {
    builtin_scene(BUILTIN_SCENES[index].0).expect("built in")
}

fn small() -> impl Strategy<Value = Fx> {
    (-40i64..=40).prop_map(|n| Fx::from_ratio(n, 4))
}

fn vec3() -> impl Strategy<Value = Vec3<Fx>> {
    (small(), small(), small()).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

fn target() -> impl Strategy<Value = Target> {
    prop_oneof![
        (0u32..8, 0u32..2).prop_map(|(i, g)| Target::Particle(Handle::new(i, g))),
        (0u16..3).prop_map(Target::ParticleGroup),
    ]
}

/// Any command, with small values.
fn command() -> impl Strategy<Value = Command<Fx>> {
    prop_oneof![
        (target(), vec3(), proptest::option::of(vec3())).prop_map(|(target, force, point)| {
            Command::ApplyForce {
                target,
                force,
                point,
            }
        }),
        (target(), vec3(), proptest::option::of(vec3())).prop_map(|(target, impulse, point)| {
            Command::ApplyImpulse {
                target,
                impulse,
                point,
            }
        }),
        (target(), vec3()).prop_map(|(target, velocity)| Command::SetVelocity { target, velocity }),
        (0u32..3, vec3(), vec3()).prop_map(|(template, position, velocity)| Command::Spawn {
            template,
            position,
            velocity
        }),
        target().prop_map(|target| Command::Remove { target }),
        (target(), vec3())
            .prop_map(|(target, position)| Command::MoveKinematic { target, position }),
        (0u32..3, any::<bool>()).prop_map(|(emitter, on)| Command::SetEmitter { emitter, on }),
        vec3().prop_map(|gravity| Command::SetGravity { gravity }),
        any::<u32>().prop_map(Command::Payload),
    ]
}

/// A script: up to 8 ticks with commands, from up to 3 players each, in any order (the
/// recorder puts them in canonical order).
fn script() -> impl Strategy<Value = Vec<TickInput<Fx>>> {
    proptest::collection::btree_map(
        0..TICKS,
        proptest::collection::vec((0u8..3, proptest::collection::vec(command(), 1..3)), 1..4),
        0..8,
    )
    .prop_map(|ticks| {
        ticks
            .into_iter()
            .map(|(tick, players)| TickInput {
                tick,
                players: players
                    .into_iter()
                    .map(|(player, commands)| PlayerInput { player, commands })
                    .collect(),
            })
            .collect()
    })
}

/// Checksums after every tick from `world`'s current tick up to `until`.
fn run_to(world: &mut World<Fx>, feed_script: &[TickInput<Fx>], until: u64) -> Vec<Checksum> {
    let mut feed = InputFeed::new(feed_script);
    let mut sums = Vec::new();
    while world.tick() < until {
        let tick = world.tick();
        world.step(feed.at(tick));
        sums.push(world.checksum());
    }
    sums
}

proptest! {
    #![proptest_config(crate::property_cases::fixed_cases(12))]

    #[test]
    fn restoring_a_snapshot_continues_like_an_uninterrupted_run(
        index in 0..BUILTIN_SCENES.len(),
        at in 0..TICKS,
        detour in 1u64..20,
        script in script(),
    ) {
        let scene = scene(index);
        let mut reference = scene.build().expect("builds");
        let uninterrupted = run_to(&mut reference, &script, TICKS);

        let mut world = scene.build().expect("builds");
        run_to(&mut world, &script, at);
        let snapshot: WorldState<Fx> = world.snapshot();
        // Wander off: different inputs for a while, then come back.
        let detour_input = vec![TickInput {
            tick: at,
            players: vec![PlayerInput {
                player: 9,
                commands: vec![Command::SetGravity { gravity: Vec3::new(Fx::ONE, Fx::ONE, Fx::ONE) }],
            }],
        }];
        run_to(&mut world, &detour_input, at + detour);
        world.restore(&snapshot);
        prop_assert_eq!(world.tick(), at);
        let resumed = run_to(&mut world, &script, TICKS);
        prop_assert_eq!(&resumed[..], &uninterrupted[at as usize..]);

        // A fresh world from the snapshot, and from the snapshot through the codec.
        let mut fresh = World::from_state(snapshot.clone());
        prop_assert_eq!(&run_to(&mut fresh, &script, TICKS)[..], &uninterrupted[at as usize..]);
        let bytes = codec::encode(&snapshot).expect("encodes");
        let decoded: WorldState<Fx> = codec::decode_exact(&bytes).expect("decodes");
        prop_assert_eq!(&decoded, &snapshot);
        let mut thawed = World::from_state(decoded);
        prop_assert_eq!(&run_to(&mut thawed, &script, TICKS)[..], &uninterrupted[at as usize..]);
    }

    #[test]
    fn equal_seeds_and_inputs_give_equal_checksums(
        index in 0..BUILTIN_SCENES.len(),
        seed in any::<u64>(),
        script in script(),
    ) {
        let mut scene = scene(index);
        scene.seed = seed;
        scene.script = script;
        let every = 25.try_into().expect("non-zero");
        let first = record(&scene, TICKS, every).expect("builds");
        let second = record(&scene, TICKS, every).expect("builds");
        prop_assert_eq!(first.checkpoints(), second.checkpoints());
        prop_assert_eq!(
            verify(&first).expect("builds"),
            VerifyOutcome::Ok { ticks: TICKS, checksum: first.final_checksum() }
        );
    }

    #[test]
    fn encode_decode_encode_is_byte_identical(
        index in 0..BUILTIN_SCENES.len(),
        ticks in 0u64..40,
        every in 1u32..50,
        script in script(),
    ) {
        let mut scene = scene(index);
        scene.script = script;
        let replay = record(&scene, ticks, every.try_into().expect("non-zero")).expect("builds");
        let bytes = replay.to_bytes().expect("encodes");
        let decoded = Replay::from_bytes(&bytes, "property").expect("decodes");
        prop_assert_eq!(&decoded, &replay);
        prop_assert_eq!(decoded.to_bytes().expect("encodes"), bytes);
    }
}
