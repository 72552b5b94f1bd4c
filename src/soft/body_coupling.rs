//! Soft bodies and rigid bodies, two-way: vertex contacts with the bodies' shapes, and
//! vertices tied to body points. Both are XPBD position constraints solved with the body
//! as a second particle of generalised inverse mass w_b (Müller et al. 2020), so the body
//! takes the opposite of every correction a vertex takes ([`RigidBodies`]).
//!
//! **Contact** of vertex i (inverse mass wᵢ, ball of radius r) with a body, normal n̂ out
//! of the body and depth δ (m), at the body's surface point p = x + (δ − r) n̂: the
//! positional impulse λ = δ / (wᵢ + w_b) (kg·m) moves the vertex by wᵢ λ n̂ and the body by
//! −λ n̂ at p. Friction is positional (Macklin et al. 2014) on the tangential part Δxₜ of
//! the vertex's displacement relative to the body's point over the substep,
//! Δx − u(p) h: it is removed entirely while |Δxₜ| ≤ μ δ, else by μ δ, shared the same way
//! along its direction.
//!
//! A vertex whose tether (the long-range attachments of `constraints/tether.rs`) the
//! push would stretch is held by it: it takes part with wᵢ = 0, so the body takes the
//! whole correction, as from the pin the taut body hangs from. Without that a body
//! hundreds of times heavier than a vertex overrides the body's constraints each substep,
//! and the stretch it leaves springs back as a bounce.
//!
//! **Tie** of vertex i to the body point a (body frame), C = |xᵢ − a_world| (m) along
//! n̂ = (xᵢ − a_world)/C, compliance α (m/N), α̃ = α/h²:
//! Δλ = (−C − α̃ λ)/(wᵢ + w_b + α̃), λ += Δλ, xᵢ += wᵢ Δλ n̂, and the body takes −Δλ n̂ at
//! a_world.
//!
//! **Tether** of a tie's body point a to an anchor vertex p of an inextensible body with
//! tethers (the long-range attachments of `constraints/tether.rs`): C = |a − p| − ℓ₀ ≤ 0,
//! projected on the body alone when violated, Δλ = C / w_b. A rope's Gauss–Seidel pass
//! cannot hold a load hundreds of times heavier than its vertices; the tether holds it at
//! the rope's length.
//!
//! The impulse the bodies give the vertices, λ n̂ / h per correction, is summed over the
//! tick ([`SoftSystem::rigid_impulse`]).

use serde::{Deserialize, Serialize};

use super::rigid_bodies::RigidBodies;
use super::system::{Model, SoftSystem};
use crate::math::{Real, Vec3};
use crate::rigid::{Aabb, CollisionFilter};
use crate::types::Handle;

/// How a soft body's vertices touch the rigid bodies.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct BodyContacts<R: Real> {
    /// μ.
    pub friction: R,
    /// The layers of the bodies touched.
    pub filter: CollisionFilter,
}

/// Vertices tied to rigid-body points, one row each.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Ties<R: Real> {
    /// Per row: the vertex.
    pub vertex: Vec<u32>,
    /// Per row: the body.
    pub body: Vec<Handle>,
    /// Per row: the point in the body frame, m.
    pub local: Vec<Vec3<R>>,
    /// Per row: α, m/N.
    pub compliance: Vec<R>,
    /// Per tether of a tie's body point: the tie row, its anchor (a pinned or attached
    /// vertex) and the rest distance ℓ₀ (m) between them.
    pub tether_row: Vec<u32>,
    pub tether_anchor: Vec<u32>,
    pub tether_rest: Vec<R>,
}

/// The coupling's memory for one world substep (not state).
#[derive(Debug, Default)]
pub(crate) struct CouplingScratch<R: Real> {
    /// Per soft body: the bodies its vertices may touch.
    pub near: Vec<Vec<u32>>,
    /// Per tie: its body, `None` when removed.
    pub tied: Vec<Option<u32>>,
    /// Per tie: λ, kg·m.
    pub lambda: Vec<R>,
    /// The impulse the bodies gave the vertices this tick, N·s.
    pub impulse: Vec3<R>,
    /// The contacts of the current substep.
    pub touches: Vec<Touch<R>>,
    /// The tether rows of vertex i: `tether_rows[tether_start[i]..tether_start[i + 1]]`
    /// (built when first needed).
    pub tether_start: Vec<u32>,
    pub tether_rows: Vec<u32>,
}

/// A contact found during a substep, for its velocity pass.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Touch<R: Real> {
    vertex: u32,
    body: u32,
    /// The body's surface point, m.
    point: Vec3<R>,
    /// Unit normal out of the body.
    normal: Vec3<R>,
    /// μ.
    friction: R,
    /// The impulse the velocity pass gives the vertex, N·s, applied to the body once the
    /// body's contacts are done.
    share: Vec3<R>,
}

