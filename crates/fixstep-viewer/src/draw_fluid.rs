//! Fluid particles as dots coloured by density, inside the tank's edges.

use super::colour::STATIC;
use super::draw_list::{Figure, Layer, Paint, Primitive};
use fixstep::fluid::FluidSystem;
use fixstep::math::Real;

/// Appends the twelve edges of the tank, then a dot per fluid particle (by id), painted
/// with its density ratio ρ/ρ₀ at the last substep (1 for a particle emitted since).
pub fn draw_fluid<R: Real>(fluid: &FluidSystem<R>, out: &mut Vec<Primitive>) {
    let tank = &fluid.settings().tank;
    let (lo, hi) = (tank.min.to_f64(), tank.max.to_f64());
    let corner = |i: usize| {
        core::array::from_fn::<f64, 3, _>(|k| if i >> k & 1 == 1 { hi[k] } else { lo[k] })
    };
    // Corners i and i + 2^k differ along axis k only: each pair is one edge.
    for i in 0..8 {
        for k in 0..3 {
            if i >> k & 1 == 0 {
                out.push(Primitive {
                    figure: Figure::Line {
                        a: corner(i),
                        b: corner(i | 1 << k),
                    },
                    paint: Paint::Rgb(STATIC),
                    layer: Layer::Scenery,
                });
            }
        }
    }
    let densities = fluid.densities();
    for (i, position) in fluid.positions().iter().enumerate() {
        let ratio = densities.get(i).map_or(1.0, |d| d.to_f64());
        out.push(Primitive {
            figure: Figure::Dot {
                at: position.to_f64(),
            },
            paint: Paint::Density(ratio),
            layer: Layer::Moving,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::colour::Palette;
    use fixstep::math::Fx;
    use fixstep_scenes::builtin_scene;

    #[test]
    fn the_tank_and_one_dot_per_fluid_particle_coloured_by_density() {
        let scene = builtin_scene::<Fx>("dam_break").expect("built-in");
        let mut world = scene.build().expect("builds");
        for tick in 0..10 {
            world.step(&fixstep::world::TickInput {
                tick,
                ..Default::default()
            });
        }
        let fluid = world.fluid().expect("the dam break has fluid");
        let mut out = Vec::new();
        draw_fluid(fluid, &mut out);
        let lines = out
            .iter()
            .filter(|p| matches!(p.figure, Figure::Line { .. }))
            .count();
        assert_eq!(lines, 12, "the tank's edges");
        out.retain(|p| matches!(p.figure, Figure::Dot { .. }));
        assert_eq!(out.len(), fluid.len());
        assert!(!fluid.is_empty());
        let palette = Palette { top_speed: 1.0 };
        let colours: Vec<[u8; 3]> = out.iter().map(|p| palette.colour(p.paint)).collect();
        // Water is blue, and compressed water (lower in the column) is darker than the
        // stretched surface.
        assert!(colours.iter().all(|c| c[2] > c[0] && c[2] > c[1]));
        assert_ne!(
            palette.colour(Paint::Density(0.97)),
            palette.colour(Paint::Density(1.03))
        );
    }
}
