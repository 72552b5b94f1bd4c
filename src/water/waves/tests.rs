//! The wave step's kernel against the scalar step ([`WaterSystem::scalar_wave_step`]): with
//! every backend the processor has and on the portable lanes (no backend), on grids whose
//! widths leave tails, with heights and flows from calm water through the narrow and wide
//! products to values at the edges of their bounds and the ends of the format (whose
//! blocks take the scalar operators), open and reflective borders, the heights, flows and
//! saturation count are the scalar step's, bit for bit.

use crate::math::saturation::count_saturations;
use crate::math::wide::{backends, with_backend};
use crate::math::{Fx, Pcg32, Real, Vec3};
use crate::water::{WaterBorder, WaterDesc, WaterSystem};

/// A `columns` × `rows` surface with random heights and flows up to `scale` (m, m²/s),
/// one value in `rare` at an end of the format (none when `rare` is 0).
fn surface(
    rng: &mut Pcg32,
    (columns, rows): (u32, u32),
    border: WaterBorder,
    scale: f64, // ok-det: test input
    rare: u32,
) -> WaterSystem<Fx> {
    let desc = WaterDesc {
        origin: Vec3::ZERO,
        cells: (columns, rows),
        cell_size: Fx::from_ratio(2, 25),
        depth: Fx::HALF,
        wave_speed: None,
        damping: Fx::from_ratio(1, 10),
        density: Fx::from_int(1000),
        border,
        particles: Vec::new(),
        bodies: None,
    };
    let gravity = Vec3::new(Fx::ZERO, Fx::from_f64(-9.81), Fx::ZERO);
    let mut water = WaterSystem::from_desc(&desc, Fx::from_ratio(1, 60), gravity).unwrap();
    let edges = [
        Fx::MAX,
        Fx::MIN,
        Fx::from_bits(1 << 31),
        Fx::from_bits((1 << 31) - 1),
        Fx::from_bits(-(1 << 31)),
        Fx::from_bits(-(1 << 31) - 1),
        Fx::from_bits(1 << 46),
        Fx::from_bits((1 << 46) - 1),
        Fx::from_bits(-(1 << 46)),
        Fx::from_bits(-(1 << 46) - 1),
    ];
    let mut value = || {
        if rare > 0 && rng.below(rare) == 0 {
            edges[rng.below(edges.len() as u32) as usize]
        } else {
            rng.range(Fx::from_f64(-scale), Fx::from_f64(scale))
        }
    };
    for u in water.heights.iter_mut() {
        *u = value();
    }
    for q in water.flow_x.iter_mut().chain(water.flow_z.iter_mut()) {
        *q = value();
    }
    water
}

#[test]
fn the_kernel_gives_the_scalar_steps_bits() {
    let mut rng = Pcg32::new(5, 17);
    let dt = Fx::from_ratio(1, 60);
    for trial in 0..70u32 {
        let cells = ([1, 2, 7, 8, 9, 17, 33][trial as usize % 7], 1 + trial % 11);
        let border = [WaterBorder::Reflective, WaterBorder::Open][trial as usize % 2];
        let scale = [0.1, 0.5, 100.0, 20_000.0, 1e6][trial as usize % 5];
        let rare = [0, 0, 40][trial as usize % 3];
        let start = surface(&mut rng, cells, border, scale, rare);
        let outcome = |water: WaterSystem<Fx>, saturations| {
            (water.heights, water.flow_x, water.flow_z, saturations)
        };
        let mut water = start.clone();
        let ((), saturations) = count_saturations(|| {
            let h = dt / Fx::from_int(water.settings.substeps as i32);
            for _ in 0..3 * water.settings.substeps {
                let factors = water.factors(h);
                water.scalar_wave_step(&factors);
            }
        });
        let scalar = outcome(water, saturations);
        let backends = backends().into_iter().map(Some).chain([None]);
        for backend in backends {
            let mut water = start.clone();
            let ((), saturations) = count_saturations(|| {
                with_backend(backend, || {
                    for _ in 0..3 {
                        water.step(dt);
                    }
                })
            });
            assert!(
                outcome(water, saturations) == scalar,
                "trial {trial} ({cells:?}, {border:?}, scale {scale}): {backend:?} differs"
            );
        }
    }
}
