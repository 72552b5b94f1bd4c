//! Sensors: bodies that detect the bodies they overlap, and exert and feel no contact
//! force.
//!
//! The collide stage sets aside the broadphase pairs with one sensor (pairs of two sensors
//! are dropped, as in Box2D). A pair overlaps when some part pair's manifold, computed with
//! no speculative margin, has a point of separation ≤ 0 m: the shapes share volume or
//! touch. Pairs of two bodies that do not move this step (static or sleeping) keep their
//! last answer, as contacts do.
//!
//! The overlapping pairs are state ([`RigidSystem::sensor_overlaps`]): a snapshot carries
//! them, so the `sensor_enter` and `sensor_exit` events they raise are the same after a
//! restore.

use super::collide::for_each_manifold;
use super::events::{EventKind, sorted_difference};
use super::system::RigidSystem;
use crate::math::Real;

impl<R: Real> RigidSystem<R> {
    /// After a collide stage: the sensor pairs that overlap now, replacing the previous
    /// list, with an event for each pair that entered or left.
    pub(crate) fn update_sensor_overlaps(&mut self) {
        let bodies = &self.bodies;
        let still = |a: u32, b: u32| {
            let (a, b) = (a as usize, b as usize);
            bodies.alive[a] && bodies.alive[b] && !bodies.is_moving(a) && !bodies.is_moving(b)
        };
        let transforms = &self.scratch.transforms;
        let overlapping = |a: u32, b: u32| {
            let (a, b) = (a as usize, b as usize);
            let mut touching = false;
            for_each_manifold(
                &bodies.shape[a],
                &transforms[a],
                &bodies.shape[b],
                &transforms[b],
                R::ZERO,
                |_, _, manifold| {
                    touching |= manifold.points().iter().any(|p| p.separation <= R::ZERO);
                },
            );
            touching
        };
        let mut now: Vec<(u32, u32)> = self
            .sensor_overlaps
            .iter()
            .copied()
            .filter(|&(a, b)| still(a, b))
            .chain(
                self.scratch
                    .sensor_pairs
                    .iter()
                    .copied()
                    .filter(|&(a, b)| overlapping(a, b)),
            )
            .collect();
        now.sort_unstable();
        now.dedup();
        let before = core::mem::take(&mut self.sensor_overlaps);
        let mut found = Vec::new();
        sorted_difference(before.into_iter(), now.iter().copied(), |pair, entered| {
            let kind = if entered {
                EventKind::SensorEnter
            } else {
                EventKind::SensorExit
            };
            found.push((kind, pair));
        });
        for (kind, (a, b)) in found {
            self.push_pair_event(kind, a, b);
        }
        self.sensor_overlaps = now;
    }

    /// The sensor pairs that overlap, as (lower slot, higher slot), ascending.
    pub fn sensor_overlaps(
        &self,
    ) -> impl Iterator<Item = (crate::types::Handle, crate::types::Handle)> + '_ {
        self.sensor_overlaps.iter().map(|&(a, b)| {
            (
                self.bodies.handle(a as usize),
                self.bodies.handle(b as usize),
            )
        })
    }
}