impl<R: Real> SoftSystem<R> {
    /// Whether some vertex touches or is tied to the rigid bodies.
    pub(crate) fn couples(&self) -> bool {
        !self.ties.vertex.is_empty() || self.bodies.iter().any(|b| b.contacts.is_some())
    }

    /// The impulse the rigid bodies gave the vertices during the last tick (contacts and
    /// ties), N·s; a pinned vertex passes its share to its pin. Zero without coupling.
    pub fn rigid_impulse(&self) -> Vec3<R> {
        self.scratch.coupling.impulse
    }

    /// Starts a world substep of `dt` seconds with `bodies` in view: the bodies each soft
    /// body may touch, the ties' bodies.
    pub(crate) fn find_bodies(&mut self, bodies: &mut dyn RigidBodies<R>, dt: R, gravity: Vec3<R>) {
        bodies.begin(dt, self.settings.substeps);
        let coupling = &mut self.scratch.coupling;
        if coupling.tether_start.len() != self.vertices.len() + 1 {
            (coupling.tether_start, coupling.tether_rows) =
                rows_by_vertex(&self.tethers.vertex, self.vertices.len());
        }
        coupling.near.resize_with(self.bodies.len(), Vec::new);
        let x = &self.vertices.position;
        let v = &self.vertices.velocity;
        for (body, near) in self.bodies.iter().zip(&mut coupling.near) {
            near.clear();
            let Some(contacts) = body.contacts else {
                continue;
            };
            let range = body.range();
            let Some(&first) = x.get(range.start) else {
                continue;
            };
            let mut bounds = Aabb {
                min: first,
                max: first,
            };
            let mut speed = R::ZERO;
            for i in range {
                bounds.min = bounds.min.min_elem(x[i]);
                bounds.max = bounds.max.max_elem(x[i]);
                speed = speed.max(v[i].abs().max_component());
            }
            let travel = (speed + gravity.abs().max_component() * dt) * dt;
            bounds = bounds.expanded(body.radius + travel + travel);
            bodies.near(&bounds, contacts.filter, near);
        }
        coupling.tied.clear();
        coupling
            .tied
            .extend(self.ties.body.iter().map(|&b| bodies.of_body(b)));
        coupling.lambda.clear();
        coupling.lambda.resize(self.ties.vertex.len(), R::ZERO);
    }

    /// One pass of the coupling constraints in an XPBD substep of `h` seconds: each coupled
    /// body's contacts, then the ties.
    pub(crate) fn project_coupling(&mut self, bodies: &mut dyn RigidBodies<R>, h: R) {
        let inv_h = h.recip();
        let x = &mut self.vertices.position;
        let w = &self.vertices.inv_mass;
        let previous = &self.scratch.previous;
        let coupling = &mut self.scratch.coupling;
        let touches = &mut coupling.touches;
        touches.clear();
        for (body, near) in self.bodies.iter().zip(&coupling.near) {
            let Some(contacts) = body.contacts else {
                continue;
            };
            if near.is_empty() || body.model != Model::Xpbd {
                continue;
            }
            for i in body.range() {
                for &b in near {
                    if !bodies.may_touch(b, x[i], body.radius) {
                        continue;
                    }
                    let Some((normal, depth)) = bodies.contact(b, x[i], previous[i], body.radius)
                    else {
                        continue;
                    };
                    let p = x[i].add_scaled(normal, depth - body.radius);
                    touches.push(Touch {
                        vertex: i as u32,
                        body: b,
                        point: p,
                        normal,
                        friction: contacts.friction,
                        share: Vec3::ZERO,
                    });
                    if w[i] == R::ZERO {
                        continue;
                    }
                    let start = x[i];
                    x[i] = x[i].add_scaled(normal, depth);
                    let moved = (x[i] - previous[i]) - bodies.velocity_at(b, p) * h;
                    let tangential = moved - normal * moved.dot(normal);
                    if let Some((direction, slip)) = tangential.try_normalize() {
                        x[i] = x[i].add_scaled(direction, -slip.min(contacts.friction * depth));
                    }
                    let given = (x[i] - start) * (w[i].recip() * inv_h);
                    bodies.push(b, p, -given);
                    coupling.impulse += given;
                }
            }
        }
        let alpha_scale = inv_h * inv_h;
        let t = &self.ties;
        for r in 0..t.vertex.len() {
            let Some(b) = coupling.tied[r] else {
                continue;
            };
            let i = t.vertex[r] as usize;
            let anchor = bodies.point(b, t.local[r]);
            let Some((normal, gap)) = (x[i] - anchor).try_normalize() else {
                continue;
            };
            let alpha = t.compliance[r] * alpha_scale;
            let denominator = w[i] + bodies.inverse_mass(b, anchor, normal) + alpha;
            if denominator == R::ZERO {
                continue;
            }
            let delta = (-gap - alpha * coupling.lambda[r]) / denominator;
            coupling.lambda[r] += delta;
            let impulse = normal * delta;
            x[i] = x[i].add_scaled(impulse, w[i]);
            bodies.correct(b, anchor, -impulse);
            coupling.impulse = coupling.impulse.add_scaled(impulse, inv_h);
        }
        for k in 0..t.tether_row.len() {
            let row = t.tether_row[k] as usize;
            let Some(b) = coupling.tied[row] else {
                continue;
            };
            let point = bodies.point(b, t.local[row]);
            let Some((normal, distance)) = (point - x[t.tether_anchor[k] as usize]).try_normalize()
            else {
                continue;
            };
            let excess = distance - t.tether_rest[k];
            let w = bodies.inverse_mass(b, point, normal);
            if excess <= R::ZERO || w == R::ZERO {
                continue;
            }
            bodies.correct(b, point, normal * -(excess / w));
        }
    }
}

