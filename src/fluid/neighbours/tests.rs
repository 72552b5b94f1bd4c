//! The neighbour search's dispatch, with every backend of the kernel this processor runs
//! and with none, against the scalar form, entry for entry, on random points, a lattice (pairs exactly one spacing
//! apart, ties of the support) and points far outside the grid: the fresh search, the
//! selection of candidates with a skin and the lists evaluated from them (which must be
//! the fresh search's).

use super::NeighbourLists;
use super::skin::{CandidateRows, Reach};
use crate::fluid::grid::CellGrid;
use crate::fluid::kernel::Kernel;
use crate::math::cpu::{each_backend, kernels_present};
use crate::math::{Fx, Pcg32, Real, Vec3};

/// Both searches of `queries` among `points` (a grid over [0, 0.1 m]³), compared, with
/// every backend; returns whether the kernel took the search, which must be the same
/// answer for every backend.
fn compare(queries: &[Vec3<Fx>], points: &[Vec3<Fx>], spacing: Fx, skip_self: bool) -> bool {
    let mut taken = None;
    each_backend(|| {
        let now = compare_once(queries, points, spacing, skip_self);
        if kernels_present() {
            assert!(taken.is_none_or(|t| t == now), "backends disagree");
            taken = Some(now);
        }
    });
    taken.unwrap_or(false)
}

/// [`compare`] with the backend in force.
fn compare_once(queries: &[Vec3<Fx>], points: &[Vec3<Fx>], spacing: Fx, skip_self: bool) -> bool {
    let kernel = Kernel::<Fx>::calibrated(spacing, Fx::TWO);
    let mut grid = CellGrid::new(
        Vec3::ZERO,
        Vec3::splat(Fx::from_ratio(1, 10)),
        kernel.support,
    );
    grid.fill(points);
    let (mut fast, mut slow) = (NeighbourLists::default(), NeighbourLists::default());
    fast.build(queries, points, &grid, &kernel, skip_self);
    slow.build_scalar(queries, points, &grid, &kernel, skip_self);
    assert_same(&fast, &slow);
    let reach = Reach::new(&kernel, &grid);
    let (mut rows, mut rows_scalar) = (CandidateRows::default(), CandidateRows::default());
    let (mut built, mut built_scalar) = (NeighbourLists::default(), NeighbourLists::default());
    let searched = (points, &grid);
    built.build_keeping_candidates(&mut rows, queries, searched, &reach, &kernel, skip_self);
    built_scalar.build_keeping_candidates_scalar(
        &mut rows_scalar,
        queries,
        searched,
        &reach,
        &kernel,
        skip_self,
    );
    assert_same(&built, &slow);
    assert_same(&built_scalar, &slow);
    assert_eq!(rows.len(), queries.len());
    assert_eq!(rows_scalar.len(), queries.len());
    for i in 0..queries.len() {
        assert_eq!(rows.row(i), rows_scalar.row(i), "candidates of {i}");
    }
    let (mut from_rows, mut from_rows_scalar) =
        (NeighbourLists::default(), NeighbourLists::default());
    from_rows.evaluate(&rows, queries, points, &kernel);
    from_rows_scalar.evaluate_scalar(&rows, queries, points, &kernel);
    assert_same(&from_rows, &slow);
    assert_same(&from_rows_scalar, &slow);
    let taken = kernel_takes(queries, points, &grid, &kernel, skip_self);
    assert_eq!(
        taken,
        kernel_takes_rows(&rows, queries, points, &grid, &kernel, skip_self)
    );
    taken
}

/// The lists `a` and `b`, entry for entry.
fn assert_same(a: &NeighbourLists<Fx>, b: &NeighbourLists<Fx>) {
    assert_eq!(a.start, b.start);
    assert_eq!(a.index, b.index);
    assert_eq!(a.value, b.value);
    assert_eq!(a.gradients, b.gradients);
}

/// Whether the kernels took both the selection and the evaluation from `rows`.
#[cfg(vector_kernels)]
fn kernel_takes_rows(
    rows: &CandidateRows,
    queries: &[Vec3<Fx>],
    points: &[Vec3<Fx>],
    grid: &CellGrid<Fx>,
    kernel: &Kernel<Fx>,
    skip_self: bool,
) -> bool {
    let reach = Reach::new(kernel, grid);
    let mut selected = CandidateRows::default();
    let selects = super::kernel::select(&mut selected, queries, points, grid, &reach, skip_self);
    let mut lists = NeighbourLists::default();
    let evaluates = super::kernel::evaluate(&mut lists, rows, queries, points, kernel);
    assert_eq!(selects, evaluates);
    selects
}

#[cfg(not(vector_kernels))]
fn kernel_takes_rows(
    _: &CandidateRows,
    _: &[Vec3<Fx>],
    _: &[Vec3<Fx>],
    _: &CellGrid<Fx>,
    _: &Kernel<Fx>,
    _: bool,
) -> bool {
    false
}

