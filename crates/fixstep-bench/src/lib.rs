//! Benchmarks of the integrators: accuracy against exact solutions and stability limits.
//!
//! This is reporting code, run by `fixstep bench accuracy` and `fixstep bench stability`.
//! The simulations themselves use the engine's
//! [`ParticleSystem`](fixstep::particles::ParticleSystem) in each
//! [`Real`](fixstep::math::Real) format; reference solutions, errors, timings and plots are
//! computed in `f64` and never feed back into a simulation.
//!
//! # Files
//!
//! [`format`](mod@format) the number formats · [`exact`] closed-form solutions ·
//! [`kepler_equation`] the Kepler reference · [`elliptic`] the pendulum period ·
//! [`pendulum_force`] the pendulum as a user force · [`problems`] the five problems ·
//! [`sweep`] the timed accuracy sweep · [`cloth`] implicit against semi-implicit Euler on a
//! stiff cloth · [`order`] measured orders of convergence · `plot`
//! the work-precision SVG · [`stability`] stability limits · `report` CSV files and printed
//! tables.

// ok-det: the benchmark module (reporting code); f64 appears only in reference solutions, errors, timings and plots, never in a tick.
// The modules' documentation is for developers and links to private items (read it with
// `cargo doc --document-private-items`, as the test command builds it).
#![allow(rustdoc::private_intra_doc_links)]

pub mod cloth;
pub mod elliptic;
pub mod exact;
pub mod format;
pub mod kepler_equation;
pub mod order;
pub mod pendulum_force;
mod plot;
pub mod problems;
mod report;
pub mod stability;
pub mod sweep;

pub use cloth::{ClothRow, cloth_table, run_cloth};
pub use format::NumberFormat;
pub use order::{Distrust, MeasuredOrder, OrderRow, measured_orders};
pub use plot::work_precision_svg;
pub use problems::{Outcome, Problem};
pub use report::{accuracy_csv, floors_table, orders_table, stability_csv, stability_table};
pub use stability::{
    Measured, StabilityConfig, StabilityRow, Theory, run_stability, run_stability_with_progress,
};
pub use sweep::{AccuracyConfig, AccuracyRow, run_accuracy, run_accuracy_with_progress};
