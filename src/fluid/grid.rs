//! A uniform grid of cells half a kernel support wide, filled by counting sort.
//!
//! A point's cell along each axis is found by binary search among the cell edges, so no
//! scalar is ever converted to an integer; points beyond the grid go to its outermost
//! cells, which keeps every pair closer than one support within two cells of each other
//! along each axis. Half-support cells make the 5 × 5 × 5 block around a point 15.6 H³,
//! against 27 H³ for the 3 × 3 × 3 block of support-wide cells, and the search skips the
//! rows and row ends of that block that lie wholly beyond one support.
//! Cells are numbered x fastest, then y, then z; [`CellGrid::fill`] lists the points of
//! each cell in ascending point index (the counting sort is stable), so the order of the
//! entries is the total order (cell, index), the same on every machine.
//! [`CellGrid::locate`] finds the points' cells without sorting them, for the substeps that
//! reuse their candidate lists ([`skin`](super::neighbours::skin)) and need only the order.
//!
//! The cell lists cover only the box of cells the points occupy (its [`Window`]), not the
//! whole grid: a fill costs O(points + cells of that box), so a little water in a large
//! tank pays for the cells it fills, not for the tank's. Cells outside the box are empty.
//! The box changes nothing that a search finds or its order: a row of cells is the same
//! points, clipped to the box.

#[cfg(test)]
mod tests;

use crate::math::{OverReal, Real, Vec3};

/// The most cells [`CellGrid::for_each_within`] reaches from a point's cell along an axis:
/// a radius of 3.5 supports (the searches use 1 and 1.25).
pub const MAX_SPAN: u32 = 7;

/// Cell edges and the points of each cell.
#[derive(Clone, Debug, Default)]
pub struct CellGrid<R: Real> {
    /// The width of a cell, m.
    size: R,
    /// The inner cell edges along x, y and z, ascending: cell c spans
    /// `[edges[c − 1], edges[c])`.
    edges: [Vec<R>; 3],
    /// Cells along x, y and z.
    dims: [u32; 3],
    /// The box of cells holding every point of the last fill, which the cell lists cover.
    window: Window,
    /// `entries[start[k]..start[k + 1]]` are the points of the window's cell k
    /// ([`Window::local`]).
    start: Vec<u32>,
    /// Point indices, by cell then index.
    entries: Vec<u32>,
    /// The cell of each point.
    cell_of: Vec<u32>,
    /// The cell coordinates of each point, while a fill finds the window and sorts the
    /// points into its cells (scratch).
    coords_of: Vec<[u32; 3]>,
}

/// The family of [`CellGrid`] over the scalar formats, for [`Real::as_fixed`].
pub struct CellGridOf;

impl OverReal for CellGridOf {
    type Of<R: Real> = CellGrid<R>;
}

/// A box of cells: `dims` cells along each axis from the cell `lower`; no cell when any
/// of `dims` is zero.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Window {
    lower: [u32; 3],
    dims: [u32; 3],
}

impl Window {
    /// The smallest box holding every cell of `coords` (none for none).
    fn around(coords: impl Iterator<Item = [u32; 3]>) -> Self {
        let mut bounds: Option<([u32; 3], [u32; 3])> = None;
        for c in coords {
            let (lo, hi) = bounds.get_or_insert((c, c));
            for a in 0..3 {
                lo[a] = lo[a].min(c[a]);
                hi[a] = hi[a].max(c[a]);
            }
        }
        match bounds {
            Some((lower, upper)) => Self {
                lower,
                dims: [0, 1, 2].map(|a| upper[a] - lower[a] + 1),
            },
            None => Self::default(),
        }
    }

    /// The number of cells in the box.
    fn len(&self) -> usize {
        self.dims.iter().map(|&d| d as usize).product()
    }

    /// The box's index of the cell `c`, which lies in the box: x fastest, then y, then z,
    /// as the grid numbers its cells.
    #[inline(always)]
    fn local(&self, c: [u32; 3]) -> u32 {
        let [x, y, z] = [0, 1, 2].map(|a| c[a] - self.lower[a]);
        x + self.dims[0] * (y + self.dims[1] * z)
    }

    /// The box's indices of the cells `x` of the row (y, z) that lie in the box, as a
    /// half-open range (empty when none does).
    #[inline(always)]
    fn row(&self, row: &Row) -> core::ops::Range<u32> {
        let [lx, ly, lz] = self.lower;
        let [dx, dy, dz] = self.dims;
        let (y, z) = (row.y.wrapping_sub(ly), row.z.wrapping_sub(lz));
        if y >= dy || z >= dz || row.last_x < lx || row.first_x >= lx + dx {
            return 0..0;
        }
        let first = row.first_x.max(lx) - lx;
        let last = row.last_x.min(lx + dx - 1) - lx;
        let base = dx * (y + dy * z);
        base + first..base + last + 1
    }
}

