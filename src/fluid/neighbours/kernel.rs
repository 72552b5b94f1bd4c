//! The neighbour search on the lanes of [`Wide`] for I32F32, one kernel for every backend:
//! eight candidates side by side through the support test, the survivors packed in order,
//! then eight survivors side by side through the kernel's value and gradient.
//!
//! Three searches share it: a fresh search of the grid ([`build`]; [`build_both`] runs
//! the fluid's and the boundary's in one walk of the cells), the evaluation of
//! candidate rows ([`evaluate`], see [`skin`](super::skin)) and the selection of those
//! candidates ([`select`]: the support test alone, at the candidate radius ρ in place of
//! H, which the bounds below then concern; its rows are the candidates of
//! [`NeighbourLists::build_keeping_candidates_scalar`]).
//!
//! # Same lists
//!
//! For each candidate j of query i the kernel computes, modulo 2⁶⁴, what
//! [`Kernel::evaluate`] computes: the offset o = xᵢ − xⱼ, the test |o_c| < H on each
//! component, d = o · (1/H) and q² = d_x² + d_y² + d_z², and keeps j when all of it passes
//! and q² < 1 (and j ≠ i when the queries are the points); then, for the survivors, the
//! square root q = √q², t = 1 − q, t³ = t·t·t, V₀W = c_w ((t³·t)(1 + 4q)) and
//! V₀∇W = d · (−(c_g t³)), each product rounded as the checked `*`. Before it starts it
//! checks that every coordinate of the queries and points is at most 2⁶⁰ in magnitude (as
//! raw bits), that 0 < H < 2³¹ and 0 < 1/H < 2⁶⁰, and that c_w and c_g are positive and
//! below 2⁵⁵ (2.7·10⁴ at most in a valid scene: 2⁴⁷). Then:
//!
//! - o is exact (below 2⁶¹), and so is the component test, as in the scalar form;
//! - in a lane that passes it, |o_c| < H < 2³¹ is a 32-bit signed number, so the product
//!   o_c · (1/H) is the two-multiply form of [`Wide::times`], exact, with |d_c| at most
//!   about 1; its squares and their sum are exact too;
//! - in a survivor, 0 ≤ q² < 1, so √q² < 1 is found exactly ([`sqrt`]); t, t³ and t³·t lie
//!   in [0, 1], 1 + 4q in [1, 5] (4q is exact, as the checked 4 · q is), and the products
//!   with c_w, c_g and d stay far inside the range: every product is the checked one.
//!
//! So the survivors, their order (the candidates' order) and their values and gradients
//! are the scalar form's bit for bit; lanes that fail the test hold meaningless values and
//! are dropped. Every lane is computed on its own, so packing the survivors of several
//! rows into the same blocks (to fill them) changes nothing but where the rows end, which
//! the search records as it packs. Other formats, targets and inputs beyond the bounds take
//! [`NeighbourLists::build_scalar`], [`NeighbourLists::evaluate_scalar`] and
//! [`NeighbourLists::build_keeping_candidates_scalar`].

use super::skin::{CandidateRows, Reach};
use super::{NeighbourLists, NeighbourListsOf};
use crate::fluid::grid::{CellGrid, CellGridOf};
use crate::fluid::kernel::Kernel;
use crate::math::over_real::{Scalar, Vectors};
use crate::math::sqrt::lanes_below_one::sqrt;
use crate::math::wide::{LANES, Wide, backend, kernel_entry, vector_bits};
use crate::math::{Fx, Real, Vec3};

/// [`NeighbourLists::build`] with the kernel when `R` is I32F32, a backend runs and the
/// inputs are within the bounds (see the module documentation); returns whether it did
/// (if not, the lists hold nothing of use).
pub(super) fn build<R: Real>(
    lists: &mut NeighbourLists<R>,
    queries: &[Vec3<R>],
    points: &[Vec3<R>],
    grid: &CellGrid<R>,
    kernel: &Kernel<R>,
    skip_self: bool,
) -> bool {
    let scales = [kernel.density_scale, kernel.gradient_scale];
    let support = (kernel.support, kernel.inv_support);
    let (Some(backend), Some(lists), Some(grid), Some(admitted)) = (
        backend(),
        R::as_fixed_mut::<NeighbourListsOf>(lists),
        R::as_fixed::<CellGridOf>(grid),
        admit(queries, points, support, scales, skip_self),
    ) else {
        return false;
    };
    let search = admitted.search;
    let within = Within::new(grid, search.inv_radius, grid.span(search.radius));
    build_within(
        backend,
        lists,
        admitted.queries,
        admitted.points,
        within,
        search,
    )
}

