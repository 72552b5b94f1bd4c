//! Particles as dots coloured by speed.

use super::draw_list::{Figure, Layer, Paint, Primitive};
use crate::math::Real;
use crate::particles::ParticleSystem;

/// Appends a dot per live particle, in slot order, painted with its speed |v| (m/s).
pub fn draw_particles<R: Real>(particles: &ParticleSystem<R>, out: &mut Vec<Primitive>) {
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
    use crate::math::Fx;
    use crate::scene::builtin_scene;

    #[test]
    fn one_dot_per_live_particle() {
        let scene = builtin_scene::<Fx>("fountain").expect("built-in");
        let mut world = scene.build().expect("builds");
        for tick in 0..30 {
            world.step(&crate::world::TickInput {
                tick,
                ..Default::default()
            });
        }
        let particles = world.particles().expect("fountain has particles");
        let mut out = Vec::new();
        draw_particles(particles, &mut out);
        assert_eq!(out.len(), particles.live_count() as usize);
        assert!(!out.is_empty());
    }
}
