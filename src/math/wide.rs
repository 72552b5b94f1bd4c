//! The one lane abstraction of the step's vector kernels: eight `i64` lanes holding I32F32
//! bits, behind the trait [`Wide`], with four backends: AVX-512 (`avx512::Avx512`,
//! AVX-512F, CD and DQ) and AVX2 (`avx2::Avx2`) on x86-64, NEON (`neon::Neon`) on aarch64,
//! `simd128` (`simd128::Simd128`) on wasm32 built with it.
//! A kernel is written once, generic over [`Wide`], and gives the same bits with every
//! backend; one place,
//! [`backend`], chooses the backend for this processor under the cap `FIXSTEP_SIMD`
//! ([`cpu`](super::cpu)), and [`kernel_entry!`] compiles each kernel once per backend with
//! its instructions enabled. A subsystem reaches the kernels at compile time through the
//! scalar type: [`Real::as_fixed`](super::Real::as_fixed) views its I32F32 data as such and
//! is `None` for every other format, so that `f64` and the other fixed formats compile
//! the plain path only.
//!
//! Every exact product of the kernels is proved here, once:
//!
//! # Products
//!
//! With a = a_h·2³² + a_l, a_h = ⌊(a + 2³¹)/2³²⌋ and a_l ∈ [−2³¹, 2³¹) the signed low half
//! of a, and b likewise,
//!
//! ```text
//! ⌊(a·b + 2³¹)/2³²⌋ = a·b_h + a_h·b_l + ⌊(a_l·b_l + 2³¹)/2³²⌋
//! ```
//!
//! since a·b = a·b_h·2³² + a_h·b_l·2³² + a_l·b_l; this is the checked `*` (to nearest, ties
//! toward +∞). For a value within [−2⁴⁶, 2⁴⁶) (|a_h| ≤ 2¹⁴) the term a·b_h is below 2⁶⁰,
//! so its low 64 bits are all of it. For the fused dot product Σ aᵢbᵢ rounded once, each
//! a_l·b_l is split into q·2³² + r with 0 ≤ r < 2³², so that
//! ⌊(Σ aᵢbᵢ + 2³¹)/2³²⌋ = Σ (aᵢ·b_h,ᵢ + a_h,ᵢ·b_l,ᵢ + qᵢ) + ⌊(Σ r + 2³¹)/2³²⌋, and
//! Σ r + 2³¹ < 2³⁴ cannot overflow.
//!
//! # Narrow products
//!
//! When one factor a lies in [−2³¹, 2³¹) (|a| < ½), it is its own low half (a_h = 0) and
//! the product needs two multiplies of 32-bit halves, both exact in 64 bits:
//! ⌊(a·b + 2³¹)/2³²⌋ = a·b_h + ⌊(a·b_l + 2³¹)/2³²⌋ ([`Wide::times`]).

#[cfg(target_arch = "x86_64")]
pub(crate) mod avx2;
#[cfg(target_arch = "x86_64")]
pub(crate) mod avx512;
#[cfg(target_arch = "aarch64")]
pub(crate) mod neon;
pub(crate) mod portable;
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
pub(crate) mod simd128;

#[cfg(target_arch = "x86_64")]
use avx2::Avx2;
#[cfg(target_arch = "x86_64")]
use avx512::Avx512;
#[cfg(target_arch = "aarch64")]
use neon::Neon;
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
use simd128::Simd128;

use crate::math::{Fx, Vec3};

/// The lanes of a vector.
pub(crate) const LANES: usize = 8;

/// The bit length of `bits` as an unsigned number.
#[inline(always)]
pub(crate) fn bit_length(bits: u64) -> u32 {
    u64::BITS - bits.leading_zeros()
}

/// The bit length of the largest magnitude of any component of `vectors`: a bound on them
/// all (|c| < 2^bits), as the kernels measure what they read. Inlined into a kernel, it
/// scans with the kernel's instructions.
#[inline(always)]
pub(crate) fn vector_bits(vectors: &[Vec3<Fx>]) -> u32 {
    bit_length(vectors.iter().fold(0, |bits, v| {
        bits | magnitude_of(v.x) | magnitude_of(v.y) | magnitude_of(v.z)
    }))
}

