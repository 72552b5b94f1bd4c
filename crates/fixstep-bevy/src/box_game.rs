//! The example game of `examples/box_game.rs`, shared with the tests: two players, each a
//! ball, push crates on a floor. A player's input is four direction bits; each tick the
//! ball gets an impulse of 1/4 N·s along each pressed direction. A deterministic bot can
//! play either side. The crate template (index 0) lets the game spawn crates at run time.

use std::net::SocketAddr;

use bevy::prelude::*;
use bevy_ggrs::{GgrsConfig, LocalInputs, LocalPlayers, PlayerInputs};
use fixstep::math::{Fx, Real, Vec3};
use fixstep::rigid::{BodyTemplate, RigidDesc, Shape};
use fixstep::scene::Scene;
use fixstep::world::{Command, Target};

use super::components::{BodyLink, Collider, FixedTransform, RigidBody};
use super::plugin::FixstepSystems;
use super::world::FixstepWorld;

/// GGRS's configuration of the game: one byte of input per player.
pub type BoxConfig = GgrsConfig<u8, SocketAddr>;

/// Input bit: push along −z.
pub const UP: u8 = 1;
/// Input bit: push along +z.
pub const DOWN: u8 = 2;
/// Input bit: push along −x.
pub const LEFT: u8 = 4;
/// Input bit: push along +x.
pub const RIGHT: u8 = 8;

/// The ball of player `0`.
#[derive(Component, Clone, Copy, Debug)]
pub struct Player(pub u8);

/// A crate.
#[derive(Component, Clone, Copy, Debug)]
pub struct Crate;

fn fx(num: i64, den: i64) -> Fx {
    Fx::from_ratio(num, den)
}

/// A crate's shape: a 0.6 m cube.
pub fn crate_shape() -> Shape<Fx> {
    Shape::Box {
        half_extents: Vec3::splat(fx(3, 10)),
    }
}

/// A player's shape: a ball of radius 0.4 m.
pub fn player_shape() -> Shape<Fx> {
    Shape::Sphere { radius: fx(2, 5) }
}

/// The crate's body: dynamic, 200 kg/m³ (a 43 kg crate).
pub fn crate_body() -> RigidBody {
    RigidBody {
        density: Fx::from_int(200),
        ..RigidBody::dynamic()
    }
}

/// The game's scene: 60 Hz, a body template for crates (template 0); the bodies come from
/// the entities [`setup`] spawns.
pub fn scene() -> Scene<Fx> {
    let mut scene = Scene::empty("box_game");
    scene.description = "fixstep-bevy's box game: two balls push crates".to_owned();
    scene.seed = 0x5eed;
    let template: BodyTemplate<Fx> = crate_body().template(&crate_shape());
    scene.rigid = Some(RigidDesc {
        templates: vec![template],
        ..RigidDesc::default()
    });
    scene
}

/// Spawns the floor, four crates and the two players.
pub fn setup(mut commands: Commands) {
    commands.spawn((
        RigidBody::fixed(),
        Collider(Shape::Plane {
            normal: Vec3::Y,
            offset: Fx::ZERO,
        }),
    ));
    for i in 0..4 {
        commands.spawn((
            Crate,
            crate_body(),
            Collider(crate_shape()),
            FixedTransform::from_position(Vec3::new(fx(i - 2, 1) + fx(1, 2), fx(3, 10), Fx::ZERO)),
        ));
    }
    for player in 0..2u8 {
        let z = if player == 0 { fx(-2, 1) } else { fx(2, 1) };
        commands.spawn((
            Player(player),
            RigidBody::dynamic(),
            Collider(player_shape()),
            FixedTransform::from_position(Vec3::new(Fx::ZERO, fx(2, 5), z)),
        ));
    }
}

/// The impulse of an input, N·s: 1/4 along each pressed direction.
pub fn impulse(input: u8) -> Vec3<Fx> {
    let step = fx(1, 4);
    let axis = |minus: u8, plus: u8| {
        let mut v = Fx::ZERO;
        if input & minus != 0 {
            v -= step;
        }
        if input & plus != 0 {
            v += step;
        }
        v
    };
    Vec3::new(axis(LEFT, RIGHT), Fx::ZERO, axis(UP, DOWN))
}

