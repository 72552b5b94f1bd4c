//! The world and its tick: state, stages, inputs, checksums and snapshots.

pub mod checksum;
pub mod difference;
pub mod divergence;
pub mod handle;
pub mod input;
pub mod metrics;
mod pipeline;
pub mod snapshot;
pub mod stage;
pub mod timestep;

pub use checksum::{Checksum, Part};
pub use difference::{Difference, first_difference};
pub use divergence::Divergence;
pub use handle::Handle;
pub use input::{Command, PlayerInput, Target, TickInput};
pub use metrics::Metrics;
pub use pipeline::{ObjectDigests, STATE_VERSION, Settings, TickReport, World, WorldState};
pub use snapshot::{SnapshotError, decode_snapshot, encode_snapshot};
pub use stage::{Stage, StageTimings};
pub use timestep::FixedTimestep;
