//! The viewer: pictures, animations and an interactive page of a run (`fixstep render`).
//!
//! The viewer is an edge: it reads the fixed-point state after each step, converts what it
//! draws to `f64`, and never feeds anything back into the simulation. Data flows one way:
//!
//! world → [`film::capture`] (one small module per subsystem: [`draw_rigid`],
//! [`draw_particles`], and [`draw_trails`] across ticks) → a neutral [`draw_list`] of world-space figures → a [`view`]
//! (orthographic iso, front or top, fitted to the film's bounds) → [`raster`] (tiny-skia,
//! PNG) and [`gif`], or [`html`] (the same figures as JSON for a canvas player).
//!
//! Each subsystem has one `draw_*` module emitting figures ([`Figure::Line`],
//! [`Figure::Polygon`], [`Figure::Dot`] with a [`Paint`]) and one call in
//! [`film::capture`]: rigid bodies, particles (speed scale, over the film), soft bodies
//! (mesh edges), fluids ([`draw_fluid`]: a fixed density scale).
//!
//! Output is deterministic: the same replay gives the same PNG, GIF and HTML bytes (no
//! timestamps; sorting by layer, depth and list order).

// The modules' documentation is for developers and links to private items (read it with
// `cargo doc --document-private-items`, as the test command builds it).
#![allow(rustdoc::private_intra_doc_links)]

pub mod colour;
pub mod draw_fluid;
pub mod draw_joints;
pub mod draw_list;
pub mod draw_particles;
pub mod draw_rigid;
pub mod draw_soft;
pub mod draw_trails;
pub mod draw_water;
pub mod film;
pub mod geometry;
pub mod gif;
pub mod html;
pub mod outputs;
pub mod plane_cut;
pub mod raster;
pub mod view;

pub use draw_list::{Bounds, Figure, Frame, Layer, Paint, Primitive};
pub use draw_rigid::BodyColours;
pub use film::{Film, TooManyFigures, capture};
pub use html::PageSettings;
pub use outputs::{GIF_NAME, PAGE_NAME, Written, frame_name, write_outputs};
pub use raster::{Look, encode_png, rasterise};
pub use view::{Projection, View};
