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
use super::constraints::ColourRuns;
use super::rigid_bodies::RigidBodies;
use super::system::{Model, SoftSystem};
use crate::math::{Real, Vec3};

#[cfg(vector_kernels)]
mod kernel;

/// Distance rows a chunk of a split pass holds.
const DISTANCE_CHUNK: usize = super::constraints::DISTANCE_CHUNK;
/// Vertices a chunk of the prediction and the velocity update holds (each vertex on its
/// own: any cut gives the same bits).
const VERTEX_CHUNK: usize = 512;
/// Bending rows a chunk of a split pass holds.
const HINGE_CHUNK: usize = super::constraints::HINGE_CHUNK;
#[cfg(all(test, vector_kernels))]
mod tests;

impl<R: Real> SoftSystem<R> {
    /// Advances the XPBD bodies by `dt` seconds: world substep `substep` of `substeps`.
    /// With `bodies`, the vertices also touch and are tied to the rigid bodies
    /// ([`body_coupling`](super::body_coupling)).
    pub(crate) fn step_xpbd(
        &mut self,
        dt: R,
        gravity: Vec3<R>,
        (substep, substeps): (u32, u32),
        mut bodies: Option<&mut dyn RigidBodies<R>>,
    ) {
        let n = self.settings.substeps;
        let h = dt * R::from_ratio(1, i64::from(n));
        let inv_h = h.recip();
        self.prepare(h, inv_h);
        if crate::parallel::splits() {
            self.prepare_runs();
        }
        if let Some(bodies) = bodies.as_deref_mut() {
            self.find_bodies(bodies, dt, gravity);
        }
        let total = u64::from(substeps) * u64::from(n);
        for s in 0..n {
            let done = u64::from(substep) * u64::from(n) + u64::from(s) + 1;
            if let Some(bodies) = bodies.as_deref_mut() {
                bodies.advance();
            }
            self.xpbd_substep(h, inv_h, gravity, done, total, reborrow(&mut bodies));
        }
        if let Some(bodies) = bodies {
            bodies.finish();
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
        #[cfg(vector_kernels)]
        {
            scratch.tether_blocks = self.tethers.independent_blocks();
            scratch.hinge_blocks = self.hinges.independent_blocks();
        }
        (scratch.hinge_share, scratch.hinge_relax) = self.hinges.factors(w, inv_h2);
        (scratch.attachment_share, scratch.attachment_relax) = self.attachments.factors(w, inv_h2);
        scratch.inv_h2 = inv_h2;
    }

    /// Cuts the distance and bending rows into runs that share no vertex, once, for the
    /// passes split across a pool's workers ([`ColourRuns`]).
    fn prepare_runs(&mut self) {
        let scratch = &mut self.scratch;
        let vertices = self.vertices.position.len();
        let d = &self.distances;
        if scratch.distance_runs.runs.is_empty() && !d.a.is_empty() {
            let ends: Vec<[u32; 2]> = d.a.iter().zip(&d.b).map(|(&a, &b)| [a, b]).collect();
            scratch.distance_runs = ColourRuns::new(&ends, vertices, DISTANCE_CHUNK);
        }
        let h = &self.hinges.vertices;
        if scratch.hinge_runs.runs.is_empty() && !h.is_empty() {
            scratch.hinge_runs = ColourRuns::new(h, vertices, HINGE_CHUNK);
        }
    }

    /// One substep; `done` of `total` substeps of the tick are complete at its end.
    fn xpbd_substep(
        &mut self,
        h: R,
        inv_h: R,
        gravity: Vec3<R>,
        done: u64,
        total: u64,
        mut bodies: Option<&mut dyn RigidBodies<R>>,
    ) {
        self.predict(h, gravity);
        self.distances.lambda.fill(R::ZERO);
        self.hinges.lambda.fill(Vec3::ZERO);
        self.tetrahedra.lambda.fill(R::ZERO);
        self.attachments.lambda.fill(Vec3::ZERO);
        self.attachments
            .displacements(done, total, &mut self.scratch.displacement);
        self.scratch.coupling.lambda.fill(R::ZERO);
        for _ in 0..self.settings.iterations {
            if let Some(bodies) = bodies.as_deref_mut() {
                self.project_coupling(bodies, h);
            }
            self.iterate();
        }
        let x = &self.vertices.position;
        let w = &self.vertices.inv_mass;
        let s = &self.scratch;
        for body in &self.bodies {
            if body.model != Model::Xpbd {
                continue;
            }
            let r = body.range();
            let (x, previous, w) = (&x[r.clone()], &s.previous[r.clone()], &w[r.clone()]);
            let v = &mut self.vertices.velocity[r];
            crate::parallel::for_each_chunk_mut(v, VERTEX_CHUNK, |start, v| {
                let end = start + v.len();
                let (x, previous, w) = (&x[start..end], &previous[start..end], &w[start..end]);
                #[cfg(vector_kernels)]
                if kernel::update_velocities(0..v.len(), x, previous, w, v, inv_h) {
                    return;
                }
                for i in 0..v.len() {
                    update_velocity(i, x, previous, w, v, inv_h);
                }
            });
        }
        if let Some(bodies) = bodies {
            self.settle_contacts(bodies);
        }
    }

    /// One Gauss–Seidel pass over the constraints and the static colliders (step 3 of the
    /// [substep](self)).
    fn iterate(&mut self) {
        let x = &mut self.vertices.position;
        let w = &self.vertices.inv_mass;
        let s = &mut self.scratch;
        self.tethers.solve(
            x,
            #[cfg(vector_kernels)]
            &s.tether_blocks,
        );
        if crate::parallel::splits() {
            self.distances
                .solve_split(x, &s.distance, &s.distance_runs, &mut s.moved);
            self.hinges.solve_split(
                x,
                (&s.hinge_share, &s.hinge_relax),
                &s.hinge_runs,
                &mut s.moved,
            );
        } else {
            self.distances.solve(x, &s.distance);
            self.hinges.solve(
                x,
                &s.hinge_share,
                &s.hinge_relax,
                #[cfg(vector_kernels)]
                &s.hinge_blocks,
            );
        }
        let s = &self.scratch;
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
            let motion = Motion {
                h,
                gravity,
                retain: (R::ONE + h * body.damping).recip(),
                damped: body.damping != R::ZERO,
                wind: body.wind,
                drag: body.drag,
            };
            let r = body.range();
            // One chunk unless the loop splits (each vertex on its own: any cut, the same
            // bits).
            let chunk = if crate::parallel::splits() {
                VERTEX_CHUNK
            } else {
                r.len().max(1)
            };
            let jobs: Vec<Vertices<'_, R>> = x[r.clone()]
                .chunks_mut(chunk)
                .zip(v[r.clone()].chunks_mut(chunk))
                .zip(previous[r.clone()].chunks_mut(chunk))
                .zip(w[r].chunks(chunk))
                .map(|(((x, v), previous), w)| Vertices { x, v, previous, w })
                .collect();
            crate::parallel::for_each_job(jobs, |mut vertices| {
                let n = vertices.w.len();
                #[cfg(vector_kernels)]
                if kernel::predict(0..n, &mut vertices, &motion) {
                    return;
                }
                for i in 0..n {
                    predict_vertex(i, &mut vertices, &motion);
                }
            });
        }
    }
}

