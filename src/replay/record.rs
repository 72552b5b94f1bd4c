//! Recording: run a scene tick by tick, keep the inputs and the checkpoints.

use core::num::NonZeroU32;

use super::feed::InputFeed;
use super::file::Replay;
use super::format::Checkpoint;
use crate::math::Fx;
use crate::scene::{Scene, SceneError};
use crate::world::{STATE_VERSION, TickInput, TickReport, World};

/// The checkpoint interval `fixstep run --record` uses: one a second at 60 Hz.
pub const DEFAULT_CHECKSUM_EVERY: NonZeroU32 = NonZeroU32::new(60).unwrap();

/// Runs a world from a scene and records what a [`Replay`] needs: the inputs given (in
/// canonical form) and a [`Checkpoint`] at tick 0, every `checksum_every` ticks, and at
/// the end.
#[derive(Debug)]
pub struct Recorder {
    scene: Scene<Fx>,
    world: World<Fx>,
    checksum_every: NonZeroU32,
    inputs: Vec<TickInput<Fx>>,
    checkpoints: Vec<Checkpoint>,
}

impl Recorder {
    /// Builds the scene's world at tick 0. The scene's script is not fed automatically:
    /// pass its inputs to [`Recorder::step`] (see [`record`]).
    pub fn new(scene: &Scene<Fx>, checksum_every: NonZeroU32) -> Result<Self, SceneError> {
        let scene = Scene {
            script: Vec::new(),
            ..scene.clone()
        };
        let world = build_world(&scene)?;
        let checkpoints = vec![Checkpoint::capture(&world)];
        Ok(Self {
            scene,
            world,
            checksum_every,
            inputs: Vec::new(),
            checkpoints,
        })
    }

    /// The world being recorded.
    pub fn world(&self) -> &World<Fx> {
        &self.world
    }

    /// Starts collecting per-stage timings (they are not recorded).
    pub fn enable_timing(&mut self) {
        self.world.enable_timing();
    }

    /// Starts checking the world for divergence every `every` ticks (not recorded).
    pub fn enable_divergence_check(&mut self, every: u64) {
        self.world.enable_divergence_check(every);
    }

    /// Runs one tick with `input` (its `tick` field is ignored: the input applies to the
    /// world's current tick).
    pub fn step(&mut self, input: &TickInput<Fx>) -> TickReport {
        let report = if input.is_empty() {
            self.world.step(input)
        } else {
            let mut canonical = input.clone();
            canonical.tick = self.world.tick();
            canonical.canonicalize();
            canonical.players.retain(|p| !p.commands.is_empty());
            let report = self.world.step(&canonical);
            self.inputs.push(canonical);
            report
        };
        if self
            .world
            .tick()
            .is_multiple_of(u64::from(self.checksum_every.get()))
        {
            self.checkpoints.push(Checkpoint::capture(&self.world));
        }
        report
    }

    /// Takes the checkpoints captured so far out of the recorder (to write them as they come,
    /// see [`StreamingRecorder`](super::StreamingRecorder)).
    pub(super) fn drain_checkpoints(&mut self) -> std::vec::Drain<'_, Checkpoint> {
        self.checkpoints.drain(..)
    }

    /// The replay of the ticks run so far.
    pub fn finish(mut self) -> Replay {
        let ticks = self.world.tick();
        if self.checkpoints.last().is_none_or(|c| c.tick != ticks) {
            self.checkpoints.push(Checkpoint::capture(&self.world));
        }
        Replay {
            state_version: STATE_VERSION,
            scene: self.scene,
            inputs: self.inputs,
            ticks,
            checksum_every: self.checksum_every,
            checkpoints: self.checkpoints,
        }
    }
}

/// Builds a scene's world for recording or verifying. A replay holds no code, so a scene
/// with user forces (`User(name: ...)`) must have them registered, which these worlds
/// cannot do: such scenes are refused, naming the force.
pub(super) fn build_world(scene: &Scene<Fx>) -> Result<World<Fx>, SceneError> {
    let world = scene.build()?;
    if let Some(particles) = world.particles() {
        particles
            .check_user_forces()
            .map_err(|e| e.within("particles"))?;
    }
    Ok(world)
}

/// Records `ticks` ticks of `scene`, feeding its script.
pub fn record(
    scene: &Scene<Fx>,
    ticks: u64,
    checksum_every: NonZeroU32,
) -> Result<Replay, SceneError> {
    let mut recorder = Recorder::new(scene, checksum_every)?;
    let mut feed = InputFeed::new(&scene.script);
    for tick in 0..ticks {
        recorder.step(feed.at(tick));
    }
    Ok(recorder.finish())
}

/// Records a replay's scene and inputs again with this build's engine: the same ticks and
/// checkpoint interval, this build's state version and fresh checkpoints.
pub fn rerecord(replay: &Replay) -> Result<Replay, SceneError> {
    let mut recorder = Recorder::new(replay.scene(), replay.checksum_every())?;
    let mut feed = InputFeed::new(replay.inputs());
    for tick in 0..replay.ticks() {
        recorder.step(feed.at(tick));
    }
    Ok(recorder.finish())
}
