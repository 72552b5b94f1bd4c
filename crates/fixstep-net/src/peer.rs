//! A networked session: one peer of a lockstep or rollback game over GGRS.
//!
//! The peer simulates two worlds. The *game* world is the one GGRS drives: in rollback mode
//! it runs ahead on predicted remote inputs, and GGRS saves, loads and re-simulates it. The
//! *confirmed* world (a [`Recorder`]) only ever steps with inputs that can no longer change,
//! in tick order; it gives the session's final checksum and its replay, which verifies
//! offline like any other.
//!
//! Desync detection compares the 128-bit checksums ([`super::checksum128`]) of the peers
//! every `desync_every` ticks. In rollback mode GGRS does it, with the checksums of the
//! states it saved. In lockstep mode GGRS saves no state, so the peers compare themselves:
//! each one's input for a tick that is a multiple of the interval carries its checksum of
//! the state at that tick, and every peer compares the reports when the tick's confirmed
//! inputs arrive.

use std::net::SocketAddr;
use std::time::{Duration, Instant};

use ggrs::{DesyncDetection, GgrsError, GgrsEvent, P2PSession, PlayerType, SessionBuilder};

use super::checksum::{checksum128, differing_part};
use super::config::FixstepConfig;
use super::handshake::{HandshakeError, Introduction, check_remotes, handshake};
use super::hello::Heard;
use super::input::{NetInput, tick_input};
use super::nudge::{has_dynamic_body, nudge_first_body};
use super::requests::fulfil;
use super::scene_world::build_world;
use super::socket::PeerSocket;
use super::source::InputSource;
use fixstep::math::Fx;
use fixstep::replay::{DEFAULT_CHECKSUM_EVERY, Recorder, Replay, scene_id};
use fixstep::scene::Scene;
use fixstep::world::{Part, World};

/// Frames a rollback peer may run ahead of its last confirmed frame.
pub const ROLLBACK_WINDOW: usize = 8;

/// How long a peer keeps exchanging packets after its result is known, so that the other
/// peers receive its last inputs and checksums (GGRS resends unacknowledged ones every
/// 200 ms).
const LINGER: Duration = Duration::from_millis(1000);

/// A remote that stays silent this long is disconnected.
const DISCONNECT_TIMEOUT: Duration = Duration::from_secs(5);

/// Pause between two polls when the session could not advance.
const IDLE_POLL: Duration = Duration::from_micros(500);

/// Lockstep or rollback.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Every tick waits for every peer's input (a GGRS prediction window of 0).
    Lockstep,
    /// Ticks run ahead on predicted inputs and roll back on a misprediction.
    Rollback,
}

/// Everything a peer needs.
#[derive(Clone, Debug)]
pub struct PeerOptions {
    /// The scene every peer runs.
    pub scene: Scene<Fx>,
    /// Local UDP port (0: any free port).
    pub local_port: u16,
    /// The other peers, in ascending player index (the local player's index is skipped).
    pub remotes: Vec<SocketAddr>,
    /// The local player's index.
    pub player: usize,
    /// Ticks to run.
    pub ticks: u64,
    /// Lockstep or rollback.
    pub mode: Mode,
    /// Where the local player's inputs come from.
    pub inputs: InputSource,
    /// Ticks between two desync checks (at least 1).
    pub desync_every: u32,
    /// For testing desync detection: once the game world has run this many ticks (and
    /// again whenever a rollback re-simulates past it), move a body by one ulp.
    pub nudge_at: Option<u64>,
    /// Wall-time limit of the whole session, synchronisation included.
    pub timeout: Duration,
}

/// A desync between this peer and a remote one.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DesyncReport {
    /// The tick whose states differ.
    pub frame: i64,
    /// This peer's 128-bit checksum of that state.
    pub local: u128,
    /// The remote peer's.
    pub remote: u128,
    /// The remote peer.
    pub remote_addr: SocketAddr,
    /// The first part whose digest differs, when one does.
    pub part: Option<Part>,
}

