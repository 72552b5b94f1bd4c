//! The counting-sort grid and the neighbour lists against brute force, and the lists found
//! from candidates with a skin against a fresh search.

use fixstep::fluid::grid::CellGrid;
use fixstep::fluid::kernel::Kernel;
use fixstep::fluid::neighbours::NeighbourLists;
use fixstep::fluid::neighbours::skin::{CandidateRows, Reach, SkinLists};
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

/// The lists the step finds from candidates with a skin ([`SkinLists`]) against a fresh
/// search, in every substep of random motion: particles drifting up to 0.43 mm per
/// substep (H = 1 cm, so the candidates last several substeps while particles change
/// cells, which reorders rows), and one particle jumping 3 mm, which must force a new
/// selection. Fluid and boundary lists alike, entry for entry and in order.
#[test]
fn reused_candidates_give_the_fresh_lists_as_particles_move() {
    let kernel = Kernel::<Fx>::calibrated(Fx::from_ratio(5, 1000), Fx::TWO);
    let new_grid = || {
        CellGrid::new(
            Vec3::ZERO,
            Vec3::splat(Fx::from_ratio(1, 10)),
            kernel.support,
        )
    };
    let mut pts = points(1500, 3);
    let boundary = points(600, 4);
    let mut boundary_grid = new_grid();
    boundary_grid.fill(&boundary);
    let mut grid = new_grid();
    let reach = Reach::new(&kernel, &grid);
    let mut rng = Pcg32::new(5, 9);
    let quarter_mm = Fx::from_ratio(1, 4000).to_bits() as u64;
    let drift: Vec<Vec3<Fx>> = (0..pts.len())
        .map(|_| {
            let mut c = || {
                Fx::from_bits((rng.next_u64() % (2 * quarter_mm)) as i64) - Fx::from_ratio(1, 4000)
            };
            Vec3::new(c(), c(), c())
        })
        .collect();
    let mut skin = SkinLists::default();
    let (mut fluid, mut walls) = (NeighbourLists::default(), NeighbourLists::default());
    let (mut reused, mut reordered, mut jump_rebuilt) = (0, 0, false);
    let mut built_scalar = None;
    for substep in 0..40 {
        for (p, &v) in pts.iter_mut().zip(&drift) {
            *p += v;
        }
        if substep == 25 {
            pts[700].x += Fx::from_ratio(3, 1000);
        }
        if skin.covers(&pts, &reach) {
            reused += 1;
            grid.locate(&pts);
            let before = skin.fluid.clone();
            skin.fluid.order_by_cells(grid.cells());
            reordered += (0..pts.len())
                .filter(|&i| before.row(i) != skin.fluid.row(i))
                .count();
            fluid.evaluate(&skin.fluid, &pts, &pts, &kernel);
            walls.evaluate(&skin.walls, &pts, &boundary, &kernel);
        } else {
            jump_rebuilt |= substep == 25;
            grid.fill(&pts);
            let lists = [&mut fluid, &mut walls];
            skin.build(
                &pts,
                &grid,
                &boundary,
                &boundary_grid,
                &reach,
                &kernel,
                lists,
            );
            // The scalar form of the build's single pass, which targets without AVX-512
            // take: the same candidates.
            let (mut rows, mut wall_rows) = (CandidateRows::default(), CandidateRows::default());
            let (mut built, mut built_walls) =
                (NeighbourLists::default(), NeighbourLists::default());
            let (fluid_set, wall_set) = ((&pts[..], &grid), (&boundary[..], &boundary_grid));
            built
                .build_keeping_candidates_scalar(&mut rows, &pts, fluid_set, &reach, &kernel, true);
            built_walls.build_keeping_candidates_scalar(
                &mut wall_rows,
                &pts,
                wall_set,
                &reach,
                &kernel,
                false,
            );
            for i in 0..pts.len() {
                assert_eq!(rows.row(i), skin.fluid.row(i), "substep {substep}");
                assert_eq!(wall_rows.row(i), skin.walls.row(i), "substep {substep}");
            }
            assert_eq!(rows.len(), pts.len());
            assert_eq!(wall_rows.len(), pts.len());
            built_scalar = Some((built, built_walls));
        }
        // The scalar forms, which targets without AVX-512 take.
        let (fluid_scalar, walls_scalar) = built_scalar.take().unwrap_or_else(|| {
            let (mut fluid_scalar, mut walls_scalar) =
                (NeighbourLists::default(), NeighbourLists::default());
            fluid_scalar.evaluate_scalar(&skin.fluid, &pts, &pts, &kernel);
            walls_scalar.evaluate_scalar(&skin.walls, &pts, &boundary, &kernel);
            (fluid_scalar, walls_scalar)
        });
        let mut fresh_grid = new_grid();
        fresh_grid.fill(&pts);
        let (mut fresh, mut fresh_walls) = (NeighbourLists::default(), NeighbourLists::default());
        fresh.build(&pts, &pts, &fresh_grid, &kernel, true);
        fresh_walls.build(&pts, &boundary, &boundary_grid, &kernel, false);
        for (found, expected) in [
            (&fluid, &fresh),
            (&walls, &fresh_walls),
            (&fluid_scalar, &fresh),
            (&walls_scalar, &fresh_walls),
        ] {
            assert_eq!(found.start, expected.start, "substep {substep}");
            assert_eq!(found.index, expected.index, "substep {substep}");
            assert_eq!(found.value, expected.value, "substep {substep}");
            assert_eq!(found.gradients, expected.gradients, "substep {substep}");
        }
    }
    assert!(reused >= 20, "reused in {reused} substeps of 40");
    assert!(reordered > 0, "no row changed order");
    assert!(jump_rebuilt, "the jump did not force a new selection");
}

