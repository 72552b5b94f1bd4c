//! The neighbour search in AVX-512F (with AVX-512CD's leading-zero count for the square
//! root) for I32F32: eight candidates side by side through the support test, the
//! survivors packed in order, then eight survivors side by side through the kernel's value
//! and gradient.
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
//!   o_c · (1/H) is the two-multiply form of [`lanes::product`](crate::fluid::lanes::product),
//!   exact, with |d_c| at most about 1; its squares and their sum are exact too;
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

use core::any::Any;
use core::arch::x86_64::{
    __m512i, __mmask8, _mm512_add_epi64, _mm512_castsi512_si256, _mm512_cvtepu32_epi64,
    _mm512_loadu_si512, _mm512_mask_cmpgt_epi64_mask, _mm512_mask_cmplt_epi64_mask,
    _mm512_mask_cmplt_epu64_mask, _mm512_mask_cmpneq_epi64_mask, _mm512_maskz_compress_epi64,
    _mm512_maskz_loadu_epi32, _mm512_set1_epi64, _mm512_setzero_si512, _mm512_slli_epi64,
    _mm512_storeu_si512, _mm512_sub_epi64,
};
use core::mem::size_of;

use crate::math::sqrt::lanes_below_one::sqrt;

use super::NeighbourLists;
use super::skin::{CandidateRows, Reach};
use crate::fluid::grid::CellGrid;
use crate::fluid::kernel::Kernel;
use crate::fluid::lanes::{mul, product};
use crate::math::wide::vector_bits;
use crate::math::{Fx, Real, Vec3};
use crate::soft::lanes::gather3;

// The layout the loads rely on: `Fx` is one `i64`, `Vec3<Fx>` x, y, z in a row.
const _: () = {
    assert!(size_of::<Fx>() == 8);
    assert!(size_of::<Vec3<Fx>>() == 24);
};

/// [`NeighbourLists::build`] with the kernel when `R` is I32F32, the processor has
/// AVX-512F and CD and the inputs are within the bounds (see the module documentation);
/// returns whether it did (if not, the lists hold nothing of use).
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
    let (Some(lists), Some(grid), Some(admitted)) = (
        (lists as &mut dyn Any).downcast_mut::<NeighbourLists<Fx>>(),
        (grid as &dyn Any).downcast_ref::<CellGrid<Fx>>(),
        admit(queries, points, support, scales, skip_self),
    ) else {
        return false;
    };
    let search = &admitted.search;
    let within = Within::new(grid, search.inv_radius, grid.span(search.radius));
    let (queries, points) = (admitted.queries, admitted.points);
    // SAFETY: `admit` detected AVX-512F and CD and checked the bounds.
    unsafe { build_kernel(lists, queries, points, within, search) }
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
    let (Some(fluid), Some(walls), Some(grid), Some(boundary_grid)) = (
        (fluid as &mut dyn Any).downcast_mut::<NeighbourLists<Fx>>(),
        (walls as &mut dyn Any).downcast_mut::<NeighbourLists<Fx>>(),
        (grid as &dyn Any).downcast_ref::<CellGrid<Fx>>(),
        (boundary_grid as &dyn Any).downcast_ref::<CellGrid<Fx>>(),
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
    let searches = [
        (among_fluid.points, &among_fluid.search),
        (among_walls.points, &among_walls.search),
    ];
    // SAFETY: `admit` detected AVX-512F and CD and checked the bounds of both searches.
    unsafe {
        build_both_kernel(
            [fluid, walls],
            among_fluid.queries,
            [grid, boundary_grid],
            span,
            searches,
        )
    }
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
    let (Some(lists), Some(admitted)) = (
        (lists as &mut dyn Any).downcast_mut::<NeighbourLists<Fx>>(),
        admit(queries, points, support, scales, false),
    ) else {
        return false;
    };
    let (queries, points) = (admitted.queries, admitted.points);
    // SAFETY: `admit` detected AVX-512F and CD and checked the bounds.
    unsafe { build_kernel(lists, queries, points, candidates, &admitted.search) }
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
    let (Some(grid), Some(admitted)) = (
        (grid as &dyn Any).downcast_ref::<CellGrid<Fx>>(),
        admit(queries, points, radius, scales, skip_self),
    ) else {
        return false;
    };
    let within = Within::new(grid, admitted.search.inv_radius, reach.span);
    let (queries, points) = (admitted.queries, admitted.points);
    // SAFETY: `admit` detected AVX-512F and CD and checked the bounds.
    unsafe { select_kernel(rows, queries, points, within, &admitted.search) }
}

