//! The fixstep world as a Bevy resource: the state, the scene it was built from, the input
//! of the coming tick and the inputs of every tick so far (for the replay).

use core::num::NonZeroU32;

use bevy::prelude::Resource;
use fixstep::math::Fx;
use fixstep::replay::{Recorder, Replay};
use fixstep::scene::{Scene, SceneError};
use fixstep::world::{Command, PlayerInput, TickInput, World};

/// The player index under which the plugin's own commands (spawns and removals of the
/// plugin's components) enter a tick's input: after every game player.
pub const PLUGIN_PLAYER: u8 = u8::MAX;

/// The simulation. Built at `PostStartup` from the plugin's scene and the entities then
/// carrying [`RigidBody`](super::RigidBody), [`Joint`](super::Joint) and
/// [`Character`](super::Character); rolled back as a whole with bevy_ggrs.
#[derive(Resource)]
pub struct FixstepWorld {
    pub(crate) world: World<Fx>,
    pub(crate) scene: Scene<Fx>,
    /// The commands of the coming tick, by player.
    pub(crate) input: TickInput<Fx>,
    /// The input of every tick run, `history[t]` for tick t (its length is the tick).
    pub(crate) history: Vec<TickInput<Fx>>,
}

impl FixstepWorld {
    /// A world built from `scene` (its script is not fed: games give inputs).
    pub fn new(scene: Scene<Fx>) -> Result<Self, SceneError> {
        let scene = Scene {
            script: Vec::new(),
            ..scene
        };
        let world = scene.build()?;
        Ok(Self {
            world,
            scene,
            input: TickInput::default(),
            history: Vec::new(),
        })
    }

    /// The world (read only: change it with commands, so that the change is in the input).
    pub fn world(&self) -> &World<Fx> {
        &self.world
    }

    /// The scene the world was built from, with the startup entities' bodies, joints and
    /// characters: what a replay records.
    pub fn scene(&self) -> &Scene<Fx> {
        &self.scene
    }

    /// The world's 64-bit checksum.
    pub fn checksum(&self) -> u64 {
        self.world.checksum().total
    }

    /// Queues `command` for `player` in the coming tick.
    pub fn push(&mut self, player: u8, command: Command<Fx>) {
        match self.input.players.iter_mut().find(|p| p.player == player) {
            Some(input) => input.commands.push(command),
            None => self.input.players.push(PlayerInput {
                player,
                commands: vec![command],
            }),
        }
    }

    /// Runs one tick on the queued commands and keeps the input; returns the tick run.
    pub(crate) fn step(&mut self) -> u64 {
        let mut input = core::mem::take(&mut self.input);
        input.tick = self.world.tick();
        input.players.retain(|p| !p.commands.is_empty());
        input.canonicalize();
        self.world.step(&input);
        self.history.push(input);
        self.world.tick() - 1
    }

    /// The inputs of every tick run so far.
    pub fn history(&self) -> &[TickInput<Fx>] {
        &self.history
    }

    /// The replay of the first `ticks` ticks run (all of them if fewer ran), re-simulated
    /// from the scene so that its checkpoints are those `fixstep verify` recomputes, with a
    /// checkpoint every `checksum_every` ticks. Under rollback, record ticks that are
    /// confirmed: later ones may still be simulated again.
    pub fn replay(&self, ticks: u64, checksum_every: NonZeroU32) -> Result<Replay, SceneError> {
        let mut recorder = Recorder::new(&self.scene, checksum_every)?;
        let ticks = usize::try_from(ticks).unwrap_or(usize::MAX);
        for input in self.history.iter().take(ticks) {
            recorder.step(input);
        }
        Ok(recorder.finish())
    }

    /// Restores `snapshot`'s world and forgets the inputs of the ticks after it.
    pub(crate) fn restore(&mut self, snapshot: &fixstep::world::WorldState<Fx>) {
        self.world.restore(snapshot);
        let tick = usize::try_from(self.world.tick()).unwrap_or(usize::MAX);
        self.history.truncate(tick);
        self.input = TickInput::default();
    }
}