/// How a session ended.
#[derive(Debug)]
pub enum PeerOutcome {
    /// Every tick ran; the confirmed world's replay.
    Finished(Box<Replay>),
    /// The peers' states differed.
    Desync(DesyncReport),
}

/// The state of a running peer.
struct Peer {
    options: PeerOptions,
    session: P2PSession<FixstepConfig>,
    players: usize,
    game: World<Fx>,
    confirmed: Recorder,
    /// Parts of the scene's state, in [`Part`] order.
    parts: Vec<Part>,
    /// The inputs last used for each tick, indexed by tick; emptied once the confirmed world
    /// has used them.
    inputs_log: Vec<Vec<NetInput>>,
    /// A desync found by the lockstep reports.
    lockstep_desync: Option<DesyncReport>,
}

/// Whether the wall clock has reached `deadline`: the session's timeouts, never simulated
/// state.
fn passed(deadline: Instant) -> bool {
    Instant::now() >= deadline // ok-det: network session timeout, never simulated state
}

/// Runs a peer until every tick is confirmed, a desync is detected, a remote disconnects
/// or the timeout expires (the last two are errors).
pub fn run_peer(options: PeerOptions) -> Result<PeerOutcome, String> {
    let deadline = Instant::now() + options.timeout; // ok-det: network session timeout, never simulated state
    let mut peer = Peer::start(options, deadline)?;
    let desync = loop {
        if passed(deadline) {
            return Err(peer.timeout_message());
        }
        if let Some(report) = peer.poll()? {
            break Some(report);
        }
        if let Some(report) = peer.lockstep_desync.take() {
            break Some(report);
        }
        if peer.confirmed.world().tick() >= peer.options.ticks {
            break None;
        }
    };
    peer.linger(deadline.min(Instant::now() + LINGER)); // ok-det: network session timeout, never simulated state
    Ok(match desync {
        Some(report) => PeerOutcome::Desync(report),
        None => PeerOutcome::Finished(Box::new(peer.confirmed.finish())),
    })
}

impl Peer {
    /// Checks the options, binds the socket and runs the handshake (until `deadline`),
    /// then starts the GGRS session.
    fn start(options: PeerOptions, deadline: Instant) -> Result<Self, String> {
        let players = options.remotes.len() + 1;
        if players > usize::from(u8::MAX) {
            return Err(format!("{} remotes: at most 254", options.remotes.len()));
        }
        if options.player >= players {
            return Err(format!(
                "--player-index {}: must be below the number of players, {players} (1 + the \
                 number of remotes)",
                options.player
            ));
        }
        if options.desync_every == 0 {
            return Err("the desync interval must be at least 1 tick".to_owned());
        }
        let game = build_world(&options.scene)?;
        if options.nudge_at.is_some() && !has_dynamic_body(&game) {
            return Err(format!(
                "{}: --nudge-at needs a scene with a dynamic rigid body",
                options.scene.name
            ));
        }
        let confirmed = Recorder::new(&options.scene, DEFAULT_CHECKSUM_EVERY)
            .map_err(|e| format!("{}: {e}", options.scene.name))?;
        let parts = game.checksum().parts.iter().map(|(p, _)| *p).collect();
        check_remotes(options.local_port, &options.remotes)?;
        let me = Introduction {
            scene_hash: scene_id(&options.scene)
                .map_err(|e| format!("{}: cannot encode the scene: {e}", options.scene.name))?
                .hash,
            scene_name: options.scene.name.clone(),
            players: players as u8,
            player: options.player as u8,
        };
        let mut socket = PeerSocket::bind(options.local_port, &options.remotes)
            .map_err(|e| format!("--local-port {}: cannot bind: {e}", options.local_port))?;
        handshake(socket.udp(), &me, &options.remotes, deadline).map_err(|e| match e {
            HandshakeError::TimedOut { .. } => format!(
                "timed out after {:.1} s, still synchronising with the remote peers ({e})",
                options.timeout.as_secs_f64()
            ),
            HandshakeError::Disagreement(why) => why,
        })?;
        socket.answer_hellos_with(me.hello(Heard::Answer).encode());
        let session = Self::session(&options, players, socket)
            .map_err(|e| format!("cannot start the session: {e}"))?;
        Ok(Self {
            options,
            session,
            players,
            game,
            confirmed,
            parts,
            inputs_log: Vec::new(),
            lockstep_desync: None,
        })
    }

