//! The pieces of a networked session that need no network: inputs and the commands they map
//! to, the bot, scripted inputs and the 128-bit checksum.
#![cfg(feature = "net")]

use fixstep::math::{Fx, Real, Vec3};
use fixstep::world::{Command, Handle, Part, Target};
use fixstep_net::{
    Action, Bot, InputSource, NetInput, build_world, checksum128, differing_part, nudge_first_body,
    read_script, total,
};
use fixstep_scenes::builtin_scene;

fn scratch_file(name: &str, text: &str) -> std::path::PathBuf {
    let path = std::env::temp_dir().join(format!("fixstep-net-{}-{name}", std::process::id()));
    std::fs::write(&path, text).expect("write a scratch file");
    path
}

#[test]
fn an_input_maps_to_one_exact_command() {
    let kick = NetInput {
        action: Action::ImpulseBody,
        target: 3,
        impulse: [-8, 160, 1],
        ..NetInput::default()
    };
    assert_eq!(
        kick.command(),
        Some(Command::ApplyImpulse {
            target: Target::Body(Handle::new(3, 0)),
            impulse: Vec3::new(
                Fx::from_ratio(-1, 2),
                Fx::from_int(10),
                Fx::from_ratio(1, 16)
            ),
            point: None,
        })
    );
    let payload = NetInput {
        action: Action::Payload,
        payload: 7,
        ..NetInput::default()
    };
    assert_eq!(payload.command(), Some(Command::Payload(7)));
    // The checksum report is never applied to the world.
    let idle = NetInput {
        checksum_report: [1, 2],
        ..NetInput::default()
    };
    assert_eq!(idle.command(), None);
}

#[test]
fn the_bot_is_a_pure_function_of_seed_player_and_tick() {
    let world = build_world(&builtin_scene("showcase").expect("scene")).expect("world");
    let bot = Bot::new(42, &world);
    let again = Bot::new(42, &world);
    let ticks = 0..2000u64;
    let active = ticks
        .clone()
        .filter(|&t| bot.input(0, t) != NetInput::default())
        .count();
    // One tick in eight on average: 250 of 2000, within 5 standard deviations.
    assert!((175..=325).contains(&active), "{active} active ticks");
    for tick in ticks {
        assert_eq!(bot.input(1, tick), again.input(1, tick));
    }
    let differ = (0..200)
        .filter(|&t| bot.input(0, t) != bot.input(1, t))
        .count();
    assert!(differ > 0, "both players play the same inputs");
}

#[test]
fn a_script_gives_its_inputs_and_idles_elsewhere() {
    let path = scratch_file(
        "script.ron",
        "[(tick: 30, input: (action: ImpulseBody, target: 3, impulse: (0, 160, 0))), \
          (tick: 31, input: (action: Payload, payload: 9))]",
    );
    let script = read_script(&path).expect("a valid script");
    let source = InputSource::Script(script);
    assert_eq!(source.input(0, 30).impulse, [0, 160, 0]);
    assert_eq!(source.input(0, 31).payload, 9);
    assert_eq!(source.input(0, 32), NetInput::default());
    let _ = std::fs::remove_file(path);
}

#[test]
fn a_script_with_ticks_out_of_order_is_refused() {
    let path = scratch_file(
        "bad-script.ron",
        "[(tick: 5, input: ()), (tick: 5, input: ())]",
    );
    let error = read_script(&path).expect_err("ticks do not increase");
    assert!(
        error.ends_with("[1].tick: ticks must increase (got 5 after 5)"),
        "{error}"
    );
    let _ = std::fs::remove_file(path);
}

#[test]
fn the_128_bit_checksum_names_the_part_that_differs() {
    let world = build_world(&builtin_scene("showcase").expect("scene")).expect("world");
    let before = checksum128(&world);
    assert_eq!(total(before), world.checksum().total);
    let mut nudged = build_world(&builtin_scene("showcase").expect("scene")).expect("world");
    assert!(nudge_first_body(&mut nudged));
    let after = checksum128(&nudged);
    assert_ne!(total(before), total(after));
    let parts = [Part::Core, Part::Particles, Part::Rigid];
    assert_eq!(differing_part(&parts, before, after), Some(Part::Rigid));
    assert_eq!(differing_part(&parts, before, before), None);
}
