//! √x per lane for 0 ≤ x < 1 as I32F32 bits (0 ≤ x < 2³²), in AVX-512F and CD:
//! round(√n) with n = x·2³², correctly rounded to nearest like
//! [`Real::sqrt`](crate::math::Real::sqrt) of I32F32, from an estimate by Newton's method
//! on integers that two exact steps then correct. The fluid's neighbour search takes the
//! roots of q² = |xᵢ − xⱼ|²/H² with it, and the rigid solver's square roots
//! (`rigid::solver::avx512::sqrt`) take it when every value lies in its domain.
//!
//! # The estimate
//!
//! Every step is an integer operation, the same on every machine.
//!
//! 1. **Normalise.** With k the even shift that brings x's top bit to bit 31 or 30
//!    (from its leading zeros), m = x·2ᵏ lies in [2³⁰, 2³²), that is u = m/2³² in
//!    [¼, 1), and √n = √(m·2³²) · 2^(−k/2).
//! 2. **Table.** y₀ ≈ 1/√u to about 6 % from the top four bits of m: 1/√u at the middle
//!    of u's sixteenth, as Y = y·2³⁰ < 2³¹ ([`RECIPROCAL_ROOTS`]).
//! 3. **Newton on 1/√u**, three times: y ← y + y·(1 − u·y²)/2. The relative error e
//!    becomes about (3/2)·e², so 6 % → 0.5 % → 4·10⁻⁵ → 2·10⁻⁹, below the 2⁻³⁰ of the
//!    format's truncations. In integers: A = ⌊Y²/2³¹⌋ (y²·2²⁹ ≤ 2³¹), B = m·A
//!    (u·y²·2⁶¹ < 2⁶³), E = ⌊(2⁶¹ − B)/2²⁹⌋ ((1 − u·y²)·2³², signed, |E| < 2³¹), then
//!    Y ← Y + ⌊⌊Y/2⌋·E / 2³²⌋, every product of two 32-bit factors exact in 64 bits.
//! 4. **Root.** S₀ = min(⌊m·Y/2³⁰⌋, 2³² − 1) ≈ √(m·2³²) = m·y, then one Newton step on
//!    the root itself, S₁ = S₀ + δ/(2S₀) with δ = m·2³² − S₀² (exact) and 1/(2S₀) ≈ y/2³³,
//!    computed as ⌊⌊δ/2⁸⌋·⌊Y/2⌋ / 2⁵⁴⌋ and capped at 2³² − 1 again. S₀ is off by a few
//!    units (y by a few 2⁻³⁰), so |δ| ≈ 2S₀·|S₀ − √(m·2³²)| is far below 2³⁹ and ⌊δ/2⁸⌋ a
//!    32-bit signed number; δ is the difference of two numbers below 2⁶⁴, exact modulo
//!    2⁶⁴. The step leaves S₁ within one below the root.
//! 5. **Scale back.** r = ⌊S₁ / 2^(k/2)⌋.
//!
//! # The exact correction
//!
//! With n = x·2³² exact and r < 2³² (so r² is exact in 64 bits): r ← r − 1 if r² > n;
//! then r ← r + 1 if n − r² > 2r (that is, (r + 1)² ≤ n); then, with r = ⌊√n⌋, the
//! rounding r ← r + 1 if n − r² > r (n > (r + ½)² − ¼, and n is whole, so no tie occurs).
//! The result is round(√n) whenever the estimate is within one of ⌊√n⌋. The committed
//! code matches `Fx::sqrt` for every x in [0, 2³²) (`cargo test --release -- --ignored
//! square_root`); a trial without the two corrections (the rounding step alone) matched
//! for every x too. They stay so that the result rests on the weaker bound, which the
//! analysis above gives with room to spare, and not on that exhaustive coincidence.
//!
//! x = 0 gives 0 (m = 0, so Y, S₀ and r are 0). Lanes with x ≥ 2³² or x < 0 (the
//! search's lanes that failed the support test) hold meaningless values: the callers
//! drop or replace them.