impl<R: Real> SoftSystem<R> {
    /// The velocity pass of the substep's contacts, after the velocities are updated,
    /// Jacobi-style over each body's c contacts with mass splitting (Tonge et al. 2012:
    /// each contact sees the body with inverse mass c·w_b, and the body takes the sum at
    /// the end): a contact whose vertex approaches the body, v_n = (vᵢ − u(p))·n̂ < 0, is
    /// stopped by the impulse Jₙ = −v_n/(w + c w_b) (N·s) on the vertex and −Jₙ on the
    /// body, with dynamic friction Jₜ = −v̂ₜ min(|vₜ|/(w + c w_b,ₜ), μ Jₙ) on the tangential
    /// velocity; w is the vertex's inverse mass, or 0 when a taut tether holds it against
    /// the push (see the [module](self)).
    pub(crate) fn settle_contacts(&mut self, bodies: &mut dyn RigidBodies<R>) {
        let x = &self.vertices.position;
        let v = &mut self.vertices.velocity;
        let w = &self.vertices.inv_mass;
        let tethers = &self.tethers;
        let coupling = &mut self.scratch.coupling;
        let (start, rows) = (&coupling.tether_start, &coupling.tether_rows);
        coupling.touches.sort_by_key(|t| t.body);
        for group in coupling.touches.chunk_by_mut(|a, b| a.body == b.body) {
            let split = R::from_int(group.len() as i32);
            for touch in group.iter_mut() {
                touch.share = Vec3::ZERO;
                let i = touch.vertex as usize;
                let (b, p, n) = (touch.body, touch.point, touch.normal);
                let relative = v[i] - bodies.velocity_at(b, p);
                let normal_speed = relative.dot(n);
                if normal_speed >= R::ZERO {
                    continue;
                }
                let held = rows[start[i] as usize..start[i + 1] as usize]
                    .iter()
                    .any(|&k| {
                        let k = k as usize;
                        let out = x[i] - x[tethers.anchor[k] as usize];
                        let rest = tethers.rest[k];
                        out.dot(n) > R::ZERO
                            && out.length_squared() >= rest * rest - rest * rest.mul_pow2_recip(9)
                    });
                let inv_mass = if held { R::ZERO } else { w[i] };
                let sum = inv_mass + split * bodies.inverse_mass(b, p, n);
                if sum == R::ZERO {
                    continue;
                }
                let normal_impulse = -normal_speed / sum;
                touch.share = n * normal_impulse;
                let tangential = relative - n * normal_speed;
                if let Some((direction, speed)) = tangential.try_normalize() {
                    let sum = inv_mass + split * bodies.inverse_mass(b, p, direction);
                    if sum > R::ZERO {
                        let stop = (speed / sum).min(touch.friction * normal_impulse);
                        touch.share = touch.share.add_scaled(direction, -stop);
                    }
                }
                v[i] = v[i].add_scaled(touch.share, inv_mass);
                coupling.impulse += touch.share;
            }
            for touch in group.iter() {
                if touch.share != Vec3::ZERO {
                    bodies.push(touch.body, touch.point, -touch.share);
                }
            }
        }
    }
}

/// The tether rows of each of `vertices` vertices, given each row's vertex: (start, rows),
/// vertex i's rows being `rows[start[i]..start[i + 1]]`, in row order.
fn rows_by_vertex(vertex_of_row: &[u32], vertices: usize) -> (Vec<u32>, Vec<u32>) {
    let mut start = vec![0u32; vertices + 1];
    for &v in vertex_of_row {
        start[v as usize + 1] += 1;
    }
    for i in 0..vertices {
        start[i + 1] += start[i];
    }
    let mut next = start.clone();
    let mut rows = vec![0u32; vertex_of_row.len()];
    for (k, &v) in vertex_of_row.iter().enumerate() {
        rows[next[v as usize] as usize] = k as u32;
        next[v as usize] += 1;
    }
    (start, rows)
}