/// The cells `first_x..=last_x` of the row (y, z) of a grid.
#[derive(Clone, Copy, Debug)]
struct Row {
    y: u32,
    z: u32,
    first_x: u32,
    last_x: u32,
}

impl<R: Real> CellGrid<R> {
    /// A grid of cells `support`/2 wide whose first cell starts at `lower` and whose last
    /// cell ends at or beyond `upper`. The caller bounds the cell count
    /// ([`CellGrid::cells_along`]).
    pub fn new(lower: Vec3<R>, upper: Vec3<R>, support: R) -> Self {
        let size = support * R::HALF;
        let axis = |lo: R, hi: R| {
            let mut edges = Vec::new();
            let mut edge = lo + size;
            while edge < hi {
                edges.push(edge);
                edge += size;
            }
            edges
        };
        let edges = [
            axis(lower.x, upper.x),
            axis(lower.y, upper.y),
            axis(lower.z, upper.z),
        ];
        let dims = edges.each_ref().map(|e| e.len() as u32 + 1);
        Self {
            size,
            edges,
            dims,
            window: Window::default(),
            start: vec![0],
            entries: Vec::new(),
            cell_of: Vec::new(),
            coords_of: Vec::new(),
        }
    }

    /// The number of cells an axis from `lower` to `upper` gets for a kernel support
    /// `support`, for bounding the grid before building it.
    pub fn cells_along(lower: R, upper: R, support: R) -> u64 {
        let size = support * R::HALF;
        let mut count = 1;
        let mut edge = lower + size;
        while edge < upper {
            count += 1;
            edge += size;
        }
        count
    }

    /// The cell coordinates of `p`, clamped to the grid.
    #[inline]
    pub fn coords(&self, p: Vec3<R>) -> [u32; 3] {
        [
            self.edges[0].partition_point(|&e| e <= p.x) as u32,
            self.edges[1].partition_point(|&e| e <= p.y) as u32,
            self.edges[2].partition_point(|&e| e <= p.z) as u32,
        ]
    }

    /// The index of the cell at `c`.
    #[inline(always)]
    pub fn cell_index(&self, c: [u32; 3]) -> u32 {
        c[0] + self.dims[0] * (c[1] + self.dims[1] * c[2])
    }

    /// The fewest cells that span `radius` along an axis: the `span` for which
    /// [`CellGrid::for_each_within`] visits every point closer than `radius` (2 for one
    /// kernel support, the cells being half as wide), if at most [`MAX_SPAN`].
    pub fn span(&self, radius: R) -> u32 {
        let mut span = 1;
        let mut reach = self.size;
        while reach < radius {
            span += 1;
            reach += self.size;
        }
        span
    }

    /// The cell of each point of the last [`CellGrid::fill`] or [`CellGrid::locate`], by
    /// point index.
    #[inline]
    pub fn cells(&self) -> &[u32] {
        &self.cell_of
    }

    /// Finds the cell of each of `points` ([`CellGrid::cells`]) without sorting them: the
    /// cell lists keep the points of the last [`CellGrid::fill`].
    pub fn locate(&mut self, points: &[Vec3<R>]) {
        self.cell_of.clear();
        for &p in points {
            let c = self.coords(p);
            self.cell_of.push(self.cell_index(c));
        }
    }

    /// Sorts `points` into their cells by counting sort, over the box of cells they occupy
    /// ([`Window`]): O(points + cells of that box), no comparison.
    pub fn fill(&mut self, points: &[Vec3<R>]) {
        self.cell_of.clear();
        self.coords_of.clear();
        for &p in points {
            let c = self.coords(p);
            self.cell_of.push(self.cell_index(c));
            self.coords_of.push(c);
        }
        self.window = Window::around(self.coords_of.iter().copied());
        let window = self.window;
        self.start.clear();
        self.start.resize(window.len() + 1, 0);
        for &c in &self.coords_of {
            self.start[window.local(c) as usize + 1] += 1;
        }
        for c in 1..self.start.len() {
            self.start[c] += self.start[c - 1];
        }
        self.entries.clear();
        self.entries.resize(points.len(), 0);
        // Each cell's next free entry, in the first `start.len() − 1` slots of a cursor run
        // over `start` itself: place, then restore the starts by shifting back.
        for (index, &c) in self.coords_of.iter().enumerate() {
            let at = &mut self.start[window.local(c) as usize];
            self.entries[*at as usize] = index as u32;
            *at += 1;
        }
        for c in (1..self.start.len()).rev() {
            self.start[c] = self.start[c - 1];
        }
        self.start[0] = 0;
    }

