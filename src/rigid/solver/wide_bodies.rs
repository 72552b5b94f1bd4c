//! The solver's bodies and constraint blocks in the lanes of [`Wide`]: what the contact
//! kernels load and store beyond the lane vocabulary itself, a solver body's velocities and
//! motions in particular: lane by lane through arrays by default, and by rows and a
//! transpose in AVX-512 ([`avx512`]).

#[cfg(target_arch = "x86_64")]
mod avx512;

use core::mem::{offset_of, size_of};

use super::body::SolverBody;
use super::lanes::{LANES, Lanes3};
use crate::math::wide::Wide;
use crate::math::{Fx, Vec3};

pub(crate) const BODY_WORDS: i64 = (size_of::<SolverBody<Fx>>() / 8) as i64;
pub(crate) const V: i64 = (offset_of!(SolverBody<Fx>, v) / 8) as i64;
pub(crate) const W: i64 = (offset_of!(SolverBody<Fx>, w) / 8) as i64;
const DP: i64 = (offset_of!(SolverBody<Fx>, dp) / 8) as i64;
const DTHETA: i64 = (offset_of!(SolverBody<Fx>, dtheta) / 8) as i64;

// The layout the loads rely on: `Fx` is one `i64`, `Vec3<Fx>` x, y, z in a row, the body
// a whole number of words; v, ω, Δp and Δθ in a row from word 0, so that words 0–7 (v, ω,
// Δp_x, Δp_y) and 8–15 (Δp_z, Δθ, ...) are two rows of eight.
const _: () = {
    assert!(size_of::<Fx>() == 8);
    assert!(size_of::<Vec3<Fx>>() == 24);
    assert!(size_of::<SolverBody<Fx>>().is_multiple_of(8));
    assert!(V == 0 && W == 3 && DP == 6 && DTHETA == 9);
    assert!(BODY_WORDS >= 16);
    assert!(LANES == 8);
};

// The solver's blocks are as wide as the vectors.
const _: () = assert!(LANES == crate::math::wide::LANES);

/// The loads and stores of solver bodies, for every backend of [`Wide`].
pub(crate) trait WideBodies: Wide {
    /// The velocities v, ω and, when `with_motion`, the motions Δp, Δθ (zero otherwise)
    /// of the bodies `indices` in the lanes of `active` (zero elsewhere), one vector per
    /// component. Lane by lane (the default): the words of each body of `active` gathered
    /// into arrays, then loaded.
    ///
    /// # Safety
    /// The index of every lane of `active` must be that of a body of `bodies`.
    #[inline(always)]
    unsafe fn load_bodies(
        self,
        bodies: &[SolverBody<Fx>],
        indices: &[u32; LANES],
        active: u8,
        with_motion: bool,
    ) -> [[Self::V; 3]; 4] {
        let mut words = [[[0; LANES]; 3]; 4];
        for (l, &index) in indices.iter().enumerate() {
            if active & (1 << l) == 0 {
                continue;
            }
            let body = &bodies[index as usize];
            let [dp, dtheta] = if with_motion {
                [body.dp, body.dtheta]
            } else {
                [Vec3::ZERO; 2]
            };
            for (vector, value) in words.iter_mut().zip([body.v, body.w, dp, dtheta]) {
                vector[0][l] = value.x.to_bits();
                vector[1][l] = value.y.to_bits();
                vector[2][l] = value.z.to_bits();
            }
        }
        let mut out = [[self.zero(); 3]; 4];
        for (out, words) in out.iter_mut().zip(&words) {
            for (out, words) in out.iter_mut().zip(words) {
                *out = self.load_words(*words);
            }
        }
        out
    }

    /// Writes v and ω of the bodies `indices` in the lanes of `active`. Lane by lane (the
    /// default), from arrays.
    ///
    /// # Safety
    /// As for [`load_bodies`](Self::load_bodies).
    #[inline(always)]
    unsafe fn store_velocities(
        self,
        bodies: &mut [SolverBody<Fx>],
        indices: &[u32; LANES],
        active: u8,
        [v, w]: [[Self::V; 3]; 2],
    ) {
        let [vx, vy, vz] = [
            self.store_words(v[0]),
            self.store_words(v[1]),
            self.store_words(v[2]),
        ];
        let [wx, wy, wz] = [
            self.store_words(w[0]),
            self.store_words(w[1]),
            self.store_words(w[2]),
        ];
        for (l, &index) in indices.iter().enumerate() {
            if active & (1 << l) == 0 {
                continue;
            }
            let body = &mut bodies[index as usize];
            body.v = Vec3::new(
                Fx::from_bits(vx[l]),
                Fx::from_bits(vy[l]),
                Fx::from_bits(vz[l]),
            );
            body.w = Vec3::new(
                Fx::from_bits(wx[l]),
                Fx::from_bits(wy[l]),
                Fx::from_bits(wz[l]),
            );
        }
    }

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

#[cfg(target_arch = "x86_64")]
impl WideBodies for crate::math::wide::avx2::Avx2 {}

#[cfg(target_arch = "aarch64")]
impl WideBodies for crate::math::wide::neon::Neon {}

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
impl WideBodies for crate::math::wide::simd128::Simd128 {}