/// The skin's reuse test: within the limit it holds, a particle beyond it, a particle
/// more or less, or lists never built, and it does not.
#[test]
fn the_candidates_hold_only_near_their_anchors() {
    let kernel = Kernel::<Fx>::calibrated(Fx::from_ratio(5, 1000), Fx::TWO);
    let mut grid = CellGrid::new(
        Vec3::ZERO,
        Vec3::splat(Fx::from_ratio(1, 10)),
        kernel.support,
    );
    let mut pts = points(300, 6);
    grid.fill(&pts);
    let reach = Reach::new(&kernel, &grid);
    let mut no_boundary = grid.clone();
    no_boundary.fill(&[]);
    let mut skin = SkinLists::default();
    assert!(!skin.covers(&pts, &reach), "never built");
    let (mut fluid, mut walls) = (NeighbourLists::default(), NeighbourLists::default());
    let lists = [&mut fluid, &mut walls];
    skin.build(&pts, &grid, &[], &no_boundary, &reach, &kernel, lists);
    assert!(skin.covers(&pts, &reach));
    // δ = (σ/2 − 2⁻⁸) H = (1/8 − 1/256) cm = 1.21 mm.
    pts[10].y += Fx::from_ratio(12, 10_000);
    assert!(skin.covers(&pts, &reach), "1.2 mm");
    pts[10].y += Fx::from_ratio(2, 100_000);
    assert!(!skin.covers(&pts, &reach), "1.22 mm");
    pts[10].y -= Fx::from_ratio(2, 100_000);
    pts[20] = Vec3::new(Fx::MAX, Fx::MIN, Fx::MAX);
    assert!(!skin.covers(&pts, &reach), "a saturated displacement");
    pts.truncate(200);
    assert!(!skin.covers(&pts, &reach), "fewer particles");
}

/// The `f64` baseline takes the scalar forms everywhere: a new selection's lists (one pass
/// of the grid) are the fresh search's, entry for entry, and its candidates evaluate to
/// them again.
#[test]
fn a_new_selection_in_f64_finds_the_fresh_lists() {
    let kernel = Kernel::<f64>::calibrated(0.005, 2.0);
    let mut grid = CellGrid::new(Vec3::ZERO, Vec3::splat(0.1), kernel.support);
    let pts: Vec<Vec3<f64>> = points(1500, 8)
        .iter()
        .map(|p| Vec3::new(p.x.to_f64(), p.y.to_f64(), p.z.to_f64()))
        .collect();
    grid.fill(&pts);
    let reach = Reach::new(&kernel, &grid);
    let mut rows = CandidateRows::default();
    let (mut built, mut fresh, mut evaluated) = (
        NeighbourLists::default(),
        NeighbourLists::default(),
        NeighbourLists::default(),
    );
    built.build_keeping_candidates(&mut rows, &pts, (&pts, &grid), &reach, &kernel, true);
    fresh.build(&pts, &pts, &grid, &kernel, true);
    evaluated.evaluate(&rows, &pts, &pts, &kernel);
    assert!(
        fresh.index.len() > 4 * pts.len(),
        "about six neighbours each"
    );
    for lists in [&built, &evaluated] {
        assert_eq!(lists.start, fresh.start);
        assert_eq!(lists.index, fresh.index);
        assert_eq!(lists.value, fresh.value);
        assert_eq!(lists.gradients, fresh.gradients);
    }
    let candidates: usize = (0..rows.len()).map(|i| rows.row(i).len()).sum();
    assert!(candidates > fresh.index.len(), "the skin adds candidates");
}
