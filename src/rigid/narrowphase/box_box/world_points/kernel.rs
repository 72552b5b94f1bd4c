//! The four world transforms of a face contact's points as one kernel on I32F32, written
//! once against [`Wide`] and run with the backend [`backend`] picks (AVX-512 or AVX2),
//! with the bits of [`Transform::point`]:
//!
//! ```text
//! (R p)_c + t_c = (R_c0 p_0 + R_c1 p_1) + R_c2 p_2 + t_c    (m; R_cm = column m's c)
//! ```
//!
//! each product rounded on its own as the scalar `*` rounds it. Lane i holds point i
//! (lanes past the fourth hold zero), one vector per component of the points; each
//! element R_cm of the rotation and t_c of the translation is the same in every lane.
//!
//! # Exactness
//!
//! Every operand (each p_i,m, R_cm and t_c) is checked to lie in [−2⁴⁶, 2⁴⁶) as raw bits:
//! each product then is below 2⁶⁰ and each sum below 2⁶², so no operation of the scalar
//! form saturates and the wrapping arithmetic of [`Wide`] gives its exact results
//! ([`Wide::mul`]). When an operand fails, nothing is written and the caller transforms
//! the points one by one.

use super::ManifoldPointsOf;
use crate::math::wide::{LANES, Wide, backend, kernel_entry};
use crate::math::{Fx, Real, Vec3};
use crate::rigid::manifold::MAX_MANIFOLD_POINTS;
use crate::rigid::transform::{Transform, TransformOf};

// The points fit the lanes of one vector.
const _: () = assert!(MAX_MANIFOLD_POINTS <= LANES);

/// Writes R pᵢ + t (m) for the four points `local` (m) to `world` when `R` is I32F32, the
/// processor has a backend and every operand is within the bound (module documentation),
/// and says whether it did.
#[inline]
pub(super) fn to_world<R: Real>(
    xf: &Transform<R>,
    local: &[Vec3<R>; MAX_MANIFOLD_POINTS],
    world: &mut [Vec3<R>; MAX_MANIFOLD_POINTS],
) -> bool {
    match (
        R::as_fixed::<TransformOf>(xf),
        R::as_fixed::<ManifoldPointsOf>(local),
        R::as_fixed_mut::<ManifoldPointsOf>(world),
        backend(),
    ) {
        (Some(xf), Some(local), Some(world), Some(backend)) => {
            transform_on(backend, xf, local, world)
        }
        _ => false,
    }
}

kernel_entry! {
    /// [`transform`] with the instructions of `backend`.
    fn transform_on(
        xf: &Transform<Fx>,
        local: &[Vec3<Fx>; MAX_MANIFOLD_POINTS],
        world: &mut [Vec3<Fx>; MAX_MANIFOLD_POINTS],
    ) -> bool = transform;
}

/// The kernel (module documentation).
#[inline(always)]
fn transform<W: Wide>(
    w: W,
    xf: &Transform<Fx>,
    local: &[Vec3<Fx>; MAX_MANIFOLD_POINTS],
    world: &mut [Vec3<Fx>; MAX_MANIFOLD_POINTS],
) -> bool {
    let mut words = [[0i64; LANES]; 3];
    for (i, p) in local.iter().enumerate() {
        words[0][i] = p.x.to_bits();
        words[1][i] = p.y.to_bits();
        words[2][i] = p.z.to_bits();
    }
    let p = w.load_components(&words);
    let columns = xf.rotation.cols.map(|c| c.to_array().map(Fx::to_bits));
    let translation = xf.translation.to_array().map(Fx::to_bits);
    let mut unchecked = w.out_of_bound3(p);
    let mut out = [w.zero(); 3];
    for c in 0..3 {
        let r = [
            w.splat(columns[0][c]),
            w.splat(columns[1][c]),
            w.splat(columns[2][c]),
        ];
        let t = w.splat(translation[c]);
        unchecked |= w.out_of_bound3(r) | w.out_of_bound(t);
        let sum = w.add(w.mul(r[0], p[0]), w.mul(r[1], p[1]));
        out[c] = w.add(w.add(sum, w.mul(r[2], p[2])), t);
    }
    if unchecked != 0 {
        return false;
    }
    let [x, y, z] = out.map(|v| w.store_words(v));
    for (i, point) in world.iter_mut().enumerate() {
        *point = Vec3::new(
            Fx::from_bits(x[i]),
            Fx::from_bits(y[i]),
            Fx::from_bits(z[i]),
        );
    }
    true
}
