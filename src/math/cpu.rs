//! Which vector instruction sets the step's kernels may use: those the processor has,
//! capped by the environment variable `FIXSTEP_SIMD`, read once per process:
//!
//! | `FIXSTEP_SIMD` | kernels used on x86-64 |
//! |---|---|
//! | unset, empty or `avx512` | AVX-512 (F, CD and DQ) where the processor has it, else AVX2, else none |
//! | `avx2` | AVX2 where the processor has it, else none |
//! | `scalar` | none: every stage runs its scalar code |
//!
//! Every kernel gives the bits of the scalar code it replaces, so the cap changes speed
//! only, never a result; it exists so that one machine can run, and the determinism matrix
//! can verify against the committed replays, each path a processor may take. A value
//! other than those above is ignored by the library (no cap), and refused by the `fixstep`
//! command ([`cap_from_env`]). Other targets have no kernels.

use std::sync::OnceLock;

/// The widest vector instruction set the kernels may use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum SimdCap {
    /// No kernels.
    Scalar,
    /// AVX2 kernels at most.
    Avx2,
    /// Every kernel the processor can run.
    Avx512,
}

/// The environment variable that caps the kernels.
pub const SIMD_VARIABLE: &str = "FIXSTEP_SIMD";

/// The cap `FIXSTEP_SIMD` sets, or why its value is not one.
pub fn cap_from_env() -> Result<SimdCap, String> {
    let value = std::env::var(SIMD_VARIABLE).unwrap_or_default();
    match value.as_str() {
        "" | "avx512" => Ok(SimdCap::Avx512),
        "avx2" => Ok(SimdCap::Avx2),
        "scalar" => Ok(SimdCap::Scalar),
        other => Err(format!(
            "environment variable {SIMD_VARIABLE}: `{other}` is not one of avx512, avx2, scalar"
        )),
    }
}

/// The cap in force, read once.
pub fn cap() -> SimdCap {
    static CAP: OnceLock<SimdCap> = OnceLock::new();
    *CAP.get_or_init(|| cap_from_env().unwrap_or(SimdCap::Avx512))
}

/// Whether the kernels may use the AVX-512 backend of [`wide`](super::wide): AVX-512F, CD
/// and DQ.
#[cfg(target_arch = "x86_64")]
pub(crate) fn avx512_kernels() -> bool {
    cap() >= SimdCap::Avx512
        && std::arch::is_x86_feature_detected!("avx512f")
        && std::arch::is_x86_feature_detected!("avx512cd")
        && std::arch::is_x86_feature_detected!("avx512dq")
}

/// Whether the kernels may use AVX2.
#[cfg(target_arch = "x86_64")]
pub(crate) fn avx2() -> bool {
    cap() >= SimdCap::Avx2 && std::arch::is_x86_feature_detected!("avx2")
}

/// Runs `f` with each backend of the vector kernels this processor runs
/// ([`wide::backends`](super::wide::backends)), then with none (the scalar forms); once,
/// with none, off x86-64. For tests that compare the kernels with the scalar forms.
#[cfg(test)]
pub(crate) fn each_backend(mut f: impl FnMut()) {
    #[cfg(target_arch = "x86_64")]
    {
        use super::wide::{backends, with_backend};
        for backend in backends() {
            with_backend(Some(backend), &mut f);
        }
        with_backend(None, f);
    }
    #[cfg(not(target_arch = "x86_64"))]
    f();
}

/// Whether vector kernels run on this thread now (under [`each_backend`], with the
/// backend it chose).
#[cfg(test)]
pub(crate) fn kernels_present() -> bool {
    #[cfg(target_arch = "x86_64")]
    return super::wide::backend().is_some();
    #[cfg(not(target_arch = "x86_64"))]
    false
}
