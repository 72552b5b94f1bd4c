//! The water surface as one of the world's subsystems.

use super::WaterSystem;
use crate::math::saturation::at_range_edge;
use crate::math::state_hash::StateHasher;
use crate::math::{Real, Vec3};
use crate::types::{Handle, Metrics, Part, SceneError, Stage, StepContext, Subsystem};

impl<R: Real> Subsystem<R> for WaterSystem<R> {
    fn stage(&self) -> Stage {
        Stage::Water
    }

    fn part(&self) -> Part {
        Part::Water
    }

    /// One world substep of the waves, itself split into the surface's wave steps.
    fn step(&mut self, context: &mut StepContext<'_, R>) {
        WaterSystem::step(self, context.dt);
    }

    fn hash_state(&self, hasher: &mut StateHasher) {
        WaterSystem::hash_state(self, hasher);
    }

    /// The surface has no objects, so no per-object digests: a desync is named by its
    /// part's sub-checksum.
    fn slot_digests(&self) -> Vec<(Handle, u32)> {
        Vec::new()
    }

    /// The surface's heights are not objects; its energy stays out of the world's sums.
    fn add_metrics(&self, _gravity: Vec3<R>, _metrics: &mut Metrics) {}

    /// The first cell (its slot as the handle's index) whose height or outgoing flow is at
    /// the range's edge.
    fn saturated_object(&self) -> Option<Handle> {
        let n = self.settings.columns as usize;
        let flow = |flows: &[R], e: usize| flows.get(e).copied().unwrap_or(R::ZERO);
        (0..self.heights.len())
            .find(|&i| {
                let (column, row) = (i % n, i / n);
                let q_x = if column + 1 < n {
                    flow(&self.flow_x, column + (n - 1) * row)
                } else {
                    R::ZERO
                };
                at_range_edge(Vec3::new(self.heights[i], q_x, flow(&self.flow_z, i)))
            })
            .map(|i| Handle::new(i as u32, 0))
    }

    fn validate(&self) -> Result<(), SceneError> {
        WaterSystem::validate(self)
    }

    fn restore_from(&mut self, restored: Self) {
        WaterSystem::restore_from(self, restored);
    }
}