    fn session(
        options: &PeerOptions,
        players: usize,
        socket: PeerSocket,
    ) -> Result<P2PSession<FixstepConfig>, GgrsError> {
        let window = match options.mode {
            Mode::Lockstep => 0,
            Mode::Rollback => ROLLBACK_WINDOW,
        };
        let detection = match options.mode {
            Mode::Lockstep => DesyncDetection::Off,
            Mode::Rollback => DesyncDetection::On {
                interval: options.desync_every,
            },
        };
        let fps = usize::try_from(options.scene.tick_rate).unwrap_or(usize::MAX);
        let mut builder = SessionBuilder::<FixstepConfig>::new()
            .with_num_players(players)?
            .with_max_prediction_window(window)
            .with_desync_detection_mode(detection)
            .with_disconnect_timeout(DISCONNECT_TIMEOUT)
            .with_fps(fps)?
            .add_player(PlayerType::Local, options.player)?;
        let remote_handles = (0..players).filter(|&h| h != options.player);
        for (handle, address) in remote_handles.zip(&options.remotes) {
            builder = builder.add_player(PlayerType::Remote(*address), handle)?;
        }
        builder.start_p2p_session(socket)
    }

    /// One round: exchange packets, then give the local input and advance if the session
    /// runs. Returns a desync GGRS detected.
    fn poll(&mut self) -> Result<Option<DesyncReport>, String> {
        self.session.poll_remote_clients();
        for event in self.session.events().collect::<Vec<_>>() {
            match event {
                GgrsEvent::DesyncDetected {
                    frame,
                    local_checksum,
                    remote_checksum,
                    addr,
                } => {
                    return Ok(Some(DesyncReport {
                        frame: i64::from(frame),
                        local: local_checksum,
                        remote: remote_checksum,
                        remote_addr: addr,
                        part: differing_part(&self.parts, local_checksum, remote_checksum),
                    }));
                }
                GgrsEvent::Disconnected { addr } => {
                    return Err(format!(
                        "peer {addr} disconnected at frame {} (confirmed up to tick {})",
                        self.session.current_frame(),
                        self.confirmed.world().tick()
                    ));
                }
                _ => {}
            }
        }
        if !self.advance()? {
            std::thread::sleep(IDLE_POLL);
        }
        self.step_confirmed();
        Ok(None)
    }

    /// Gives the local input for the session's current frame and fulfils GGRS's requests.
    /// Returns whether the game world advanced.
    fn advance(&mut self) -> Result<bool, String> {
        if self.session.current_state() != ggrs::SessionState::Running {
            return Ok(false);
        }
        let frame = self.session.current_frame();
        let tick = u64::try_from(frame).unwrap_or(0);
        let player = self.options.player;
        let mut input = self.options.inputs.input(player as u8, tick);
        if self.options.mode == Mode::Lockstep && self.is_check_tick(tick) {
            // In lockstep the game world is at the session's frame and never predicted.
            let sum = checksum128(&self.game);
            input.checksum_report = [(sum >> 64) as u64, sum as u64];
        }
        self.session
            .add_local_input(player, input)
            .map_err(|e| format!("frame {frame}: {e}"))?;
        let requests = match self.session.advance_frame() {
            Ok(requests) => requests,
            Err(GgrsError::PredictionThreshold | GgrsError::NotSynchronized) => return Ok(false),
            Err(e) => return Err(format!("frame {frame}: {e}")),
        };
        let before = self.game.tick();
        let check = self.options.mode == Mode::Lockstep;
        let every = u64::from(self.options.desync_every);
        let nudge_at = self.options.nudge_at;
        let log = &mut self.inputs_log;
        let desync = &mut self.lockstep_desync;
        let remotes = &self.options.remotes;
        let parts = &self.parts;
        fulfil(
            &self.options.scene,
            &mut self.game,
            requests,
            |world, inputs| {
                let tick = world.tick();
                let index = usize::try_from(tick).map_err(|e| e.to_string())?;
                if log.len() <= index {
                    log.resize(index + 1, Vec::new());
                }
                log[index] = inputs.to_vec();
                if check && tick > 0 && tick.is_multiple_of(every) && desync.is_none() {
                    *desync = compare_reports(inputs, player, remotes, parts, tick);
                }
                Ok(())
            },
            |world| {
                if Some(world.tick()) == nudge_at {
                    nudge_first_body(world);
                }
            },
        )?;
        Ok(self.game.tick() != before)
    }

