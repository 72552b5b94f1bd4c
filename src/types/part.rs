//! The parts of the world state that have their own sub-checksum.

use core::fmt;

use serde::{Deserialize, Serialize};

/// A part of the world state with its own sub-checksum.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Part {
    /// Tick, settings, RNG and game payload digest.
    Core,
    /// The particle system.
    Particles,
    /// The rigid bodies and their contacts.
    Rigid,
    /// The soft bodies.
    Soft,
    /// The fluid particles and emitters.
    Fluid,
    /// The kinematic characters.
    Characters,
    /// The water surface.
    Water,
}

impl Part {
    /// The byte that stands for the part in the world checksum.
    pub const fn code(self) -> u8 {
        match self {
            Part::Core => 0,
            Part::Particles => 1,
            Part::Rigid => 2,
            Part::Soft => 3,
            Part::Fluid => 4,
            Part::Characters => 5,
            Part::Water => 6,
        }
    }

    /// The part's name in reports.
    pub const fn name(self) -> &'static str {
        match self {
            Part::Core => "core",
            Part::Particles => "particles",
            Part::Rigid => "rigid",
            Part::Soft => "soft",
            Part::Fluid => "fluid",
            Part::Characters => "characters",
            Part::Water => "water",
        }
    }
}

impl fmt::Display for Part {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
