//! Trails: the recent path of each particle as a line fading into the background, for
//! scenes with few particles (orbits, pendulums), where a dot alone hides the motion.

use std::collections::VecDeque;

use super::colour::BACKGROUND;
use super::draw_list::{Figure, Layer, Paint, Primitive};
use super::geometry::P3;
use fixstep::math::Real;
use fixstep::particles::ParticleSystem;
use fixstep::world::Handle;

/// Ticks of path kept behind each particle (1.5 s at 60 Hz).
const TRAIL_TICKS: usize = 90;

/// Trails are drawn only while at most this many particles live; beyond, they would
/// cover the picture.
const MAX_PARTICLES: u32 = 64;

/// Colour of the newest end of a trail, sRGB.
const TRAIL: [u8; 3] = [84, 96, 136];

/// The recent positions of each particle slot.
#[derive(Clone, Debug, Default)]
pub struct Trails {
    slots: Vec<Trail>,
}

#[derive(Clone, Debug, Default)]
struct Trail {
    /// The particle the positions belong to; a new particle in the slot starts afresh.
    handle: Option<Handle>,
    points: VecDeque<P3>,
}

impl Trails {
    /// Adds the current position of every live particle (call once per tick).
    pub fn record<R: Real>(&mut self, particles: &ParticleSystem<R>) {
        if particles.live_count() > MAX_PARTICLES {
            self.slots.clear();
            return;
        }
        self.slots
            .resize_with(particles.slot_count(), Trail::default);
        let mut seen = vec![false; self.slots.len()];
        for handle in particles.handles() {
            let (Some(trail), Some(position)) = (
                self.slots.get_mut(handle.index as usize),
                particles.position(handle),
            ) else {
                continue;
            };
            if trail.handle != Some(handle) {
                trail.handle = Some(handle);
                trail.points.clear();
            }
            trail.points.push_back(position.to_f64());
            if trail.points.len() > TRAIL_TICKS {
                trail.points.pop_front();
            }
            seen[handle.index as usize] = true;
        }
        for (trail, seen) in self.slots.iter_mut().zip(seen) {
            if !seen {
                *trail = Trail::default();
            }
        }
    }

    /// Appends each trail as lines, oldest first, mixed from the background (oldest) to
    /// [`TRAIL`] (newest).
    pub fn draw(&self, out: &mut Vec<Primitive>) {
        for trail in &self.slots {
            let n = trail.points.len();
            for (k, (a, b)) in trail
                .points
                .iter()
                .zip(trail.points.iter().skip(1))
                .enumerate()
            {
                let f = (k + 1) as f64 / n as f64;
                let colour = core::array::from_fn(|c| {
                    let (from, to) = (f64::from(BACKGROUND[c]), f64::from(TRAIL[c]));
                    (from + (to - from) * f).round() as u8
                });
                out.push(Primitive {
                    figure: Figure::Line { a: *a, b: *b },
                    paint: Paint::Rgb(colour),
                    layer: Layer::Trail,
                });
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use fixstep::math::Fx;
    use fixstep::world::TickInput;
    use fixstep_scenes::builtin_scene;

    #[test]
    fn each_orbiting_body_leaves_a_trail_of_the_ticks_it_lived() {
        let scene = builtin_scene::<Fx>("orbits").expect("built-in");
        let mut world = scene.build().expect("builds");
        let mut trails = Trails::default();
        for tick in 0..10 {
            trails.record(world.particles().expect("particles"));
            world.step(&TickInput {
                tick,
                ..Default::default()
            });
        }
        let mut out = Vec::new();
        trails.draw(&mut out);
        let live = world.particles().expect("particles").live_count() as usize;
        assert_eq!(out.len(), live * 9, "10 positions, 9 segments per particle");
    }
}
