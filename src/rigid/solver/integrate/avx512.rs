//! The orientation update of up to eight I32F32 bodies in AVX-512 (F and DQ), one `i64`
//! lane per body, with the bits of [`Quat::integrate`] on its path near unit length:
//!
//! ```text
//! a = ω·(h·½),  q' = (w − a·u, u + a w + a × u)
//! ε = |q'|² − 1                       (the lane is left to the caller when |ε| > 2⁻¹⁰)
//! q₁ = q' (1 − ε·½)
//! δ = e − e·(e·2⁻¹⁶),  e = Σ(2⁸ q₁ᵢ)² − 2⁸·2⁸
//! q₂ = q₁ − (q₁ δ)·(2⁻¹⁶·½)
//! ```
//!
//! every product rounded on its own as the scalar operators round it, and the sums exact.
//!
//! # Exactness
//!
//! Every value that enters a product (ω, h·½, a, q, q', ε, q₁, 2⁸q₁, e, e·2⁻¹⁶, δ, q₁δ and
//! the constants) is checked to lie in [−2⁴⁶, 2⁴⁶) as raw bits, and every sum has at most
//! five terms, each such a value or a product below 2⁶⁰: no operation of the scalar form
//! saturates, and the kernel's wrapping arithmetic gives its exact results
//! ([`solver::avx512`](crate::rigid::solver::avx512)). A lane that fails a check, or whose
//! |ε| is past 2⁻¹⁰ (where [`Quat::integrate`] takes [`Quat::normalize`] instead), is not
//! written and is left to the caller.

use core::any::Any;
use core::arch::x86_64::{
    __m512i, __mmask8, _mm512_abs_epi64, _mm512_cmpgt_epi64_mask, _mm512_cmpneq_epi64_mask,
    _mm512_loadu_si512, _mm512_storeu_si512,
};

use crate::math::quat::{near_unit_excess, square_prescale, square_unscale};
use crate::math::{Fx, Quat, Real};
use crate::rigid::solver::avx512::{
    add, has_kernels, mul, mul3, out_of_bound, out_of_bound3, splat, sub,
};
use crate::rigid::solver::body::SolverBody;
use crate::rigid::solver::lanes::LANES;

/// Integrates over `h` seconds the orientations of the bodies `bodies` (at most
/// [`LANES`]), body l's orientation being `orientations[slots[l]]`, with the kernel when
/// `R` is I32F32 and the processor has AVX-512F and DQ. Returns the lanes it is done with:
/// those it integrated and those at rest (ω = 0, left as they are); the caller integrates
/// the others.
pub(super) fn integrate_orientations<R: Real>(
    bodies: &[SolverBody<R>],
    slots: &[u32],
    orientations: &mut [Quat<R>],
    h: R,
) -> u8 {
    if !has_kernels() {
        return 0;
    }
    let Some(&h) = (&h as &dyn Any).downcast_ref::<Fx>() else {
        return 0;
    };
    // SAFETY: `R` is `Fx` (the downcast succeeded), so the slices' types are unchanged.
    let (bodies, orientations) = unsafe {
        (
            &*(core::ptr::from_ref(bodies) as *const [SolverBody<Fx>]),
            &mut *(core::ptr::from_mut(orientations) as *mut [Quat<Fx>]),
        )
    };
    // SAFETY: AVX-512F and DQ were detected on this processor just above.
    unsafe { integrate_block(bodies, slots, orientations, h) }
}

