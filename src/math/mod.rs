//! Fixed-point math: the scalar, its integer-only functions, vectors, quaternions, matrices,
//! the deterministic RNG and the canonical state hasher.

pub mod exp;
pub mod fixed_scalar;
pub mod float_scalar;
pub mod real;
pub mod saturation;
pub mod sqrt;
pub mod trig;
pub mod vec3;

pub use fixed_scalar::{Fixed, FracBits, Fx, FxI32F32, FxI40F24, FxI48F16};
pub use real::{ParseRealError, Real};
pub use vec3::Vec3;
