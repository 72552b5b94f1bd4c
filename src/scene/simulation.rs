//! A world stepped with its inputs: a scene's script (or a replay's inputs) fed tick by
//! tick, so that nobody has to look the script up by hand.

use super::description::Scene;
use crate::math::{Fx, Real};
use crate::types::{PlayerInput, SceneError, TickInput};
use crate::world::{TickReport, World};

/// A world and the inputs it is fed: [`Simulation::step`] applies the input scripted for
/// the world's current tick (none when the script has nothing then), and
/// [`Simulation::step_with`] adds the game's own commands to it.
///
/// The input is looked up by the world's tick, not by a cursor, so a world restored to an
/// earlier tick through [`Simulation::world_mut`] (rollback) is fed its script again.
#[derive(Debug)]
pub struct Simulation<R: Real = Fx> {
    world: World<R>,
    inputs: Vec<TickInput<R>>,
}

impl<R: Real> Simulation<R> {
    /// Builds the scene's world at tick 0, to be fed the scene's script.
    pub fn new(scene: &Scene<R>) -> Result<Self, SceneError> {
        Ok(Self::resume(scene.build()?, scene.script.clone()))
    }

    /// A world built elsewhere (a scene's, restored from a snapshot, or a replay's), fed
    /// `inputs` (a scene's script or a replay's inputs) from its current tick on. The
    /// inputs are put in ascending tick order.
    pub fn resume(world: World<R>, mut inputs: Vec<TickInput<R>>) -> Self {
        inputs.sort_by_key(|input| input.tick);
        Self { world, inputs }
    }

    /// The input scripted for the next step (the world's current tick), if any.
    pub fn scripted(&self) -> Option<&TickInput<R>> {
        input_at(&self.inputs, self.world.tick())
    }

    /// Runs one tick with its scripted input.
    pub fn step(&mut self) -> TickReport {
        let tick = self.world.tick();
        match input_at(&self.inputs, tick) {
            Some(input) => self.world.step(input),
            None => self.world.step(&TickInput {
                tick,
                players: Vec::new(),
            }),
        }
    }

    /// Runs one tick with its scripted input and `players`' commands: each player's
    /// scripted commands first, then the given ones.
    pub fn step_with(&mut self, players: &[PlayerInput<R>]) -> TickReport {
        let tick = self.world.tick();
        let mut input = TickInput {
            tick,
            players: self
                .scripted()
                .map(|s| s.players.clone())
                .unwrap_or_default(),
        };
        input.players.extend_from_slice(players);
        input.canonicalize();
        self.world.step(&input)
    }

    /// The world.
    pub fn world(&self) -> &World<R> {
        &self.world
    }

    /// The world, to read and change (restore a snapshot, enable timing, …).
    pub fn world_mut(&mut self) -> &mut World<R> {
        &mut self.world
    }

    /// The inputs fed, in ascending tick order.
    pub fn inputs(&self) -> &[TickInput<R>] {
        &self.inputs
    }

    /// The world, without its inputs.
    pub fn into_world(self) -> World<R> {
        self.world
    }
}

/// The input for `tick` among `inputs` (in ascending tick order), if any.
pub(super) fn input_at<R: Real>(inputs: &[TickInput<R>], tick: u64) -> Option<&TickInput<R>> {
    inputs
        .binary_search_by_key(&tick, |input| input.tick)
        .ok()
        .map(|i| &inputs[i])
}
