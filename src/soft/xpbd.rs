//! The XPBD solve loop (Macklin et al. 2016, with the small substeps of Macklin et al.
//! 2019), for every XPBD body at once.
//!
//! Each substep of length h = Δt/substeps:
//! 1. predict: v ← v / (1 + h c) + h (g + w·drag·(wind − v)), x_prev ← x, x ← x + h v
//!    (damping the carried velocity only, so that a body at rest feels all of g)
//!    (pinned vertices, w = 0, stay);
//! 2. λ ← 0 for every constraint;
//! 3. `iterations` Gauss–Seidel passes, each over tethers, distances, bending, volumes,
//!    attachments and collisions, in that order and in row order within each kind (the
//!    tethers first, so that the edges have the last word; distance and bending rows are
//!    in colour order, fixed at build);
//! 4. v ← (x − x_prev)/h.
//!
//! The factors of the rows with constant denominators are computed when h first appears
//! and reused while it stays the same.

use super::collide::project_positions;
use super::system::{Model, SoftSystem};
use crate::math::{Real, Vec3};

impl<R: Real> SoftSystem<R> {
    /// Advances the XPBD bodies by `dt` seconds: world substep `substep` of `substeps`.
    pub(crate) fn step_xpbd(&mut self, dt: R, gravity: Vec3<R>, substep: u32, substeps: u32) {
        let n = self.settings.substeps;
        let h = dt * R::from_ratio(1, i64::from(n));
        let inv_h = h.recip();
        self.prepare(h, inv_h);
        let total = u64::from(substeps) * u64::from(n);
        for s in 0..n {
            let done = u64::from(substep) * u64::from(n) + u64::from(s) + 1;
            self.xpbd_substep(h, inv_h, gravity, done, total);
        }
    }

    /// Sizes the scratch arrays and computes α̃ and the constant denominators for the
    /// substep `h` (s), unless they are already those of `h`.
    fn prepare(&mut self, h: R, inv_h: R) {
        let scratch = &mut self.scratch;
        scratch
            .previous
            .resize(self.vertices.position.len(), Vec3::ZERO);
        if scratch.substep == Some(h) {
            return;
        }
        scratch.substep = Some(h);
        let inv_h2 = inv_h * inv_h;
        let w = &self.vertices.inv_mass;
        scratch.distance = self.distances.factors(w, inv_h2);
        (scratch.hinge_share, scratch.hinge_relax) = self.hinges.factors(w, inv_h2);
        (scratch.attachment_share, scratch.attachment_relax) = self.attachments.factors(w, inv_h2);
        scratch.inv_h2 = inv_h2;
    }

    /// One substep; `done` of `total` substeps of the tick are complete at its end.
    fn xpbd_substep(&mut self, h: R, inv_h: R, gravity: Vec3<R>, done: u64, total: u64) {
        self.predict(h, gravity);
        self.distances.lambda.fill(R::ZERO);
        self.hinges.lambda.fill(Vec3::ZERO);
        self.tetrahedra.lambda.fill(R::ZERO);
        self.attachments.lambda.fill(Vec3::ZERO);
        self.attachments
            .displacements(done, total, &mut self.scratch.displacement);
        let x = &mut self.vertices.position;
        let w = &self.vertices.inv_mass;
        let s = &self.scratch;
        for _ in 0..self.settings.iterations {
            self.tethers.solve(x);
            self.distances.solve(x, &s.distance);
            self.hinges.solve(x, &s.hinge_share, &s.hinge_relax);
            self.tetrahedra.solve(x, w, s.inv_h2);
            self.attachments
                .solve(x, &s.displacement, &s.attachment_share, &s.attachment_relax);
            if !self.colliders.is_empty() {
                for body in &self.bodies {
                    if body.model == Model::Xpbd {
                        project_positions(
                            &self.colliders,
                            x,
                            &s.previous,
                            w,
                            body.range(),
                            body.radius,
                        );
                    }
                }
            }
        }
        for body in &self.bodies {
            if body.model != Model::Xpbd {
                continue;
            }
            for i in body.range() {
                if w[i] != R::ZERO {
                    self.vertices.velocity[i] = (x[i] - s.previous[i]) * inv_h;
                }
            }
        }
    }

    /// Step 1 of the [substep](self): external accelerations, damping and the predicted
    /// positions.
    fn predict(&mut self, h: R, gravity: Vec3<R>) {
        let v = &mut self.vertices.velocity;
        let x = &mut self.vertices.position;
        let w = &self.vertices.inv_mass;
        let previous = &mut self.scratch.previous;
        for body in &self.bodies {
            if body.model != Model::Xpbd {
                continue;
            }
            let retain = (R::ONE + h * body.damping).recip();
            let windy = body.drag != R::ZERO;
            for i in body.range() {
                previous[i] = x[i];
                if w[i] == R::ZERO {
                    continue;
                }
                let mut acceleration = gravity;
                if windy {
                    acceleration = acceleration.add_scaled(body.wind - v[i], w[i] * body.drag);
                }
                let mut velocity = v[i];
                if body.damping != R::ZERO {
                    velocity *= retain;
                }
                velocity = velocity.add_scaled(acceleration, h);
                v[i] = velocity;
                x[i] = x[i].add_scaled(velocity, h);
            }
        }
    }
}
