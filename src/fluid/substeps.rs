//! Adaptive substeps: how many fluid substeps a world substep takes when the fluid has a
//! CFL number ([`FluidDesc::cfl`](super::FluidDesc::cfl)).
//!
//! The time-step limit Δt ≤ C H / u bounds how far a particle travels in one substep, in
//! kernel supports. The fixed count is checked once, when the scene builds, against the
//! fastest flow the scene may reach (c/10 for DFSPH, c for WCSPH). With a CFL number the
//! step measures the flow instead: u is the fastest particle's speed at the start of the
//! step (or a due emitter's), plus |g| Δt for what gravity adds during it, plus c for
//! WCSPH, whose pressure waves travel at the speed of sound. A fluid at rest then takes one
//! substep, and a dam break as many as its front needs.
//!
//! Every quantity is the state's or the settings', so the count is the same on every
//! machine, and it never exceeds the scene's `substeps`.

use super::desc::FluidSolver;
use super::system::FluidSystem;
use crate::math::{Real, Vec3};

impl<R: Real> FluidSystem<R> {
    /// The substeps of the next world substep of `dt` seconds under `gravity` (m/s²): the
    /// settings' count, or with a CFL number C the fewest n ≤ that count with
    /// Δt (u + |g| Δt) ≤ n C H (m), u in m/s as the [module](self) says.
    pub(crate) fn substep_count(&self, dt: R, gravity: Vec3<R>) -> u32 {
        let s = &self.settings;
        if s.cfl == R::ZERO {
            return s.substeps;
        }
        let fastest_squared = self
            .velocities
            .iter()
            .fold(R::ZERO, |m, v| m.max(v.length_squared()));
        let emitted = self
            .emitters
            .iter()
            .filter(|e| e.remaining > 0)
            .fold(R::ZERO, |m, e| m.max(e.speed));
        let mut speed = fastest_squared.sqrt().max(emitted) + gravity.length() * dt;
        if s.solver == FluidSolver::Wcsph {
            speed += s.speed_of_sound;
        }
        let travel = speed * dt;
        let reach = s.cfl * s.kernel.support;
        let mut n = 1;
        let mut covered = reach;
        while n < s.substeps && travel > covered {
            n += 1;
            covered += reach;
        }
        n
    }
}

#[cfg(test)]
mod tests {
    use crate::fixstep_scenes::fluid as presets;
    use crate::fluid::{FluidSolver, FluidSystem};
    use crate::math::{Fx, Real, Vec3};

    /// Δt = 5 ms.
    fn dt() -> Fx {
        Fx::from_ratio(1, 200)
    }

    fn gravity() -> Vec3<Fx> {
        Vec3::new(Fx::ZERO, Fx::from_ratio(-981, 100), Fx::ZERO)
    }

    /// Martin & Moyce's column at 10 particles across a (H = 11.43 mm), DFSPH, at most
    /// `cap` substeps, CFL number `cfl`.
    fn column(solver: FluidSolver, cap: u32, cfl: Fx) -> FluidSystem<Fx> {
        let mut desc = presets::dam_break::<Fx>(10, 2, solver);
        desc.substeps = cap;
        desc.cfl = cfl;
        FluidSystem::from_desc(&desc, dt()).expect("the column builds")
    }

    /// The count from the rule written out in `f64`: the fewest n with
    /// Δt (u + |g| Δt) ≤ n C H.
    fn expected(speed: f64, cfl: f64, support: f64, cap: u32) -> u32 // ok-det: test reference
    {
        let travel = (speed + 9.81 * 0.005) * 0.005;
        ((travel / (cfl * support)).ceil() as u32).clamp(1, cap)
    }

    #[test]
    fn without_a_cfl_number_the_count_is_fixed() {
        let mut fluid = column(FluidSolver::Dfsph, 9, Fx::ZERO);
        fluid.velocities[3] = Vec3::new(Fx::ZERO, Fx::from_int(-100), Fx::ZERO);
        assert_eq!(fluid.substep_count(dt(), gravity()), 9);
        fluid.velocities[3] = Vec3::ZERO;
        assert_eq!(fluid.substep_count(dt(), gravity()), 9);
    }

    #[test]
    fn a_fluid_at_rest_takes_one_substep() {
        let fluid = column(FluidSolver::Dfsph, 9, Fx::from_ratio(1, 5));
        assert_eq!(fluid.substep_count(dt(), gravity()), 1);
    }

    #[test]
    fn the_fastest_particle_sets_the_count() {
        let cfl = Fx::from_ratio(1, 5);
        let mut fluid = column(FluidSolver::Dfsph, 40, cfl);
        let support = fluid.settings().kernel.support.to_f64();
        for (speed, id) in [(0.3, 0), (0.9, 17), (1.4, 33), (2.0, 5), (7.5, 61)] {
            let velocities = &mut fluid.velocities;
            velocities.iter_mut().for_each(|v| *v = Vec3::ZERO);
            // Along a diagonal, so that the speed is a length, not a component.
            let c = Fx::from_f64(speed / 3f64.sqrt());
            velocities[id] = Vec3::new(c, -c, c);
            velocities[id + 1] = Vec3::new(c, c, c) * Fx::HALF;
            let n = fluid.substep_count(dt(), gravity());
            let want = expected(speed, 0.2, support, 40);
            assert!(want > 1 || speed < 0.5, "the case tests the count");
            assert_eq!(n, want, "speed {speed} m/s");
        }
    }

    #[test]
    fn the_count_never_exceeds_the_scenes_substeps() {
        let mut fluid = column(FluidSolver::Dfsph, 5, Fx::from_ratio(1, 5));
        fluid.velocities[0] = Vec3::new(Fx::from_int(30_000), Fx::ZERO, Fx::ZERO);
        assert_eq!(fluid.substep_count(dt(), gravity()), 5);
    }

    #[test]
    fn wcsph_counts_the_speed_of_sound() {
        // c = 20 m/s: Δt (c + |g| Δt) = 0.1002 m, 43.8 supports of 0.2 H.
        let fluid = column(FluidSolver::Wcsph, 160, Fx::from_ratio(1, 5));
        let support = fluid.settings().kernel.support.to_f64();
        assert_eq!(
            fluid.substep_count(dt(), gravity()),
            expected(20.0, 0.2, support, 160)
        );
        assert_eq!(fluid.substep_count(dt(), gravity()), 44);
    }

    #[test]
    fn a_due_emitter_counts_its_speed() {
        let mut desc = presets::pour::<Fx>(100);
        desc.cfl = Fx::from_ratio(1, 10);
        desc.emitters[0].velocity = Vec3::new(Fx::ZERO, Fx::from_int(-3), Fx::ZERO);
        let mut fluid = FluidSystem::from_desc(&desc, dt()).expect("pour builds");
        let support = fluid.settings().kernel.support.to_f64();
        let due = fluid.substep_count(dt(), gravity());
        assert_eq!(due, expected(3.0, 0.1, support, 10));
        assert!(due > 1);
        fluid.emitters[0].remaining = 0;
        assert_eq!(fluid.substep_count(dt(), gravity()), 1);
    }
}