/// The bodies in view for one call, leaving `bodies` usable afterwards.
fn reborrow<'a, R: Real>(
    bodies: &'a mut Option<&mut dyn RigidBodies<R>>,
) -> Option<&'a mut dyn RigidBodies<R>> {
    match bodies {
        Some(b) => Some(&mut **b),
        None => None,
    }
}

/// What the prediction of one body's vertices reads besides the vertices.
struct Motion<R: Real> {
    /// h, s.
    h: R,
    /// g, m/s².
    gravity: Vec3<R>,
    /// 1/(1 + h c) for the body's damping c.
    retain: R,
    /// Whether c ≠ 0 (the velocity is multiplied by `retain` only then).
    damped: bool,
    /// Air velocity, m/s.
    wind: Vec3<R>,
    /// Air drag per vertex, kg/s.
    drag: R,
}

/// The vertex arrays the prediction reads and writes.
struct Vertices<'a, R: Real> {
    /// x, m.
    x: &'a mut [Vec3<R>],
    /// v, m/s.
    v: &'a mut [Vec3<R>],
    /// x at the start of the substep, m.
    previous: &'a mut [Vec3<R>],
    /// w, 1/kg.
    w: &'a [R],
}

/// Step 1 for vertex `i`: x_prev ← x and, unless pinned,
/// v ← v / (1 + h c) + h (g + w·drag·(wind − v)), x ← x + h v.
#[inline(always)]
fn predict_vertex<R: Real>(i: usize, vertices: &mut Vertices<'_, R>, m: &Motion<R>) {
    let Vertices { x, v, previous, w } = vertices;
    previous[i] = x[i];
    if w[i] == R::ZERO {
        return;
    }
    let mut acceleration = m.gravity;
    if m.drag != R::ZERO {
        acceleration = acceleration.add_scaled(m.wind - v[i], w[i] * m.drag);
    }
    let mut velocity = v[i];
    if m.damped {
        velocity *= m.retain;
    }
    velocity = velocity.add_scaled(acceleration, m.h);
    v[i] = velocity;
    x[i] = x[i].add_scaled(velocity, m.h);
}

/// Step 4 for vertex `i` unless pinned: v ← (x − x_prev)/h, with 1/h `inv_h` (1/s).
#[inline(always)]
fn update_velocity<R: Real>(
    i: usize,
    x: &[Vec3<R>],
    previous: &[Vec3<R>],
    w: &[R],
    v: &mut [Vec3<R>],
    inv_h: R,
) {
    if w[i] != R::ZERO {
        v[i] = (x[i] - previous[i]) * inv_h;
    }
}
