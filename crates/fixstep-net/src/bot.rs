//! A deterministic bot: each player's input as a pure function of (seed, player, tick).
//!
//! Rollback re-simulates ticks and asks for their inputs again, and every peer must be able
//! to reproduce a player's inputs from the recording, so the bot keeps no state between
//! ticks: the input for a tick comes from a fresh [`Pcg32`] seeded from the bot's seed and
//! the tick, on a stream of its own per player. Only integers are drawn.

use super::input::{Action, NetInput};
use fixstep::math::Fx;
use fixstep::math::rng::Pcg32;
use fixstep::rigid::BodyKind;
use fixstep::world::World;

/// The bot's RNG streams start here (one per player): "netbot" in ASCII.
const BOT_STREAM: u64 = 0x6e65_7462_6f74;

/// Odd 64-bit constant (2⁶⁴/φ) spreading consecutive ticks over the seed space.
const TICK_SPREAD: u64 = 0x9e37_79b9_7f4a_7c15;

/// The bot acts on one tick in `ACT_ONE_IN` on average and idles otherwise.
const ACT_ONE_IN: u32 = 8;

/// Largest horizontal velocity change of a kicked body, in 1/16 m/s (1.5 m/s).
const BODY_DV_HORIZONTAL: u32 = 24;

/// Largest upward velocity change of a kicked body, in 1/16 m/s (3 m/s).
const BODY_DV_UP: u32 = 48;

/// Largest horizontal impulse on a particle group, in 1/16 N·s (0.5 N·s).
const GROUP_IMPULSE_HORIZONTAL: u32 = 8;

/// Largest upward impulse on a particle group, in 1/16 N·s (1 N·s).
const GROUP_IMPULSE_UP: u32 = 16;

/// The bot of one session: its seed and what the scene offers to act on.
#[derive(Clone, Debug)]
pub struct Bot {
    seed: u64,
    /// Slot and mass of every dynamic body of the scene at tick 0.
    bodies: Vec<(u16, Fx)>,
    /// Whether the scene has particles (group 0 is kicked).
    particles: bool,
    /// How many body templates the scene has (spawns pick one).
    templates: u16,
}

impl Bot {
    /// A bot for the world `world` (at tick 0) with seed `seed`.
    pub fn new(seed: u64, world: &World<Fx>) -> Self {
        let bodies = world
            .rigid()
            .map(|rigid| {
                rigid
                    .handles()
                    .filter(|&h| rigid.kind(h) == Some(BodyKind::Dynamic))
                    .filter_map(|h| {
                        let slot = u16::try_from(h.index).ok()?;
                        Some((slot, rigid.mass(h)?))
                    })
                    .collect()
            })
            .unwrap_or_default();
        Self {
            seed,
            bodies,
            particles: world.particles().is_some(),
            templates: world.rigid().map_or(0, |r| {
                u16::try_from(r.templates().len()).unwrap_or(u16::MAX)
            }),
        }
    }

    /// Player `player`'s input for `tick`. Seven ticks in eight are idle; otherwise the
    /// player kicks a random dynamic body (Δv uniform in ±1.5 m/s horizontally and 0–3 m/s
    /// up, J = m·Δv), or the particles of group 0 (J in ±0.5 N·s horizontally, 0–1 N·s up),
    /// or, one action in four or when the scene has neither, sends a random payload. In a
    /// scene with body templates, half the other actions spawn a body instead (see below).
    pub fn input(&self, player: u8, tick: u64) -> NetInput {
        let mut rng = Pcg32::new(
            self.seed ^ tick.wrapping_mul(TICK_SPREAD),
            BOT_STREAM + u64::from(player),
        );
        if rng.below(ACT_ONE_IN) != 0 {
            return NetInput::default();
        }
        let payload = rng.below(4) == 0;
        if !payload && self.templates > 0 && rng.below(2) == 0 {
            // Spawn from a random template within ±4 m horizontally, 4–8 m up, thrown at
            // up to ±3 m/s horizontally.
            return NetInput {
                action: Action::SpawnBody,
                target: rng.below(u32::from(self.templates)) as u16,
                position: [
                    symmetric(&mut rng, 64) as i16,
                    (64 + rng.below(65)) as i16,
                    symmetric(&mut rng, 64) as i16,
                ],
                impulse: [
                    symmetric(&mut rng, 48) as i16,
                    0,
                    symmetric(&mut rng, 48) as i16,
                ],
                ..NetInput::default()
            };
        }
        if !payload && let Some(&(slot, mass)) = self.pick_body(&mut rng) {
            let dv = [
                symmetric(&mut rng, BODY_DV_HORIZONTAL),
                rng.below(BODY_DV_UP + 1) as i64,
                symmetric(&mut rng, BODY_DV_HORIZONTAL),
            ];
            return NetInput {
                action: Action::ImpulseBody,
                target: slot,
                impulse: dv.map(|dv| mass_times(mass, dv)),
                ..NetInput::default()
            };
        }
        if !payload && self.particles {
            let impulse = [
                symmetric(&mut rng, GROUP_IMPULSE_HORIZONTAL),
                rng.below(GROUP_IMPULSE_UP + 1) as i64,
                symmetric(&mut rng, GROUP_IMPULSE_HORIZONTAL),
            ];
            return NetInput {
                action: Action::ImpulseGroup,
                target: 0,
                impulse: impulse.map(|j| j as i16),
                ..NetInput::default()
            };
        }
        NetInput {
            action: Action::Payload,
            payload: rng.next_u32(),
            ..NetInput::default()
        }
    }

    fn pick_body(&self, rng: &mut Pcg32) -> Option<&(u16, Fx)> {
        let count = u32::try_from(self.bodies.len()).ok().filter(|&n| n > 0)?;
        self.bodies.get(rng.below(count) as usize)
    }
}

/// A uniform integer in [−`bound`, `bound`].
fn symmetric(rng: &mut Pcg32, bound: u32) -> i64 {
    i64::from(rng.below(2 * bound + 1)) - i64::from(bound)
}

/// m·Δv in 1/16 N·s for Δv in 1/16 m/s: the fixed-point mass times `dv`, truncated toward
/// −∞ and clamped to the `i16` range of [`NetInput::impulse`].
fn mass_times(mass: Fx, dv: i64) -> i16 {
    let units = (i128::from(mass.to_bits()) * i128::from(dv)) >> 32;
    units.clamp(i128::from(i16::MIN), i128::from(i16::MAX)) as i16
}