/// [`NeighbourLists::build_both`] with the kernel, on the conditions of [`build`] for both
/// searches and when both grids have the same cells ([`CellGrid::same_cells`]); returns
/// whether it did (if not, the lists hold nothing of use).
pub(super) fn build_both<R: Real>(
    [fluid, walls]: [&mut NeighbourLists<R>; 2],
    queries: &[Vec3<R>],
    [(points, grid), (boundary, boundary_grid)]: [(&[Vec3<R>], &CellGrid<R>); 2],
    kernel: &Kernel<R>,
) -> bool {
    let scales = [kernel.density_scale, kernel.gradient_scale];
    let support = (kernel.support, kernel.inv_support);
    let (Some(backend), Some(fluid), Some(walls), Some(grid), Some(boundary_grid)) = (
        backend(),
        R::as_fixed_mut::<NeighbourListsOf>(fluid),
        R::as_fixed_mut::<NeighbourListsOf>(walls),
        R::as_fixed::<CellGridOf>(grid),
        R::as_fixed::<CellGridOf>(boundary_grid),
    ) else {
        return false;
    };
    let (Some(among_fluid), Some(among_walls)) = (
        admit(queries, points, support, scales, true),
        admit(queries, boundary, support, scales, false),
    ) else {
        return false;
    };
    if !grid.same_cells(boundary_grid) {
        return false;
    }
    let span = grid.span(among_fluid.search.radius);
    build_both_within(
        backend,
        [fluid, walls],
        among_fluid.queries,
        [grid, boundary_grid],
        span,
        [
            (among_fluid.points, among_fluid.search),
            (among_walls.points, among_walls.search),
        ],
    )
}

/// [`NeighbourLists::evaluate`] with the kernel, on the conditions of [`build`]; returns
/// whether it did (if not, the lists hold nothing of use).
pub(super) fn evaluate<R: Real>(
    lists: &mut NeighbourLists<R>,
    candidates: &CandidateRows,
    queries: &[Vec3<R>],
    points: &[Vec3<R>],
    kernel: &Kernel<R>,
) -> bool {
    let scales = [kernel.density_scale, kernel.gradient_scale];
    let support = (kernel.support, kernel.inv_support);
    let (Some(backend), Some(lists), Some(admitted)) = (
        backend(),
        R::as_fixed_mut::<NeighbourListsOf>(lists),
        admit(queries, points, support, scales, false),
    ) else {
        return false;
    };
    let (queries, points) = (admitted.queries, admitted.points);
    build_from_rows(backend, lists, queries, points, candidates, admitted.search)
}

/// The candidates of [`NeighbourLists::build_keeping_candidates`]: the kernel's support
/// test at the candidate radius ρ (no kernel value is computed), on the conditions of
/// [`build`] with ρ and 1/ρ in place of H and 1/H; returns whether it did (if not, the
/// rows hold nothing of use).
pub(super) fn select<R: Real>(
    rows: &mut CandidateRows,
    queries: &[Vec3<R>],
    points: &[Vec3<R>],
    grid: &CellGrid<R>,
    reach: &Reach<R>,
    skip_self: bool,
) -> bool {
    // No kernel value is computed: any scales within the bounds will do.
    let scales = [R::ONE, R::ONE];
    let radius = (reach.radius, reach.inv_radius);
    let (Some(backend), Some(grid), Some(admitted)) = (
        backend(),
        R::as_fixed::<CellGridOf>(grid),
        admit(queries, points, radius, scales, skip_self),
    ) else {
        return false;
    };
    let within = Within::new(grid, admitted.search.inv_radius, reach.span);
    let (queries, points) = (admitted.queries, admitted.points);
    select_within(backend, rows, queries, points, within, admitted.search)
}

kernel_entry! {
    /// [`build_kernel`] over the grid's points within the radius.
    fn build_within(
        lists: &mut NeighbourLists<Fx>,
        queries: &[Vec3<Fx>],
        points: &[Vec3<Fx>],
        candidates: Within<'_>,
        search: Search,
    ) -> bool = build_kernel;
}

kernel_entry! {
    /// [`build_kernel`] over candidate rows.
    fn build_from_rows(
        lists: &mut NeighbourLists<Fx>,
        queries: &[Vec3<Fx>],
        points: &[Vec3<Fx>],
        candidates: &CandidateRows,
        search: Search,
    ) -> bool = build_kernel;
}

