//! The arithmetic a constraint row is written in, so that one formula serves both the
//! guarded pass and the checked one (see [`guarded`](crate::math::guarded)).
//!
//! A row is computed first with [`Guarded`] operators (no range check per operation, one
//! guard for the row); when the guard stays clear, every value equals what the checked
//! operators give, bit for bit, and is kept. When it trips, the row is computed again with
//! [`Checked`] operators, which saturate and count as always. Either way the result is the
//! checked operators' result.

use crate::math::{Guard, Real, Vec3};

/// `+`, `−` and `×` of a scalar format, checked or guarded.
pub(crate) trait Arithmetic<R: Real> {
    fn add(&mut self, a: R, b: R) -> R;
    fn sub(&mut self, a: R, b: R) -> R;
    fn mul(&mut self, a: R, b: R) -> R;

    /// a − b per component.
    #[inline(always)]
    fn sub3(&mut self, a: Vec3<R>, b: Vec3<R>) -> Vec3<R> {
        Vec3::new(self.sub(a.x, b.x), self.sub(a.y, b.y), self.sub(a.z, b.z))
    }

    /// a + v·s per component (two roundings: the product, then the sum).
    #[inline(always)]
    fn add_scaled3(&mut self, a: Vec3<R>, v: Vec3<R>, s: R) -> Vec3<R> {
        let (x, y, z) = (self.mul(v.x, s), self.mul(v.y, s), self.mul(v.z, s));
        Vec3::new(self.add(a.x, x), self.add(a.y, y), self.add(a.z, z))
    }

    /// a·a = (aₓaₓ + a_ya_y) + a_za_z.
    #[inline(always)]
    fn length_squared3(&mut self, a: Vec3<R>) -> R {
        let (x, y, z) = (self.mul(a.x, a.x), self.mul(a.y, a.y), self.mul(a.z, a.z));
        let xy = self.add(x, y);
        self.add(xy, z)
    }
}

/// The checked operators of [`Real`].
pub(crate) struct Checked;

impl<R: Real> Arithmetic<R> for Checked {
    #[inline(always)]
    fn add(&mut self, a: R, b: R) -> R {
        a + b
    }
    #[inline(always)]
    fn sub(&mut self, a: R, b: R) -> R {
        a - b
    }
    #[inline(always)]
    fn mul(&mut self, a: R, b: R) -> R {
        a * b
    }
}

/// The guarded operators of [`Real`] with one guard.
pub(crate) struct Guarded(pub Guard);

impl<R: Real> Arithmetic<R> for Guarded {
    #[inline(always)]
    fn add(&mut self, a: R, b: R) -> R {
        a.guarded_add(b, &mut self.0)
    }
    #[inline(always)]
    fn sub(&mut self, a: R, b: R) -> R {
        a.guarded_sub(b, &mut self.0)
    }
    #[inline(always)]
    fn mul(&mut self, a: R, b: R) -> R {
        a.guarded_mul(b, &mut self.0)
    }
}
