//! Stage 3 of a rigid step: build the solver's bodies and constraints, run the
//! [solver](super::solver), and copy the velocities and impulses back.

use super::material::{mix_friction, mix_restitution};
use super::solver::{STATIC_BODY, Softness, SolverBody, prepare_constraint};
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

        // Constraints: contacts with at least one body of finite mass that moves.
        solver.constraints.clear();
        for (k, contact) in self.contacts.iter().enumerate() {
            let (a, b) = (contact.key.body_a as usize, contact.key.body_b as usize);
            let (ia, ib) = (solver.index_of_slot[a], solver.index_of_slot[b]);
            let sa = &solver.bodies[ia as usize];
            let sb = &solver.bodies[ib as usize];
            if (ia == STATIC_BODY && ib == STATIC_BODY)
                || (sa.inv_mass == R::ZERO && sb.inv_mass == R::ZERO)
            {
                continue;
            }
            let (ma, mb) = (&bodies.material[a], &bodies.material[b]);
            solver.constraints.push(prepare_constraint(
                contact,
                k as u32,
                (ia, bodies.position[a]),
                (ib, bodies.position[b]),
                &solver.bodies,
                mix_friction(ma.friction, mb.friction),
                mix_restitution(ma.restitution, mb.restitution),
            ));
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
        let soft = Softness::new(hertz, zeta, h);
        let soft_static = Softness::new((hertz * R::TWO).min(cap), zeta, h);
        let max_push = settings.max_push_velocity;

        for _ in 0..substeps {
            solver.integrate_velocities(bodies, h, gravity);
            for c in &solver.constraints {
                c.warm_start(&mut solver.bodies);
            }
            for c in &mut solver.constraints {
                let s = if c.has_rigid_partner() {
                    &soft_static
                } else {
                    &soft
                };
                c.solve(&mut solver.bodies, s, inv_h, max_push, true);
            }
            solver.integrate_positions(bodies, h);
            for c in &mut solver.constraints {
                let s = if c.has_rigid_partner() {
                    &soft_static
                } else {
                    &soft
                };
                c.solve(&mut solver.bodies, s, inv_h, max_push, false);
            }
        }
        let threshold = settings.restitution_threshold;
        for c in &mut solver.constraints {
            c.apply_restitution(&mut solver.bodies, threshold);
        }
        for c in &solver.constraints {
            c.store_impulses(&mut self.contacts[c.contact as usize]);
        }
        for (sb, &slot) in solver.bodies.iter().zip(&solver.slots).skip(1) {
            let i = slot as usize;
            bodies.linear_velocity[i] = sb.v;
            bodies.angular_velocity[i] = sb.w;
        }
    }
}