    fn is_check_tick(&self, tick: u64) -> bool {
        tick > 0 && tick.is_multiple_of(u64::from(self.options.desync_every))
    }

    /// Steps the confirmed world through every tick whose inputs are final: confirmed by
    /// every peer, and already used by the game world after any rollback they caused.
    /// Remote inputs arrive only while GGRS polls the socket, which `advance_frame` does
    /// before it checks its predictions and requests the rollback; so once its requests are
    /// fulfilled, the inputs logged for every confirmed tick are the confirmed ones.
    fn step_confirmed(&mut self) {
        let confirmed = u64::try_from(self.session.confirmed_frame()).ok();
        let final_ticks = match self.options.mode {
            // Lockstep advances only confirmed ticks: every tick the game ran is final.
            Mode::Lockstep => Some(self.game.tick()),
            Mode::Rollback => confirmed.map(|c| (c + 1).min(self.game.tick())),
        };
        let Some(final_ticks) = final_ticks else {
            return;
        };
        while self.confirmed.world().tick() < final_ticks.min(self.options.ticks) {
            let tick = self.confirmed.world().tick();
            let Some(inputs) = usize::try_from(tick)
                .ok()
                .and_then(|t| self.inputs_log.get_mut(t))
            else {
                return;
            };
            // A final tick is never re-simulated: its inputs are not needed again.
            let input = tick_input(&self.options.scene, tick, &std::mem::take(inputs));
            self.confirmed.step(&input);
        }
    }

    /// Keeps the session going until `until`, ignoring its events, so that the other peers
    /// get this peer's last packets.
    fn linger(&mut self, until: Instant) {
        while !passed(until) {
            self.session.poll_remote_clients();
            self.session.events().for_each(drop);
            if !matches!(self.advance(), Ok(true)) {
                std::thread::sleep(IDLE_POLL);
            }
        }
    }

    fn timeout_message(&self) -> String {
        let state = match self.session.current_state() {
            ggrs::SessionState::Synchronizing => {
                "still synchronising with the remote peers".to_owned()
            }
            ggrs::SessionState::Running => format!(
                "at frame {}, confirmed up to tick {}",
                self.session.current_frame(),
                self.confirmed.world().tick()
            ),
        };
        format!(
            "timed out after {:.1} s, {state} ({} players)",
            self.options.timeout.as_secs_f64(),
            self.players
        )
    }
}

/// In lockstep mode, compares the checksum reports in the confirmed inputs of a check tick:
/// the local player's against each remote player's.
fn compare_reports(
    inputs: &[NetInput],
    player: usize,
    remotes: &[SocketAddr],
    parts: &[Part],
    tick: u64,
) -> Option<DesyncReport> {
    let unpack = |r: [u64; 2]| (u128::from(r[0]) << 64) | u128::from(r[1]);
    let local = unpack(inputs.get(player)?.checksum_report);
    let remote_players = (0..inputs.len()).filter(|&p| p != player);
    for (p, addr) in remote_players.zip(remotes) {
        let remote = unpack(inputs[p].checksum_report);
        if remote != local {
            return Some(DesyncReport {
                frame: i64::try_from(tick).unwrap_or(i64::MAX),
                local,
                remote,
                remote_addr: *addr,
                part: differing_part(parts, local, remote),
            });
        }
    }
    None
}
