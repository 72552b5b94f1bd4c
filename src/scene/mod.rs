//! Scenes: descriptions of a world, checked and turned into worlds and simulations that
//! feed them their scripts; RON scene files (the `ron` feature). The built-in scenes live
//! in the `fixstep-scenes` crate.

mod description;
#[cfg(feature = "ron")]
mod load;
pub mod mass_ratios;
mod simulation;
mod spawn_check;

pub use crate::types::{MAX_SUBSTEPS, MAX_TICK_RATE, SceneError};
pub use description::Scene;
#[cfg(feature = "ron")]
pub use load::{load_scene_file, parse_scene};
pub use simulation::Simulation;