/// The deterministic bot's input for `player` on `frame`: a new random direction every 20
/// frames (splitmix64 of seed, player and the 20-frame block).
pub fn bot_input(seed: u64, player: u8, frame: u64) -> u8 {
    let mut z = seed ^ (u64::from(player) << 56) ^ (frame / 20);
    z = z.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^= z >> 31;
    (z & 0xf) as u8
}

/// The frame the bot plays next, counted by [`read_bot_inputs`] (not rolled back: GGRS
/// asks for each local input once).
#[derive(Resource, Default, Debug)]
pub struct BotFrame(pub u64);

/// The seed of the local bots.
#[derive(Resource, Clone, Copy, Debug)]
pub struct BotSeed(pub u64);

/// bevy_ggrs's `ReadInputs` system: the local players' inputs from the bot.
pub fn read_bot_inputs(
    mut commands: Commands,
    local: Res<LocalPlayers>,
    seed: Res<BotSeed>,
    mut frame: ResMut<BotFrame>,
) {
    let inputs = local
        .0
        .iter()
        .map(|&handle| {
            let player = u8::try_from(handle).unwrap_or(u8::MAX);
            (handle, bot_input(seed.0, player, frame.0))
        })
        .collect();
    frame.0 += 1;
    commands.insert_resource(LocalInputs::<BoxConfig>(inputs));
}

/// Turns the players' inputs of the frame into impulses on their balls (player `i`'s
/// commands under player index `i`), in player order.
pub fn apply_inputs(
    inputs: Res<PlayerInputs<BoxConfig>>,
    players: Query<(&Player, &BodyLink)>,
    mut fixstep: ResMut<FixstepWorld>,
) {
    let mut balls: Vec<(u8, BodyLink)> = players.iter().map(|(p, l)| (p.0, *l)).collect();
    balls.sort_unstable_by_key(|(p, _)| *p);
    for (player, link) in balls {
        let Some((input, _status)) = inputs.get(usize::from(player)) else {
            continue;
        };
        if *input == 0 {
            continue;
        }
        fixstep.push(
            player,
            Command::ApplyImpulse {
                target: Target::Body(link.0),
                impulse: impulse(*input),
                point: None,
            },
        );
    }
}

/// The game's systems for an app that already has `GgrsPlugin::<BoxConfig>` and
/// `FixstepPlugin::ggrs(scene())`.
pub fn add_game(app: &mut App, bot_seed: u64) {
    app.insert_resource(BotSeed(bot_seed))
        .init_resource::<BotFrame>()
        .add_systems(Startup, setup)
        .add_systems(bevy_ggrs::ReadInputs, read_bot_inputs)
        .add_systems(
            bevy_ggrs::GgrsSchedule,
            apply_inputs.before(FixstepSystems::Step),
        );
}

/// Spawns a crate every `every` ticks (above the middle of the floor) and, half a period
/// later, despawns the crate of lowest body handle with `despawn_rollback`: run-time
/// spawns and despawns under rollback.
#[derive(Resource, Clone, Copy, Debug)]
pub struct CrateCycle {
    /// Ticks between spawns (at least 2).
    pub every: u64,
}

/// The system of [`CrateCycle`], before the step.
pub fn cycle_crates(
    cycle: Res<CrateCycle>,
    fixstep: Res<FixstepWorld>,
    crates: Query<(Entity, &BodyLink), With<Crate>>,
    mut commands: Commands,
) {
    use bevy_ggrs::prelude::RollbackDespawnCommandExtension;
    let every = cycle.every.max(2);
    let tick = fixstep.world().tick();
    if tick.is_multiple_of(every) {
        let lane = i64::try_from((tick / every) % 5).unwrap_or(0) - 2;
        commands.spawn((
            Crate,
            crate_body(),
            Collider(crate_shape()),
            FixedTransform::from_position(Vec3::new(fx(lane, 2), fx(3, 2), fx(1, 2))),
        ));
    } else if tick % every == every / 2
        && let Some((entity, _)) = crates.iter().min_by_key(|(_, link)| link.0)
    {
        commands.entity(entity).despawn_rollback();
    }
}