kernel_entry! {
    /// [`build_both_kernel`] with the instructions of `backend`.
    fn build_both_within(
        lists: [&mut NeighbourLists<Fx>; 2],
        queries: &[Vec3<Fx>],
        grids: [&CellGrid<Fx>; 2],
        span: u32,
        searches: [(&[Vec3<Fx>], Search); 2],
    ) -> bool = build_both_kernel;
}

kernel_entry! {
    /// [`select_kernel`] with the instructions of `backend`.
    fn select_within(
        rows: &mut CandidateRows,
        queries: &[Vec3<Fx>],
        points: &[Vec3<Fx>],
        candidates: Within<'_>,
        search: Search,
    ) -> bool = select_kernel;
}

/// The inputs in I32F32 and the constants of a search within a radius (`radius`: the
/// radius and its inverse) with the kernel scales `scales` (c_w, c_g), when `R` is I32F32
/// and the inputs are within the bounds of the module documentation.
fn admit<'a, R: Real>(
    queries: &'a [Vec3<R>],
    points: &'a [Vec3<R>],
    (radius, inv_radius): (R, R),
    scales: [R; 2],
    skip_self: bool,
) -> Option<Admitted<'a>> {
    let fx = |value: &R| R::as_fixed::<Scalar>(value).copied();
    let (radius, inv_radius) = (fx(&radius)?, fx(&inv_radius)?);
    let [density_scale, gradient_scale] = [fx(&scales[0])?, fx(&scales[1])?];
    let (queries, points) = (
        R::as_fixed::<Vectors>(queries)?,
        R::as_fixed::<Vectors>(points)?,
    );
    let coordinate_bits = vector_bits(queries).max(vector_bits(points));
    let within = |value: Fx, bits: u32| 0 < value.to_bits() && value.to_bits() < 1 << bits;
    if coordinate_bits > 60
        || !within(radius, 31)
        || !within(inv_radius, 60)
        || !within(density_scale, 55)
        || !within(gradient_scale, 55)
    {
        return None;
    }
    let search = Search {
        radius,
        inv_radius,
        density_scale,
        gradient_scale,
        points: points.len(),
        skip_self,
    };
    Some(Admitted {
        queries,
        points,
        search,
    })
}

/// What [`admit`] returns: the queries and points in I32F32 and the search's constants.
struct Admitted<'a> {
    queries: &'a [Vec3<Fx>],
    points: &'a [Vec3<Fx>],
    search: Search,
}

/// The constants of a search.
#[derive(Clone, Copy)]
struct Search {
    /// The radius (H, or ρ for a selection), m.
    radius: Fx,
    /// Its inverse, 1/m.
    inv_radius: Fx,
    /// c_w.
    density_scale: Fx,
    /// c_g.
    gradient_scale: Fx,
    /// The number of points, for the index check.
    points: usize,
    skip_self: bool,
}

/// A search's constants in lanes.
#[derive(Clone, Copy)]
struct SearchLanes<W: Wide> {
    /// The radius.
    support: W::V,
    /// The radius negated.
    neg_support: W::V,
    /// The radius's inverse.
    inv_support: W::V,
    /// 1.
    one: W::V,
    /// c_w.
    density_scale: W::V,
    /// c_g.
    gradient_scale: W::V,
    /// The number of points.
    points: W::V,
    skip_self: bool,
}

impl<W: Wide> SearchLanes<W> {
    #[inline(always)]
    fn new(w: W, search: &Search) -> Self {
        Self {
            support: w.splat(search.radius.to_bits()),
            neg_support: w.splat(-search.radius.to_bits()),
            inv_support: w.splat(search.inv_radius.to_bits()),
            one: w.splat(Fx::ONE.to_bits()),
            density_scale: w.splat(search.density_scale.to_bits()),
            gradient_scale: w.splat(search.gradient_scale.to_bits()),
            points: w.splat(search.points as i64),
            skip_self: search.skip_self,
        }
    }
}

/// Where the candidates of each query come from.
trait Candidates {
    /// The candidates of query `i` at `xi`, in order.
    fn of(&mut self, i: usize, xi: Vec3<Fx>) -> &[u32];
}

