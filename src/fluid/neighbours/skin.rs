//! Candidate lists with a skin (Verlet lists), from which the neighbour lists of several
//! substeps are evaluated without searching the grid again.
//!
//! # What is reused, and why the lists are the same
//!
//! A build records, for every fluid particle i, the candidates j of its fluid and boundary
//! neighbours closer than ρ = (1 + σ) H (σ = [`SKIN`] of the support H) at the particles'
//! positions aᵢ then (the anchors). A later substep reuses the candidates while every
//! fluid particle is within δ = (σ/2 − 2⁻⁸) H of its anchor, its particle count unchanged
//! (boundary particles never move), and evaluates each candidate with the same test and
//! the same kernel values as a fresh search ([`NeighbourLists::evaluate`]); the build
//! evaluates each candidate as it finds it, in the same order, with the same values
//! ([`NeighbourLists::build_keeping_candidates`]: one pass of the grid). Then:
//!
//! - **the same pairs.** A pair the kernel accepts now lies within H(1 + 2⁻¹⁰) (the
//!   test compares rounded values; every rounding is far below 2⁻¹⁰ of H in each format),
//!   so at the anchors it lay within H(1 + 2⁻¹⁰) + 2δ < ρ (1 − 2⁻¹⁰), where the rounded
//!   candidate test, measured in radii ρ like the kernel's in supports, accepted it. Every
//!   pair the kernel accepts is a candidate, and the candidates it rejects are dropped, as
//!   a fresh search drops the grid's other points;
//! - **the same order.** A fresh search lists a row's neighbours by (cell, index) of the
//!   current positions ([`CellGrid::for_each_within`]). A build lists the candidates in
//!   that order; each reusing substep locates the fluid particles' cells
//!   ([`CellGrid::locate`]) and re-sorts the fluid rows whose order the motion changed
//!   ([`CandidateRows::order_by_cells`]), a pass over each row when nothing moved to
//!   another cell. The boundary rows keep their order, as the boundary never moves;
//! - **the same values.** Each pair's V₀W and V₀∇W come from the same offset through the
//!   same operations.
//!
//! Nothing here is state: validity is a property of the current positions against the
//! anchors, whatever happened in between (a restore, a clone, a jump), and a skipped reuse
//! only costs a search. The lists equal a fresh search's in every substep, so no result
//! depends on when the candidates were built.

#[cfg(test)]
mod tests;

use super::NeighbourLists;
use crate::fluid::grid::CellGrid;
use crate::fluid::kernel::Kernel;
use crate::math::{Real, Vec3};

/// The skin σ, in supports: candidates are sought within (1 + σ) H. A quarter support
/// (5 mm at H = 2 cm) measured fastest on the benchmark cube (docs/PERFORMANCE.md).
pub const SKIN: (i64, i64) = (1, 4);

// 1/64 ≤ σ ≤ 1: δ = (σ/2 − 2⁻⁸) H is positive, the margin H + 2δ < ρ (1 − 2⁻¹⁰) − 2⁻¹⁰ H
// of the module documentation holds, and ρ ≤ 2H spans at most 5 grid cells of H/2
// (rounding included), within the grid's [`MAX_SPAN`](crate::fluid::grid::MAX_SPAN).
const _: () = assert!(SKIN.1 <= 64 * SKIN.0 && SKIN.0 <= SKIN.1);

/// Candidate neighbours of each query, as compressed rows: the candidates of query i are
/// `index[start[i]..start[i + 1]]`.
#[derive(Clone, Debug, Default)]
pub struct CandidateRows {
    /// Row starts, one per query plus one.
    start: Vec<u32>,
    /// Candidate indices into the searched points.
    index: Vec<u32>,
}

impl CandidateRows {
    /// The number of rows (queries).
    #[inline]
    pub fn len(&self) -> usize {
        self.start.len().saturating_sub(1)
    }

    /// Whether there is no row.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The candidates of query `i`.
    #[inline(always)]
    pub fn row(&self, i: usize) -> &[u32] {
        &self.index[self.start[i] as usize..self.start[i + 1] as usize]
    }

    /// Sorts every row by (`cells[j]`, j), the order of a fresh search over a grid whose
    /// points lie in `cells`; a row already in that order (one pass to check) is left.
    pub fn order_by_cells(&mut self, cells: &[u32]) {
        let key = |&j: &u32| (cells[j as usize], j);
        for i in 0..self.len() {
            let row = &mut self.index[self.start[i] as usize..self.start[i + 1] as usize];
            if !row.is_sorted_by_key(key) {
                row.sort_unstable_by_key(key);
            }
        }
    }

    /// Empties the rows, leaving the start of the first.
    pub(super) fn clear(&mut self) {
        self.start.clear();
        self.index.clear();
        self.start.push(0);
    }

    /// Appends the candidates `candidates` to the current row (the vector search's way).
    #[cfg(vector_kernels)]
    #[inline(always)]
    pub(super) fn extend(&mut self, candidates: impl IntoIterator<Item = u32>) {
        self.index.extend(candidates);
    }

