//! Kinematic characters: capsules, spheres or boxes that walk, climb, step, jump and ride
//! over the rigid bodies without being simulated as bodies (after Rapier's
//! `KinematicCharacterController` and Jolt's `CharacterVirtual`).
//!
//! A character's state ([`Character`]) is part of the world state: snapshots carry it and
//! the checksum hashes it (a part of its own, [`Part::Characters`](crate::types::Part),
//! present only when the scene has characters). Inputs drive it with
//! [`Command::MoveCharacter`](crate::types::Command::MoveCharacter). Once per tick, after
//! every other stage, each character in index order moves by shape casts against the
//! bodies and the other characters ([`movement`]): move-and-slide with a skin, auto-step,
//! snap to ground, riding the body it stands on, pushing dynamic bodies, and standing as an
//! immovable obstacle to the dynamic bodies moved into it. The world lends it the bodies
//! through [`Surroundings`]. The user guide is `docs/characters.md`.
//!
//! # Files
//!
//! [`desc`] what a scene says · [`system`] the characters' state and commands ·
//! [`surroundings`] what a character sees of the world · [`crowd`] the other characters
//! as obstacles · [`movement`] one tick of one character · [`hashing`] the canonical hash
//! · [`subsystem`] the world's contract.

mod crowd;
pub mod desc;
mod hashing;
pub mod movement;
mod subsystem;
pub mod surroundings;
pub mod system;

pub use desc::{CharacterDesc, CharacterSettings};
pub use surroundings::{BodyMotion, NoSurroundings, Surroundings};
pub use system::{Character, CharacterEvent, CharacterSystem};
