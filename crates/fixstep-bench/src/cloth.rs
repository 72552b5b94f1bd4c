// ok-det: benchmark driver; the cloth runs in I32F32, only timings, stretches and the stability verdict are f64 reporting values.
//! The trade the physics notes describe: implicit Euler against semi-implicit Euler on a
//! stiff 64 × 64 spring-mass cloth, each at the largest stable step it takes.
//!
//! # The test
//!
//! A 2 m × 2 m sheet of 64 × 64 vertices (1 kg in all, so 0.24 g each) pinned at its two top
//! corners, springs along the grid edges and diagonals (the spring-mass cloth's topology)
//! of stiffness [`STIFFNESS`] N/m and damping 0.01 N·s/m, under gravity, hanging
//! horizontally at the start so that it swings down. For each integrator the world's
//! substeps per 60 Hz tick go 1, 2, 4, … up to [`MAX_SUBSTEPS`]; a run is **stable** when
//! over [`SECONDS`] s of simulated time the divergence check stays quiet, nothing
//! saturates and the largest edge stretch stays below 50 %. The smallest stable substep
//! count (the largest stable step) is then timed over the same run: the table reports the
//! step, the wall time per simulated second and the final largest stretch.

use std::time::Instant;

use fixstep::math::{Fx, Real, Vec3};
use fixstep::particles::Integrator;
use fixstep::scene::Scene;
use fixstep::soft::{SoftBodyDesc, SoftDesc, SoftModel, SoftShape, XpbdSettings};
use fixstep::world::{TickInput, World};

/// Vertices along each side.
pub const SIDE: u32 = 64;
/// Spring stiffness, N/m.
pub const STIFFNESS: i32 = 2000;
/// The most substeps per tick tried.
pub const MAX_SUBSTEPS: u32 = 64;
/// Simulated seconds per run.
pub const SECONDS: u64 = 2;
const TICK_RATE: u32 = 60;

/// One integrator's result.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClothRow {
    /// The scheme.
    pub integrator: Integrator,
    /// The fewest substeps per 60 Hz tick found stable, if any up to [`MAX_SUBSTEPS`].
    pub substeps: Option<u32>,
    /// Wall time per simulated second at that step, ms.
    pub milliseconds_per_second: f64,
    /// The largest edge stretch at the end of the run, as a fraction of rest length.
    pub max_stretch: f64,
}

/// The cloth scene with `integrator` at `substeps` per tick.
pub fn cloth_scene(integrator: Integrator, substeps: u32) -> Scene<Fx> {
    let mut scene = Scene::empty("implicit-cloth");
    scene.tick_rate = TICK_RATE;
    scene.substeps = substeps;
    let mut body = SoftBodyDesc {
        shape: SoftShape::Cloth {
            origin: Vec3::new(-Fx::ONE, Fx::TWO, Fx::ZERO),
            u: Vec3::new(Fx::TWO, Fx::ZERO, Fx::ZERO),
            v: Vec3::new(Fx::ZERO, Fx::ZERO, Fx::TWO),
            columns: SIDE,
            rows: SIDE,
        },
        model: SoftModel::SpringMass {
            integrator,
            stiffness: Fx::from_int(STIFFNESS),
            damping: Fx::from_ratio(1, 100),
        },
        mass: Fx::ONE,
        pins: vec![0, SIDE - 1],
        attachments: Vec::new(),
        body_attachments: Vec::new(),
        body_contacts: None,
        velocity: Vec3::ZERO,
        damping: Fx::ZERO,
        radius: Fx::from_ratio(1, 100),
        wind: Vec3::ZERO,
        drag: Fx::ZERO,
    };
    body.damping = Fx::ZERO;
    scene.soft = Some(SoftDesc {
        bodies: vec![body],
        colliders: Vec::new(),
        solver: XpbdSettings::default(),
    });
    scene
}

/// Runs the cloth for [`SECONDS`] s; returns (stable, wall seconds, final largest stretch).
fn run(integrator: Integrator, substeps: u32) -> (bool, f64, f64) {
    let mut world: World<Fx> = cloth_scene(integrator, substeps)
        .build()
        .expect("the cloth builds");
    world.enable_divergence_check(10);
    let started = Instant::now(); // ok-det: wall time is reported, never simulated
    let mut stable = true;
    for _ in 0..SECONDS * u64::from(TICK_RATE) {
        let tick = world.tick();
        world.step(&TickInput {
            tick,
            players: Vec::new(),
        });
        if world.divergence().is_some()
            || world.saturations_total() > 0
            || world.metrics().max_stretch > 0.5
        {
            stable = false;
            break;
        }
    }
    let wall = started.elapsed().as_secs_f64();
    (stable, wall, world.metrics().max_stretch)
}

/// Measures each of `integrators` (see the [module documentation](self)).
pub fn run_cloth(integrators: &[Integrator]) -> Vec<ClothRow> {
    integrators
        .iter()
        .map(|&integrator| {
            let mut substeps = 1;
            while substeps <= MAX_SUBSTEPS {
                let (stable, wall, max_stretch) = run(integrator, substeps);
                if stable {
                    return ClothRow {
                        integrator,
                        substeps: Some(substeps),
                        milliseconds_per_second: 1e3 * wall / SECONDS as f64,
                        max_stretch,
                    };
                }
                substeps *= 2;
            }
            ClothRow {
                integrator,
                substeps: None,
                milliseconds_per_second: f64::INFINITY,
                max_stretch: f64::INFINITY,
            }
        })
        .collect()
}

/// The table of `rows`, one line each after a header.
pub fn cloth_table(rows: &[ClothRow]) -> Vec<String> {
    let mut lines = vec![format!(
        "{SIDE}x{SIDE} spring-mass cloth, k = {STIFFNESS} N/m, 1 kg: the largest stable step of each integrator"
    )];
    lines.push(format!(
        "{:<18} {:>9} {:>10} {:>16} {:>12}",
        "integrator", "substeps", "step (ms)", "ms per sim. s", "max stretch"
    ));
    for row in rows {
        match row.substeps {
            Some(substeps) => lines.push(format!(
                "{:<18} {:>9} {:>10.3} {:>16.1} {:>11.2}%",
                row.integrator.name(),
                substeps,
                1e3 / f64::from(TICK_RATE * substeps),
                row.milliseconds_per_second,
                100.0 * row.max_stretch
            )),
            None => lines.push(format!(
                "{:<18} unstable up to {MAX_SUBSTEPS} substeps",
                row.integrator.name()
            )),
        }
    }
    lines
}
