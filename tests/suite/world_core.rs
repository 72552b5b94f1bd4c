//! The world spine: first differences between states, command order, the fixed timestep.

use core::time::Duration;

use fixstep::math::{Fx, Real, Vec3};
use fixstep::world::{
    Command, FixedTimestep, Handle, Part, PlayerInput, Target, TickInput, World, first_difference,
};
use fixstep_scenes::builtin_scene;

fn orbits() -> World<Fx> {
    builtin_scene::<Fx>("orbits").unwrap().build().unwrap()
}

fn input(tick: u64, players: Vec<(u8, Vec<Command<Fx>>)>) -> TickInput<Fx> {
    TickInput {
        tick,
        players: players
            .into_iter()
            .map(|(player, commands)| PlayerInput { player, commands })
            .collect(),
    }
}

#[test]
fn identical_states_have_no_difference() {
    let mut a = orbits();
    let mut b = orbits();
    for tick in 0..30 {
        a.step(&TickInput {
            tick,
            players: vec![],
        });
        b.step(&TickInput {
            tick,
            players: vec![],
        });
    }
    assert_eq!(first_difference(&a.snapshot(), &b.snapshot()), None);
}

#[test]
fn the_first_differing_particle_is_named() {
    let mut a = orbits();
    let mut b = orbits();
    let nudged = Handle::new(2, 0);
    assert!(b.particles().unwrap().is_alive(nudged));
    b.step(&input(
        0,
        vec![(
            0,
            vec![Command::ApplyImpulse {
                target: Target::Particle(nudged),
                impulse: Vec3::new(Fx::from_ratio(1, 1000), Fx::ZERO, Fx::ZERO),
                point: None,
            }],
        )],
    ));
    a.step(&TickInput::default());
    let difference = first_difference(&a.snapshot(), &b.snapshot()).expect("states differ");
    assert_eq!(difference.part, Part::Particles);
    assert_eq!(difference.id, Some(nudged));
    assert_eq!(
        a.checksum().first_differing_part(&b.checksum()),
        Some(Part::Particles)
    );
    assert!(difference.to_string().contains("first differing id 2v0"));
}

#[test]
fn core_differences_come_first() {
    let mut a = orbits();
    let mut b = orbits();
    a.step(&input(0, vec![(0, vec![Command::Payload(7)])]));
    b.step(&input(0, vec![(0, vec![Command::Payload(8)])]));
    let difference = first_difference(&a.snapshot(), &b.snapshot()).unwrap();
    assert_eq!((difference.part, difference.id), (Part::Core, None));
}

#[test]
fn players_apply_in_ascending_index_whatever_the_given_order() {
    let gravity = |g: i32| Command::SetGravity {
        gravity: Vec3::new(Fx::ZERO, Fx::from_int(g), Fx::ZERO),
    };
    let mut a = orbits();
    let mut b = orbits();
    a.step(&input(
        0,
        vec![(0, vec![gravity(-1)]), (3, vec![gravity(-3)])],
    ));
    b.step(&input(
        0,
        vec![(3, vec![gravity(-3)]), (0, vec![gravity(-1)])],
    ));
    assert_eq!(a.settings().gravity.y, Fx::from_int(-3));
    assert_eq!(a.checksum(), b.checksum());
}

#[test]
fn commands_on_missing_targets_are_counted_not_fatal() {
    let mut world = orbits();
    let report = world.step(&input(
        0,
        vec![(
            1,
            vec![
                Command::Remove {
                    target: Target::Particle(Handle::new(999, 0)),
                },
                Command::SetEmitter {
                    emitter: 40,
                    on: true,
                },
                Command::Payload(1),
            ],
        )],
    ));
    assert_eq!(report.ignored_commands, 2);
    assert_eq!(world.tick(), 1);
}

#[test]
fn fixed_timestep_counts_ticks_and_interpolates() {
    let mut clock = FixedTimestep::new(60, 5);
    let tick = clock.tick_duration();
    assert_eq!(tick, Duration::from_nanos(16_666_666));
    assert_eq!(clock.advance(tick / 2), 0);
    assert!((clock.alpha() - 0.5).abs() < 1e-6);
    assert_eq!(clock.advance(tick), 1);
    assert!((clock.alpha() - 0.5).abs() < 1e-6);
    // A long stall runs at most 5 ticks and drops the rest of the backlog.
    assert_eq!(clock.advance(Duration::from_secs(2)), 5);
    assert!(clock.alpha() < 1.0);
    assert_eq!(clock.advance(Duration::ZERO), 0);
    // 60 frames of 1/60 s give 60 ticks in total.
    let mut steady = FixedTimestep::new(60, 5);
    let ticks: u32 = (0..60).map(|_| steady.advance(tick)).sum();
    assert_eq!(ticks, 60);
}

#[test]
fn a_checkpoint_names_the_first_particle_that_diverged() {
    use fixstep::replay::Checkpoint;
    let mut a = orbits();
    let mut b = orbits();
    let nudged = Handle::new(1, 0);
    a.step(&TickInput::default());
    b.step(&input(
        0,
        vec![(
            0,
            vec![Command::SetVelocity {
                target: Target::Particle(nudged),
                velocity: Vec3::ZERO,
            }],
        )],
    ));
    let recorded = Checkpoint::capture(&a);
    assert_eq!(recorded.first_differing_object(&a.object_digests()), None);
    assert_eq!(
        recorded.first_differing_object(&b.object_digests()),
        Some((Part::Particles, nudged))
    );
}