/// The inputs in I32F32 and the constants of a search within a radius (`radius`: the
/// radius and its inverse) with the kernel scales `scales` (c_w, c_g), when `R` is I32F32,
/// the processor has AVX-512F and CD and the inputs are within the bounds of the module
/// documentation.
fn admit<'a, R: Real>(
    queries: &'a [Vec3<R>],
    points: &'a [Vec3<R>],
    (radius, inv_radius): (R, R),
    scales: [R; 2],
    skip_self: bool,
) -> Option<Admitted<'a>> {
    if !crate::math::cpu::avx512f() || !crate::math::cpu::avx512cd() {
        return None;
    }
    let fx = |value: &R| (value as &dyn Any).downcast_ref::<Fx>().copied();
    let (radius, inv_radius) = (fx(&radius)?, fx(&inv_radius)?);
    let [density_scale, gradient_scale] = [fx(&scales[0])?, fx(&scales[1])?];
    // SAFETY: `R` is `Fx` (the downcasts succeeded), so the slices' type is unchanged.
    let (queries, points) = unsafe {
        (
            &*(core::ptr::from_ref(queries) as *const [Vec3<Fx>]),
            &*(core::ptr::from_ref(points) as *const [Vec3<Fx>]),
        )
    };
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
    // SAFETY: AVX-512F and CD were detected above.
    let lanes = |bits: i64| unsafe { _mm512_set1_epi64(bits) };
    let search = Search {
        radius,
        inv_radius,
        support: lanes(radius.to_bits()),
        neg_support: lanes(-radius.to_bits()),
        inv_support: lanes(inv_radius.to_bits()),
        one: lanes(Fx::ONE.to_bits()),
        density_scale: lanes(density_scale.to_bits()),
        gradient_scale: lanes(gradient_scale.to_bits()),
        points: lanes(points.len() as i64),
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

/// The constants of a search: its radius (H, or ρ for a selection), then everything in
/// lanes.
struct Search {
    /// The radius, m.
    radius: Fx,
    /// Its inverse, 1/m.
    inv_radius: Fx,
    /// The radius.
    support: __m512i,
    /// The radius negated.
    neg_support: __m512i,
    /// The radius's inverse.
    inv_support: __m512i,
    /// 1.
    one: __m512i,
    /// c_w.
    density_scale: __m512i,
    /// c_g.
    gradient_scale: __m512i,
    /// The number of points, for the index check.
    points: __m512i,
    skip_self: bool,
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

impl Within<'_> {
    /// The candidates of a query at `xi`.
    #[inline]
    #[target_feature(enable = "avx512f,avx512cd")]
    fn collect(&mut self, xi: Vec3<Fx>) -> &[u32] {
        self.found.clear();
        let found = &mut self.found;
        self.grid
            .for_each_within(xi, self.inv_radius, self.span, |row| append(found, row));
        &self.found
    }
}

impl Candidates for Within<'_> {
    #[inline(always)]
    fn of(&mut self, _: usize, xi: Vec3<Fx>) -> &[u32] {
        // SAFETY: a `Within` is made only for a search that `admit` let through, which
        // detected AVX-512F and CD.
        unsafe { self.collect(xi) }
    }
}

