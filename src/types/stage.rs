//! The named stages of a tick, in the order they run.

/// The stages of [`World::step`](crate::world::World::step), in the order they run.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Stage {
    /// Apply the tick's commands: players in ascending index, commands in order.
    ApplyInputs,
    /// Particles: emit, age, accumulate forces, integrate (once per substep).
    Particles,
    /// Rigid bodies: collide, wake, solve, sleep (once per substep).
    Rigid,
    /// Soft bodies: XPBD substeps and spring-mass integration (once per substep).
    Soft,
    /// Fluid: emit, neighbours, density, pressure solve, advect (once per substep).
    Fluid,
    /// Kinematic characters: move-and-slide against the bodies (once per tick).
    Characters,
    /// Water surface: the wave steps (once per substep); its float forces are applied
    /// earlier, right after the inputs.
    Water,
    /// Advance the tick counter and clear per-tick accumulators.
    EndTick,
}

impl Stage {
    /// Every stage, in execution order.
    pub const ALL: [Stage; 8] = [
        Stage::ApplyInputs,
        Stage::Particles,
        Stage::Rigid,
        Stage::Soft,
        Stage::Fluid,
        Stage::Characters,
        Stage::Water,
        Stage::EndTick,
    ];

    /// The stage's name as printed in timing tables.
    pub const fn name(self) -> &'static str {
        match self {
            Stage::ApplyInputs => "apply_inputs",
            Stage::Particles => "particles",
            Stage::Rigid => "rigid",
            Stage::Soft => "soft",
            Stage::Fluid => "fluid",
            Stage::Characters => "characters",
            Stage::Water => "water",
            Stage::EndTick => "end_tick",
        }
    }
}
