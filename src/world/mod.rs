//! The world and its tick: state, stages, inputs, checksums and snapshots.

mod character_coupling;
pub mod checksum;
pub mod difference;
pub mod divergence;
mod fluid_coupling;
pub mod health;
mod particle_coupling;
mod pipeline;
mod queries;
pub mod scene_id;
pub mod snapshot;
pub(crate) mod soft_coupling;
pub mod stage;
mod stage_watch;
pub mod timestep;
mod water_coupling;

pub use checksum::Checksum;
pub use difference::{Difference, first_difference};
pub use divergence::{Divergence, DivergenceScale};
pub use health::{Health, SaturationSite};
pub use pipeline::{ObjectDigests, STATE_VERSION, Settings, TickReport, World, WorldState};
pub use scene_id::SceneId;
pub use snapshot::{MAX_SNAPSHOT_LEN, Snapshot, SnapshotError, decode_snapshot, encode_snapshot};
pub use stage::StageTimings;
pub use timestep::FixedTimestep;

// The shared types, published here where the world's users first found them.
pub use crate::types::{Command, Handle, Metrics, Part, PlayerInput, Stage, Target, TickInput};