/// Appends `row` to `found` sixteen at a time: a masked load, then a whole store into the
/// spare capacity. A grid row holds a few points (one per cell at rest), which a call to
/// `memcpy` per row (`extend_from_slice`) copied at several times the cost.
#[inline]
#[target_feature(enable = "avx512f,avx512cd")]
fn append(found: &mut Vec<u32>, row: &[u32]) {
    let len = found.len();
    found.reserve(row.len() + 16);
    let mut first = 0;
    while first < row.len() {
        let count = (row.len() - first).min(16) as u32;
        let mask = (u32::MAX >> (32 - count)) as u16;
        // SAFETY: the masked load reads only `row[first..first + count]`; the store writes
        // 16 values from `len + first`, within the capacity reserved above.
        unsafe {
            let lanes = _mm512_maskz_loadu_epi32(mask, row.as_ptr().add(first).cast());
            _mm512_storeu_si512(found.as_mut_ptr().add(len + first).cast(), lanes);
        }
        first += 16;
    }
    // SAFETY: the `row.len()` values past `len` were stored above.
    unsafe { found.set_len(len + row.len()) };
}

impl Candidates for &CandidateRows {
    #[inline(always)]
    fn of(&mut self, i: usize, _: Vec3<Fx>) -> &[u32] {
        self.row(i)
    }
}

/// The survivors of the candidates of one query or more, in order: index, d and q², packed
/// eight at a time with room for eight more.
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
    #[inline]
    #[target_feature(enable = "avx512f,avx512cd")]
    fn append(&mut self, keep: __mmask8, values: [__m512i; 5]) {
        let at = self.len;
        for (list, lanes) in self.lanes.iter_mut().zip(values) {
            if list.len() < at + 8 {
                list.resize(at + 8, 0);
            }
            // Packed in a register, then stored whole: a compressing store to memory is
            // slow on some processors (Zen 4).
            // SAFETY: eight values into `list[at..at + 8]`, which exists.
            unsafe {
                _mm512_storeu_si512(
                    list.as_mut_ptr().add(at).cast(),
                    _mm512_maskz_compress_epi64(keep, lanes),
                );
            }
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
///
/// # Safety
/// The processor must have AVX-512F and CD; the bounds of [`build`] must hold.
#[target_feature(enable = "avx512f,avx512cd")]
unsafe fn build_kernel(
    lists: &mut NeighbourLists<Fx>,
    queries: &[Vec3<Fx>],
    points: &[Vec3<Fx>],
    mut candidates: impl Candidates,
    search: &Search,
) -> bool {
    lists.clear();
    let mut survivors = Survivors::default();
    for (i, &xi) in queries.iter().enumerate() {
        let candidates = candidates.of(i, xi);
        // SAFETY: the caller's conditions are this function's.
        if !unsafe { add_row(lists, &mut survivors, candidates, i, xi, points, search) } {
            return false;
        }
    }
    evaluate_survivors(lists, &survivors, search);
    true
}

/// [`build_kernel`] for two sets of points in grids of the same cells (the fluid, then
/// the boundary), in one walk of the cells: each list gets the rows its own search would.
///
/// # Safety
/// The processor must have AVX-512F and CD; the bounds of [`build`] must hold for both
/// searches.
#[target_feature(enable = "avx512f,avx512cd")]
unsafe fn build_both_kernel(
    lists: [&mut NeighbourLists<Fx>; 2],
    queries: &[Vec3<Fx>],
    [grid, other]: [&CellGrid<Fx>; 2],
    span: u32,
    searches: [(&[Vec3<Fx>], &Search); 2],
) -> bool {
    let mut survivors: [Survivors; 2] = Default::default();
    let mut found: [Vec<u32>; 2] = Default::default();
    let inv_radius = searches[0].1.inv_radius;
    let [fluid, walls] = lists;
    let mut lists = [fluid, walls];
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
            let (points, search) = searches[k];
            // SAFETY: the caller's conditions are this function's.
            if !unsafe { add_row(list, &mut survivors[k], &found[k], i, xi, points, search) } {
                return false;
            }
        }
    }
    for (k, list) in lists.into_iter().enumerate() {
        evaluate_survivors(list, &survivors[k], searches[k].1);
    }
    true
}

