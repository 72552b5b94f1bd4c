//! The counting-sort grid and the neighbour lists against brute force.

use fixstep::fluid::grid::CellGrid;
use fixstep::fluid::kernel::Kernel;
use fixstep::fluid::neighbours::NeighbourLists;
use fixstep::math::{Fx, Pcg32, Real, Vec3};

/// Random points in a 0.1 m cube and a few outside the grid.
fn points(n: usize, seed: u64) -> Vec<Vec3<Fx>> {
    let mut rng = Pcg32::new(seed, 7);
    let mut out: Vec<Vec3<Fx>> = (0..n)
        .map(|_| {
            let mut c = || Fx::from_ratio(i64::from(rng.next_u32() % 100_000), 1_000_000);
            Vec3::new(c(), c(), c())
        })
        .collect();
    out.push(Vec3::from_f64(0.05, 0.5, 0.05));
    out.push(Vec3::from_f64(0.05, 0.51, 0.05));
    out.push(Vec3::from_f64(-0.3, 0.0, 0.02));
    out
}

#[test]
fn grid_lists_match_brute_force_in_deterministic_order() {
    let pts = points(2000, 1);
    let kernel = Kernel::<Fx>::calibrated(Fx::from_ratio(5, 1000), Fx::TWO);
    let mut grid = CellGrid::new(
        Vec3::ZERO,
        Vec3::splat(Fx::from_ratio(1, 10)),
        kernel.support,
    );
    grid.fill(&pts);
    let mut lists = NeighbourLists::default();
    lists.build(&pts, &pts, &grid, &kernel, true);
    for (i, &xi) in pts.iter().enumerate() {
        let brute: Vec<u32> = (0..pts.len())
            .filter(|&j| j != i && kernel.evaluate(xi - pts[j]).is_some())
            .map(|j| j as u32)
            .collect();
        let mut found = lists.index[lists.range(i)].to_vec();
        // The lists run by (cell, id): sorted by id within each cell, so the same set.
        let cells: Vec<u32> = found
            .iter()
            .map(|&j| grid.cell_index(grid.coords(pts[j as usize])))
            .collect();
        assert!(
            cells
                .windows(2)
                .zip(found.windows(2))
                .all(|(c, j)| c[0] < c[1] || (c[0] == c[1] && j[0] < j[1])),
            "particle {i}: not in (cell, id) order"
        );
        found.sort_unstable();
        assert_eq!(found, brute, "particle {i}");
    }
}

#[test]
fn rebuilding_gives_the_same_lists() {
    let pts = points(500, 2);
    let kernel = Kernel::<Fx>::calibrated(Fx::from_ratio(5, 1000), Fx::TWO);
    let build = || {
        let mut grid = CellGrid::new(
            Vec3::ZERO,
            Vec3::splat(Fx::from_ratio(1, 10)),
            kernel.support,
        );
        grid.fill(&pts);
        let mut lists = NeighbourLists::default();
        lists.build(&pts, &pts, &grid, &kernel, true);
        lists
    };
    let (a, b) = (build(), build());
    assert_eq!(a.index, b.index);
    assert_eq!(a.value, b.value);
    assert_eq!(a.gradients, b.gradients);
}
