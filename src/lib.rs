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
//! [`scene::parse_scene`] or [`scene::load_scene_file`]) builds a [`World`](world::World).
//! A game then calls [`World::step`](world::World::step) once per tick with that tick's
//! [`TickInput`](world::TickInput): the commands of every player; a
//! [`Simulation`](scene::Simulation) does it for a scene with a script, feeding each
//! tick's scripted input and the game's own commands. Reading and building fail with one
//! error, [`SceneError`](scene::SceneError), naming the file, line and field.
//! [`prelude`] brings all of these in one import. A tick runs the
//! [`Stage`](types::Stage)s in order:
//!
//! 1. `ApplyInputs`: the commands, players in ascending index;
//! 2. `Particles` ([`particles`]): emitters, forces and seven integrators;
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
//! encoding); [`prelude`] re-exports what a game needs. The tools (the `fixstep` command, the viewer, the network peer, the
//! benchmarks) and the built-in scenes are crates of their own (`crates/` in the
//! repository); this crate depends on nothing a game does not need.
//!
//! # Example
//!
//! A box dropped on the ground, kicked up by a player at tick 60:
//!
//! ```
//! use fixstep::prelude::*;
//!
//! // A scene from RON text (or `load_scene_file(path)`, or `Scene` built in code).
//! let scene = parse_scene::<Fx>(
//!     r#"(
//!         name: "drop",
//!         rigid: (bodies: [
//!             (kind: Static, shape: Plane(normal: (x: 0.0, y: 1.0, z: 0.0), offset: 0.0)),
//!             (shape: Box(half_extents: (x: 0.5, y: 0.5, z: 0.5)), position: (x: 0.0, y: 3.0, z: 0.0)),
//!         ]),
//!     )"#,
//!     "drop.ron",
//! )?;
//! // A simulation builds the world and feeds it the scene's script (this one has none).
//! let mut simulation = Simulation::new(&scene)?;
//! let rigid = simulation.world().rigid().expect("the scene has rigid bodies");
//! let cube: Handle = rigid.handles().nth(1).expect("bodies in scene order");
//! for _ in 0..90 {
//!     if simulation.world().tick() == 60 {
//!         // Player 0 kicks the 1000 kg cube up at 5 m/s.
//!         let impulse = Vec3::new(Fx::ZERO, Fx::from_int(5000), Fx::ZERO);
//!         let kick = Command::ApplyImpulse { target: Target::Body(cube), impulse, point: None };
//!         simulation.step_with(&[PlayerInput { player: 0, commands: vec![kick] }]);
//!     } else {
//!         simulation.step();
//!     }
//! }
//! let world = simulation.world();
//! let height = world.rigid().unwrap().position(cube).unwrap().y;
//! assert!(height > Fx::from_int(1), "half a second after the kick, the cube is up: {height}");
//! println!("checksum: {}", hex(world.checksum().total)); // the same bits on every machine
//!
//! // One error type for reading and building: file, line, field.
//! let error = parse_scene::<Fx>("(name: \"bad\", tick_rate: 0)", "bad.ron")?
//!     .build()
//!     .expect_err("a tick rate of 0 is refused");
//! assert_eq!(error.field, "tick_rate");
//! # Ok::<(), SceneError>(())
//! ```

// The modules' documentation describes the engine's internals for its developers and links
// to private modules and items; read it with `cargo doc --document-private-items`, where
// every link resolves (the test command builds it so, with warnings as errors).
#![allow(rustdoc::private_intra_doc_links)]

pub mod character;
pub mod codec;
pub mod fluid;
pub mod math;
pub mod parallel;
pub mod particles;
pub mod prelude;
pub mod replay;
pub mod rigid;
pub mod scene;
pub mod soft;
pub mod types;
pub mod water;
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