#[cfg(vector_kernels)]
fn kernel_takes(
    queries: &[Vec3<Fx>],
    points: &[Vec3<Fx>],
    grid: &CellGrid<Fx>,
    kernel: &Kernel<Fx>,
    skip_self: bool,
) -> bool {
    let mut lists = NeighbourLists::default();
    super::kernel::build(&mut lists, queries, points, grid, kernel, skip_self)
}

#[cfg(not(vector_kernels))]
fn kernel_takes(_: &[Vec3<Fx>], _: &[Vec3<Fx>], _: &CellGrid<Fx>, _: &Kernel<Fx>, _: bool) -> bool {
    false
}

/// `n` random points in the 0.1 m cube, raw bits.
fn random(n: usize, seed: u64) -> Vec<Vec3<Fx>> {
    let mut rng = Pcg32::new(seed, 11);
    let tenth = Fx::from_ratio(1, 10).to_bits() as u64;
    (0..n)
        .map(|_| {
            let mut c = || Fx::from_bits((rng.next_u64() % tenth) as i64);
            Vec3::new(c(), c(), c())
        })
        .collect()
}

#[test]
fn random_points_match_the_scalar_search() {
    for seed in 0..6 {
        let points = random(1500, seed);
        let taken = compare(&points, &points, Fx::from_ratio(5, 1000), true);
        assert_eq!(taken, kernels_present());
        let queries = random(300, seed + 100);
        compare(&queries, &points, Fx::from_ratio(5, 1000), false);
    }
}

#[test]
fn a_lattice_with_pairs_on_the_support_matches() {
    // Spacing 5 mm, support 1 cm: pairs two spacings apart lie exactly on the support.
    let spacing = Fx::from_ratio(5, 1000);
    let mut points = Vec::new();
    for k in 0..12 {
        for j in 0..12 {
            for i in 0..12 {
                points.push(Vec3::new(
                    spacing * Fx::from_int(i),
                    spacing * Fx::from_int(j),
                    spacing * Fx::from_int(k),
                ));
            }
        }
    }
    let taken = compare(&points, &points, spacing, true);
    assert_eq!(taken, kernels_present());
}

#[test]
fn a_dense_cluster_matches() {
    // 2500 points in a 2 cm cube, cells 5 mm wide: about 40 points per cell, so that the
    // grid rows the vector search copies end to end hold many registers' worth of points.
    let points: Vec<_> = random(2500, 21)
        .into_iter()
        .map(|p| p * Fx::from_ratio(1, 5))
        .collect();
    let taken = compare(&points, &points, Fx::from_ratio(5, 1000), true);
    assert_eq!(taken, kernels_present());
}

#[test]
fn points_beyond_the_grid_and_the_bounds_match() {
    let mut points = random(400, 9);
    points.push(Vec3::from_f64(-0.3, 0.0, 0.02));
    points.push(Vec3::from_f64(0.05, 5.0e6, 0.05));
    let taken = compare(&points, &points, Fx::from_ratio(5, 1000), true);
    assert_eq!(taken, kernels_present());
    // Coordinates beyond 2⁶⁰ as bits (2.7·10⁸ m): the scalar search.
    points.push(Vec3::new(Fx::MAX, Fx::ZERO, Fx::MIN));
    assert!(!compare(&points, &points, Fx::from_ratio(5, 1000), true));
}

#[test]
fn both_searches_in_one_walk_match_two_scalar_searches() {
    let spacing = Fx::from_ratio(5, 1000);
    let kernel = Kernel::<Fx>::calibrated(spacing, Fx::TWO);
    let tenth = Vec3::splat(Fx::from_ratio(1, 10));
    for seed in 0..4 {
        let fluid = random(1200, seed);
        // Boundary points: a dense random cloud, and a lattice plane through it whose
        // points lie on cell edges, so that neither grid's rows are the other's.
        let mut boundary = random(2000, seed + 50);
        for j in 0..20 {
            for i in 0..20 {
                let at = |k: i32| spacing * Fx::from_int(k);
                boundary.push(Vec3::new(at(i), at(j), Fx::from_ratio(1, 20)));
            }
        }
        let mut grid = CellGrid::new(Vec3::ZERO, tenth, kernel.support);
        grid.fill(&fluid);
        // The same cells, then other cells (the walk cannot be shared).
        for lower in [Vec3::ZERO, Vec3::splat(Fx::from_ratio(-3, 1000))] {
            let mut boundary_grid = CellGrid::new(lower, tenth, kernel.support);
            boundary_grid.fill(&boundary);
            let (mut fast, mut fast_walls) = (NeighbourLists::default(), NeighbourLists::default());
            NeighbourLists::build_both(
                [&mut fast, &mut fast_walls],
                &fluid,
                &grid,
                (&boundary, &boundary_grid),
                &kernel,
            );
            let (mut slow, mut slow_walls) = (NeighbourLists::default(), NeighbourLists::default());
            slow.build_scalar(&fluid, &fluid, &grid, &kernel, true);
            slow_walls.build_scalar(&fluid, &boundary, &boundary_grid, &kernel, false);
            assert_same(&fast, &slow);
            assert_same(&fast_walls, &slow_walls);
            assert!(!slow_walls.index.is_empty());
        }
    }
}