    /// Closes the current row.
    #[inline(always)]
    pub(super) fn end_row(&mut self) {
        self.start.push(self.index.len() as u32);
    }
}

/// The candidate radius ρ = (1 + σ) H and what the search and the reuse test derive from
/// it. The default reaches nothing and holds no particle.
#[derive(Clone, Copy, Debug, Default)]
pub struct Reach<R: Real> {
    /// ρ, m.
    pub radius: R,
    /// 1/ρ, 1/m.
    pub inv_radius: R,
    /// The grid cells ρ spans along an axis ([`CellGrid::span`]).
    pub span: u32,
    /// 1/H, 1/m.
    inv_support: R,
    /// (δ/H)² = (σ/2 − 2⁻⁸)²: the squared displacement from the anchor, in supports, at
    /// which the candidates may miss a pair.
    limit: R,
}

impl<R: Real> Reach<R> {
    /// The reach of `kernel` with the skin [`SKIN`], over the cells of `grid`.
    pub fn new(kernel: &Kernel<R>, grid: &CellGrid<R>) -> Self {
        let (num, den) = SKIN;
        let radius = kernel.support + kernel.support * R::from_ratio(num, den);
        let half_skin = R::from_ratio(num, 2 * den) - R::from_ratio(1, 256);
        Self {
            radius,
            inv_radius: radius.recip(),
            span: grid.span(radius),
            inv_support: kernel.inv_support,
            limit: half_skin * half_skin,
        }
    }

    /// Whether `offset` = xᵢ − xⱼ is within ρ, tested as [`Kernel::evaluate`] tests the
    /// support: every component below ρ, then |offset/ρ|² < 1.
    #[inline(always)]
    pub fn contains(&self, offset: Vec3<R>) -> bool {
        let r = self.radius;
        if offset.x.abs() >= r || offset.y.abs() >= r || offset.z.abs() >= r {
            return false;
        }
        (offset * self.inv_radius).length_squared() < R::ONE
    }

    /// Whether a particle at `position` is still close enough to its anchor `anchor`:
    /// |(x − a)/H|² below the limit (false for anything that does not compare below it).
    #[inline(always)]
    fn holds(&self, position: Vec3<R>, anchor: Vec3<R>) -> bool {
        ((position - anchor) * self.inv_support).length_squared() < self.limit
    }
}

/// The candidates of a fluid's neighbour lists, fluid and boundary, with the positions
/// they were found at: see the [module documentation](self).
#[derive(Clone, Debug, Default)]
pub struct SkinLists<R: Real> {
    /// Fluid candidates of each fluid particle.
    pub fluid: CandidateRows,
    /// Boundary candidates of each fluid particle.
    pub walls: CandidateRows,
    /// The fluid particles' positions at the build (m); empty before the first.
    anchors: Vec<Vec3<R>>,
    /// Whether the rows were built for these anchors.
    built: bool,
}

impl<R: Real> SkinLists<R> {
    /// Whether the candidates hold every pair a fresh search would find for fluid
    /// particles at `positions`: built, with as many particles, each within δ of its
    /// anchor.
    pub fn covers(&self, positions: &[Vec3<R>], reach: &Reach<R>) -> bool {
        self.built
            && self.anchors.len() == positions.len()
            && positions
                .iter()
                .zip(&self.anchors)
                .all(|(&x, &a)| reach.holds(x, a))
    }

    /// Whether candidates built now can serve the next substep too, for fluid particles
    /// moving at `velocities` (m/s) over substeps of `h` seconds: every particle would stay
    /// within δ of its anchor even if it moved 2|v|h, twice its current speed's
    /// displacement (the margin covers a substep's acceleration). Otherwise the next
    /// substep would search again anyway, and a search within the support alone is
    /// cheaper than one within the candidate radius.
    ///
    /// (2 h |v|_max / H)² < (δ/H)², with |v|²_max the largest squared speed.
    pub fn may_last(&self, velocities: &[Vec3<R>], h: R, reach: &Reach<R>) -> bool {
        let fastest = velocities
            .iter()
            .map(|v| v.length_squared())
            .fold(R::ZERO, R::max);
        let reach_per_speed = (h + h) * reach.inv_support;
        fastest * (reach_per_speed * reach_per_speed) < reach.limit
    }

    /// Forgets the candidates (after the lists were found without them).
    pub fn discard(&mut self) {
        self.built = false;
    }

    /// Finds the candidates of the fluid particles at `positions` (sorted into `grid`)
    /// among themselves and among the boundary particles `boundary` (sorted into
    /// `boundary_grid`), anchors them there, and finds from the same pass of the grid the
    /// neighbour lists `fluid_lists` and `wall_lists` of these positions
    /// ([`NeighbourLists::build_keeping_candidates`]).
    #[allow(clippy::too_many_arguments)]
    pub fn build(
        &mut self,
        positions: &[Vec3<R>],
        grid: &CellGrid<R>,
        boundary: &[Vec3<R>],
        boundary_grid: &CellGrid<R>,
        reach: &Reach<R>,
        kernel: &Kernel<R>,
        [fluid_lists, wall_lists]: [&mut NeighbourLists<R>; 2],
    ) {
        let fluid = (positions, grid);
        fluid_lists.build_keeping_candidates(
            &mut self.fluid,
            positions,
            fluid,
            reach,
            kernel,
            true,
        );
        let walls = (boundary, boundary_grid);
        wall_lists.build_keeping_candidates(
            &mut self.walls,
            positions,
            walls,
            reach,
            kernel,
            false,
        );
        self.anchors.clear();
        self.anchors.extend_from_slice(positions);
        self.built = true;
    }
}

