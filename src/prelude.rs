//! What a game needs in one import: `use fixstep::prelude::*;` brings the world, scenes and
//! their simulation, handles, inputs and commands, the scalar and vectors, checksums,
//! snapshots and the errors.

pub use crate::math::{Fx, Quat, Real, Vec3};
pub use crate::rigid::{BodyDesc, BodyKind, RigidDesc, Shape};
pub use crate::scene::{Scene, SceneError, Simulation};
#[cfg(feature = "ron")]
pub use crate::scene::{load_scene_file, parse_scene};
pub use crate::world::checksum::hex;
pub use crate::world::{
    Checksum, Command, FixedTimestep, Handle, PlayerInput, SnapshotError, Target, TickInput,
    TickReport, World, WorldState, decode_snapshot, encode_snapshot,
};
