//! Stage 3 of a rigid step: build the solver's bodies and constraints, run the
//! [solver](super::solver), copy the velocities and impulses back, and break the joints
//! that were overloaded.

use super::solver::{BouncePass, JointPass, STATIC_BODY, Softness, SolvePass, SolverBody};
use super::system::RigidSystem;
use crate::math::{Real, Vec3};

impl<R: Real> RigidSystem<R> {
    /// Stage 3: one solver step of `dt` seconds under `gravity` (m/s²).
    pub(crate) fn solve(&mut self, dt: R, gravity: Vec3<R>) {
        let n = self.bodies.len();
        let bodies = &mut self.bodies;
        let solver = &mut self.scratch.solver;
        // The collision stage placed every live body at its current pose, and nothing has
        // moved since: its rotation matrices are this step's.
        let transforms = &self.scratch.transforms;
        debug_assert_eq!(transforms.len(), n);

        // Solver bodies: the static body, then every moving body in slot order.
        solver.bodies.clear();
        solver.slots.clear();
        solver.index_of_slot.clear();
        solver.index_of_slot.resize(n, STATIC_BODY);
        solver.bodies.push(SolverBody::default());
        solver.slots.push(u32::MAX);
        for (i, placement) in transforms.iter().enumerate().take(n) {
            if !bodies.is_moving(i) {
                continue;
            }
            solver.index_of_slot[i] = solver.bodies.len() as u32;
            solver.slots.push(i as u32);
            let rotation = placement.rotation;
            debug_assert_eq!(rotation, bodies.orientation[i].to_mat3(), "slot {i}");
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
        let joints = &mut self.joints;
        let has_joints = !joints.is_empty();
        if has_joints {
            solver.prepare_joints(joints, bodies, h);
            solver.list_spinning(bodies);
        }
        // Joints: `iterations` passes each time, stiff to a fifth of the substep rate per
        // iteration (measured: beyond about a third per iteration a hanging chain of 20 links
        // blows up).
        let joint_iterations = if has_joints { joints.iterations } else { 0 };
        let joint_cap = inv_h * R::from_ratio(1, 5) * R::from_int(joint_iterations as i32);
        let joint_solve = JointPass {
            soft: Softness::new(joints.hertz.min(joint_cap), joints.damping_ratio, h),
            inv_h,
            use_bias: true,
        };
        let joint_relax = JointPass {
            use_bias: false,
            ..joint_solve
        };

        // Restitution has work only where a contact with restitution approaches fast enough.
        let may_bounce = solver.may_bounce(settings.restitution_threshold);
        for substep in 0..substeps {
            if has_joints {
                solver.begin_spinning(bodies);
            }
            solver.integrate_velocities(bodies, h, gravity);
            if has_joints {
                solver.record_spinning(h);
                if substep > 0 {
                    solver.refresh_inverse_inertias(bodies);
                    solver.update_joints(joints, bodies, h);
                }
                solver.warm_start_joints();
            }
            let (blocks, solver_bodies) = solver.blocks_and_bodies();
            for block in blocks.iter_mut() {
                block.warm_start(solver_bodies);
            }
            for _ in 0..joint_iterations {
                solver.solve_joints(&joint_solve);
            }
            let (blocks, solver_bodies) = solver.blocks_and_bodies();
            for block in blocks.iter_mut() {
                block.solve(solver_bodies, &solve);
            }
            solver.integrate_positions(bodies, h);
            if has_joints {
                solver.advance_joint_errors(h);
            }
            for iteration in 0..joint_iterations {
                solver.correct_spinning(h, iteration == 0);
                solver.solve_joints(&joint_relax);
            }
            if has_joints {
                solver.correct_spinning(h, false);
            }
            let (blocks, solver_bodies) = solver.blocks_and_bodies();
            for block in blocks.iter_mut() {
                block.solve(solver_bodies, &relax);
            }
            if may_bounce {
                solver.add_substep_impulses(substep == 0);
            }
        }
        let bounce = BouncePass {
            threshold: settings.restitution_threshold,
            gravity,
            h,
        };
        if may_bounce {
            solver.restitution(&bounce);
        }
        for block in solver.blocks() {
            block.store_impulses(&mut self.contacts);
        }
        if has_joints {
            solver.store_joint_impulses(joints);
        }
        for (sb, &slot) in solver.bodies.iter().zip(&solver.slots).skip(1) {
            let i = slot as usize;
            bodies.linear_velocity[i] = sb.v;
            bodies.angular_velocity[i] = sb.w;
        }
        if has_joints {
            self.break_overloaded_joints(h);
        }
    }
}
