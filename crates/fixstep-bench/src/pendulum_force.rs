//! The pendulum as a user force: the particle system has no constraints, so a bob on a rigid
//! rod cannot be built from its force generators. The benchmark integrates the pendulum's
//! 1-D equation instead, letting a particle's x coordinate stand for the angle θ.

use fixstep::math::{Real, Vec3};
use fixstep::particles::{ParticleForce, ParticleView};

/// The restoring "force" of θ'' = −ω₀² sin θ on unit-mass particles whose x coordinate is
/// the angle θ (rad) and whose x velocity is θ' (rad/s): F_x = −m ω₀² sin θ, with ω₀² = g/L
/// in 1/s². It uses the format's own `sin` (the engine's integer kernel in fixed point), so
/// the six integrators of the particle system step the pendulum exactly as they would any
/// other force.
#[derive(Clone, Copy, Debug)]
pub struct PendulumForce<R: Real> {
    /// ω₀² = g/L, 1/s².
    pub omega0_squared: R,
}

impl<R: Real> ParticleForce<R> for PendulumForce<R> {
    fn accumulate(&self, particles: &ParticleView<'_, R>, forces: &mut [Vec3<R>]) {
        for (i, force) in forces.iter_mut().enumerate() {
            let inv_mass = particles.inv_masses[i];
            if inv_mass != R::ZERO {
                let theta = particles.positions[i].x;
                force.x -= self.omega0_squared * theta.sin() / inv_mass;
            }
        }
    }
}