/// The world's checksum right after tick `tick` ran (kept up to date under rollback: a
/// re-simulated tick writes it again; once the tick is confirmed it is final).
#[derive(Resource, Clone, Copy, Debug)]
pub struct ChecksumAt {
    /// The tick count after which the checksum is taken.
    pub tick: u64,
    /// The checksum, once the world has reached `tick`.
    pub checksum: Option<u64>,
}

/// The system of [`ChecksumAt`], after the step.
pub fn record_checksum(fixstep: Res<FixstepWorld>, mut at: ResMut<ChecksumAt>) {
    if fixstep.world().tick() == at.tick {
        at.checksum = Some(fixstep.checksum());
    }
}

/// A headless app of the game over `session` (GGRS frames at 60 Hz, each `update` one
/// frame of game time), its local players played by the bot `bot_seed`, recording the
/// checksum after `ticks` ticks; with `cycle`, crates come and go.
pub fn headless_app(
    session: bevy_ggrs::Session<BoxConfig>,
    bot_seed: u64,
    ticks: u64,
    cycle: Option<u64>,
) -> App {
    let mut app = App::new();
    app.add_plugins(MinimalPlugins)
        .add_plugins(bevy_ggrs::GgrsPlugin::<BoxConfig>::default())
        .add_plugins(super::FixstepPlugin::ggrs(scene()))
        .insert_resource(bevy::time::TimeUpdateStrategy::ManualDuration(
            core::time::Duration::from_micros(16_667),
        ))
        .insert_resource(session)
        .insert_resource(ChecksumAt {
            tick: ticks,
            checksum: None,
        })
        .add_systems(
            bevy_ggrs::GgrsSchedule,
            record_checksum.after(FixstepSystems::Step),
        );
    add_game(&mut app, bot_seed);
    if let Some(every) = cycle {
        app.insert_resource(CrateCycle { every }).add_systems(
            bevy_ggrs::GgrsSchedule,
            cycle_crates
                .before(FixstepSystems::Step)
                .before(apply_inputs),
        );
    }
    app
}

/// A GGRS P2P session of two players: `local` (0 or 1) on `socket`, the other at
/// `remote`; input delay 0, prediction up to 8 frames, desync detection every 10 frames.
pub fn p2p_session<S>(
    local: usize,
    socket: S,
    remote: SocketAddr,
) -> Result<bevy_ggrs::Session<BoxConfig>, ggrs::GgrsError>
where
    S: ggrs::NonBlockingSocket<SocketAddr> + 'static,
{
    let session = ggrs::SessionBuilder::<BoxConfig>::new()
        .with_num_players(2)?
        .with_input_delay(0)
        .with_max_prediction_window(8)
        .with_desync_detection_mode(ggrs::DesyncDetection::On { interval: 10 })
        .add_player(ggrs::PlayerType::Local, local)?
        .add_player(ggrs::PlayerType::Remote(remote), 1 - local)?
        .start_p2p_session(socket)?;
    Ok(bevy_ggrs::Session::P2P(session))
}

/// A GGRS sync test session of two local players rolling back `check_distance` frames.
pub fn sync_test_session(
    check_distance: usize,
) -> Result<bevy_ggrs::Session<BoxConfig>, ggrs::GgrsError> {
    let session = ggrs::SessionBuilder::<BoxConfig>::new()
        .with_num_players(2)?
        .with_input_delay(0)
        .with_check_distance(check_distance)
        .with_max_prediction_window(check_distance + 1)
        .add_player(ggrs::PlayerType::Local, 0)?
        .add_player(ggrs::PlayerType::Local, 1)?
        .start_synctest_session()?;
    Ok(bevy_ggrs::Session::SyncTest(session))
}

/// Counts an app's rollbacks (runs of bevy_ggrs's `LoadWorld`).
#[derive(Resource, Default, Debug)]
pub struct Rollbacks(pub u64);

fn count_rollbacks(mut rollbacks: ResMut<Rollbacks>) {
    rollbacks.0 += 1;
}

/// What [`run_loopback_pair`] ends with.
#[derive(Debug)]
pub struct PairOutcome {
    /// Each peer's checksum after `ticks` ticks.
    pub checksums: [u64; 2],
    /// Each peer's number of rollbacks.
    pub rollbacks: [u64; 2],
    /// Peer 0's replay of the `ticks` ticks (confirmed inputs only).
    pub replay: fixstep::replay::Replay,
    /// Rounds run (each round two app updates, the peers taking turns of three).
    pub updates: u32,
}

