//! Rigid bodies in the fluid (issue [coupling]): Archimedes' principle. A box of density
//! ρ_b floats in water of density ρ₀ with the fraction ρ_b/ρ₀ of its height below the free
//! surface, and comes to rest; a box denser than water sinks to the floor. A kinematic
//! body moving through the water pushes it and is not pushed; the `harbour` scene restored
//! mid-run continues bit for bit.

use fixstep::fluid::{FluidBlock, FluidBodiesDesc, FluidBox, FluidDesc, FluidSolver};
use fixstep::math::{Fx, Real, Vec3};
use fixstep::rigid::{BodyDesc, BodyKind, CollisionFilter, RigidDesc, Shape};
use fixstep::scene::Scene;
use fixstep::world::{Handle, TickInput, World};

fn v(x: f64, y: f64, z: f64) -> Vec3<Fx> {
    Vec3::new(Fx::from_f64(x), Fx::from_f64(y), Fx::from_f64(z))
}

/// The tank's inside, m.
const TANK: [f64; 3] = [0.24, 0.2, 0.16];
/// Water depth at rest, m, the particle spacing, m, and the box's side, m.
const DEPTH: f64 = 0.12;
const SPACING: f64 = 0.01;
const SIDE: f64 = 0.08;
/// The box's height, m: half its width, so that it floats flat (a cube of relative density
/// 0.5 tips over onto an edge: its metacentre lies below its centre of mass).
const HEIGHT: f64 = 0.04;

/// Water `DEPTH` deep in the tank, DFSPH or WCSPH, and a box of `density` whose bottom
/// starts at the water's surface, centred; the tank's walls are also static rigid boxes (on
/// layer 2, which the fluid ignores) so that the box stays in it.
fn floating(density: f64, solver: FluidSolver) -> Scene<Fx> {
    let tank = FluidBox {
        min: Vec3::ZERO,
        max: v(TANK[0], TANK[1], TANK[2]),
    };
    let mut fluid = FluidDesc::new(solver, Fx::from_f64(SPACING), tank);
    fluid.substeps = match solver {
        FluidSolver::Dfsph => 10,
        FluidSolver::Wcsph => 24,
    };
    if solver == FluidSolver::Wcsph {
        // The flow stays well under 0.5 m/s, so c = 5 m/s keeps WCSPH's compression near
        // 1 % and lets 24 substeps a tick meet its time-step limit. A closed tank radiates
        // no waves away, and without viscosity the box still rocked at 2 cm/s after 4 s.
        fluid.speed_of_sound = Fx::from_int(5);
        fluid.viscosity = Fx::from_ratio(5, 100);
    }
    fluid.blocks.push(FluidBlock {
        region: FluidBox {
            min: Vec3::ZERO,
            max: v(TANK[0], DEPTH, TANK[2]),
        },
        velocity: Vec3::ZERO,
    });
    fluid.bodies = Some(FluidBodiesDesc {
        filter: CollisionFilter { layers: 1, mask: 1 },
    });
    let mut floater = BodyDesc::new(
        Shape::Box {
            half_extents: v(SIDE / 2.0, HEIGHT / 2.0, SIDE / 2.0),
        },
        v(TANK[0] / 2.0, DEPTH + HEIGHT / 2.0, TANK[2] / 2.0),
    );
    floater.density = Fx::from_f64(density);
    let wall = |centre: Vec3<Fx>, half: Vec3<Fx>| {
        let mut body = BodyDesc::new(Shape::Box { half_extents: half }, centre);
        body.kind = BodyKind::Static;
        body.filter = CollisionFilter {
            layers: 2,
            mask: u32::MAX,
        };
        body
    };
    let t = 0.05;
    let [x, y, z] = TANK;
    let walls = [
        wall(v(x / 2.0, -t, z / 2.0), v(x, t, z)),
        wall(v(-t, y / 2.0, z / 2.0), v(t, y, z)),
        wall(v(x + t, y / 2.0, z / 2.0), v(t, y, z)),
        wall(v(x / 2.0, y / 2.0, -t), v(x, y, t)),
        wall(v(x / 2.0, y / 2.0, z + t), v(x, y, t)),
    ];
    let mut bodies = vec![floater];
    bodies.extend(walls);
    let mut scene = Scene::empty("floating");
    scene.rigid = Some(RigidDesc {
        bodies,
        ..RigidDesc::default()
    });
    scene.fluid = Some(fluid);
    scene
}

