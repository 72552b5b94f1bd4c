//! Neighbour lists with their kernel values, built once per substep and read by every
//! pass and solver iteration of that substep.
//!
//! The lists are compressed rows: the neighbours of fluid particle i are entries
//! `start[i]..start[i + 1]`, in the grid's order (cell, then index), which is the same on
//! every machine. Each entry keeps the neighbour's index, V₀W and V₀∇ᵢW (see
//! [`kernel`](super::kernel)), so the square root of a pair is taken once per substep.
//!
//! A fresh search of the grid ([`NeighbourLists::build`]) defines the lists. The step
//! finds the same lists, bit for bit and in the same order, from candidate lists with a
//! skin that several substeps reuse ([`skin`], [`NeighbourLists::evaluate`]); the substep
//! that finds new candidates evaluates them in the same pass of the grid
//! ([`NeighbourLists::build_keeping_candidates`]).

#[cfg(vector_kernels)]
mod kernel;
pub mod skin;
#[cfg(test)]
mod tests;

use super::grid::CellGrid;
use super::kernel::Kernel;
use crate::math::{OverReal, Real, Vec3};

/// Neighbours of each fluid particle among one set of points (fluid or boundary).
#[derive(Clone, Debug, Default)]
pub struct NeighbourLists<R: Real> {
    /// Row starts, one per fluid particle plus one.
    pub start: Vec<u32>,
    /// Neighbour indices into the searched set.
    pub index: Vec<u32>,
    /// V₀W of each pair (dimensionless).
    pub value: Vec<R>,
    /// V₀∇ᵢW of each pair, 1/m, by component (x, y, z): structure of arrays, which the
    /// vector kernels of [`row_sums`](super::row_sums) load as it is.
    pub gradients: [Vec<R>; 3],
}

/// The family of [`NeighbourLists`] over the scalar formats, for
/// [`Real::as_fixed`].
pub struct NeighbourListsOf;

impl OverReal for NeighbourListsOf {
    type Of<R: Real> = NeighbourLists<R>;
}

impl<R: Real> NeighbourLists<R> {
    /// The number of particles listed (rows).
    #[inline]
    pub fn len(&self) -> usize {
        self.start.len().saturating_sub(1)
    }

    /// Whether no particle is listed.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The entries of particle `i`: `start[i]..start[i + 1]`.
    #[inline(always)]
    pub fn range(&self, i: usize) -> core::ops::Range<usize> {
        self.start[i] as usize..self.start[i + 1] as usize
    }

    /// V₀∇ᵢW of entry `e`, 1/m.
    #[inline(always)]
    pub fn gradient(&self, e: usize) -> Vec3<R> {
        let [x, y, z] = &self.gradients;
        Vec3::new(x[e], y[e], z[e])
    }

    /// Finds, for each of `queries`, every point of `points` (sorted into `grid`) closer
    /// than the kernel support, except the query itself when `skip_self` (the queries are
    /// the points).
    ///
    /// In I32F32 on x86-64 with AVX-512 or AVX2 the candidates are tested, and the
    /// survivors' kernel values computed, eight at a time ([`kernel`]), with the same lists as
    /// [`NeighbourLists::build_scalar`] bit for bit.
    pub fn build(
        &mut self,
        queries: &[Vec3<R>],
        points: &[Vec3<R>],
        grid: &CellGrid<R>,
        kernel: &Kernel<R>,
        skip_self: bool,
    ) {
        #[cfg(vector_kernels)]
        if kernel::build(self, queries, points, grid, kernel, skip_self) {
            return;
        }
        self.build_scalar(queries, points, grid, kernel, skip_self);
    }

    /// [`NeighbourLists::build`] of `fluid`, the neighbours of the `positions` among
    /// themselves (sorted into `grid`, each particle skipping itself), and of `walls`,
    /// their neighbours among the `boundary` points (sorted into `boundary_grid`): the
    /// same lists. Where the vector search runs and both grids have the same cells, one
    /// walk of the cells serves both searches (the cells around each particle, their
    /// distances and the rows within reach are found once).
    pub fn build_both(
        [fluid, walls]: [&mut Self; 2],
        positions: &[Vec3<R>],
        grid: &CellGrid<R>,
        (boundary, boundary_grid): (&[Vec3<R>], &CellGrid<R>),
        kernel: &Kernel<R>,
    ) {
        #[cfg(vector_kernels)]
        if kernel::build_both(
            [&mut *fluid, &mut *walls],
            positions,
            [(positions, grid), (boundary, boundary_grid)],
            kernel,
        ) {
            return;
        }
        fluid.build(positions, positions, grid, kernel, true);
        walls.build(positions, boundary, boundary_grid, kernel, false);
    }

    /// [`NeighbourLists::build`], one candidate after another with [`Kernel::evaluate`].
    pub fn build_scalar(
        &mut self,
        queries: &[Vec3<R>],
        points: &[Vec3<R>],
        grid: &CellGrid<R>,
        kernel: &Kernel<R>,
        skip_self: bool,
    ) {
        self.search(queries, (points, grid), kernel, skip_self, |_| true);
    }

    /// [`NeighbourLists::build_scalar`] for the queries that `wanted` accepts; the others
    /// get empty rows without a search (the particles far from every rigid body).
    pub fn build_where(
        &mut self,
        queries: &[Vec3<R>],
        points: &[Vec3<R>],
        grid: &CellGrid<R>,
        kernel: &Kernel<R>,
        wanted: impl Fn(Vec3<R>) -> bool,
    ) {
        self.search(queries, (points, grid), kernel, false, wanted);
    }

    /// The scalar search behind both: each query `wanted` accepts looks through the cells
    /// of `grid` around it (skipping itself when `skip_self`); every query gets a row.
    fn search(
        &mut self,
        queries: &[Vec3<R>],
        (points, grid): (&[Vec3<R>], &CellGrid<R>),
        kernel: &Kernel<R>,
        skip_self: bool,
        wanted: impl Fn(Vec3<R>) -> bool,
    ) {
        self.clear();
        let span = grid.span(kernel.support);
        for (i, &xi) in queries.iter().enumerate() {
            if wanted(xi) {
                grid.for_each_within(xi, kernel.inv_support, span, |candidates| {
                    for &j in candidates {
                        if skip_self && j as usize == i {
                            continue;
                        }
                        if let Some((value, gradient)) = kernel.evaluate(xi - points[j as usize]) {
                            self.push(j, value, gradient);
                        }
                    }
                });
            }
            self.start.push(self.index.len() as u32);
        }
    }

    /// Empties the lists, leaving the start of the first row.
    fn clear(&mut self) {
        self.start.clear();
        self.index.clear();
        self.value.clear();
        for g in &mut self.gradients {
            g.clear();
        }
        self.start.push(0);
    }

    /// Appends an entry to the current row.
    #[inline(always)]
    fn push(&mut self, j: u32, value: R, gradient: Vec3<R>) {
        self.index.push(j);
        self.value.push(value);
        self.gradients[0].push(gradient.x);
        self.gradients[1].push(gradient.y);
        self.gradients[2].push(gradient.z);
    }
}
