//! Built-in scenes, addressable by name.

use super::description::Scene;
use crate::math::Real;
use crate::particles::presets;

/// Name and one-line description of every built-in scene, in listing order.
pub const BUILTIN_SCENES: [(&str, &str); 3] = [
    (
        "showcase",
        "everything fixstep simulates so far: emitters, springs and damping",
    ),
    (
        "fountain",
        "emitters spraying particles up against gravity and quadratic drag",
    ),
    (
        "orbits",
        "bodies on Kepler-like orbits around a softened point mass",
    ),
];

/// The built-in scene called `name`.
pub fn builtin_scene<R: Real>(name: &str) -> Option<Scene<R>> {
    let (name, description) = BUILTIN_SCENES.iter().find(|(n, _)| *n == name)?;
    let mut scene = Scene::empty(name);
    scene.description = (*description).to_owned();
    scene.seed = 0x5eed;
    match *name {
        "showcase" => {
            scene.particles = Some(presets::showcase_particles());
            scene.ticks = 600;
        }
        "fountain" => {
            scene.particles = Some(presets::fountain());
            scene.ticks = 600;
        }
        "orbits" => {
            scene.gravity = crate::math::Vec3::ZERO;
            scene.particles = Some(presets::orbits());
            scene.ticks = 1200;
        }
        _ => return None,
    }
    Some(scene)
}
