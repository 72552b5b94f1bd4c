//! A run's health: what a driver should warn about after stepping a world, gathered from
//! the ticks' reports.
//!
//! Three things go wrong in a valid scene without stopping the run:
//! - **saturations**: fixed-point values hit the numeric range and were clamped
//!   ([`crate::math::saturation`]); the first tick that saturated names the stage it
//!   happened in and, when some object holds a value at the range's edge after the tick,
//!   that object ([`SaturationSite`]), and the first object to reach the edge is kept;
//! - **capped contacts**: a rigid step found more than
//!   [`MAX_PAIRS`](crate::rigid::broadphase::MAX_PAIRS) overlapping bounding boxes, and kept
//!   only the contacts with static bodies, so other bodies may pass through each other
//!   ([`RigidSystem::capped_steps`](crate::rigid::RigidSystem::capped_steps));
//! - **divergence**: the energy per simulated point grew past the monitor's limit
//!   ([`super::divergence`]).
//!
//! All of it is reporting, outside the simulated state: it never enters a checksum, and a
//! re-simulated run reports the same.

use super::divergence::Divergence;
use crate::types::{Handle, Part, Stage};

/// Where a tick's first saturation happened.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SaturationSite {
    /// The tick (its number before the step, as [`World::tick`](super::World::tick) was).
    pub tick: u64,
    /// How many saturations the tick counted in all stages.
    pub count: u64,
    /// The first stage, in the order the tick ran them, that saturated.
    pub stage: Stage,
    /// The first object (lowest slot) of that stage's subsystem whose position or velocity
    /// holds a value at the edge of the numeric range after the tick, with its part; `None`
    /// when no object does (the clamped value was an intermediate, such as a contact
    /// impulse, and did not stay in the state) or the stage has no objects. Finding the
    /// object that caused each clamped operation would take a check per operation in the
    /// step's inner loops; this scan costs one pass over the stage's objects, and only on
    /// ticks that saturated.
    pub object: Option<(Part, Handle)>,
}

/// What a run so far has to warn about (see the [module](self) documentation); a world
/// keeps one ([`World::health`](super::World::health)).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Health {
    /// Saturations over every tick run.
    pub saturations: u64,
    /// The first tick that saturated, and where.
    pub first_saturation: Option<SaturationSite>,
    /// The first saturating tick after which some object held a value at the range's edge,
    /// with that object: the same tick as `first_saturation` when it names an object, a
    /// later one when the first saturations were intermediates (a force, an impulse) and
    /// the state reached the edge only later.
    pub first_saturated_object: Option<(u64, Part, Handle)>,
    /// Ticks with at least one rigid step whose contacts were capped.
    pub capped_ticks: u64,
    /// The first of them.
    pub first_capped_tick: Option<u64>,
    /// The first divergence, when the check is on
    /// ([`World::enable_divergence_check`](super::World::enable_divergence_check)).
    pub divergence: Option<Divergence>,
}

impl Health {
    /// Adds one tick's figures: its saturations and the site of the first, if any, and
    /// whether some rigid step of it had its contacts capped.
    pub(crate) fn add_tick(
        &mut self,
        tick: u64,
        saturations: u64,
        site: Option<SaturationSite>,
        capped: bool,
    ) {
        self.saturations += saturations;
        if let Some(site) = site {
            self.first_saturation.get_or_insert(site);
            if let Some((part, handle)) = site.object {
                self.first_saturated_object
                    .get_or_insert((site.tick, part, handle));
            }
        }
        if capped {
            self.capped_ticks += 1;
            self.first_capped_tick.get_or_insert(tick);
        }
    }
}