/// The draft of a box centred at `centre` (m): the depth of its bottom below the free
/// surface, where the water away from the box (beyond one box side of its centre) stands:
/// the volume of that water above the bottom, at rest density (each particle a slab one
/// spacing thick about its centre), over that water's area. So the draft is the far
/// field's hydrostatic pressure at the box's bottom over ρ₀g, which Archimedes' balance
/// sets (ρ₀ g d A = m g); the highest particles alone would read the surface low, as an SPH
/// fluid's top layer sits closer to the one beneath (a few mm at 1 cm spacing).
fn draft(world: &World<Fx>, centre: [f64; 3]) -> f64 {
    let bottom = centre[1] - HEIGHT / 2.0;
    let far = |p: [f64; 3]| (p[0] - centre[0]).abs() >= SIDE || (p[2] - centre[2]).abs() >= SIDE;
    let volume: f64 = world
        .fluid()
        .expect("fluid")
        .positions()
        .iter()
        .map(|p| p.to_f64())
        .filter(|&p| far(p))
        .map(|p| ((p[1] + SPACING / 2.0 - bottom) / SPACING).clamp(0.0, 1.0) * SPACING.powi(3))
        .sum();
    let near_x = (centre[0] + SIDE).min(TANK[0]) - (centre[0] - SIDE).max(0.0);
    let near_z = (centre[2] + SIDE).min(TANK[2]) - (centre[2] - SIDE).max(0.0);
    volume / (TANK[0] * TANK[2] - near_x * near_z)
}

/// The fastest point of body `handle`: |v| + |ω| r with r the box's half diagonal, m/s.
fn fastest_point(world: &World<Fx>, handle: Handle) -> f64 {
    let rigid = world.rigid().expect("rigid");
    let v = rigid
        .linear_velocity(handle)
        .expect("alive")
        .length()
        .to_f64();
    let w = rigid
        .angular_velocity(handle)
        .expect("alive")
        .length()
        .to_f64();
    let reach = (SIDE * SIDE / 2.0 + HEIGHT * HEIGHT / 4.0).sqrt();
    v + w * reach
}

/// Floats a box of 500 kg/m³ under `solver` for `ticks` ticks at 60 Hz; returns its draft
/// at the end (m) and its fastest point over the last `settled` ticks (m/s).
fn float_half_dense_box(solver: FluidSolver, ticks: u64, settled: u64) -> (f64, f64) {
    let mut world = floating(500.0, solver).build().expect("builds");
    let floater = Handle::new(0, 0);
    let mut fastest = 0.0f64;
    for tick in 0..ticks {
        world.step(&TickInput::default());
        if tick >= ticks - settled {
            fastest = fastest.max(fastest_point(&world, floater));
        }
    }
    let centre = world
        .rigid()
        .expect("rigid")
        .position(floater)
        .expect("alive")
        .to_f64();
    (draft(&world, centre), fastest)
}

/// Archimedes: d = h ρ_b/ρ₀ = 2 cm, within 3 % of the box's height (1.2 mm).
fn assert_archimedes(solver: FluidSolver, draft: f64, fastest: f64) {
    let expected = HEIGHT * 500.0 / 1000.0;
    assert!(
        (draft - expected).abs() <= 0.03 * HEIGHT,
        "{solver:?}: draft {draft:.5} m, Archimedes {expected:.5} m"
    );
    assert!(
        fastest < 0.01,
        "{solver:?}: still moving at {fastest:.4} m/s"
    );
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "4608 particles for 3 s: checked by the release test run"
)]
fn a_box_half_as_dense_as_water_floats_half_submerged_and_comes_to_rest_dfsph() {
    let (draft, fastest) = float_half_dense_box(FluidSolver::Dfsph, 180, 20);
    assert_archimedes(FluidSolver::Dfsph, draft, fastest);
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "4608 particles for 3 s, 24 substeps a tick: checked by the release test run"
)]
fn a_box_half_as_dense_as_water_floats_half_submerged_and_comes_to_rest_wcsph() {
    let (draft, fastest) = float_half_dense_box(FluidSolver::Wcsph, 180, 20);
    assert_archimedes(FluidSolver::Wcsph, draft, fastest);
}

#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "4608 particles for up to 1.5 s: checked by the release test run"
)]
fn a_box_twice_as_dense_as_water_sinks_to_the_floor() {
    let mut world = floating(2000.0, FluidSolver::Dfsph)
        .build()
        .expect("builds");
    let sinker = Handle::new(0, 0);
    let bottom = |world: &World<Fx>| {
        let centre = world
            .rigid()
            .expect("rigid")
            .position(sinker)
            .expect("alive");
        centre.to_f64()[1] - HEIGHT / 2.0
    };
    // On the floor, or on the last layer of water it could not squeeze out (one spacing),
    // within 90 ticks.
    let mut ticks = 0;
    while bottom(&world) >= SPACING && ticks < 90 {
        world.step(&TickInput::default());
        ticks += 1;
    }
    let bottom = bottom(&world);
    assert!(
        bottom < SPACING,
        "bottom {bottom:.4} m above the floor after 1.5 s"
    );
}

