//! Scenes: built-in and RON files, checked and turned into worlds.

pub mod builtin;
mod description;
mod load;

pub use crate::types::{MAX_SUBSTEPS, MAX_TICK_RATE, SceneError};
pub use builtin::{BUILTIN_SCENES, builtin_scene};
pub use description::Scene;
pub use load::{load_scene_file, parse_scene};
