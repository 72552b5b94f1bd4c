//! Scenes: descriptions of a world, checked and turned into worlds; RON scene files (the
//! `ron` feature). The built-in scenes live in the `fixstep-scenes` crate.

mod description;
pub mod error;
#[cfg(feature = "ron")]
mod load;

pub(crate) use description::check_rates;
pub use description::{MAX_SUBSTEPS, MAX_TICK_RATE, Scene};
pub use error::SceneError;
#[cfg(feature = "ron")]
pub use load::{load_scene_file, parse_scene};