    /// Calls `visit` with the points of every cell that may hold a point closer than a
    /// radius ρ to `p` (`inv_radius` = 1/ρ, `span` = [`CellGrid::span`] of ρ: 2 for ρ = H,
    /// at most [`MAX_SPAN`]): of the cells within `span` of p's cell along each axis (125
    /// for a span of 2), the rows whose nearest y and z distances to p already reach ρ are
    /// skipped, and each remaining row is trimmed at both ends the same way along x. Cells
    /// come in ascending index, points in ascending index within each cell: one slice per
    /// row, whose cells are contiguous, and none for a row whose cells are empty.
    /// Distances are measured in radii (scaled before squaring, once per cell coordinate)
    /// and compared with 1 + 2⁻⁸, so rounding never skips a cell it must visit.
    #[inline]
    pub fn for_each_within(
        &self,
        p: Vec3<R>,
        inv_radius: R,
        span: u32,
        mut visit: impl FnMut(&[u32]),
    ) {
        self.for_each_row_within(p, inv_radius, span, |row| {
            let points = self.points_in(&row);
            if !points.is_empty() {
                visit(points);
            }
        });
    }

    /// [`CellGrid::for_each_within`] in this grid and in `other`, which has the same cells
    /// ([`CellGrid::same_cells`]), at once: `visit(0, points)` for this grid's points of a
    /// row, then `visit(1, points)` for `other`'s, row by row. Each grid's slices are those
    /// its own [`CellGrid::for_each_within`] gives, in the same order; the cells, the gaps
    /// and the rows within reach, which depend on the cells alone, are found once.
    #[inline]
    pub fn for_each_within_both(
        &self,
        other: &Self,
        p: Vec3<R>,
        inv_radius: R,
        span: u32,
        mut visit: impl FnMut(usize, &[u32]),
    ) {
        self.for_each_row_within(p, inv_radius, span, |row| {
            for (k, grid) in [self, other].into_iter().enumerate() {
                let points = grid.points_in(&row);
                if !points.is_empty() {
                    visit(k, points);
                }
            }
        });
    }

    /// Whether `other` has the same cells (width and edges along each axis) as this grid,
    /// so that a cell index means the same cell in both and a search visits the same ones.
    pub fn same_cells(&self, other: &Self) -> bool {
        self.size == other.size && self.edges == other.edges
    }

    /// The points of the cells of `row` (those outside the window hold none).
    #[inline(always)]
    fn points_in(&self, row: &Row) -> &[u32] {
        let cells = self.window.row(row);
        let first = self.start[cells.start as usize] as usize;
        let last = self.start[cells.end as usize] as usize;
        &self.entries[first..last]
    }

    /// The rows of cells that [`CellGrid::for_each_within`] visits, in ascending order of
    /// cell index.
    #[inline(always)]
    fn for_each_row_within(
        &self,
        p: Vec3<R>,
        inv_radius: R,
        span: u32,
        mut visit: impl FnMut(Row),
    ) {
        let span = span.min(MAX_SPAN);
        let c = self.coords(p);
        let lo = c.map(|v| v.saturating_sub(span));
        let hi = [0, 1, 2].map(|a| c[a].saturating_add(span).min(self.dims[a] - 1));
        let reach = R::ONE + R::from_ratio(1, 256);
        let coordinate = [p.x, p.y, p.z];
        // The squared distance, in radii, from p to each cell from lo to hi along each
        // axis (0 inside).
        let mut gaps = [[R::ZERO; 2 * MAX_SPAN as usize + 1]; 3];
        for (axis, gaps) in gaps.iter_mut().enumerate() {
            let edges = &self.edges[axis];
            let x = coordinate[axis];
            for (cell, g2) in (lo[axis]..=hi[axis]).zip(gaps.iter_mut()) {
                let gap = if cell < c[axis] {
                    x - edges[cell as usize]
                } else if cell > c[axis] {
                    edges[cell as usize - 1] - x
                } else {
                    continue;
                };
                let g = gap * inv_radius;
                *g2 = g * g;
            }
        }
        let gap2 = |axis: usize, cell: u32| gaps[axis][(cell - lo[axis]) as usize];
        for z in lo[2]..=hi[2] {
            let gz = gap2(2, z);
            if gz > reach {
                continue;
            }
            for y in lo[1]..=hi[1] {
                let gyz = gz + gap2(1, y);
                if gyz > reach {
                    continue;
                }
                let mut first_x = lo[0];
                while first_x < c[0] && gyz + gap2(0, first_x) > reach {
                    first_x += 1;
                }
                let mut last_x = hi[0];
                while last_x > c[0] && gyz + gap2(0, last_x) > reach {
                    last_x -= 1;
                }
                visit(Row {
                    y,
                    z,
                    first_x,
                    last_x,
                });
            }
        }
    }
}
