//! Particles as dots coloured by speed, springs, rods and cables as lines.

use super::draw_list::{Figure, Layer, Paint, Primitive};
use fixstep::math::Real;
use fixstep::particles::ParticleSystem;

/// Colour of spring lines, sRGB.
const SPRING: [u8; 3] = [90, 96, 110];
/// Colour of rods, sRGB.
const ROD: [u8; 3] = [150, 110, 60];
/// Colour of cables, sRGB.
const CABLE: [u8; 3] = [60, 60, 60];

/// Appends a line per spring (scene order), then per rod and cable (scene order), then a
/// dot per live particle (slot order) painted with its speed |v| (m/s).
pub fn draw_particles<R: Real>(particles: &ParticleSystem<R>, out: &mut Vec<Primitive>) {
    for (a, b) in particles.spring_ends() {
        out.push(Primitive {
            figure: Figure::Line {
                a: a.to_f64(),
                b: b.to_f64(),
            },
            paint: Paint::Rgb(SPRING),
            layer: Layer::Moving,
        });
    }
    for (a, b, rod) in particles.link_ends() {
        out.push(Primitive {
            figure: Figure::Line {
                a: a.to_f64(),
                b: b.to_f64(),
            },
            paint: Paint::Rgb(if rod { ROD } else { CABLE }),
            layer: Layer::Moving,
        });
    }
    let live = particles
        .positions()
        .iter()
        .zip(particles.velocities())
        .zip(particles.alive())
        .filter(|(_, alive)| **alive);
    for ((position, velocity), _) in live {
        let [vx, vy, vz] = velocity.to_f64();
        out.push(Primitive {
            figure: Figure::Dot {
                at: position.to_f64(),
            },
            paint: Paint::Speed((vx * vx + vy * vy + vz * vz).sqrt()),
            layer: Layer::Moving,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use fixstep::math::Fx;
    use fixstep_scenes::builtin_scene;

    #[test]
    fn one_dot_per_live_particle_and_a_line_per_spring() {
        let scene = builtin_scene::<Fx>("showcase").expect("built-in");
        let mut world = scene.build().expect("builds");
        for tick in 0..30 {
            world.step(&fixstep::world::TickInput {
                tick,
                ..Default::default()
            });
        }
        let particles = world.particles().expect("the showcase has particles");
        let mut out = Vec::new();
        draw_particles(particles, &mut out);
        let dots = out
            .iter()
            .filter(|p| matches!(p.figure, Figure::Dot { .. }));
        assert_eq!(dots.count(), particles.live_count() as usize);
        assert!(particles.live_count() > 0);
        let lines = out
            .iter()
            .filter(|p| matches!(p.figure, Figure::Line { .. }));
        assert_eq!(lines.count(), particles.spring_ends().count());
        assert!(
            particles.spring_ends().count() > 0,
            "the showcase has springs"
        );
    }
}