/// The grid's points within a radius, the slices of the grid's rows copied end to end so
/// that the blocks of eight are full but for the last.
struct Within<'a> {
    grid: &'a CellGrid<Fx>,
    inv_radius: Fx,
    span: u32,
    found: Vec<u32>,
}

impl<'a> Within<'a> {
    fn new(grid: &'a CellGrid<Fx>, inv_radius: Fx, span: u32) -> Self {
        Self {
            grid,
            inv_radius,
            span,
            found: Vec::new(),
        }
    }
}

impl Candidates for Within<'_> {
    #[inline(always)]
    fn of(&mut self, _: usize, xi: Vec3<Fx>) -> &[u32] {
        self.found.clear();
        let found = &mut self.found;
        self.grid
            .for_each_within(xi, self.inv_radius, self.span, |row| append(found, row));
        &self.found
    }
}

/// Appends `row` to `found`, a word at a time into the spare capacity: a grid row holds a
/// few points (one per cell at rest), which a call to `memcpy` per row
/// (`extend_from_slice`) copied at several times the cost.
#[inline(always)]
fn append(found: &mut Vec<u32>, row: &[u32]) {
    found.reserve(row.len());
    let spare = found.spare_capacity_mut();
    for (slot, &j) in spare.iter_mut().zip(row) {
        slot.write(j);
    }
    // SAFETY: the `row.len()` values past the length were written just above (the spare
    // capacity holds at least that many).
    unsafe { found.set_len(found.len() + row.len()) };
}

impl Candidates for &CandidateRows {
    #[inline(always)]
    fn of(&mut self, i: usize, _: Vec3<Fx>) -> &[u32] {
        self.row(i)
    }
}

/// The survivors of the candidates of one query or more, in order: index, d and q², packed
/// eight at a time, with room for eight more past the last (so that a block of eight may
/// start at any survivor).
#[derive(Default)]
struct Survivors {
    len: usize,
    lanes: [Vec<i64>; 5],
}

impl Survivors {
    /// Forgets the survivors.
    fn clear(&mut self) {
        self.len = 0;
    }

    /// Appends the lanes of `keep` of `values` (index, d_x, d_y, d_z, q²), in lane order.
    #[inline(always)]
    fn append<W: Wide>(&mut self, w: W, keep: u8, values: [W::V; 5]) {
        let at = self.len;
        for (list, lanes) in self.lanes.iter_mut().zip(values) {
            if list.len() < at + 2 * LANES {
                list.resize(at + 2 * LANES, 0);
            }
            // SAFETY: `list[at..at + 8]` exists.
            unsafe { w.store_kept(list.as_mut_ptr().add(at), keep, lanes) };
        }
        self.len += keep.count_ones() as usize;
    }

    /// The survivors' indices.
    fn indices(&self) -> impl Iterator<Item = u32> + '_ {
        self.lanes[0][..self.len].iter().map(|&j| j as u32)
    }
}

/// The search: the survivors of each query's candidates with their kernel values; returns
/// false when a candidate is not a point's index (the lists then hold nothing of use).
#[inline(always)]
fn build_kernel<W: Wide>(
    w: W,
    lists: &mut NeighbourLists<Fx>,
    queries: &[Vec3<Fx>],
    points: &[Vec3<Fx>],
    mut candidates: impl Candidates,
    search: Search,
) -> bool {
    let search = SearchLanes::new(w, &search);
    lists.clear();
    let mut survivors = Survivors::default();
    for (i, &xi) in queries.iter().enumerate() {
        let candidates = candidates.of(i, xi);
        if !add_row(w, lists, &mut survivors, candidates, i, xi, points, &search) {
            return false;
        }
    }
    evaluate_survivors(w, lists, &survivors, &search);
    true
}

/// [`build_kernel`] for two sets of points in grids of the same cells (the fluid, then
/// the boundary), in one walk of the cells: each list gets the rows its own search would.
#[inline(always)]
fn build_both_kernel<W: Wide>(
    w: W,
    lists: [&mut NeighbourLists<Fx>; 2],
    queries: &[Vec3<Fx>],
    [grid, other]: [&CellGrid<Fx>; 2],
    span: u32,
    [(fluid_points, fluid), (wall_points, walls)]: [(&[Vec3<Fx>], Search); 2],
) -> bool {
    let inv_radius = fluid.inv_radius;
    let searches = [
        (fluid_points, SearchLanes::new(w, &fluid)),
        (wall_points, SearchLanes::new(w, &walls)),
    ];
    let mut survivors: [Survivors; 2] = Default::default();
    let mut found: [Vec<u32>; 2] = Default::default();
    let mut lists = lists;
    for list in &mut lists {
        list.clear();
    }
    for (i, &xi) in queries.iter().enumerate() {
        for found in &mut found {
            found.clear();
        }
        grid.for_each_within_both(other, xi, inv_radius, span, |k, row| {
            append(&mut found[k], row);
        });
        for (k, list) in lists.iter_mut().enumerate() {
            let (points, search) = &searches[k];
            if !add_row(w, list, &mut survivors[k], &found[k], i, xi, points, search) {
                return false;
            }
        }
    }
    for (k, list) in lists.into_iter().enumerate() {
        evaluate_survivors(w, list, &survivors[k], &searches[k].1);
    }
    true
}

