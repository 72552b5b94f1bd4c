//! The solver's bodies and constraint blocks in the lanes of [`Wide`]: what the contact
//! kernels load and store beyond the lane vocabulary itself, a solver body's velocities and
//! motions in particular, whose record layout each backend reads its own way.

mod avx2;
mod avx512;

pub(crate) use avx512::{BODY_WORDS, V, W};

use super::body::SolverBody;
use super::lanes::{LANES, Lanes3};
use crate::math::Fx;
use crate::math::wide::Wide;

// The solver's blocks are as wide as the vectors.
const _: () = assert!(LANES == crate::math::wide::LANES);

/// The loads and stores of solver bodies, for every backend of [`Wide`].
pub(crate) trait WideBodies: Wide {
    /// The velocities v, ω and, when `with_motion`, the motions Δp, Δθ (zero otherwise)
    /// of the bodies `indices` in the lanes of `active` (zero elsewhere), one vector per
    /// component.
    ///
    /// # Safety
    /// The index of every lane of `active` must be that of a body of `bodies`.
    unsafe fn load_bodies(
        self,
        bodies: &[SolverBody<Fx>],
        indices: &[u32; LANES],
        active: u8,
        with_motion: bool,
    ) -> [[Self::V; 3]; 4];

    /// Writes v and ω of the bodies `indices` in the lanes of `active`.
    ///
    /// # Safety
    /// As for [`load_bodies`](Self::load_bodies).
    unsafe fn store_velocities(
        self,
        bodies: &mut [SolverBody<Fx>],
        indices: &[u32; LANES],
        active: u8,
        velocities: [[Self::V; 3]; 2],
    );

    /// The three lane arrays of a block's vector.
    #[inline(always)]
    fn load3(self, lanes: &Lanes3<Fx>) -> [Self::V; 3] {
        [
            self.load(&lanes.x),
            self.load(&lanes.y),
            self.load(&lanes.z),
        ]
    }

    /// Writes the lanes of `mask` to the three lane arrays of a block's vector; the others
    /// keep their values.
    #[inline(always)]
    fn store_lanes3(self, lanes: &mut Lanes3<Fx>, mask: u8, value: [Self::V; 3]) {
        self.store_lanes(&mut lanes.x, mask, value[0]);
        self.store_lanes(&mut lanes.y, mask, value[1]);
        self.store_lanes(&mut lanes.z, mask, value[2]);
    }
}
