//! The orientation update of up to eight I32F32 bodies at once, one `i64` lane per body,
//! with the bits of [`Quat::integrate`] on its path near unit length:
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
//! Written once against [`Wide`], it runs with the AVX-512 or the AVX2 backend, whichever
//! the processor has ([`backend`]).
//!
//! # Exactness
//!
//! Every value that enters a product (ω, h·½, a, q, q', ε, q₁, 2⁸q₁, e, e·2⁻¹⁶, δ, q₁δ and
//! the constants) is checked to lie in [−2⁴⁶, 2⁴⁶) as raw bits, and every sum has at most
//! five terms, each such a value or a product below 2⁶⁰: no operation of the scalar form
//! saturates, and the kernel's wrapping arithmetic gives its exact results ([`Wide::mul`]).
//! A lane that fails a check, or whose |ε| is past 2⁻¹⁰ (where [`Quat::integrate`] takes
//! [`Quat::normalize`] instead), is not written and is left to the caller.

use crate::math::over_real::{OverReal, Scalar};
use crate::math::quat::{near_unit_excess, square_prescale, square_unscale};
use crate::math::wide::{Wide, backend, kernel_entry};
use crate::math::{Fx, Quat, Real};
use crate::rigid::solver::body::{SolverBodiesOf, SolverBody};
use crate::rigid::solver::lanes::LANES;

/// The family of orientation lists, `[Quat<R>]`, for [`Real::as_fixed`].
struct QuatsOf;

impl OverReal for QuatsOf {
    type Of<R: Real> = [Quat<R>];
}

/// Integrates over `h` seconds the orientations of the bodies `bodies` (at most
/// [`LANES`]), body l's orientation being `orientations[slots[l]]`, with the kernel when
/// `R` is I32F32 and the processor has AVX-512 (F and DQ) or AVX2. Returns the lanes it is
/// done with: those it integrated and those at rest (ω = 0, left as they are); the caller
/// integrates the others.
pub(super) fn integrate_orientations<R: Real>(
    bodies: &[SolverBody<R>],
    slots: &[u32],
    orientations: &mut [Quat<R>],
    h: R,
) -> u8 {
    let Some(backend) = backend() else {
        return 0;
    };
    let (Some(&h), Some(bodies), Some(orientations)) = (
        R::as_fixed::<Scalar>(&h),
        R::as_fixed::<SolverBodiesOf>(bodies),
        R::as_fixed_mut::<QuatsOf>(orientations),
    ) else {
        return 0;
    };
    integrate_on(backend, bodies, slots, orientations, h)
}

kernel_entry! {
    /// [`integrate_block`] with the instructions of `backend`.
    fn integrate_on(
        bodies: &[SolverBody<Fx>],
        slots: &[u32],
        orientations: &mut [Quat<Fx>],
        h: Fx,
    ) -> u8 = integrate_block;
}

/// Σ qᵢ², each square rounded on its own, in the order of [`Quat`]'s components.
#[inline(always)]
fn square_sum<W: Wide>(w: W, q: &[W::V; 4]) -> W::V {
    w.add(
        w.add(
            w.add(w.mul(q[0], q[0]), w.mul(q[1], q[1])),
            w.mul(q[2], q[2]),
        ),
        w.mul(q[3], q[3]),
    )
}

/// Each component times the same factor.
#[inline(always)]
fn scale4<W: Wide>(w: W, q: &[W::V; 4], factor: W::V) -> [W::V; 4] {
    [
        w.mul(q[0], factor),
        w.mul(q[1], factor),
        w.mul(q[2], factor),
        w.mul(q[3], factor),
    ]
}

#[inline(always)]
fn out_of_bound4<W: Wide>(w: W, q: &[W::V; 4]) -> u8 {
    w.out_of_bound(q[0]) | w.out_of_bound(q[1]) | w.out_of_bound(q[2]) | w.out_of_bound(q[3])
}

