//! Scenes: built-in and RON files, checked and turned into worlds.

pub mod builtin;
mod description;
pub mod error;
mod load;

pub use builtin::{BUILTIN_SCENES, builtin_scene};
pub(crate) use description::check_rates;
pub use description::{MAX_SUBSTEPS, MAX_TICK_RATE, Scene};
pub use error::SceneError;
pub use load::{load_scene_file, parse_scene};
