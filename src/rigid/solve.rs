//! Stage 3 of a rigid step: build the solver's bodies and constraints, run the
//! [solver](super::solver), and copy the velocities and impulses back.

use super::solver::{STATIC_BODY, Softness, SolvePass, SolverBody};
use super::system::RigidSystem;
use crate::math::{Real, Vec3};

impl<R: Real> RigidSystem<R> {
    /// Stage 3: one solver step of `dt` seconds under `gravity` (m/s²).
    pub(crate) fn solve(&mut self, dt: R, gravity: Vec3<R>) {
        let n = self.bodies.len();
        let bodies = &mut self.bodies;
        let solver = &mut self.scratch.solver;

        // Solver bodies: the static body, then every moving body in slot order.
        solver.bodies.clear();
        solver.slots.clear();
        solver.index_of_slot.clear();
        solver.index_of_slot.resize(n, STATIC_BODY);
        solver.bodies.push(SolverBody::default());
        solver.slots.push(u32::MAX);
        for i in 0..n {
            if !bodies.is_moving(i) {
                continue;
            }
            solver.index_of_slot[i] = solver.bodies.len() as u32;
            solver.slots.push(i as u32);
            let rotation = bodies.orientation[i].to_mat3();
            solver.bodies.push(SolverBody {
                v: bodies.linear_velocity[i],
                w: bodies.angular_velocity[i],
                dp: Vec3::ZERO,
                dtheta: Vec3::ZERO,
                inv_mass: bodies.inv_mass[i],
                // Zero for kinematic bodies (their stored inverse inertia is zero).
                inv_inertia: rotation.rotate_inertia(bodies.inv_inertia[i]),
            });
        }

        let settings = &self.settings;
        let substeps = settings.substeps;
        let h = dt / R::from_int(substeps as i32);
        let inv_h = R::from_int(substeps as i32) / dt;
        // Box2D's cap: the contact spring at most a quarter of the substep rate. Contacts with
        // a static or kinematic body get twice the stiffness, within the same cap.
        let cap = inv_h * R::from_ratio(1, 4);
        let hertz = settings.contact_hertz.min(cap);
        let zeta = settings.contact_damping_ratio;
        let solve = SolvePass {
            soft: Softness::new(hertz, zeta, h),
            soft_static: Softness::new((hertz * R::TWO).min(cap), zeta, h),
            inv_h,
            max_push: settings.max_push_velocity,
            use_bias: true,
        };
        let relax = SolvePass {
            use_bias: false,
            ..solve
        };
        solver.prepare(&self.contacts, bodies, &solve);

        for _ in 0..substeps {
            solver.integrate_velocities(bodies, h, gravity);
            let (blocks, solver_bodies) = solver.blocks_and_bodies();
            for block in blocks.iter_mut() {
                block.warm_start(solver_bodies);
            }
            for block in blocks.iter_mut() {
                block.solve(solver_bodies, &solve);
            }
            solver.integrate_positions(bodies, h);
            let (blocks, solver_bodies) = solver.blocks_and_bodies();
            for block in blocks.iter_mut() {
                block.solve(solver_bodies, &relax);
            }
        }
        let threshold = settings.restitution_threshold;
        let (blocks, solver_bodies) = solver.blocks_and_bodies();
        for block in blocks.iter_mut() {
            block.apply_restitution(solver_bodies, threshold);
        }
        for block in solver.blocks() {
            block.store_impulses(&mut self.contacts);
        }
        for (sb, &slot) in solver.bodies.iter().zip(&solver.slots).skip(1) {
            let i = slot as usize;
            bodies.linear_velocity[i] = sb.v;
            bodies.angular_velocity[i] = sb.w;
        }
    }
}