/// The kernel (see the module documentation).
#[inline(always)]
fn integrate_block<W: Wide>(
    w: W,
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
    let q = [
        w.load_words(words[0]),
        w.load_words(words[1]),
        w.load_words(words[2]),
        w.load_words(words[3]),
    ];
    let omega = [
        w.load_words(words[4]),
        w.load_words(words[5]),
        w.load_words(words[6]),
    ];
    let active = ((1u16 << count) - 1) as u8;
    let zero = w.zero();
    let at_rest = w.equal(omega[0], zero) & w.equal(omega[1], zero) & w.equal(omega[2], zero);
    let spinning = active & !at_rest;

    let half_h = w.splat((h * Fx::HALF).to_bits());
    let [qw, u @ ..] = q;
    let a = w.times3::<false>(omega, half_h);
    let mut bad =
        w.out_of_bound(half_h) | w.out_of_bound3(omega) | out_of_bound4(w, &q) | w.out_of_bound3(a);
    // q' = (w − a·u, u + a w + a × u), each product rounded on its own.
    let a_dot_u = w.rounded_dot(a, u);
    let cross = w.cross(a, u);
    let turned = [
        w.sub(qw, a_dot_u),
        w.add(u[0], w.add(w.mul(a[0], qw), cross[0])),
        w.add(u[1], w.add(w.mul(a[1], qw), cross[1])),
        w.add(u[2], w.add(w.mul(a[2], qw), cross[2])),
    ];
    bad |= out_of_bound4(w, &turned);
    let one = w.splat(Fx::ONE.to_bits());
    let excess = w.sub(square_sum(w, &turned), one);
    let near = !w.greater(w.abs(excess), w.splat(near_unit_excess::<Fx>().to_bits()));
    // q₁ = q' (1 − ε·½).
    let first = w.sub(one, w.mul(excess, w.splat(Fx::HALF.to_bits())));
    bad |= w.out_of_bound(excess) | w.out_of_bound(first);
    let estimate = scale4(w, &turned, first);
    bad |= out_of_bound4(w, &estimate);
    // The norm defect of q₁: e = Σ(k q₁ᵢ)² − k·k with k = 2⁸, δ = e − e·(e·2⁻¹⁶).
    let prescale = square_prescale::<Fx>();
    let scaled = scale4(w, &estimate, w.splat(prescale.to_bits()));
    bad |= out_of_bound4(w, &scaled);
    let e = w.sub(
        square_sum(w, &scaled),
        w.splat((prescale * prescale).to_bits()),
    );
    let unscaled = w.mul(e, w.splat(square_unscale::<Fx>().to_bits()));
    bad |= w.out_of_bound(e) | w.out_of_bound(unscaled);
    let defect = w.sub(e, w.mul(e, unscaled));
    bad |= w.out_of_bound(defect);
    // q₂ = q₁ − (q₁ δ)·(2⁻¹⁶·½).
    let half_unscale = w.splat((square_unscale::<Fx>() * Fx::HALF).to_bits());
    let products = scale4(w, &estimate, defect);
    bad |= out_of_bound4(w, &products);
    let result = [
        w.store_words(w.sub(estimate[0], w.mul(products[0], half_unscale))),
        w.store_words(w.sub(estimate[1], w.mul(products[1], half_unscale))),
        w.store_words(w.sub(estimate[2], w.mul(products[2], half_unscale))),
        w.store_words(w.sub(estimate[3], w.mul(products[3], half_unscale))),
    ];

    let done = spinning & near & !bad;
    for (l, &slot) in slots.iter().take(count).enumerate() {
        if done & (1 << l) != 0 {
            orientations[slot as usize] = Quat::new(
                Fx::from_bits(result[0][l]),
                Fx::from_bits(result[1][l]),
                Fx::from_bits(result[2][l]),
                Fx::from_bits(result[3][l]),
            );
        }
    }
    done | (active & !spinning)
}