/// Tests the candidates of query `i` at `xi` and closes its row; evaluates the pending
/// survivors once there are enough. False when a candidate is not a point's index.
///
/// # Safety
/// The processor must have AVX-512F and CD; the bounds of [`build`] must hold.
#[inline]
#[target_feature(enable = "avx512f,avx512cd")]
unsafe fn add_row(
    lists: &mut NeighbourLists<Fx>,
    survivors: &mut Survivors,
    candidates: &[u32],
    i: usize,
    xi: Vec3<Fx>,
    points: &[Vec3<Fx>],
    search: &Search,
) -> bool {
    // SAFETY: the caller's conditions are this function's.
    if !unsafe { test_candidates(survivors, candidates, i, xi, points, search) } {
        return false;
    }
    // The survivors of several rows are evaluated together, in full blocks: the row ends
    // where its survivors will have been appended.
    lists.start.push((lists.index.len() + survivors.len) as u32);
    if survivors.len >= PENDING {
        evaluate_survivors(lists, survivors, search);
        survivors.clear();
    }
    true
}

/// How many survivors wait before they are evaluated: enough for many groups of four full
/// blocks, few enough to stay in the first-level cache.
const PENDING: usize = 256;

/// The selection: the survivors of each query's candidates, indices only; returns false
/// when a candidate is not a point's index (the rows then hold nothing of use).
///
/// # Safety
/// The processor must have AVX-512F and CD; the bounds of [`build`] must hold.
#[target_feature(enable = "avx512f,avx512cd")]
unsafe fn select_kernel(
    rows: &mut CandidateRows,
    queries: &[Vec3<Fx>],
    points: &[Vec3<Fx>],
    mut candidates: Within<'_>,
    search: &Search,
) -> bool {
    rows.clear();
    let mut survivors = Survivors::default();
    for (i, &xi) in queries.iter().enumerate() {
        survivors.clear();
        let candidates = candidates.of(i, xi);
        // SAFETY: the caller's conditions are this function's.
        if !unsafe { test_candidates(&mut survivors, candidates, i, xi, points, search) } {
            return false;
        }
        rows.extend(survivors.indices());
        rows.end_row();
    }
    true
}

/// Tests `candidates` for query `i` at `xi`, eight at a time, and appends the survivors
/// with d and q²; false when a candidate is not a point's index.
///
/// # Safety
/// The processor must have AVX-512F and CD; the bounds of [`build`] must hold.
#[inline]
#[target_feature(enable = "avx512f,avx512cd")]
unsafe fn test_candidates(
    survivors: &mut Survivors,
    candidates: &[u32],
    i: usize,
    xi: Vec3<Fx>,
    points: &[Vec3<Fx>],
    search: &Search,
) -> bool {
    let x = [xi.x, xi.y, xi.z].map(|c| _mm512_set1_epi64(c.to_bits()));
    let me = _mm512_set1_epi64(i as i64);
    let mut first = 0;
    while first < candidates.len() {
        let count = (candidates.len() - first).min(8);
        let mask = ((1u16 << count) - 1) as __mmask8;
        // SAFETY: the masked load reads only the `count` candidates from `first`.
        let index32 = unsafe {
            _mm512_maskz_loadu_epi32(u16::from(mask), candidates.as_ptr().add(first).cast())
        };
        first += count;
        let j = _mm512_cvtepu32_epi64(_mm512_castsi512_si256(index32));
        if _mm512_mask_cmplt_epu64_mask(mask, j, search.points) != mask {
            return false;
        }
        let mut keep = mask;
        if search.skip_self {
            keep = _mm512_mask_cmpneq_epi64_mask(keep, j, me);
        }
        // Every index in use is below `points.len()` (checked above).
        let Some(xj) = gather3(points, &candidates[first - count..first]) else {
            return false;
        };
        let offset: [__m512i; 3] = core::array::from_fn(|c| _mm512_sub_epi64(x[c], xj[c]));
        for o in offset {
            keep = _mm512_mask_cmplt_epi64_mask(keep, o, search.support);
            keep = _mm512_mask_cmpgt_epi64_mask(keep, o, search.neg_support);
        }
        if keep == 0 {
            continue;
        }
        let d = offset.map(|o| product::<true>(search.inv_support, o));
        let q2 = _mm512_add_epi64(
            _mm512_add_epi64(mul(d[0], d[0]), mul(d[1], d[1])),
            mul(d[2], d[2]),
        );
        keep = _mm512_mask_cmplt_epi64_mask(keep, q2, search.one);
        survivors.append(keep, [j, d[0], d[1], d[2], q2]);
    }
    true
}