/// Tests the candidates of query `i` at `xi` and closes its row; evaluates the pending
/// survivors once there are enough. False when a candidate is not a point's index.
#[inline(always)]
#[allow(clippy::too_many_arguments)] // the kernel's state, passed down
fn add_row<W: Wide>(
    w: W,
    lists: &mut NeighbourLists<Fx>,
    survivors: &mut Survivors,
    candidates: &[u32],
    i: usize,
    xi: Vec3<Fx>,
    points: &[Vec3<Fx>],
    search: &SearchLanes<W>,
) -> bool {
    if !test_candidates(w, survivors, candidates, i, xi, points, search) {
        return false;
    }
    // The survivors of several rows are evaluated together, in full blocks: the row ends
    // where its survivors will have been appended.
    lists.start.push((lists.index.len() + survivors.len) as u32);
    if survivors.len >= PENDING {
        evaluate_survivors(w, lists, survivors, search);
        survivors.clear();
    }
    true
}

/// How many survivors wait before they are evaluated: enough for many groups of four full
/// blocks, few enough to stay in the first-level cache.
const PENDING: usize = 256;

/// The selection: the survivors of each query's candidates, indices only; returns false
/// when a candidate is not a point's index (the rows then hold nothing of use).
#[inline(always)]
fn select_kernel<W: Wide>(
    w: W,
    rows: &mut CandidateRows,
    queries: &[Vec3<Fx>],
    points: &[Vec3<Fx>],
    mut candidates: Within<'_>,
    search: Search,
) -> bool {
    let search = SearchLanes::new(w, &search);
    rows.clear();
    let mut survivors = Survivors::default();
    for (i, &xi) in queries.iter().enumerate() {
        survivors.clear();
        let candidates = candidates.of(i, xi);
        if !test_candidates(w, &mut survivors, candidates, i, xi, points, &search) {
            return false;
        }
        rows.extend(survivors.indices());
        rows.end_row();
    }
    true
}

/// Tests `candidates` for query `i` at `xi`, eight at a time, and appends the survivors
/// with d and q²; false when a candidate is not a point's index.
#[inline(always)]
fn test_candidates<W: Wide>(
    w: W,
    survivors: &mut Survivors,
    candidates: &[u32],
    i: usize,
    xi: Vec3<Fx>,
    points: &[Vec3<Fx>],
    search: &SearchLanes<W>,
) -> bool {
    let x = [
        w.splat(xi.x.to_bits()),
        w.splat(xi.y.to_bits()),
        w.splat(xi.z.to_bits()),
    ];
    let me = w.splat(i as i64);
    let mut first = 0;
    while first < candidates.len() {
        let count = (candidates.len() - first).min(LANES);
        let mask = ((1u16 << count) - 1) as u8;
        // SAFETY: the `count` candidates from `first` exist.
        let j = unsafe { w.load_prefix_u32(candidates.as_ptr().add(first), count) };
        let block = &candidates[first..first + count];
        first += count;
        // The lanes past `count` hold zero, below any positive number of points.
        if w.at_least_unsigned(j, search.points) != 0 {
            return false;
        }
        let mut keep = mask;
        if search.skip_self {
            keep &= !w.equal(j, me);
        }
        let Some(xj) = w.gather_vectors(points, block) else {
            return false;
        };
        let offset = [w.sub(x[0], xj[0]), w.sub(x[1], xj[1]), w.sub(x[2], xj[2])];
        for o in offset {
            keep &= w.greater(search.support, o) & w.greater(o, search.neg_support);
        }
        if keep == 0 {
            continue;
        }
        let d = [
            w.times::<true>(offset[0], search.inv_support),
            w.times::<true>(offset[1], search.inv_support),
            w.times::<true>(offset[2], search.inv_support),
        ];
        let q2 = w.add(
            w.add(w.mul(d[0], d[0]), w.mul(d[1], d[1])),
            w.mul(d[2], d[2]),
        );
        keep &= w.greater(search.one, q2);
        survivors.append(w, keep, [j, d[0], d[1], d[2], q2]);
    }
    true
}