impl<R: Real> NeighbourLists<R> {
    /// The lists [`NeighbourLists::build`] would find for `queries` among `points`, from
    /// `candidates` that hold every pair the kernel accepts, in the order it would list
    /// them: the candidates that pass [`Kernel::evaluate`], in order, with its values.
    ///
    /// In I32F32 on x86-64 with AVX-512 or AVX2 eight candidates at a time, with the same lists
    /// as [`NeighbourLists::evaluate_scalar`] bit for bit.
    pub fn evaluate(
        &mut self,
        candidates: &CandidateRows,
        queries: &[Vec3<R>],
        points: &[Vec3<R>],
        kernel: &Kernel<R>,
    ) {
        #[cfg(vector_kernels)]
        if super::kernel::evaluate(self, candidates, queries, points, kernel) {
            return;
        }
        self.evaluate_scalar(candidates, queries, points, kernel);
    }

    /// [`NeighbourLists::evaluate`], one candidate after another.
    pub fn evaluate_scalar(
        &mut self,
        candidates: &CandidateRows,
        queries: &[Vec3<R>],
        points: &[Vec3<R>],
        kernel: &Kernel<R>,
    ) {
        self.clear();
        for (i, &xi) in queries.iter().enumerate() {
            for &j in candidates.row(i) {
                if let Some((value, gradient)) = kernel.evaluate(xi - points[j as usize]) {
                    self.push(j, value, gradient);
                }
            }
            self.start.push(self.index.len() as u32);
        }
    }

    /// The lists [`NeighbourLists::build`] finds for `queries` among `points` (sorted into
    /// `grid`: the pair `searched`), and in `candidates` every point within the candidate
    /// radius ρ of each query ([`Reach::contains`], the query itself left out when
    /// `skip_self`), in the grid's order (cell, index): the rows a later substep evaluates.
    ///
    /// One pass over the grid within ρ: each query's candidates are selected, then
    /// evaluated with [`Kernel::evaluate`] while the row is fresh in cache, so the lists are
    /// those [`NeighbourLists::evaluate`] finds from the candidates (the same candidates in
    /// the same order, the same offsets through the same operations), which are the fresh
    /// search's (module documentation). In I32F32 on x86-64 with AVX-512 or AVX2 the candidates
    /// are selected, then evaluated, eight at a time, with the same rows and lists as
    /// [`NeighbourLists::build_keeping_candidates_scalar`] bit for bit.
    pub fn build_keeping_candidates(
        &mut self,
        candidates: &mut CandidateRows,
        queries: &[Vec3<R>],
        searched: (&[Vec3<R>], &CellGrid<R>),
        reach: &Reach<R>,
        kernel: &Kernel<R>,
        skip_self: bool,
    ) {
        #[cfg(vector_kernels)]
        {
            let (points, grid) = searched;
            if super::kernel::select(candidates, queries, points, grid, reach, skip_self) {
                self.evaluate(candidates, queries, points, kernel);
                return;
            }
        }
        self.build_keeping_candidates_scalar(
            candidates, queries, searched, reach, kernel, skip_self,
        );
    }

    /// [`NeighbourLists::build_keeping_candidates`], one point after another. The test at
    /// ρ stores every point in the row and keeps it by advancing the row's end, with no
    /// branch on the outcome (which is a coin toss: about half the points of the cells
    /// visited are candidates); the kernel then evaluates the query's row. A candidate's
    /// offset is below ρ along each axis, so computing it a second time saturates nothing
    /// and the saturation counter reads as after a selection and an evaluation.
    pub fn build_keeping_candidates_scalar(
        &mut self,
        candidates: &mut CandidateRows,
        queries: &[Vec3<R>],
        (points, grid): (&[Vec3<R>], &CellGrid<R>),
        reach: &Reach<R>,
        kernel: &Kernel<R>,
        skip_self: bool,
    ) {
        self.clear();
        candidates.clear();
        for (i, &xi) in queries.iter().enumerate() {
            grid.for_each_within(xi, reach.inv_radius, reach.span, |near| {
                let row = &mut candidates.index;
                let first = row.len();
                row.resize(first + near.len(), 0);
                let mut end = first;
                for &j in near {
                    row[end] = j;
                    let selected =
                        !(skip_self && j as usize == i) && reach.contains(xi - points[j as usize]);
                    end += usize::from(selected);
                }
                row.truncate(end);
            });
            candidates.end_row();
            for &j in candidates.row(i) {
                if let Some((value, gradient)) = kernel.evaluate(xi - points[j as usize]) {
                    self.push(j, value, gradient);
                }
            }
            self.start.push(self.index.len() as u32);
        }
    }
}
