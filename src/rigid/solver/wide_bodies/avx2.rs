//! [`WideBodies`] on AVX2: a solver body's words read and written lane by lane through
//! arrays.

use super::WideBodies;
use crate::math::wide::{Wide, avx2::Avx2};
use crate::math::{Fx, Vec3};
use crate::rigid::solver::body::SolverBody;
use crate::rigid::solver::lanes::LANES;

impl WideBodies for Avx2 {
    /// Lane by lane: the words of each body of `active` gathered into arrays, then loaded.
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

    /// Lane by lane, from arrays.
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
}