use core::arch::x86_64::{
    __m512i, _mm512_add_epi64, _mm512_and_si512, _mm512_cmpgt_epu64_mask, _mm512_loadu_si512,
    _mm512_lzcnt_epi64, _mm512_mask_add_epi64, _mm512_mask_sub_epi64, _mm512_min_epu64,
    _mm512_mul_epi32, _mm512_mul_epu32, _mm512_permutex2var_epi64, _mm512_set1_epi64,
    _mm512_slli_epi64, _mm512_sllv_epi64, _mm512_srai_epi64, _mm512_srli_epi64, _mm512_srlv_epi64,
    _mm512_sub_epi64,
};

/// Y = 2³⁰/√u at the middle of each sixteenth [j/16, (j + 1)/16) of u, for j = 4..15
/// (√(2⁶⁰·32/(2j + 1)), rounded down; below 2³¹ for every j); 0 for j < 4, which only
/// x = 0 reaches.
const RECIPROCAL_ROOTS: [i64; 16] = {
    let mut table = [0i64; 16];
    let mut j = 4;
    while j < 16 {
        let square = (1u128 << 65) / (2 * j as u128 + 1);
        let mut root = 0u128;
        let mut bit = 1u128 << 63;
        while bit > 0 {
            if (root + bit) * (root + bit) <= square {
                root += bit;
            }
            bit >>= 1;
        }
        table[j] = root as i64;
        j += 1;
    }
    table
};

/// round(√(x·2³²)) per lane for 0 ≤ x < 2³², in `BLOCKS` registers side by side (module
/// documentation).
#[inline]
#[target_feature(enable = "avx512f,avx512cd")]
pub(crate) fn sqrt<const BLOCKS: usize>(x: [__m512i; BLOCKS]) -> [__m512i; BLOCKS] {
    let one = _mm512_set1_epi64(1);
    let below_2_32 = _mm512_set1_epi64(u32::MAX.into());
    // SAFETY: 16 readable i64 at the table's start, eight from each pointer.
    let table = unsafe {
        [
            _mm512_loadu_si512(RECIPROCAL_ROOTS.as_ptr().cast()),
            _mm512_loadu_si512(RECIPROCAL_ROOTS.as_ptr().add(8).cast()),
        ]
    };
    let shift: [__m512i; BLOCKS] = core::array::from_fn(|b| {
        _mm512_and_si512(
            _mm512_sub_epi64(_mm512_lzcnt_epi64(x[b]), _mm512_set1_epi64(32)),
            _mm512_set1_epi64(!1),
        )
    });
    let m: [__m512i; BLOCKS] = core::array::from_fn(|b| _mm512_sllv_epi64(x[b], shift[b]));
    let mut y: [__m512i; BLOCKS] = core::array::from_fn(|b| {
        _mm512_permutex2var_epi64(table[0], _mm512_srli_epi64::<28>(m[b]), table[1])
    });
    for _ in 0..3 {
        y = core::array::from_fn(|b| {
            let a = _mm512_srli_epi64::<31>(_mm512_mul_epu32(y[b], y[b]));
            let e = _mm512_srai_epi64::<29>(_mm512_sub_epi64(
                _mm512_set1_epi64(1 << 61),
                _mm512_mul_epu32(m[b], a),
            ));
            let step = _mm512_mul_epi32(_mm512_srli_epi64::<1>(y[b]), e);
            _mm512_add_epi64(y[b], _mm512_srai_epi64::<32>(step))
        });
    }
    let s0: [__m512i; BLOCKS] = core::array::from_fn(|b| {
        _mm512_min_epu64(
            _mm512_srli_epi64::<30>(_mm512_mul_epu32(m[b], y[b])),
            below_2_32,
        )
    });
    let mut r: [__m512i; BLOCKS] = core::array::from_fn(|b| {
        let delta = _mm512_sub_epi64(
            _mm512_slli_epi64::<32>(m[b]),
            _mm512_mul_epu32(s0[b], s0[b]),
        );
        let step = _mm512_mul_epi32(_mm512_srai_epi64::<8>(delta), _mm512_srli_epi64::<1>(y[b]));
        let s1 = _mm512_min_epu64(
            _mm512_add_epi64(s0[b], _mm512_srai_epi64::<54>(step)),
            below_2_32,
        );
        _mm512_srlv_epi64(s1, _mm512_srli_epi64::<1>(shift[b]))
    });
    let n: [__m512i; BLOCKS] = core::array::from_fn(|b| _mm512_slli_epi64::<32>(x[b]));
    r = core::array::from_fn(|b| {
        let over = _mm512_cmpgt_epu64_mask(_mm512_mul_epu32(r[b], r[b]), n[b]);
        _mm512_mask_sub_epi64(r[b], over, r[b], one)
    });
    r = core::array::from_fn(|b| {
        let rest = _mm512_sub_epi64(n[b], _mm512_mul_epu32(r[b], r[b]));
        let under = _mm512_cmpgt_epu64_mask(rest, _mm512_add_epi64(r[b], r[b]));
        _mm512_mask_add_epi64(r[b], under, r[b], one)
    });
    core::array::from_fn(|b| {
        let rest = _mm512_sub_epi64(n[b], _mm512_mul_epu32(r[b], r[b]));
        let up = _mm512_cmpgt_epu64_mask(rest, r[b]);
        _mm512_mask_add_epi64(r[b], up, r[b], one)
    })
}