/// Appends the survivors to the lists' entries with V₀W and V₀∇ᵢW (the caller closes the
/// rows), eight at a time, up to four blocks of eight side by side (so that their square
/// roots, each a chain of dependent steps, overlap).
#[inline(always)]
fn evaluate_survivors<W: Wide>(
    w: W,
    lists: &mut NeighbourLists<Fx>,
    survivors: &Survivors,
    search: &SearchLanes<W>,
) {
    let mut first = 0;
    while first < survivors.len {
        first = match (survivors.len - first).div_ceil(LANES) {
            1 => evaluate_blocks::<W, 1>(w, lists, survivors, first, search),
            2 => evaluate_blocks::<W, 2>(w, lists, survivors, first, search),
            3 => evaluate_blocks::<W, 3>(w, lists, survivors, first, search),
            _ => evaluate_blocks::<W, 4>(w, lists, survivors, first, search),
        };
    }
}

/// Evaluates and appends `BLOCKS` blocks of eight survivors from `first` (the last may be
/// partial); returns the next survivor.
#[inline(always)]
fn evaluate_blocks<W: Wide, const BLOCKS: usize>(
    w: W,
    lists: &mut NeighbourLists<Fx>,
    survivors: &Survivors,
    first: usize,
    search: &SearchLanes<W>,
) -> usize {
    let [index, dx, dy, dz, q2] = &survivors.lanes;
    let mut squares = [w.zero(); BLOCKS];
    for (b, square) in squares.iter_mut().enumerate() {
        *square = load_block(w, q2, first + LANES * b);
    }
    let roots = sqrt(w, squares);
    // All the blocks' values before any is stored, so that their chains of products
    // overlap.
    let mut values = [[w.zero(); 4]; BLOCKS];
    for (b, value) in values.iter_mut().enumerate() {
        *value = kernel_values(
            w,
            roots[b],
            [
                load_block(w, dx, first + LANES * b),
                load_block(w, dy, first + LANES * b),
                load_block(w, dz, first + LANES * b),
            ],
            search,
        );
    }
    let count = (survivors.len - first).min(LANES * BLOCKS);
    lists
        .index
        .extend(index[first..first + count].iter().map(|&j| j as u32));
    let [gx, gy, gz] = &mut lists.gradients;
    let outputs = [&mut lists.value, gx, gy, gz];
    // Only the first `count` lanes of the blocks are survivors: each list grows by those,
    // with no placeholder written first.
    for (output, list) in outputs.into_iter().enumerate() {
        for (b, value) in values.iter().enumerate() {
            let kept = count.saturating_sub(LANES * b).min(LANES);
            let words = w.store_words(value[output]);
            list.extend(words[..kept].iter().map(|&bits| Fx::from_bits(bits)));
        }
    }
    (first + LANES * BLOCKS).min(survivors.len)
}

/// V₀W and V₀∇ᵢW (x, y, z) of eight survivors from q = √q² and d, as
/// [`Kernel::evaluate_within`] computes them (see the module documentation).
#[inline(always)]
fn kernel_values<W: Wide>(w: W, q: W::V, d: [W::V; 3], search: &SearchLanes<W>) -> [W::V; 4] {
    let t = w.sub(search.one, q);
    let t3 = w.mul(w.mul(t, t), t);
    let grow = w.add(search.one, w.shift_left(q, 2));
    let value = w.mul(search.density_scale, w.mul(w.mul(t3, t), grow));
    let slope = w.sub(w.zero(), w.mul(search.gradient_scale, t3));
    [
        value,
        w.mul(d[0], slope),
        w.mul(d[1], slope),
        w.mul(d[2], slope),
    ]
}

/// The eight survivors' values from `at` (`append` keeps eight slots beyond every survivor
/// it stored, and the blocks start at survivors it stored).
#[inline(always)]
fn load_block<W: Wide>(w: W, lanes: &[i64], at: usize) -> W::V {
    let mut words = [0; LANES];
    words.copy_from_slice(&lanes[at..at + LANES]);
    w.load_words(words)
}
