//! Broadphase (placeholder until the broadphase branch lands).

use super::aabb::Aabb;
use crate::math::{Fx, Real};

/// Brute force, for now.
#[derive(Debug, Default)]
pub struct BroadPhase<R: Real = Fx> {
    _marker: core::marker::PhantomData<R>,
}

impl<R: Real> BroadPhase<R> {
    /// A broadphase with nothing cached.
    pub fn new() -> Self {
        Self::default()
    }

    /// Every overlapping pair with at least one active box, ascending.
    pub fn find_pairs(
        &mut self,
        boxes: &[Aabb<R>],
        active: &[bool],
        present: &[bool],
        out: &mut Vec<(u32, u32)>,
    ) {
        out.clear();
        for a in 0..boxes.len() {
            for b in a + 1..boxes.len() {
                if present[a]
                    && present[b]
                    && (active[a] || active[b])
                    && boxes[a].overlaps(&boxes[b])
                {
                    out.push((a as u32, b as u32));
                }
            }
        }
    }
}
