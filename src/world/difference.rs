//! Where two world states first differ: the part, and the first differing object.

use core::fmt;

use super::pipeline::WorldState;
use crate::math::Real;
use crate::types::Handle;
use crate::types::Part;

/// The first difference between two states, in [`Part`] order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Difference {
    /// The part that differs.
    pub part: Part,
    /// The first object (ascending slot index) whose state differs, when the difference is
    /// in an object rather than in the part's shared state (emitters, forces, settings).
    pub id: Option<Handle>,
}

impl fmt::Display for Difference {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.id {
            Some(id) => write!(f, "subsystem {}, first differing id {id}", self.part),
            None => write!(f, "subsystem {}, no single object differs", self.part),
        }
    }
}

/// The first difference between two states, or `None` when they are identical.
///
/// Parts are compared in [`Part`] order: core (tick, settings, RNG, payload digest), then
/// particles (first by slot, then the shared state), then the fluid (first by particle id,
/// then the shared state).
pub fn first_difference<R: Real>(a: &WorldState<R>, b: &WorldState<R>) -> Option<Difference> {
    let core_equal = a.tick == b.tick
        && a.settings == b.settings
        && a.rng == b.rng
        && a.payload_digest == b.payload_digest;
    if !core_equal {
        return Some(Difference {
            part: Part::Core,
            id: None,
        });
    }
    let particles = match (&a.particles, &b.particles) {
        (Some(pa), Some(pb)) => match pa.first_difference(pb) {
            Some(id) => Some(Difference {
                part: Part::Particles,
                id: Some(id),
            }),
            None if pa != pb => Some(Difference {
                part: Part::Particles,
                id: None,
            }),
            None => None,
        },
        (None, None) => None,
        _ => Some(Difference {
            part: Part::Particles,
            id: None,
        }),
    };
    particles.or_else(|| fluid_difference(a, b))
}

/// The first fluid particle (by id) whose position or velocity differs, or the fluid as a
/// whole when its shared state or presence differs.
fn fluid_difference<R: Real>(a: &WorldState<R>, b: &WorldState<R>) -> Option<Difference> {
    if a.fluid == b.fluid {
        return None;
    }
    let id = match (&a.fluid, &b.fluid) {
        (Some(fa), Some(fb)) => fa
            .slot_digests()
            .iter()
            .zip(fb.slot_digests())
            .find(|(x, y)| **x != *y)
            .map(|(x, _)| x.0),
        _ => None,
    };
    Some(Difference {
        part: Part::Fluid,
        id,
    })
}
