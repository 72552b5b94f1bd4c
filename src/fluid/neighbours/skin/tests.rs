//! The step's reuse of candidates, seen from the fluid: the lists of every substep are a
//! fresh search's, and no result depends on the scratch (a clone starts without
//! candidates, a restore keeps candidates anchored elsewhere).

use crate::fixstep_scenes::fluid as presets;
use crate::fluid::neighbours::NeighbourLists;
use crate::fluid::{FluidSolver, FluidSystem};
use crate::math::{Fx, Real, Vec3};

/// The benchmark's cube at 8³ particles, DFSPH at Δt = 5 ms in 3 substeps.
fn cube() -> (FluidSystem<Fx>, Fx, Vec3<Fx>) {
    let dt = Fx::from_ratio(1, 200);
    let desc = presets::cube::<Fx>(8, FluidSolver::Dfsph, 3);
    let fluid = FluidSystem::from_desc(&desc, dt).expect("the cube builds");
    (
        fluid,
        dt,
        Vec3::new(Fx::ZERO, Fx::from_ratio(-981, 100), Fx::ZERO),
    )
}

/// Whether the next substep of `fluid` reuses its candidates.
fn reuses(fluid: &FluidSystem<Fx>) -> bool {
    fluid
        .scratch
        .skin
        .covers(&fluid.positions, &fluid.scratch.reach)
}

/// Asserts that the lists of `fluid`'s scratch are those of a fresh search at its
/// positions.
fn assert_fresh_lists(fluid: &FluidSystem<Fx>, step: usize) {
    let s = &fluid.scratch;
    let mut grid = s.grid.clone();
    grid.fill(&fluid.positions);
    let kernel = &fluid.settings.kernel;
    let (mut fresh, mut walls) = (NeighbourLists::default(), NeighbourLists::default());
    fresh.build(&fluid.positions, &fluid.positions, &grid, kernel, true);
    walls.build(
        &fluid.positions,
        &s.boundary,
        &s.boundary_grid,
        kernel,
        false,
    );
    for (found, expected) in [(&s.fluid, &fresh), (&s.walls, &walls)] {
        assert_eq!(found.start, expected.start, "step {step}");
        assert_eq!(found.index, expected.index, "step {step}");
        assert_eq!(found.value, expected.value, "step {step}");
        assert_eq!(found.gradients, expected.gradients, "step {step}");
    }
}

#[test]
fn the_step_finds_the_fresh_searchs_lists() {
    let (mut fluid, dt, gravity) = cube();
    let h = dt * Fx::from_ratio(1, 3);
    let mut reused = 0;
    for step in 0..15 {
        fluid.step(dt, gravity);
        reused += usize::from(reuses(&fluid));
        fluid.find_neighbours(h);
        assert_fresh_lists(&fluid, step);
    }
    assert!(reused >= 5, "reused after {reused} steps of 15");
}

/// A cube thrown at 1.5 m/s moves 2.5 mm per substep of 5/3 ms: twice that is more than
/// the 2.4 mm (δ at H = 2 cm) its candidates allow, so the step searches within the
/// support and keeps no candidates, with the same lists; once the cube has stopped against
/// the wall the candidates come back.
#[test]
fn a_fast_flow_searches_within_the_support_alone() {
    let dt = Fx::from_ratio(1, 200);
    let h = dt * Fx::from_ratio(1, 3);
    let mut desc = presets::cube::<Fx>(8, FluidSolver::Dfsph, 3);
    desc.blocks[0].velocity = Vec3::new(Fx::from_ratio(3, 2), Fx::ZERO, Fx::ZERO);
    let mut fluid = FluidSystem::from_desc(&desc, dt).expect("the cube builds");
    let gravity = Vec3::new(Fx::ZERO, Fx::from_ratio(-981, 100), Fx::ZERO);
    fluid.prepare();
    let s = &fluid.scratch;
    assert!(!s.skin.may_last(&fluid.velocities, h, &s.reach));
    let slower: Vec<_> = fluid
        .velocities
        .iter()
        .map(|&v| v * Fx::from_ratio(1, 4))
        .collect();
    assert!(
        s.skin.may_last(&slower, h, &s.reach),
        "at 0.375 m/s, 2|v|h = 1.25 mm"
    );
    fluid.step(dt, gravity);
    assert!(!reuses(&fluid), "a fast flow keeps no candidates");
    fluid.find_neighbours(h);
    assert_fresh_lists(&fluid, 0);
    let mut slow = false;
    for step in 1..200 {
        fluid.step(dt, gravity);
        fluid.find_neighbours(h);
        assert_fresh_lists(&fluid, step);
        if reuses(&fluid) {
            slow = true;
            break;
        }
    }
    assert!(slow, "the settled cube never reused its candidates again");
}

#[test]
fn a_clone_and_a_restore_step_as_the_uninterrupted_run() {
    let (mut straight, dt, gravity) = cube();
    for _ in 0..4 {
        straight.step(dt, gravity);
    }
    // A moment at which the uninterrupted run goes on with its candidates.
    let mut waited = 0;
    while !reuses(&straight) {
        straight.step(dt, gravity);
        waited += 1;
        assert!(waited < 10, "the run never reuses its candidates");
    }
    let clone = straight.clone();
    // A system whose candidates were found at other positions, then restored.
    let (mut restored, _, _) = cube();
    for _ in 0..3 {
        restored.step(dt, gravity);
    }
    restored.restore_from(straight.clone());
    let mut clone_run = clone;
    for _ in 0..6 {
        straight.step(dt, gravity);
        clone_run.step(dt, gravity);
        restored.step(dt, gravity);
    }
    let bits = |f: &FluidSystem<Fx>| {
        f.positions
            .iter()
            .chain(&f.velocities)
            .flat_map(|v| [v.x, v.y, v.z].map(Fx::to_bits))
            .collect::<Vec<_>>()
    };
    assert_eq!(bits(&clone_run), bits(&straight));
    assert_eq!(bits(&restored), bits(&straight));
}