/// Appends the survivors to the lists' entries with V₀W and V₀∇ᵢW (the caller closes the
/// rows), eight at a time, up to four blocks of eight side by side (so that their square
/// roots, each a chain of dependent steps, overlap).
#[target_feature(enable = "avx512f,avx512cd")]
fn evaluate_survivors(lists: &mut NeighbourLists<Fx>, survivors: &Survivors, search: &Search) {
    let mut first = 0;
    while first < survivors.len {
        first = match (survivors.len - first).div_ceil(8) {
            1 => evaluate_blocks::<1>(lists, survivors, first, search),
            2 => evaluate_blocks::<2>(lists, survivors, first, search),
            3 => evaluate_blocks::<3>(lists, survivors, first, search),
            _ => evaluate_blocks::<4>(lists, survivors, first, search),
        };
    }
}

/// Evaluates and appends `BLOCKS` blocks of eight survivors from `first` (the last may be
/// partial); returns the next survivor.
#[inline]
#[target_feature(enable = "avx512f,avx512cd")]
fn evaluate_blocks<const BLOCKS: usize>(
    lists: &mut NeighbourLists<Fx>,
    survivors: &Survivors,
    first: usize,
    search: &Search,
) -> usize {
    let [index, dx, dy, dz, q2] = &survivors.lanes;
    // SAFETY: `append` keeps eight slots beyond every survivor it stored, and the blocks
    // start at survivors it stored.
    let load = |lanes: &Vec<i64>, block: usize| unsafe {
        _mm512_loadu_si512(lanes.as_ptr().add(first + 8 * block).cast())
    };
    let roots = sqrt::<BLOCKS>(core::array::from_fn(|b| load(q2, b)));
    // All the blocks' values before any is stored, so that their chains of products
    // overlap.
    let values: [_; BLOCKS] = core::array::from_fn(|b| {
        kernel_values(roots[b], [load(dx, b), load(dy, b), load(dz, b)], search)
    });
    let count = (survivors.len - first).min(8 * BLOCKS);
    lists
        .index
        .extend(index[first..first + count].iter().map(|&j| j as u32));
    let [gx, gy, gz] = &mut lists.gradients;
    let outputs = [&mut lists.value, gx, gy, gz];
    for (output, list) in outputs.into_iter().enumerate() {
        let len = list.len();
        list.reserve(8 * BLOCKS);
        for (b, (value, gradient)) in values.iter().enumerate() {
            let lanes = if output == 0 {
                *value
            } else {
                gradient[output - 1]
            };
            // SAFETY: eight values into the capacity reserved just above, past the length;
            // `Fx` is one `i64` (asserted above).
            unsafe { _mm512_storeu_si512(list.as_mut_ptr().add(len + 8 * b).cast(), lanes) };
        }
        // SAFETY: the first `count` of the values stored are the survivors' (the blocks'
        // other lanes, past them, are left out).
        unsafe { list.set_len(len + count) };
    }
    (first + 8 * BLOCKS).min(survivors.len)
}

/// V₀W and V₀∇ᵢW of eight survivors from q = √q² and d, as [`Kernel::evaluate_within`]
/// computes them (see the module documentation).
#[inline]
#[target_feature(enable = "avx512f,avx512cd")]
fn kernel_values(q: __m512i, d: [__m512i; 3], search: &Search) -> (__m512i, [__m512i; 3]) {
    let t = _mm512_sub_epi64(search.one, q);
    let t3 = mul(mul(t, t), t);
    let grow = _mm512_add_epi64(search.one, _mm512_slli_epi64::<2>(q));
    let value = mul(search.density_scale, mul(mul(t3, t), grow));
    let slope = _mm512_sub_epi64(_mm512_setzero_si512(), mul(search.gradient_scale, t3));
    (value, d.map(|c| mul(c, slope)))
}
