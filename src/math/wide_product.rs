//! The exact 128-bit product of two `i64`, the core of every fixed-point product.
//!
//! x86-64, aarch64 and most 64-bit targets multiply 64 × 64 → 128 bits in one or two
//! instructions, and `a as i128 * b as i128` compiles to them. wasm32 has no such
//! instruction: there the same expression becomes a call to the runtime's `__multi3`, a
//! full 128 × 128-bit multiply whose 128-bit result goes through linear memory, which made
//! fixed point in wasm several times slower than `f64`. On wasm32 the product is therefore
//! assembled from four 64-bit products of 32-bit halves, inline:
//!
//! ```text
//! a = a_h·2³² + a_l,  b = b_h·2³² + b_l      (a_h, b_h signed, a_l, b_l in [0, 2³²))
//! a·b = a_h·b_h·2⁶⁴ + (a_h·b_l + a_l·b_h)·2³² + a_l·b_l
//! ```
//!
//! Each partial product fits its 64-bit type: |a_h·b_h| ≤ 2⁶², |a_l·b_h| < 2³²·2³¹ = 2⁶³,
//! a_l·b_l < 2⁶⁴ unsigned; the sum is taken in `i128`, whose additions and shifts wasm32
//! compiles inline. The result is the same integer on every target.

/// a·b exactly, as an `i128`.
#[inline(always)]
pub(crate) fn wide_product(a: i64, b: i64) -> i128 {
    #[cfg(target_arch = "wasm32")]
    {
        from_halves(a, b)
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        a as i128 * b as i128
    }
}

/// a·b from four products of 32-bit halves (module doc).
#[cfg(any(target_arch = "wasm32", test))]
#[inline(always)]
fn from_halves(a: i64, b: i64) -> i128 {
    let (a_low, a_high) = (i64::from(a as u32), a >> 32);
    let (b_low, b_high) = (i64::from(b as u32), b >> 32);
    let high = i128::from(a_high * b_high);
    let middle = i128::from(a_high * b_low) + i128::from(a_low * b_high);
    let low = i128::from((a_low as u64) * (b_low as u64));
    (high << 64) + (middle << 32) + low
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The extremes, zero, ±1 and the halves' edges, against the 128-bit multiply.
    #[test]
    fn halves_give_the_exact_product_at_the_edges() {
        let edges = [
            i64::MIN,
            i64::MIN + 1,
            -(1 << 32) - 1,
            -(1 << 32),
            -(1 << 31),
            -1,
            0,
            1,
            (1 << 31) - 1,
            1 << 31,
            (1 << 32) - 1,
            1 << 32,
            i64::MAX - 1,
            i64::MAX,
        ];
        for &a in &edges {
            for &b in &edges {
                assert_eq!(from_halves(a, b), a as i128 * b as i128, "{a} · {b}");
            }
        }
    }

    proptest! {
        #[test]
        fn halves_give_the_exact_product(a: i64, b: i64) {
            prop_assert_eq!(from_halves(a, b), a as i128 * b as i128);
        }
    }
}