/// The bit length of the largest magnitude in `values`, as [`vector_bits`].
#[inline(always)]
pub(crate) fn scalar_bits(values: &[Fx]) -> u32 {
    bit_length(values.iter().fold(0, |bits, &v| bits | magnitude_of(v)))
}

/// |v| or |v| − 1 of one value's bits: `v ^ (v >> 63)`.
#[inline(always)]
fn magnitude_of(v: Fx) -> u64 {
    let v = v.to_bits();
    (v ^ (v >> 63)) as u64
}

/// A backend of the kernels.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Backend {
    #[cfg(target_arch = "x86_64")]
    Avx512(Avx512),
    #[cfg(target_arch = "x86_64")]
    Avx2(Avx2),
    #[cfg(target_arch = "aarch64")]
    Neon(Neon),
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    Simd128(Simd128),
}

/// The backend of the kernels on this processor: on x86-64 AVX-512 (F, CD and DQ), else
/// AVX2, else none (the blocks then go lane by lane); on aarch64 NEON. Tests may choose one
/// the processor has, or none, for the thread (`with_backend`).
#[inline]
pub(crate) fn backend() -> Option<Backend> {
    #[cfg(test)]
    if let Some(chosen) = CHOSEN.get() {
        return chosen;
    }
    #[cfg(target_arch = "x86_64")]
    return Avx512::detect()
        .map(Backend::Avx512)
        .or_else(|| Avx2::detect().map(Backend::Avx2));
    #[cfg(target_arch = "aarch64")]
    return Neon::detect().map(Backend::Neon);
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    return Simd128::detect().map(Backend::Simd128);
}

#[cfg(test)]
std::thread_local! {
    /// The backend a test chose for this thread, if it chose one.
    static CHOSEN: core::cell::Cell<Option<Option<Backend>>> = const { core::cell::Cell::new(None) };
}

/// The backends this processor runs.
#[cfg(test)]
pub(crate) fn backends() -> Vec<Backend> {
    #[cfg(target_arch = "x86_64")]
    let all = [
        Avx512::detect().map(Backend::Avx512),
        Avx2::detect().map(Backend::Avx2),
    ];
    #[cfg(target_arch = "aarch64")]
    let all = [Neon::detect().map(Backend::Neon)];
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    let all = [Simd128::detect().map(Backend::Simd128)];
    all.into_iter().flatten().collect()
}

/// Runs `f` with the kernels of `backend` (none: the lanes) on this thread.
#[cfg(test)]
pub(crate) fn with_backend<T>(backend: Option<Backend>, f: impl FnOnce() -> T) -> T {
    let before = CHOSEN.replace(Some(backend));
    let result = f();
    CHOSEN.set(before);
    result
}

/// `f` of each quarter of two values of four 128-bit registers (the NEON and `simd128`
/// backends). A macro, not a closure: the kernels are large, and a closure there may not
/// be inlined (nor, then, the intrinsics inside it).
#[cfg(any(
    target_arch = "aarch64",
    all(target_arch = "wasm32", target_feature = "simd128")
))]
macro_rules! quarters {
    ($t:ty; $a:expr, $b:expr, |$x:ident, $y:ident| $f:expr) => {{
        let (a, b): ([$t; 4], [$t; 4]) = ($a, $b);
        [
            {
                let ($x, $y) = (a[0], b[0]);
                $f
            },
            {
                let ($x, $y) = (a[1], b[1]);
                $f
            },
            {
                let ($x, $y) = (a[2], b[2]);
                $f
            },
            {
                let ($x, $y) = (a[3], b[3]);
                $f
            },
        ]
    }};
}
#[cfg(any(
    target_arch = "aarch64",
    all(target_arch = "wasm32", target_feature = "simd128")
))]
pub(crate) use quarters;

