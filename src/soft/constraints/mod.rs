//! The XPBD constraints, one kind per file. Each kind stores its rows as
//! structure-of-arrays with a Lagrange multiplier λ per row, and solves them in row order
//! (a fixed Gauss–Seidel order) with the update of Macklin et al. 2016:
//!
//! Δλ = (−C − α̃ λ) / (Σᵢ wᵢ |∇ᵢC|² + α̃),  Δxᵢ = wᵢ ∇ᵢC Δλ,  λ ← λ + Δλ,
//!
//! with α̃ = α/h² the compliance α scaled by the substep h. Rows carry μ = α̃λ instead of λ
//! and apply the update as r = −C − μ, Δxᵢ = (wᵢ∇ᵢC/D) r, μ += (α̃/D) r, which is the same
//! update in position units (λ in N·s² is below the fixed-point resolution for light
//! vertices and short substeps). Where D is constant (distance, bending, attachment), the
//! factors are computed once per substep length, so the inner loops do not divide.

mod arithmetic;
mod attachment;
mod bending;
mod colour_runs;
mod distance;
mod tether;
mod volume;

pub(crate) use attachment::Attachments;
pub(crate) use bending::{Hinges, ROW_CHUNK as HINGE_CHUNK};
pub(crate) use colour_runs::ColourRuns;
pub(crate) use distance::{DistanceFactors, Distances, ROW_CHUNK as DISTANCE_CHUNK};
pub(crate) use tether::Tethers;
pub(crate) use volume::Tetrahedra;
