//! The world a networked session simulates.

use fixstep::math::Fx;
use fixstep::scene::Scene;
use fixstep::world::World;

/// The scene's world at tick 0. Like a replay, a session carries no code, so a scene with
/// user forces (`User(name: ...)`) is refused, naming the force.
pub fn build_world(scene: &Scene<Fx>) -> Result<World<Fx>, String> {
    let world = scene.build().map_err(|e| format!("{}: {e}", scene.name))?;
    if let Some(particles) = world.particles() {
        particles
            .check_user_forces()
            .map_err(|e| format!("{}: {}", scene.name, e.within("particles")))?;
    }
    Ok(world)
}
