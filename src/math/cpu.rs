//! Which vector instruction sets the step's kernels may use: those the processor has,
//! capped by the environment variable `FIXSTEP_SIMD`, read once per process:
//!
//! | `FIXSTEP_SIMD` | kernels used |
//! |---|---|
//! | unset, empty or `avx512` | every kernel the processor runs: on x86-64 AVX-512 (F, CD and DQ) where the processor has it, else AVX2, else none; on aarch64 NEON |
//! | `avx2` | x86-64: AVX2 where the processor has it, else none |
//! | `neon` | aarch64: NEON |
//! | `simd128` | wasm32 built with `+simd128` (`RUSTFLAGS="-C target-feature=+simd128"`): `simd128` |
//! | `scalar` | none: every stage runs its scalar code (the water step its kernel on plain-Rust lanes, `math::wide::portable`) |
//!
//! Every kernel gives the bits of the scalar code it replaces, so the cap changes speed
//! only, never a result; it exists so that one machine can run, and the determinism matrix
//! can verify against the committed replays, each path a processor may take. A value
//! other than those above, or one that names instructions of another architecture (`neon`
//! on x86-64, `avx2` on aarch64), is ignored by the library (no cap for an unknown value,
//! no kernels for another architecture's), and refused by the `fixstep` command
//! ([`cap_from_env`], exit 2). Other targets have no kernels.

use std::sync::OnceLock;

/// The vector instructions the kernels may use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SimdCap {
    /// No kernels.
    Scalar,
    /// AVX2 kernels at most (x86-64).
    Avx2,
    /// Every kernel the processor can run (the default).
    Avx512,
    /// NEON kernels (aarch64).
    Neon,
    /// `simd128` kernels (wasm32 built with `+simd128`).
    Simd128,
}

impl SimdCap {
    /// Whether this cap names instructions this target's processors can have: `avx2` and
    /// `avx512` on x86-64, `neon` on aarch64 (`avx512`, the default, everywhere), `scalar`
    /// everywhere.
    pub fn available_here(self) -> bool {
        match self {
            Self::Scalar | Self::Avx512 => true,
            Self::Avx2 => cfg!(target_arch = "x86_64"),
            Self::Neon => cfg!(target_arch = "aarch64"),
            Self::Simd128 => cfg!(all(target_arch = "wasm32", target_feature = "simd128")),
        }
    }
}

/// The environment variable that caps the kernels.
pub const SIMD_VARIABLE: &str = "FIXSTEP_SIMD";

/// The cap `FIXSTEP_SIMD` sets, or why its value is not one or not available on this
/// target (`neon` off aarch64, `avx2` off x86-64).
pub fn cap_from_env() -> Result<SimdCap, String> {
    let value = std::env::var(SIMD_VARIABLE).unwrap_or_default();
    let cap = match value.as_str() {
        "" | "avx512" => SimdCap::Avx512,
        "avx2" => SimdCap::Avx2,
        "neon" => SimdCap::Neon,
        "simd128" => SimdCap::Simd128,
        "scalar" => SimdCap::Scalar,
        other => {
            return Err(format!(
                "environment variable {SIMD_VARIABLE}: `{other}` is not one of avx512, avx2, \
                 neon, simd128, scalar"
            ));
        }
    };
    if !cap.available_here() {
        return Err(format!(
            "environment variable {SIMD_VARIABLE}: `{value}` is not available on {} \
             (this target has {})",
            std::env::consts::ARCH,
            if cfg!(target_arch = "x86_64") {
                "avx512, avx2 and scalar"
            } else if cfg!(target_arch = "aarch64") {
                "neon and scalar"
            } else if cfg!(all(target_arch = "wasm32", target_feature = "simd128")) {
                "simd128 and scalar"
            } else {
                "scalar only"
            }
        ));
    }
    Ok(cap)
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
    cap() == SimdCap::Avx512
        && std::arch::is_x86_feature_detected!("avx512f")
        && std::arch::is_x86_feature_detected!("avx512cd")
        && std::arch::is_x86_feature_detected!("avx512dq")
}

/// Whether the kernels may use AVX2.
#[cfg(target_arch = "x86_64")]
pub(crate) fn avx2() -> bool {
    matches!(cap(), SimdCap::Avx2 | SimdCap::Avx512) && std::arch::is_x86_feature_detected!("avx2")
}

/// Whether the kernels may use NEON, which every aarch64 processor has.
#[cfg(target_arch = "aarch64")]
pub(crate) fn neon() -> bool {
    matches!(cap(), SimdCap::Neon | SimdCap::Avx512)
}

/// Whether the kernels may use `simd128`, which a module built with it has.
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
pub(crate) fn simd128() -> bool {
    matches!(cap(), SimdCap::Simd128 | SimdCap::Avx512)
}

/// Runs `f` with each backend of the vector kernels this processor runs
/// ([`wide::backends`](super::wide::backends)), then with none (the scalar forms); once,
/// with none, where there are no kernels. For tests that compare the kernels with the scalar forms.
#[cfg(test)]
pub(crate) fn each_backend(mut f: impl FnMut()) {
    #[cfg(vector_kernels)]
    {
        use super::wide::{backends, with_backend};
        for backend in backends() {
            with_backend(Some(backend), &mut f);
        }
        with_backend(None, f);
    }
    #[cfg(not(vector_kernels))]
    f();
}

/// Whether vector kernels run on this thread now (under [`each_backend`], with the
/// backend it chose).
#[cfg(test)]
pub(crate) fn kernels_present() -> bool {
    #[cfg(vector_kernels)]
    return super::wide::backend().is_some();
    #[cfg(not(vector_kernels))]
    false
}
