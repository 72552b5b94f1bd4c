//! Collision layers: which bodies interact, and which bodies a query sees.
//!
//! Every body carries a [`CollisionFilter`], two 32-bit sets: the layers it is on and the
//! layers it interacts with. Two bodies interact (collide, or a sensor detects the other)
//! only when each is on a layer the other's mask accepts:
//!
//! `(a.layers & b.mask) != 0 && (b.layers & a.mask) != 0`.
//!
//! The default is all ones: on every layer, accepting every layer. Jointed bodies keep
//! their joint's rule (`collide: false` drops the pair whatever the filters say).

use serde::{Deserialize, Serialize};

use crate::types::Handle;

/// The layers a body is on and the layers it interacts with.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CollisionFilter {
    /// The layers the body is on, one bit each. Default all ones.
    #[serde(default = "all_layers")]
    pub layers: u32,
    /// The layers the body interacts with. Default all ones.
    #[serde(default = "all_layers")]
    pub mask: u32,
}

fn all_layers() -> u32 {
    u32::MAX
}

impl Default for CollisionFilter {
    fn default() -> Self {
        Self::ALL
    }
}

impl CollisionFilter {
    /// On every layer, interacting with every layer.
    pub const ALL: Self = Self {
        layers: u32::MAX,
        mask: u32::MAX,
    };

    /// Whether this is the default, [`Self::ALL`].
    pub fn is_all(&self) -> bool {
        *self == Self::ALL
    }

    /// The filter on `layers` that interacts with `mask`.
    pub const fn new(layers: u32, mask: u32) -> Self {
        Self { layers, mask }
    }

    /// Whether two bodies with these filters interact: each is on a layer the other
    /// accepts.
    #[inline]
    pub const fn interacts(self, other: Self) -> bool {
        (self.layers & other.mask) != 0 && (other.layers & self.mask) != 0
    }
}

/// Which bodies a query reports.
///
/// A body passes when its filter [interacts](CollisionFilter::interacts) with `filter`,
/// its handle is not in `exclude`, and it is not a sensor unless `sensors` is true.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct QueryFilter {
    /// The query's own layers and mask; default all ones (sees every body).
    pub filter: CollisionFilter,
    /// Bodies the query ignores (the shooter itself, for example).
    pub exclude: Vec<Handle>,
    /// Whether sensors are reported. Default false: a ray passes through trigger volumes.
    pub sensors: bool,
}

impl QueryFilter {
    /// The filter that sees every body but the sensors.
    pub fn new() -> Self {
        Self::default()
    }

    /// The same filter, seeing only bodies whose layers meet `mask`.
    pub fn with_mask(mut self, mask: u32) -> Self {
        self.filter.mask = mask;
        self
    }

    /// The same filter, ignoring `handle` too.
    pub fn excluding(mut self, handle: Handle) -> Self {
        self.exclude.push(handle);
        self
    }

    /// The same filter, reporting sensors too.
    pub fn with_sensors(mut self) -> Self {
        self.sensors = true;
        self
    }

    /// Whether a body with this filter, sensor flag and handle passes.
    #[inline]
    pub fn accepts(&self, body: CollisionFilter, sensor: bool, handle: Handle) -> bool {
        self.filter.interacts(body) && (self.sensors || !sensor) && !self.exclude.contains(&handle)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_interacts_with_everything_but_an_empty_mask() {
        let all = CollisionFilter::ALL;
        assert!(all.interacts(all));
        assert!(all.interacts(CollisionFilter::new(1, 1)));
        assert!(!all.interacts(CollisionFilter::new(1, 0)));
    }

    #[test]
    fn both_sides_must_accept() {
        let player = CollisionFilter::new(0b01, 0b11);
        let bullet = CollisionFilter::new(0b10, 0b00);
        assert!(!player.interacts(bullet));
        assert!(!bullet.interacts(player));
        let debris = CollisionFilter::new(0b10, 0b01);
        assert!(player.interacts(debris));
        assert!(debris.interacts(player));
    }

    #[test]
    fn a_query_filter_skips_sensors_and_excluded_handles() {
        let h = Handle::new(3, 0);
        let f = QueryFilter::new();
        assert!(f.accepts(CollisionFilter::ALL, false, h));
        assert!(!f.accepts(CollisionFilter::ALL, true, h));
        assert!(
            f.clone()
                .with_sensors()
                .accepts(CollisionFilter::ALL, true, h)
        );
        assert!(
            !f.clone()
                .excluding(h)
                .accepts(CollisionFilter::ALL, false, h)
        );
        assert!(
            !f.with_mask(2)
                .accepts(CollisionFilter::new(1, u32::MAX), false, h)
        );
    }
}
