//! fixstep: a deterministic fixed-point 3D physics engine.
//!
//! Every simulated quantity is fixed point ([`math::Fx`], I32F32 by default), iteration order
//! is deterministic, and the same scene with the same inputs gives the same bits on every
//! machine. Data flows one way: [`scene`] → [`world`] → stages → state → checksum and
//! [`replay`]. Modules depend downward only: [`math`] → [`types`] → the subsystems
//! ([`particles`], [`rigid`], [`soft`], [`fluid`]) → [`world`] → [`scene`], [`replay`] → tools.

// The modules' documentation describes the engine's internals for its developers and links
// to private modules and items; read it with `cargo doc --document-private-items`, where
// every link resolves (the test command builds it so, with warnings as errors).
#![allow(rustdoc::private_intra_doc_links)]

pub mod codec;
pub mod fluid;
pub mod math;
pub mod particles;
pub mod replay;
pub mod rigid;
pub mod scene;
pub mod soft;
pub mod types;
pub mod world;

// The engine's unit tests build the built-in scenes from the `fixstep-scenes` crate's own
// source: as a dev-dependency that crate would link a second copy of the engine, whose types
// are not the tested crate's. Its `fixstep::` paths name this crate.
#[cfg(test)]
extern crate self as fixstep;
#[cfg(test)]
#[allow(dead_code)] // each test uses a few of the scenes
#[path = "../crates/fixstep-scenes/src/lib.rs"]
mod fixstep_scenes;

/// The README's Rust examples, compiled and run as doctests so the README stays true.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