#[cfg(test)]
mod tests {
    use super::sqrt;
    use crate::math::{Fx, Pcg32, Real};
    use core::arch::x86_64::{__m512i, _mm512_loadu_si512, _mm512_storeu_si512};

    fn present() -> bool {
        crate::math::cpu::avx512f() && crate::math::cpu::avx512cd()
    }

    /// The first values of `inputs` that the kernel, fed four blocks of eight at a time,
    /// does not root as `Fx::sqrt` does (at most ten).
    fn mismatches(inputs: impl Iterator<Item = i64>) -> Vec<i64> {
        let mut bad = Vec::new();
        let mut batch = [0i64; 32];
        let mut len = 0;
        let check = |batch: &[i64; 32], len: usize, bad: &mut Vec<i64>| {
            let mut out = [0i64; 32];
            // SAFETY: AVX-512F and CD are present (checked by the callers); 32 values
            // each way, eight per vector.
            unsafe {
                let load = |b: usize| _mm512_loadu_si512(batch[8 * b..].as_ptr().cast());
                let roots: [__m512i; 4] = sqrt(core::array::from_fn(load));
                for (b, root) in roots.into_iter().enumerate() {
                    _mm512_storeu_si512(out[8 * b..].as_mut_ptr().cast(), root);
                }
            }
            for (&x, &root) in batch[..len].iter().zip(&out) {
                if root != Fx::from_bits(x).sqrt().to_bits() && bad.len() < 10 {
                    bad.push(x);
                }
            }
        };
        for x in inputs {
            batch[len] = x;
            len += 1;
            if len == 32 {
                check(&batch, len, &mut bad);
                len = 0;
            }
        }
        batch[len..].fill(0);
        check(&batch, len, &mut bad);
        bad
    }

    /// Against `Fx::sqrt` over [0, 1): the edges, random values, and the values around
    /// every square and every rounding midpoint of a sample of roots, where an estimate
    /// one off would show.
    #[test]
    fn the_kernels_square_root_is_fx_sqrt() {
        if !present() {
            return;
        }
        let mut rng = Pcg32::new(5, 3);
        let mut inputs: Vec<i64> = vec![0, 1, 2, 3, 4, (1 << 32) - 1, (1 << 32) - 2, 1 << 31];
        for bits in 0..32 {
            inputs.extend([(1 << bits) - 1, 1 << bits, (1 << bits) + 1]);
        }
        inputs.extend((0..200_000).map(|_| i64::from(rng.next_u32())));
        for _ in 0..20_000 {
            // A root r (I32F32 bits below 2³²) and the inputs x whose x·2³² lie near r²
            // and (r + ½)².
            let r = u128::from(rng.next_u32());
            for target in [r * r, r * r + r] {
                let x = (target >> 32) as i64;
                inputs.extend(
                    [x - 1, x, x + 1]
                        .into_iter()
                        .filter(|x| (0..1 << 32).contains(x)),
                );
            }
        }
        assert!(inputs.len() > 300_000);
        assert_eq!(mismatches(inputs.into_iter()), Vec::<i64>::new());
    }

    /// Every x in [0, 2³²) against `Fx::sqrt`: the whole domain, 90 s in
    /// release (`cargo test --release -- --ignored square_root`).
    #[test]
    #[ignore = "exhaustive over 2^32 values: 90 s in release, far longer in debug"]
    fn the_kernels_square_root_is_fx_sqrt_for_every_input() {
        if !present() {
            return;
        }
        assert_eq!(mismatches(0..1 << 32), Vec::<i64>::new());
    }
}
