//! The cell lists over the occupied box ([`Window`]): what a search visits against every
//! point within reach, whatever part of the grid the points occupy, as they move between
//! fills, and with none.

use super::{CellGrid, Window};
use crate::math::{Fx, Pcg32, Real, Vec3};

/// A grid over a 1 m cube with a support of 4 cm: cells of 2 cm, 50 along each axis.
fn metre_grid() -> CellGrid<Fx> {
    CellGrid::new(Vec3::ZERO, Vec3::splat(Fx::ONE), Fx::from_ratio(4, 100))
}

/// `n` random points in the box from `lower` to `lower + side` (m).
fn cloud(n: usize, lower: [i64; 3], side: i64, seed: u64) -> Vec<Vec3<Fx>> {
    let mut rng = Pcg32::new(seed, 3);
    let mut coordinate = |lo: i64| {
        Fx::from_ratio(
            lo * 1000 + i64::from(rng.next_u32() % (side as u32 * 1000)),
            1000,
        ) * Fx::from_ratio(1, 100)
    };
    (0..n)
        .map(|_| {
            Vec3::new(
                coordinate(lower[0]),
                coordinate(lower[1]),
                coordinate(lower[2]),
            )
        })
        .collect()
}

/// Every point `for_each_within` gives for `p` at radius `radius`, in order.
fn visited(grid: &CellGrid<Fx>, p: Vec3<Fx>, radius: Fx) -> Vec<u32> {
    let mut found = Vec::new();
    grid.for_each_within(p, radius.recip(), grid.span(radius), |points| {
        found.extend_from_slice(points)
    });
    found
}

/// Checks that a search around each of `queries` visits every point of `points` closer
/// than the radius, each once, in (cell, index) order.
fn assert_searches_find_all(grid: &CellGrid<Fx>, queries: &[Vec3<Fx>], points: &[Vec3<Fx>]) {
    let radius = Fx::from_ratio(4, 100);
    for (q, &p) in queries.iter().enumerate() {
        let found = visited(grid, p, radius);
        let keys: Vec<(u32, u32)> = found
            .iter()
            .map(|&j| (grid.cells()[j as usize], j))
            .collect();
        assert!(
            keys.windows(2).all(|w| w[0] < w[1]),
            "query {q}: not in (cell, index) order"
        );
        for (j, &x) in points.iter().enumerate() {
            if (x - p).length_squared() < radius * radius {
                assert!(found.contains(&(j as u32)), "query {q}: point {j} missed");
            }
        }
    }
}

#[test]
fn lists_cover_only_the_box_the_points_occupy() {
    let mut grid = metre_grid();
    // 200 points in a 6 cm cube from (40, 60, 20) cm: cells 20..=23, 30..=33, 10..=13.
    let points = cloud(200, [40, 60, 20], 6, 1);
    grid.fill(&points);
    let window = grid.window;
    assert!(window.dims.iter().all(|&d| d <= 4), "window {window:?}");
    assert_eq!(grid.start.len(), window.len() + 1);
    assert_eq!(*grid.start.last().unwrap() as usize, points.len());
    // Queries inside, around and far from the points.
    let mut queries = cloud(50, [36, 56, 16], 14, 2);
    queries.extend(cloud(10, [0, 0, 0], 100, 3));
    assert_searches_find_all(&grid, &queries, &points);
}

#[test]
fn a_refill_moves_the_box_with_the_points() {
    let mut grid = metre_grid();
    grid.fill(&cloud(100, [0, 0, 0], 5, 4));
    let first = grid.window;
    let moved = cloud(100, [90, 80, 70], 8, 5);
    grid.fill(&moved);
    assert_ne!(grid.window, first);
    assert!(
        grid.window.lower.iter().all(|&c| c >= 35),
        "window {:?}",
        grid.window
    );
    assert_searches_find_all(&grid, &cloud(60, [86, 76, 66], 14, 6), &moved);
    // Spread over the whole grid, and beyond it (clamped to the outermost cells).
    let mut spread = cloud(300, [0, 0, 0], 100, 7);
    spread.push(Vec3::from_f64(-0.5, 0.5, 2.0));
    spread.push(Vec3::from_f64(1.5, -3.0, 0.5));
    grid.fill(&spread);
    assert_eq!(grid.window.dims, [50, 50, 50]);
    assert_searches_find_all(&grid, &spread, &spread);
}

#[test]
fn an_empty_fill_lists_nothing_anywhere() {
    let mut grid = metre_grid();
    grid.fill(&cloud(20, [10, 10, 10], 3, 8));
    grid.fill(&[]);
    assert_eq!(grid.window, Window::default());
    assert_eq!(grid.start, [0]);
    for p in cloud(20, [0, 0, 0], 100, 9) {
        assert!(visited(&grid, p, Fx::from_ratio(4, 100)).is_empty());
    }
}
