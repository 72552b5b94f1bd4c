//! Structure-of-arrays storage for a block of [`LANES`] constraints: one array per scalar
//! field, so that a field of all the block's constraints lies in one run of memory.

use crate::math::{Real, Vec3};

/// Constraints per block.
pub(crate) const LANES: usize = 8;

/// One scalar per lane.
pub(crate) type Lanes<R> = [R; LANES];

/// One vector per lane, stored as three arrays of components.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Lanes3<R: Real> {
    pub x: Lanes<R>,
    pub y: Lanes<R>,
    pub z: Lanes<R>,
}

impl<R: Real> Lanes3<R> {
    /// Every lane zero.
    pub const ZERO: Self = Self {
        x: [R::ZERO; LANES],
        y: [R::ZERO; LANES],
        z: [R::ZERO; LANES],
    };

    /// The vector of lane `l`.
    #[inline(always)]
    pub fn get(&self, l: usize) -> Vec3<R> {
        Vec3::new(self.x[l], self.y[l], self.z[l])
    }

    /// Sets the vector of lane `l`.
    #[inline(always)]
    pub fn set(&mut self, l: usize, v: Vec3<R>) {
        self.x[l] = v.x;
        self.y[l] = v.y;
        self.z[l] = v.z;
    }
}
