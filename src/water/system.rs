//! The water surface's state: its settings, the height of every cell and the flow across
//! every inner edge between cells.

use serde::{Deserialize, Serialize};

use super::desc::{WaterBodiesDesc, WaterBorder, WaterParticleFloat};
use crate::math::{Fx, Real, Vec3};

/// The surface's settings, checked and resolved from its [`WaterDesc`](super::WaterDesc).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct WaterSettings<R: Real = Fx> {
    /// The grid's corner at its lowest x and z, at the rest level (y), m.
    pub origin: Vec3<R>,
    /// Columns of cells along x.
    pub columns: u32,
    /// Rows of cells along z.
    pub rows: u32,
    /// The side of a cell, m.
    pub cell_size: R,
    /// The still water's depth, m.
    pub depth: R,
    /// The wave speed c, m/s.
    pub wave_speed: R,
    /// Damping rate of the flow, 1/s.
    pub damping: R,
    /// Density ρ, kg/m³.
    pub density: R,
    /// What the edges do to waves.
    pub border: WaterBorder,
    /// Wave steps per world substep, so that c · h / cell_size ≤ 1/2.
    pub substeps: u32,
    /// The particle groups that float.
    pub particles: Vec<WaterParticleFloat<R>>,
    /// The rigid bodies that float.
    pub bodies: Option<WaterBodiesDesc<R>>,
}

/// A height-field water surface: the linear shallow-water equations on a grid of square
/// cells, which together are the wave equation ∂²u/∂t² = c²∇²u ([`super::waves`]).
///
/// Cell (i, k) (column i along x, row k along z) is slot `i + columns · k`; its centre is
/// at `origin + ((i + ½) s, 0, (k + ½) s)` for the cell size s.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct WaterSystem<R: Real = Fx> {
    pub(super) settings: WaterSettings<R>,
    /// u, each cell's surface height above the rest level, m.
    pub(super) heights: Vec<R>,
    /// q, the flow across the edge between cells (i, k) and (i + 1, k), per metre of edge,
    /// m²/s, positive towards +x; slot `i + (columns − 1) · k`.
    pub(super) flow_x: Vec<R>,
    /// q, the flow across the edge between cells (i, k) and (i, k + 1), m²/s, positive
    /// towards +z; slot `i + columns · k`.
    pub(super) flow_z: Vec<R>,
    /// The kernel's rows of transfers (not state).
    #[serde(skip)]
    pub(super) scratch: WaveScratch,
}

/// The rows of transfers of the wave step's kernel (`waves/kernel.rs`), reused from step
/// to step. Not state: a clone starts empty, and any two compare equal.
#[derive(Debug, Default)]
pub(crate) struct WaveScratch {
    /// The transfers of a row's x edges, each one slot after its left cell, m (n + 1).
    #[cfg_attr(not(vector_kernels), allow(dead_code))]
    pub x: Vec<Fx>,
    /// The transfers of the z edges from the previous row into this one, m (n + 1).
    #[cfg_attr(not(vector_kernels), allow(dead_code))]
    pub previous: Vec<Fx>,
    /// The transfers of the z edges from this row into the next, m (n + 1).
    #[cfg_attr(not(vector_kernels), allow(dead_code))]
    pub next: Vec<Fx>,
}

impl Clone for WaveScratch {
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl PartialEq for WaveScratch {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl<R: Real> WaterSystem<R> {
    /// The settings.
    pub fn settings(&self) -> &WaterSettings<R> {
        &self.settings
    }

    /// Every cell's height above the rest level, m, by slot (`i + columns · k`).
    pub fn heights(&self) -> &[R] {
        &self.heights
    }

    /// The volume of water above the rest level (negative below it), m³: Σu · s².
    pub fn volume(&self) -> R {
        let s = self.settings.cell_size;
        self.heights.iter().fold(R::ZERO, |sum, &u| sum + u) * (s * s)
    }

    /// The sum of the heights as exact integers (raw bits), which the wave step keeps
    /// unchanged under reflective borders ([`super::waves`]).
    pub fn height_bits_sum(&self) -> i128 {
        self.heights
            .iter()
            .map(|u| i128::from(u.canonical_bits() as i64))
            .sum()
    }

    /// The surface's y at horizontal position (x, z), m: the rest level plus the bilinear
    /// interpolation of the heights at the four nearest cell centres (clamped to the grid;
    /// outside it, the nearest edge's height). `None` outside the grid's footprint.
    pub fn surface_at(&self, x: R, z: R) -> Option<R> {
        let s = &self.settings;
        let (fx, fz) = (
            (x - s.origin.x) / s.cell_size,
            (z - s.origin.z) / s.cell_size,
        );
        let inside = |f: R, n: u32| f >= R::ZERO && f <= R::from_int(n as i32);
        if !inside(fx, s.columns) || !inside(fz, s.rows) {
            return None;
        }
        let half = R::from_ratio(1, 2);
        let (i0, tx) = cell_below(fx - half, s.columns);
        let (k0, tz) = cell_below(fz - half, s.rows);
        let i1 = (i0 + 1).min(s.columns as usize - 1);
        let k1 = (k0 + 1).min(s.rows as usize - 1);
        let n = s.columns as usize;
        let u = |i: usize, k: usize| self.heights[i + n * k];
        let lerp = |a: R, b: R, t: R| a + (b - a) * t;
        let near = lerp(u(i0, k0), u(i1, k0), tx);
        let far = lerp(u(i0, k1), u(i1, k1), tx);
        Some(s.origin.y + lerp(near, far, tz))
    }
}

/// For a coordinate `f` in cells and a grid of `n` cells, the cell index below it clamped
/// to `0..n` and the fraction past it, clamped to 0..1: ⌊f⌋ and f − ⌊f⌋, by binary search
/// over the integers (no float, no conversion).
pub(super) fn cell_below<R: Real>(f: R, n: u32) -> (usize, R) {
    if f <= R::ZERO {
        return (0, R::ZERO);
    }
    let (mut lo, mut hi) = (0u32, n);
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if R::from_int(mid as i32) <= f {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let t = (f - R::from_int(lo as i32)).clamp(R::ZERO, R::ONE);
    (lo as usize, t)
}
