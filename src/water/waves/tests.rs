//! The wave step's kernels against the scalar step: with every backend the processor has,
//! on grids whose widths leave tails, with heights and flows from calm water to values at
//! the ends of the format (whose blocks take the scalar operators), open and reflective
//! borders, the heights, flows and saturation count are the scalar step's, bit for bit.

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
    let mut value = || {
        if rare > 0 && rng.below(rare) == 0 {
            [Fx::MAX, Fx::MIN][rng.below(2) as usize]
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
fn the_kernels_give_the_scalar_steps_bits() {
    let mut rng = Pcg32::new(5, 17);
    for trial in 0..60u32 {
        let cells = ([1, 2, 7, 8, 9, 17, 33][trial as usize % 7], 1 + trial % 11);
        let border = [WaterBorder::Reflective, WaterBorder::Open][trial as usize % 2];
        let scale = [0.5, 100.0, 20_000.0, 1e6][trial as usize % 4];
        let rare = [0, 0, 40][trial as usize % 3];
        let start = surface(&mut rng, cells, border, scale, rare);
        let step = |backend| {
            let mut water = start.clone();
            let ((), saturations) = count_saturations(|| {
                with_backend(backend, || {
                    for _ in 0..3 {
                        water.step(Fx::from_ratio(1, 60));
                    }
                })
            });
            (water.heights, water.flow_x, water.flow_z, saturations)
        };
        let scalar = step(None);
        for backend in backends() {
            assert!(
                step(Some(backend)) == scalar,
                "trial {trial} ({cells:?}, {border:?}, scale {scale}): {backend:?} differs"
            );
        }
    }
}
