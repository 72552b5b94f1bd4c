//! The shared layer: the types every subsystem and the world agree on, below every
//! subsystem and above [`math`](crate::math) only.
//!
//! The layers depend downward only: [`math`](crate::math) → `types` → subsystems
//! ([`particles`](crate::particles), [`rigid`](crate::rigid), [`soft`](crate::soft),
//! [`fluid`](crate::fluid)) → [`world`](crate::world) → [`scene`](crate::scene) and
//! [`replay`](crate::replay) → tools. The upper modules re-export these types where they
//! were first published (`world::Handle`, `scene::SceneError`, …).

pub mod build_error;
pub mod command;
pub mod handle;
pub mod input_file;
pub mod lattice;
pub mod metrics;
pub mod part;
pub mod rates;
pub mod stage;
pub mod subsystem;

pub use build_error::SceneError;
pub use command::{Command, PlayerInput, Target, TickInput};
pub use handle::Handle;
pub use input_file::{InputFileError, MAX_INPUT_FILE_LEN, read_input_file};
pub use lattice::lattice_copies;
pub use metrics::Metrics;
pub use part::Part;
pub use rates::{MAX_SUBSTEPS, MAX_TICK_RATE, check_rates};
pub use stage::Stage;
pub use subsystem::{StepContext, Subsystem};
