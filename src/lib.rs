//! fixstep: a deterministic fixed-point 3D physics engine for lockstep and rollback games,
//! replays and cross-machine verification.
//!
//! Every simulated quantity is fixed point ([`math::Fx`], I32F32 by default), every loop
//! runs in a fixed order, and no float enters a tick: the same scene with the same inputs
//! gives the same bits on every machine, and [`World::checksum`](world::World::checksum)
//! proves it.
//!
//! # A tour
//!
//! A [`Scene`](scene::Scene) (built in code or read from RON with
//! [`scene::parse_scene`]) builds a [`World`](world::World). A game then calls
//! [`World::step`](world::World::step) once per tick with that tick's
//! [`TickInput`](world::TickInput): the commands of every player. A tick runs the
//! [`Stage`](types::Stage)s in order:
//!
//! 1. `ApplyInputs`: the commands, players in ascending index;
//! 2. `Particles` ([`particles`]): emitters, forces and six integrators;
//! 3. `Rigid` ([`rigid`]): broadphase, narrowphase, the soft-step contact and joint solver,
//!    islands and sleep;
//! 4. `Soft` ([`soft`]): XPBD cloth, rope and lattices, and spring-mass networks;
//! 5. `Fluid` ([`fluid`]): SPH water, WCSPH or DFSPH;
//! 6. `EndTick`: per-tick accumulators cleared, the tick counted.
//!
//! Each subsystem implements the one [`Subsystem`](types::Subsystem) contract (step with a
//! [`StepContext`](types::StepContext), end of tick, canonical hashing, object digests,
//! metrics, restore, validate); the world holds those the scene has and iterates them in
//! stage order, so a stage absent from the scene costs nothing.
//!
//! [`World::snapshot`](world::World::snapshot) and [`World::restore`](world::World::restore)
//! give rollback; [`world::encode_snapshot`] puts a state in a file; [`replay`] records a
//! run with checksums at checkpoints and verifies it on another machine, naming the first
//! differing tick, subsystem and object.
//!
//! # Layers
//!
//! Modules depend downward only: [`math`] (the scalar, vectors, the generator, the state
//! hasher) → [`types`] (handles, commands, the build error, the subsystem contract) → the
//! subsystems → [`world`] → [`scene`] and [`replay`] ([`codec`] is the one binary
//! encoding). The tools (the `fixstep` command, the viewer, the network peer, the
//! benchmarks) and the built-in scenes are crates of their own (`crates/` in the
//! repository); this crate depends on nothing a game does not need.
//!
//! # Example
//!
//! ```
//! use fixstep::math::Fx;
//! use fixstep::scene::parse_scene;
//! use fixstep::world::TickInput;
//!
//! let ron = "(name: \"drop\", particles: (particles: [(position: (x: 0.0, y: 10.0, z: 0.0))]))";
//! let mut world = parse_scene::<Fx>(ron, "inline").unwrap().build().unwrap();
//! for tick in 0..60 {
//!     world.step(&TickInput { tick, players: Vec::new() });
//! }
//! assert_eq!(world.tick(), 60);
//! println!("{:016x}", world.checksum().total); // the same bits on every machine
//! ```

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
