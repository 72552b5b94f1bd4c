//! The input a peer sends for one tick, and the commands it stands for.
//!
//! GGRS exchanges one fixed-size [`NetInput`] per player and tick, serialised with serde
//! (GGRS uses bincode 1, then delta-encodes consecutive inputs, so the zeros of an idle
//! player cost almost nothing on the wire). The world never sees a `NetInput`: each one maps
//! deterministically, with integer arithmetic only, to at most one [`Command`] of its
//! player ([`NetInput::to_player_input`]).

use serde::{Deserialize, Serialize};

use fixstep::math::{Fx, Quat, Real, Vec3};
use fixstep::scene::Scene;
use fixstep::world::{Command, Handle, PlayerInput, Target, TickInput};

/// Impulse components are sent in units of 1/`IMPULSE_UNITS_PER_NS` N·s.
pub const IMPULSE_UNITS_PER_NS: i64 = 16;

/// What a player does on one tick.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Action {
    /// Nothing.
    #[default]
    Idle,
    /// An impulse on the rigid body in slot `target` (generation 0: a body of the scene).
    ImpulseBody,
    /// An impulse on every live particle of group `target`.
    ImpulseGroup,
    /// A game-logic payload ([`Command::Payload`]) with the value `payload`.
    Payload,
    /// A rigid body spawned from body template `target` ([`Command::SpawnBody`]) at
    /// `position` with velocity `impulse` (read as 1/16 m/s), unrotated, not spinning.
    SpawnBody,
    /// A joint spawned from joint template `target` ([`Command::SpawnJoint`]) between the
    /// bodies in slots `payload & 0xffff` and `payload >> 16` (generation 0: bodies of the
    /// scene), anchored at `position`, axis x.
    SpawnJoint,
}

/// One player's input for one tick, as GGRS sends it.
/// In a RON input file, missing fields are zero.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
pub struct NetInput {
    /// What the player does.
    pub action: Action,
    /// The body slot or particle group the action targets.
    pub target: u16,
    /// Impulse (x, y, z) in 1/16 N·s.
    pub impulse: [i16; 3],
    /// The payload value of [`Action::Payload`]; the two body slots of
    /// [`Action::SpawnJoint`].
    pub payload: u32,
    /// Where [`Action::SpawnBody`] and [`Action::SpawnJoint`] act, in 1/16 m.
    pub position: [i16; 3],
    /// In lockstep mode, on ticks that are multiples of the desync-detection interval: the
    /// sender's 128-bit checksum ([`super::checksum128`]) of the state at this tick, as
    /// (high, low) halves; zero otherwise. Never applied to the world.
    pub checksum_report: [u64; 2],
}

impl NetInput {
    /// The command this input stands for, if any: `ImpulseBody` →
    /// [`Command::ApplyImpulse`] on `Body(target v0)`, `ImpulseGroup` → the same on
    /// `ParticleGroup(target)`, both with impulse J = `impulse` / 16 N·s at the centre of
    /// mass; `Payload` → [`Command::Payload`]; `SpawnBody` and `SpawnJoint` → the spawn
    /// commands (positions and velocities in 1/16 m and 1/16 m/s, exactly).
    pub fn command(&self) -> Option<Command<Fx>> {
        let impulse = Vec3::new(
            impulse_component(self.impulse[0]),
            impulse_component(self.impulse[1]),
            impulse_component(self.impulse[2]),
        );
        let position = Vec3::new(
            impulse_component(self.position[0]),
            impulse_component(self.position[1]),
            impulse_component(self.position[2]),
        );
        let target = match self.action {
            Action::Idle => return None,
            Action::Payload => return Some(Command::Payload(self.payload)),
            Action::SpawnBody => {
                return Some(Command::SpawnBody {
                    template: u32::from(self.target),
                    position,
                    orientation: Quat::IDENTITY,
                    velocity: impulse,
                    angular_velocity: Vec3::ZERO,
                });
            }
            Action::SpawnJoint => {
                let slot = |s: u32| Handle::new(s, 0);
                return Some(Command::SpawnJoint {
                    template: u32::from(self.target),
                    bodies: (slot(self.payload & 0xffff), slot(self.payload >> 16)),
                    anchor: position,
                    anchor_b: None,
                    axis: Vec3::X,
                });
            }
            Action::ImpulseBody => Target::Body(Handle::new(u32::from(self.target), 0)),
            Action::ImpulseGroup => Target::ParticleGroup(self.target),
        };
        Some(Command::ApplyImpulse {
            target,
            impulse,
            point: None,
        })
    }

    /// The input of player `player` for the world: no command, or one.
    pub fn to_player_input(&self, player: u8) -> PlayerInput<Fx> {
        PlayerInput {
            player,
            commands: self.command().into_iter().collect(),
        }
    }
}

/// `units` / 16 N·s, exactly.
fn impulse_component(units: i16) -> Fx {
    Fx::from_ratio(i64::from(units), IMPULSE_UNITS_PER_NS)
}

/// The world's input for `tick`: the scene's scripted input for that tick, if any, then the
/// players' inputs (`inputs[i]` is player `i`'s), in canonical order.
pub fn tick_input(scene: &Scene<Fx>, tick: u64, inputs: &[NetInput]) -> TickInput<Fx> {
    let mut input = scene.script_at(tick).cloned().unwrap_or_default();
    input.tick = tick;
    for (player, net) in inputs.iter().enumerate() {
        let player = u8::try_from(player).unwrap_or(u8::MAX);
        input.players.push(net.to_player_input(player));
    }
    input.players.retain(|p| !p.commands.is_empty());
    input.canonicalize();
    input
}