fn loopback_socket() -> Result<(fixstep_net::PeerSocket, SocketAddr), String> {
    let loopback = SocketAddr::from(([127, 0, 0, 1], 9));
    let socket = fixstep_net::PeerSocket::bind(0, &[loopback])
        .map_err(|e| format!("cannot bind 127.0.0.1: {e}"))?;
    let addr = socket.local_addr().map_err(|e| e.to_string())?;
    Ok((socket, addr))
}

fn confirmed_frame(app: &App) -> i64 {
    match app.world().resource::<bevy_ggrs::Session<BoxConfig>>() {
        bevy_ggrs::Session::P2P(s) => i64::from(s.confirmed_frame()),
        _ => -1,
    }
}

fn desync(app: &mut App) -> Option<String> {
    let mut session = app
        .world_mut()
        .resource_mut::<bevy_ggrs::Session<BoxConfig>>();
    let bevy_ggrs::Session::P2P(s) = session.as_mut() else {
        return None;
    };
    s.events()
        .find(|e| matches!(e, ggrs::GgrsEvent::DesyncDetected { .. }))
        .map(|e| format!("{e:?}"))
}

/// Runs two peers of the game in this thread, each on its own UDP socket bound to
/// 127.0.0.1, bots on both sides, input delay 0 and prediction on, until both have
/// confirmed `ticks` ticks; at most `max_updates` rounds of two updates and `time_limit`
/// of wall time. A desync GGRS reports is an error.
pub fn run_loopback_pair(
    ticks: u64,
    bot_seed: u64,
    cycle: Option<u64>,
    max_updates: u32,
    time_limit: core::time::Duration,
) -> Result<PairOutcome, String> {
    let (socket0, addr0) = loopback_socket()?;
    let (socket1, addr1) = loopback_socket()?;
    let session = |local, socket, remote| {
        p2p_session(local, socket, remote).map_err(|e| format!("cannot start GGRS: {e}"))
    };
    let mut apps = [
        headless_app(session(0, socket0, addr1)?, bot_seed, ticks, cycle),
        headless_app(session(1, socket1, addr0)?, bot_seed, ticks, cycle),
    ];
    for app in &mut apps {
        app.init_resource::<Rollbacks>()
            .add_systems(bevy_ggrs::LoadWorld, count_rollbacks);
    }
    let start = std::time::Instant::now();
    let target = i64::try_from(ticks).unwrap_or(i64::MAX);
    for update in 1..=max_updates {
        // The peers take turns of three updates each (0 0 0 1 1 1 0 ...): in its turn a
        // peer runs up to three frames on predicted inputs of the other, and rolls back
        // when a prediction was wrong.
        for step in 0..2 {
            let peer = usize::from((update * 2 + step) / 3 % 2 == 1);
            apps[peer].update();
            if let Some(event) = desync(&mut apps[peer]) {
                return Err(format!("peer {peer}: {event}"));
            }
        }
        if apps.iter().all(|a| confirmed_frame(a) > target) {
            let checksum = |app: &App| {
                app.world()
                    .resource::<ChecksumAt>()
                    .checksum
                    .ok_or_else(|| format!("the world never reached tick {ticks}"))
            };
            let replay = apps[0]
                .world()
                .resource::<FixstepWorld>()
                .replay(ticks, fixstep::replay::DEFAULT_CHECKSUM_EVERY)
                .map_err(|e| e.to_string())?;
            return Ok(PairOutcome {
                checksums: [checksum(&apps[0])?, checksum(&apps[1])?],
                rollbacks: [
                    apps[0].world().resource::<Rollbacks>().0,
                    apps[1].world().resource::<Rollbacks>().0,
                ],
                replay,
                updates: update,
            });
        }
        if start.elapsed() > time_limit {
            return Err(format!(
                "the peers did not confirm {ticks} ticks within {time_limit:?}"
            ));
        }
    }
    Err(format!(
        "the peers did not confirm {ticks} ticks in {max_updates} updates"
    ))
}
