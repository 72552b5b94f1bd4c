//! Generational handles: an index into a dense array plus the generation of the slot.
//!
//! A handle to a removed object stays invalid forever, even after its slot is reused,
//! because reuse bumps the slot's generation. Handles order by (index, generation), so
//! iterating in handle order is the same on every machine.

use core::fmt;

use serde::{Deserialize, Serialize};

/// A stable id: slot index plus the slot's generation when the object was created.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub struct Handle {
    /// Slot in the owning subsystem's dense arrays.
    pub index: u32,
    /// Generation of the slot; a mismatch means the object was removed.
    pub generation: u32,
}

impl Handle {
    /// The handle with this index and generation.
    pub const fn new(index: u32, generation: u32) -> Self {
        Self { index, generation }
    }
}

impl fmt::Debug for Handle {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}v{}", self.index, self.generation)
    }
}

impl fmt::Display for Handle {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self, f)
    }
}