/// Defines `fn $name(backend: Backend, args…) -> ret`, which runs the generic kernel
/// `$kernel(wide, args…)` in a function compiled with the instructions of the chosen
/// backend, one such function per backend, so that the kernel and the operations of
/// [`Wide`] inline into it.
macro_rules! kernel_entry {
    ($(#[$meta:meta])* $vis:vis fn $name:ident($($arg:ident: $ty:ty),* $(,)?) -> $ret:ty = $kernel:path;) => {
        $(#[$meta])*
        $vis fn $name(backend: $crate::math::wide::Backend, $($arg: $ty),*) -> $ret {
            #[cfg(target_arch = "x86_64")]
            use $crate::math::wide::{avx2::Avx2, avx512::Avx512};
            #[cfg(target_arch = "aarch64")]
            use $crate::math::wide::neon::Neon;
            #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
            use $crate::math::wide::simd128::Simd128;
            /// # Safety
            /// The processor must have AVX-512F, CD and DQ.
            #[cfg(target_arch = "x86_64")]
            #[target_feature(enable = "avx512f,avx512cd,avx512dq")]
            unsafe fn on_avx512(wide: Avx512, $($arg: $ty),*) -> $ret {
                $kernel(wide, $($arg),*)
            }
            /// # Safety
            /// The processor must have AVX2.
            #[cfg(target_arch = "x86_64")]
            #[target_feature(enable = "avx2")]
            unsafe fn on_avx2(wide: Avx2, $($arg: $ty),*) -> $ret {
                $kernel(wide, $($arg),*)
            }
            /// NEON is part of every aarch64 processor.
            #[cfg(target_arch = "aarch64")]
            fn on_neon(wide: Neon, $($arg: $ty),*) -> $ret {
                $kernel(wide, $($arg),*)
            }
            /// The module is built with `simd128`.
            #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
            fn on_simd128(wide: Simd128, $($arg: $ty),*) -> $ret {
                $kernel(wide, $($arg),*)
            }
            match backend {
                // SAFETY: a value of a backend exists only where the processor has its
                // instructions.
                #[cfg(target_arch = "x86_64")]
                $crate::math::wide::Backend::Avx512(wide) => unsafe { on_avx512(wide, $($arg),*) },
                // SAFETY: as above.
                #[cfg(target_arch = "x86_64")]
                $crate::math::wide::Backend::Avx2(wide) => unsafe { on_avx2(wide, $($arg),*) },
                #[cfg(target_arch = "aarch64")]
                $crate::math::wide::Backend::Neon(wide) => on_neon(wide, $($arg),*),
                #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
                $crate::math::wide::Backend::Simd128(wide) => on_simd128(wide, $($arg),*),
            }
        }
    };
}
pub(crate) use kernel_entry;

/// `$body` with `$wide` bound to the backend value of `$backend`, whatever its kind: for
/// callers whose kernels are methods of a trait implemented per backend.
macro_rules! on_backend {
    ($backend:expr, $wide:ident => $body:expr) => {
        match $backend {
            #[cfg(target_arch = "x86_64")]
            $crate::math::wide::Backend::Avx512($wide) => $body,
            #[cfg(target_arch = "x86_64")]
            $crate::math::wide::Backend::Avx2($wide) => $body,
            #[cfg(target_arch = "aarch64")]
            $crate::math::wide::Backend::Neon($wide) => $body,
            #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
            $crate::math::wide::Backend::Simd128($wide) => $body,
        }
    };
}
pub(crate) use on_backend;

/// Eight `i64` lanes and the operations the kernels need, each modulo 2⁶⁴ lane by lane.
/// A value of an implementing type proves that the processor runs its instructions.
///
/// Every method is `#[inline(always)]` and carries no `#[target_feature]`: a kernel runs
/// them inside an entry point that enables the backend's instructions, where the
/// intrinsics inline into single instructions. For that, nothing between the entry point
/// and an intrinsic may be a call the compiler declines to inline: the kernels and the
/// backends use no closures or iterator adapters on vectors, only loops and macros.
pub(crate) trait Wide: Copy {
    /// Eight lanes.
    type V: Copy;

    fn zero(self) -> Self::V;
    fn splat(self, x: i64) -> Self::V;
    /// The eight words at `words` (any alignment).
    ///
    /// # Safety
    /// Eight words at `words` must be readable.
    unsafe fn load_at(self, words: *const i64) -> Self::V;

    /// Writes eight words to `out` (any alignment).
    ///
    /// # Safety
    /// Eight words at `out` must be writable.
    unsafe fn store_at(self, out: *mut i64, x: Self::V);

    #[inline(always)]
    fn load_words(self, x: [i64; LANES]) -> Self::V {
        // SAFETY: eight readable words.
        unsafe { self.load_at(x.as_ptr()) }
    }

    #[inline(always)]
    fn store_words(self, x: Self::V) -> [i64; LANES] {
        let mut out = [0; LANES];
        // SAFETY: eight writable words.
        unsafe { self.store_at(out.as_mut_ptr(), x) };
        out
    }
    fn add(self, a: Self::V, b: Self::V) -> Self::V;
    fn sub(self, a: Self::V, b: Self::V) -> Self::V;
    fn and(self, a: Self::V, b: Self::V) -> Self::V;
    fn or(self, a: Self::V, b: Self::V) -> Self::V;
    fn xor(self, a: Self::V, b: Self::V) -> Self::V;
    /// a >> 63, arithmetic: −1 in the negative lanes, 0 in the others.
    fn sign(self, a: Self::V) -> Self::V;
    fn max(self, a: Self::V, b: Self::V) -> Self::V;
    fn min(self, a: Self::V, b: Self::V) -> Self::V;
    /// |a|, wrapping (i64::MIN stays itself).
    fn abs(self, a: Self::V) -> Self::V;
    /// The signed low 32 bits of a times those of b, in 64 bits.
    fn mul_low_halves(self, a: Self::V, b: Self::V) -> Self::V;
    /// The low 64 bits of a·b_h, given a's high half a_h = [`high`](Self::high)`(a)` and
    /// b_h, both within [−2³¹, 2³¹): a 64-bit multiply where the backend has one, else
    /// a·b_h = a_h·b_h·2³² + a_l·b_h, two products of 32-bit halves (exact modulo 2⁶⁴ for
    /// any a, since a = a_h·2³² + a_l).
    fn mul_low_by_high(self, a: Self::V, a_high: Self::V, b_high: Self::V) -> Self::V;
    /// ⌊a/2³²⌋.
    fn shift_down_32(self, a: Self::V) -> Self::V;
    /// The lanes where a > b, signed.
    fn greater(self, a: Self::V, b: Self::V) -> u8;
    /// The lanes where a ≥ b, unsigned.
    fn at_least_unsigned(self, a: Self::V, b: Self::V) -> u8;
    fn equal(self, a: Self::V, b: Self::V) -> u8;
    /// `on` in the lanes of `mask`, `off` elsewhere.
    fn select(self, mask: u8, on: Self::V, off: Self::V) -> Self::V;

    /// The words of `base` at the word offsets `words` in the lanes of `active`, zero
    /// elsewhere; by default word by word into an array, then one load.
    ///
    /// # Safety
    /// In every lane of `active`, the word must lie in the allocation `base` points into.
    #[inline(always)]
    unsafe fn gather_words(self, base: *const i64, words: Self::V, active: u8) -> Self::V {
        let offsets = self.store_words(words);
        let mut out = [0; LANES];
        for (l, (word, offset)) in out.iter_mut().zip(offsets).enumerate() {
            if active & (1 << l) != 0 {
                // SAFETY: the caller's promise for the lanes of `active`.
                *word = unsafe { *base.offset(offset as isize) };
            }
        }
        self.load_words(out)
    }

    /// `values[indices[l]]` in lane l for the `count` first lanes, zero in the others; by
    /// default word by word into an array, then one load.
    ///
    /// # Safety
    /// `count` ≤ [`LANES`] and ≤ `indices.len()`; each of the first `count` indices must be
    /// below the number of words at `values`.
    #[inline(always)]
    unsafe fn gather_values(self, values: *const i64, indices: &[u32], count: usize) -> Self::V {
        let mut words = [0; LANES];
        for (l, word) in words.iter_mut().enumerate().take(count) {
            // SAFETY: the caller's conditions: index l exists and lies within `values`.
            *word = unsafe { *values.add(*indices.get_unchecked(l) as usize) };
        }
        self.load_words(words)
    }

    /// The x, y and z components of `vectors[indices[l]]` in lane l for the first (at most
    /// eight) indices, zero in the lanes past them; `None` if an index is out of bounds. By
    /// default component by component into arrays, then one load each.
    #[inline(always)]
    fn gather_vectors(self, vectors: &[Vec3<Fx>], indices: &[u32]) -> Option<[Self::V; 3]> {
        let mut words = [[0; LANES]; 3];
        for (l, &i) in indices.iter().take(LANES).enumerate() {
            let vector = vectors.get(i as usize)?;
            words[0][l] = vector.x.to_bits();
            words[1][l] = vector.y.to_bits();
            words[2][l] = vector.z.to_bits();
        }
        Some(self.load_components(&words))
    }

    /// One vector per component from words gathered lane by lane (x, y, z).
    #[inline(always)]
    fn load_components(self, words: &[[i64; LANES]; 3]) -> [Self::V; 3] {
        [
            self.load_words(words[0]),
            self.load_words(words[1]),
            self.load_words(words[2]),
        ]
    }

    /// The x, y and z components of the eight consecutive vectors `vectors[first..first +
    /// 8]` in lanes 0 to 7; `None` if they are out of bounds.
    #[inline(always)]
    fn load_run(self, vectors: &[Vec3<Fx>], first: usize) -> Option<[Self::V; 3]> {
        let run = vectors.get(first..first + LANES)?;
        let mut words = [[0; LANES]; 3];
        for (l, vector) in run.iter().enumerate() {
            words[0][l] = vector.x.to_bits();
            words[1][l] = vector.y.to_bits();
            words[2][l] = vector.z.to_bits();
        }
        Some(self.load_components(&words))
    }

    /// Third `k` (0, 1 or 2; a larger k reads the last) of the 24 words of eight
    /// consecutive vectors in memory order: words 8k to 8k + 7, where word 3i + c is
    /// component c of vector i. No transpose: for kernels that treat every component alike.
    #[inline(always)]
    fn load_third(self, vectors: &[Vec3<Fx>; LANES], k: usize) -> Self::V {
        let words = vectors
            .as_ptr()
            .cast::<i64>()
            .wrapping_add(LANES * k.min(2));
        // SAFETY: eight `Vec3<Fx>` are 24 readable `i64` (three in a row, `repr(C)`); words
        // 8k to 8k + 7 with k ≤ 2.
        unsafe { self.load_at(words) }
    }

    /// Writes third `k` of eight consecutive vectors, in the layout of
    /// [`load_third`](Self::load_third).
    #[inline(always)]
    fn store_third(self, vectors: &mut [Vec3<Fx>; LANES], k: usize, words: Self::V) {
        let out = vectors
            .as_mut_ptr()
            .cast::<i64>()
            .wrapping_add(LANES * k.min(2));
        // SAFETY: eight `Vec3<Fx>` are 24 writable `i64`; words 8k to 8k + 7 with k ≤ 2, and
        // every bit pattern is an `Fx`.
        unsafe { self.store_at(out, words) }
    }

    /// A value per vector of a run of eight (lane i of `a` for vector i) over the lanes of
    /// that vector's three components in the layout of [`load_third`](Self::load_third):
    /// lane j of result k holds lane ⌊(8k + j)/3⌋ of `a`. By default through arrays.
    #[inline(always)]
    fn spread_thirds(self, a: Self::V) -> [Self::V; 3] {
        let words = self.store_words(a);
        let mut out = [[0; LANES]; 3];
        for (k, lanes) in out.iter_mut().enumerate() {
            for (j, lane) in lanes.iter_mut().enumerate() {
                *lane = words[(LANES * k + j) / 3];
            }
        }
        [
            self.load_words(out[0]),
            self.load_words(out[1]),
            self.load_words(out[2]),
        ]
    }

    /// The four columns of eight rows of four values, one vector per column.
    #[inline(always)]
    fn load_columns(self, rows: &[[Fx; 4]; LANES]) -> [Self::V; 4] {
        let mut words = [[0; LANES]; 4];
        for (l, row) in rows.iter().enumerate() {
            for (column, value) in words.iter_mut().zip(row) {
                column[l] = value.to_bits();
            }
        }
        [
            self.load_words(words[0]),
            self.load_words(words[1]),
            self.load_words(words[2]),
            self.load_words(words[3]),
        ]
    }

    /// The `count` words at `words` in the first lanes, zero in the others; by default word
    /// by word into an array, then one load.
    ///
    /// # Safety
    /// `count` ≤ [`LANES`], and the `count` words must be readable.
    #[inline(always)]
    unsafe fn load_prefix(self, words: *const i64, count: usize) -> Self::V {
        let mut out = [0; LANES];
        for (l, word) in out.iter_mut().enumerate().take(count) {
            // SAFETY: the caller's promise: the `count` words are readable.
            *word = unsafe { *words.add(l) };
        }
        self.load_words(out)
    }

    /// The `count` unsigned 32-bit numbers at `numbers`, widened, in the first lanes, zero
    /// in the others; by default one by one into an array, then one load.
    ///
    /// # Safety
    /// `count` ≤ [`LANES`], and the `count` numbers must be readable.
    #[inline(always)]
    unsafe fn load_prefix_u32(self, numbers: *const u32, count: usize) -> Self::V {
        let mut out = [0; LANES];
        for (l, word) in out.iter_mut().enumerate().take(count) {
            // SAFETY: the caller's promise: the `count` numbers are readable.
            *word = i64::from(unsafe { *numbers.add(l) });
        }
        self.load_words(out)
    }

    /// a·2ⁿ, the bits shifted out lost (n < 64).
    fn shift_left(self, a: Self::V, n: u32) -> Self::V;
    /// ⌊a/2ⁿ⌋ of a as an unsigned number (n < 64).
    fn shift_right_unsigned(self, a: Self::V, n: u32) -> Self::V;
    /// ⌊a/2ⁿ⌋, signed (n < 64).
    fn shift_right(self, a: Self::V, n: u32) -> Self::V;
    /// a·2^(nₗ) per lane, zero where nₗ ≥ 64.
    fn shift_left_lanes(self, a: Self::V, n: Self::V) -> Self::V;
    /// ⌊a/2^(nₗ)⌋ unsigned per lane, zero where nₗ ≥ 64.
    fn shift_right_unsigned_lanes(self, a: Self::V, n: Self::V) -> Self::V;
    /// The unsigned low 32 bits of a times those of b, in 64 bits.
    fn mul_unsigned_low_halves(self, a: Self::V, b: Self::V) -> Self::V;
    /// The number of leading zero bits of each lane (64 for zero); lane by lane by
    /// default.
    #[inline(always)]
    fn leading_zeros(self, a: Self::V) -> Self::V {
        let words = self.store_words(a);
        let mut counts = [0; LANES];
        for (count, word) in counts.iter_mut().zip(words) {
            *count = i64::from(word.leading_zeros());
        }
        self.load_words(counts)
    }
    /// `table[index mod 16]` per lane: the index's low four bits choose the word; by
    /// default lane by lane.
    #[inline(always)]
    fn lookup16(self, table: &[i64; 16], index: Self::V) -> Self::V {
        let indices = self.store_words(index);
        let mut out = [0; LANES];
        for (word, index) in out.iter_mut().zip(indices) {
            *word = table[(index & 15) as usize];
        }
        self.load_words(out)
    }

    /// Writes the lanes of `keep`, in lane order, to the first words at `out`; the words
    /// after them, up to eight in all, may be overwritten. By default the words one by
    /// one, each written and the position advanced by whether it is kept (no branch).
    ///
    /// # Safety
    /// Eight words at `out` must be writable.
    #[inline(always)]
    unsafe fn store_kept(self, out: *mut i64, keep: u8, a: Self::V) {
        let words = self.store_words(a);
        let mut at = 0;
        for (l, word) in words.into_iter().enumerate() {
            // SAFETY: `at` ≤ l < 8, within the eight writable words.
            unsafe { *out.add(at) = word };
            at += usize::from((keep >> l) & 1);
        }
    }

    /// The lanes where a > b, unsigned.
    #[inline(always)]
    fn greater_unsigned(self, a: Self::V, b: Self::V) -> u8 {
        !self.at_least_unsigned(b, a)
    }

    /// The unsigned minimum.
    #[inline(always)]
    fn min_unsigned(self, a: Self::V, b: Self::V) -> Self::V {
        self.select(self.greater_unsigned(a, b), b, a)
    }

    /// The sum of the lanes, modulo 2⁶⁴.
    #[inline(always)]
    fn sum_lanes(self, a: Self::V) -> i64 {
        self.store_words(a)
            .into_iter()
            .fold(0, |sum: i64, x| sum.wrapping_add(x))
    }

    /// Whether every lane, as an unsigned number, lies below 2ⁿ (n < 64): on the or of
    /// several [`magnitude`](Self::magnitude)s, whether each value lies within
    /// [−2ⁿ, 2ⁿ). By default through [`or_lanes`](Self::or_lanes).
    #[inline(always)]
    fn below_power(self, a: Self::V, n: u32) -> bool {
        self.or_lanes(a) >> n == 0
    }

    /// The bitwise or of the lanes.
    #[inline(always)]
    fn or_lanes(self, a: Self::V) -> u64 {
        self.store_words(a)
            .into_iter()
            .fold(0, |or, x| or | x as u64)
    }

    /// |a| or |a| − 1 per lane, a ^ (a >> 63): the bits a bound on |a| needs.
    #[inline(always)]
    fn magnitude(self, a: Self::V) -> Self::V {
        self.xor(a, self.sign(a))
    }

    /// The raw bits of a lane array.
    #[inline(always)]
    fn load(self, lanes: &[Fx; LANES]) -> Self::V {
        let mut bits = [0; LANES];
        for (bits, x) in bits.iter_mut().zip(lanes) {
            *bits = x.to_bits();
        }
        self.load_words(bits)
    }

    /// Writes raw bits to a lane array.
    #[inline(always)]
    fn store(self, lanes: &mut [Fx; LANES], value: Self::V) {
        for (x, bits) in lanes.iter_mut().zip(self.store_words(value)) {
            *x = Fx::from_bits(bits);
        }
    }

    /// Writes the lanes of `mask` to a lane array; the others keep their values.
    #[inline(always)]
    fn store_lanes(self, lanes: &mut [Fx; LANES], mask: u8, value: Self::V) {
        let kept = self.load(lanes);
        self.store(lanes, self.select(mask, value, kept));
    }

    #[inline(always)]
    fn add3(self, a: [Self::V; 3], b: [Self::V; 3]) -> [Self::V; 3] {
        [
            self.add(a[0], b[0]),
            self.add(a[1], b[1]),
            self.add(a[2], b[2]),
        ]
    }

    #[inline(always)]
    fn sub3(self, a: [Self::V; 3], b: [Self::V; 3]) -> [Self::V; 3] {
        [
            self.sub(a[0], b[0]),
            self.sub(a[1], b[1]),
            self.sub(a[2], b[2]),
        ]
    }

    /// `on` in the lanes of `mask`, `off` elsewhere, component by component.
    #[inline(always)]
    fn select3(self, mask: u8, on: [Self::V; 3], off: [Self::V; 3]) -> [Self::V; 3] {
        [
            self.select(mask, on[0], off[0]),
            self.select(mask, on[1], off[1]),
            self.select(mask, on[2], off[2]),
        ]
    }

    /// `value` in the lanes of `mask`, zero elsewhere.
    #[inline(always)]
    fn keep3(self, mask: u8, value: [Self::V; 3]) -> [Self::V; 3] {
        self.select3(mask, value, [self.zero(); 3])
    }

    /// ⌊(a + 2³¹)/2³²⌋: the high half of a around its signed low half.
    #[inline(always)]
    fn high(self, a: Self::V) -> Self::V {
        self.shift_down_32(self.add(a, self.splat(1 << 31)))
    }

    /// The checked `*` of values within [−2⁴⁶, 2⁴⁶): ⌊(a·b + 2³¹)/2³²⌋ = a·b_h + a_h·b_l +
    /// ⌊(a_l·b_l + 2³¹)/2³²⌋ ([module](self) documentation).
    #[inline(always)]
    fn mul(self, a: Self::V, b: Self::V) -> Self::V {
        let (ah, bh) = (self.high(a), self.high(b));
        let upper = self.add(self.mul_low_by_high(a, ah, bh), self.mul_low_halves(ah, b));
        let low = self.high(self.mul_low_halves(a, b));
        self.add(upper, low)
    }

    /// a·b with each product rounded on its own, as [`Vec3::dot`](crate::math::Vec3::dot)
    /// rounds it: (a₀b₀ + a₁b₁) + a₂b₂, for values within [−2⁴⁶, 2⁴⁶) ([`mul`](Self::mul)).
    /// ([`dot`](Self::dot) rounds the sum once instead.)
    #[inline(always)]
    fn rounded_dot(self, a: [Self::V; 3], b: [Self::V; 3]) -> Self::V {
        self.add(
            self.add(self.mul(a[0], b[0]), self.mul(a[1], b[1])),
            self.mul(a[2], b[2]),
        )
    }

    /// a × b with each product rounded on its own, as
    /// [`Vec3::cross`](crate::math::Vec3::cross) rounds it, for values within [−2⁴⁶, 2⁴⁶).
    #[inline(always)]
    fn cross(self, a: [Self::V; 3], b: [Self::V; 3]) -> [Self::V; 3] {
        [
            self.sub(self.mul(a[1], b[2]), self.mul(a[2], b[1])),
            self.sub(self.mul(a[2], b[0]), self.mul(a[0], b[2])),
            self.sub(self.mul(a[0], b[1]), self.mul(a[1], b[0])),
        ]
    }

    /// The checked `*` of `small`, within [−2³¹, 2³¹) when `NARROW` (and within
    /// [−2⁴⁶, 2⁴⁶) otherwise), and `other`, within [−2⁴⁶, 2⁴⁶): when narrow,
    /// ⌊(a·b + 2³¹)/2³²⌋ = a·b_h + ⌊(a·b_l + 2³¹)/2³²⌋, two products of 32-bit halves
    /// (a·b_h below 2⁴⁵, a·b_l below 2⁶²) where [`mul`](Self::mul) needs three.
    #[inline(always)]
    fn times<const NARROW: bool>(self, small: Self::V, other: Self::V) -> Self::V {
        if NARROW {
            let upper = self.mul_low_halves(small, self.high(other));
            self.add(upper, self.high(self.mul_low_halves(small, other)))
        } else {
            self.mul(small, other)
        }
    }

    /// Each of `coefficients` times the same factor ([`times`](Self::times)).
    #[inline(always)]
    fn times3<const NARROW: bool>(self, coefficients: [Self::V; 3], x: Self::V) -> [Self::V; 3] {
        [
            self.times::<NARROW>(coefficients[0], x),
            self.times::<NARROW>(coefficients[1], x),
            self.times::<NARROW>(coefficients[2], x),
        ]
    }

    /// The fused dot product of `values`, within [−2³¹, 2³¹) when `NARROW`, and
    /// `coefficients`, within [−2⁴⁶, 2⁴⁶): the exact Σ aᵢbᵢ rounded once ([module](self)
    /// documentation; when narrow, a_h = 0).
    #[inline(always)]
    fn dot<const NARROW: bool>(self, values: [Self::V; 3], coefficients: [Self::V; 3]) -> Self::V {
        let mask = self.splat(0xffff_ffff);
        let mut whole = self.zero();
        let mut remainders = self.zero();
        for i in 0..3 {
            let (a, b) = (values[i], coefficients[i]);
            let ll = self.mul_low_halves(a, b);
            let upper = if NARROW {
                self.mul_low_halves(a, self.high(b))
            } else {
                let (ah, bh) = (self.high(a), self.high(b));
                self.add(self.mul_low_by_high(a, ah, bh), self.mul_low_halves(ah, b))
            };
            whole = self.add(whole, self.add(upper, self.shift_down_32(ll)));
            remainders = self.add(remainders, self.and(ll, mask));
        }
        self.add(whole, self.high(remainders))
    }

    /// The lanes where x lies outside [−2⁴⁶, 2⁴⁶).
    #[inline(always)]
    fn out_of_bound(self, x: Self::V) -> u8 {
        self.at_least_unsigned(self.add(x, self.splat(1 << 46)), self.splat(1 << 47))
    }

    #[inline(always)]
    fn out_of_bound3(self, x: [Self::V; 3]) -> u8 {
        self.out_of_bound(x[0]) | self.out_of_bound(x[1]) | self.out_of_bound(x[2])
    }

    /// The lanes where x, a value that changes during the step, lies outside the bound
    /// its products need: [−2³¹, 2³¹) for narrow products, [−2⁴⁶, 2⁴⁶) for wide ones
    /// ([`times`](Self::times)).
    #[inline(always)]
    fn beyond<const NARROW: bool>(self, x: Self::V) -> u8 {
        if NARROW {
            self.at_least_unsigned(self.add(x, self.splat(1 << 31)), self.splat(1 << 32))
        } else {
            self.out_of_bound(x)
        }
    }

    #[inline(always)]
    fn beyond3<const NARROW: bool>(self, x: [Self::V; 3]) -> u8 {
        self.beyond::<NARROW>(x[0]) | self.beyond::<NARROW>(x[1]) | self.beyond::<NARROW>(x[2])
    }
}