/// The kernel (see the module documentation).
///
/// # Safety
/// The processor must have AVX-512F and AVX-512DQ.
#[target_feature(enable = "avx512f,avx512dq")]
unsafe fn integrate_block(
    bodies: &[SolverBody<Fx>],
    slots: &[u32],
    orientations: &mut [Quat<Fx>],
    h: Fx,
) -> u8 {
    let count = bodies.len().min(slots.len()).min(LANES);
    // The lanes' q and ω, component by component (zero in lanes past `count`).
    let mut words = [[0i64; LANES]; 7];
    for (l, (body, &slot)) in bodies.iter().zip(slots).take(count).enumerate() {
        let Some(q) = orientations.get(slot as usize) else {
            return 0;
        };
        let values = [q.w, q.x, q.y, q.z, body.w.x, body.w.y, body.w.z];
        for (component, value) in words.iter_mut().zip(values) {
            component[l] = value.to_bits();
        }
    }
    // SAFETY: eight `i64`: 64 readable bytes each.
    let [w, x, y, z, ox, oy, oz] = words.map(|c| unsafe { _mm512_loadu_si512(c.as_ptr().cast()) });
    let active = ((1u16 << count) - 1) as __mmask8;
    let zero = splat(Fx::ZERO);
    let spinning = (_mm512_cmpneq_epi64_mask(ox, zero)
        | _mm512_cmpneq_epi64_mask(oy, zero)
        | _mm512_cmpneq_epi64_mask(oz, zero))
        & active;

    let half_h = splat(h * Fx::HALF);
    let omega = [ox, oy, oz];
    let u = [x, y, z];
    let a = mul3(omega, half_h);
    let mut bad = out_of_bound(half_h)
        | out_of_bound3(omega)
        | out_of_bound(w)
        | out_of_bound3(u)
        | out_of_bound3(a);
    // q' = (w − a·u, u + a w + a × u), each product rounded on its own.
    let a_dot_u = add(add(mul(a[0], u[0]), mul(a[1], u[1])), mul(a[2], u[2]));
    let cross = [
        sub(mul(a[1], u[2]), mul(a[2], u[1])),
        sub(mul(a[2], u[0]), mul(a[0], u[2])),
        sub(mul(a[0], u[1]), mul(a[1], u[0])),
    ];
    let turned = [
        sub(w, a_dot_u),
        add(u[0], add(mul(a[0], w), cross[0])),
        add(u[1], add(mul(a[1], w), cross[1])),
        add(u[2], add(mul(a[2], w), cross[2])),
    ];
    bad |= turned.iter().fold(0, |bad, &c| bad | out_of_bound(c));
    let square_sum = |q: &[__m512i; 4]| {
        add(
            add(add(mul(q[0], q[0]), mul(q[1], q[1])), mul(q[2], q[2])),
            mul(q[3], q[3]),
        )
    };
    let excess = sub(square_sum(&turned), splat(Fx::ONE));
    let near = !_mm512_cmpgt_epi64_mask(_mm512_abs_epi64(excess), splat(near_unit_excess()));
    // q₁ = q' (1 − ε·½).
    let first = sub(splat(Fx::ONE), mul(excess, splat(Fx::HALF)));
    bad |= out_of_bound(excess) | out_of_bound(first);
    let estimate = turned.map(|c| mul(c, first));
    bad |= estimate.iter().fold(0, |bad, &c| bad | out_of_bound(c));
    // The norm defect of q₁: e = Σ(k q₁ᵢ)² − k·k with k = 2⁸, δ = e − e·(e·2⁻¹⁶).
    let prescale = square_prescale::<Fx>();
    let scaled = estimate.map(|c| mul(c, splat(prescale)));
    bad |= scaled.iter().fold(0, |bad, &c| bad | out_of_bound(c));
    let e = sub(square_sum(&scaled), splat(prescale * prescale));
    let unscaled = mul(e, splat(square_unscale()));
    bad |= out_of_bound(e) | out_of_bound(unscaled);
    let defect = sub(e, mul(e, unscaled));
    bad |= out_of_bound(defect);
    // q₂ = q₁ − (q₁ δ)·(2⁻¹⁶·½).
    let half_unscale = splat(square_unscale::<Fx>() * Fx::HALF);
    let products = estimate.map(|c| mul(c, defect));
    bad |= products.iter().fold(0, |bad, &c| bad | out_of_bound(c));
    let mut result = [zero; 4];
    for (r, (&c, &p)) in result.iter_mut().zip(estimate.iter().zip(&products)) {
        *r = sub(c, mul(p, half_unscale));
    }

    let done = spinning & near & !bad;
    let mut out = [[0i64; LANES]; 4];
    for (component, value) in out.iter_mut().zip(result) {
        // SAFETY: eight `i64`: 64 writable bytes.
        unsafe { _mm512_storeu_si512(component.as_mut_ptr().cast(), value) };
    }
    for (l, &slot) in slots.iter().take(count).enumerate() {
        if done & (1 << l) != 0 {
            orientations[slot as usize] = Quat::new(
                Fx::from_bits(out[0][l]),
                Fx::from_bits(out[1][l]),
                Fx::from_bits(out[2][l]),
                Fx::from_bits(out[3][l]),
            );
        }
    }
    done | (active & !spinning)
}
