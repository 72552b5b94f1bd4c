//! Fixed-point math: the scalar, its integer-only functions, vectors, quaternions, matrices,
//! the deterministic RNG and the canonical state hasher.

pub mod cpu;
pub mod exp;
pub mod fixed_scalar;
pub mod float_scalar;
pub mod guarded;
pub mod implicit_springs;
pub mod integration;
pub mod mat3;
pub mod over_real;
pub mod quat;
pub mod real;
pub mod rng;
pub mod saturation;
pub mod spring;
pub mod sqrt;
pub mod state_hash;
pub mod trig;
pub mod vec3;
#[cfg(vector_kernels)]
pub(crate) mod wide;
pub(crate) mod wide_product;

pub use fixed_scalar::{Fixed, FracBits, Fx, FxI32F32, FxI40F24, FxI48F16};
pub use guarded::{Fraction, Guard};
pub use mat3::Mat3;
pub use over_real::OverReal;
pub use quat::Quat;
pub use real::{ParseRealError, Real};
pub use rng::Pcg32;
pub use state_hash::StateHasher;
pub use vec3::Vec3;
