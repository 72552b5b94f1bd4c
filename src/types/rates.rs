//! The tick rates and substep counts a world accepts, for scenes and snapshots alike.

use super::SceneError;

/// Highest tick rate a scene may ask for, Hz.
pub const MAX_TICK_RATE: u32 = 10_000;
/// Most substeps per tick a scene may ask for.
pub const MAX_SUBSTEPS: u32 = 1_000;

/// Checks a tick rate (1 to [`MAX_TICK_RATE`]) and a substep count (1 to [`MAX_SUBSTEPS`]);
/// the error names `tick_rate` or `substeps`.
pub fn check_rates(tick_rate: u32, substeps: u32) -> Result<(), SceneError> {
    if !(1..=MAX_TICK_RATE).contains(&tick_rate) {
        return Err(SceneError::new(
            "tick_rate",
            format!("must be 1 to {MAX_TICK_RATE} (got {tick_rate})"),
        ));
    }
    if !(1..=MAX_SUBSTEPS).contains(&substeps) {
        return Err(SceneError::new(
            "substeps",
            format!("must be 1 to {MAX_SUBSTEPS} (got {substeps})"),
        ));
    }
    Ok(())
}
