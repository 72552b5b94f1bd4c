//! The GGRS configuration of a fixstep session.

use std::net::SocketAddr;

use super::input::NetInput;
use fixstep::math::Fx;
use fixstep::world::WorldState;

/// GGRS types for fixstep: [`NetInput`] per player and tick, the [`WorldState`] as the
/// saved game state (a snapshot, restored exactly with [`World::restore`]), peers named by
/// socket address. A missing remote input is predicted to repeat the last one.
///
/// [`World::restore`]: fixstep::world::World::restore
#[derive(Debug)]
pub struct FixstepConfig;

impl ggrs::Config for FixstepConfig {
    type Input = NetInput;
    type InputPredictor = ggrs::PredictRepeatLast;
    type State = WorldState<Fx>;
    type Address = SocketAddr;
}