/// Water 10 cm deep at 2 cm spacing in a 40 × 16 cm tank, and a kinematic box 8 × 4 × 8 cm
/// under water (its top 4 cm below the surface), moving along +x at 0.1 m/s.
fn paddled() -> Scene<Fx> {
    let tank = FluidBox {
        min: Vec3::ZERO,
        max: v(0.4, 0.2, 0.16),
    };
    let mut fluid = FluidDesc::new(FluidSolver::Dfsph, Fx::from_f64(0.02), tank);
    fluid.substeps = 6;
    // The water around the box: below, above, and beside it on its four sides.
    let regions = [
        ([0.0, 0.0, 0.0], [0.4, 0.02, 0.16]),
        ([0.0, 0.06, 0.0], [0.4, 0.1, 0.16]),
        ([0.0, 0.02, 0.0], [0.06, 0.06, 0.16]),
        ([0.14, 0.02, 0.0], [0.4, 0.06, 0.16]),
        ([0.06, 0.02, 0.0], [0.14, 0.06, 0.04]),
        ([0.06, 0.02, 0.12], [0.14, 0.06, 0.16]),
    ];
    for (min, max) in regions {
        fluid.blocks.push(FluidBlock {
            region: FluidBox {
                min: v(min[0], min[1], min[2]),
                max: v(max[0], max[1], max[2]),
            },
            velocity: Vec3::ZERO,
        });
    }
    fluid.bodies = Some(FluidBodiesDesc {
        filter: CollisionFilter::default(),
    });
    let mut paddle = BodyDesc::new(
        Shape::Box {
            half_extents: v(0.04, 0.02, 0.04),
        },
        v(0.1, 0.04, 0.08),
    );
    paddle.kind = BodyKind::Kinematic;
    paddle.velocity = v(PADDLE_SPEED, 0.0, 0.0);
    let mut scene = Scene::empty("paddled");
    scene.rigid = Some(RigidDesc {
        bodies: vec![paddle],
        ..RigidDesc::default()
    });
    scene.fluid = Some(fluid);
    scene
}

/// The paddle's speed, m/s.
const PADDLE_SPEED: f64 = 0.1;

/// A kinematic box moving through water pushes the water ahead of it forward, while the
/// water as a whole flows back into the room it leaves (in a tank the water's centre of
/// mass moves against the body); the box keeps its course, and no water enters it.
#[test]
fn a_kinematic_body_moves_the_water_and_keeps_its_course() {
    let mut world = paddled().build().expect("builds");
    let paddle = Handle::new(0, 0);
    for _ in 0..30 {
        world.step(&TickInput::default());
    }
    let rigid = world.rigid().expect("rigid");
    assert_eq!(
        rigid.linear_velocity(paddle),
        Some(v(PADDLE_SPEED, 0.0, 0.0))
    );
    let centre = rigid.position(paddle).expect("alive").to_f64();
    let fluid = world.fluid().expect("fluid");
    let particles: Vec<([f64; 3], [f64; 3])> = fluid
        .positions()
        .iter()
        .zip(fluid.velocities())
        .map(|(p, u)| (p.to_f64(), u.to_f64()))
        .collect();
    let momentum: f64 = particles.iter().map(|(_, u)| u[0]).sum::<f64>();
    assert!(
        momentum < 0.0,
        "the water's momentum along x: {momentum:.5} × m"
    );
    // Within a spacing of the leading face, across it.
    let ahead: Vec<f64> = particles
        .iter()
        .filter(|(p, _)| {
            let gap = p[0] - (centre[0] + 0.04);
            (0.0..0.02).contains(&gap)
                && (p[1] - centre[1]).abs() < 0.02
                && (p[2] - centre[2]).abs() < 0.04
        })
        .map(|(_, u)| u[0])
        .collect();
    let mean_ahead = ahead.iter().sum::<f64>() / ahead.len().max(1) as f64;
    assert!(
        !ahead.is_empty() && mean_ahead > 0.25 * PADDLE_SPEED,
        "water ahead of the box at {mean_ahead:.4} m/s ({} particles)",
        ahead.len()
    );
    for (p, _) in &particles {
        let inside = [0.04, 0.02, 0.04]
            .iter()
            .enumerate()
            .all(|(a, half)| (p[a] - centre[a]).abs() < half - 0.01);
        assert!(!inside, "a particle at {p:?} inside the box at {centre:?}");
    }
}

#[test]
fn harbour_restored_mid_run_continues_like_an_uninterrupted_run() {
    crate::restore_support::restored_mid_run_continues("harbour", 60, 40);
}

#[test]
fn a_fluid_meeting_bodies_beside_soft_bodies_tied_to_them_is_refused_naming_soft() {
    let mut scene = fixstep_scenes::builtin_scene::<Fx>("flag").expect("built in");
    scene.fluid = fixstep_scenes::builtin_scene::<Fx>("harbour")
        .expect("built in")
        .fluid;
    let Err(error) = scene.build() else {
        panic!("refused")
    };
    assert_eq!(error.field, "soft", "{error:?}");
}
