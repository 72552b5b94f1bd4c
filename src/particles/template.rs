//! Compiled particle templates, what a spawn command creates from.

use serde::{Deserialize, Serialize};

use crate::math::Real;

/// A compiled particle template: what `spawn` creates.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct SpawnTemplate<R: Real> {
    /// kg; 0 pins.
    pub mass: R,
    /// 1/mass, or 0 when pinned.
    pub inv_mass: R,
    pub group: u16,
    /// s; 0 for immortal.
    pub lifetime: R,
}
