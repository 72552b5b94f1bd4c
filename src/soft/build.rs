//! Checking a scene's soft-body description and compiling it into a [`SoftSystem`].

use super::body_coupling::BodyContacts;
use super::collide::{Collider, Geometry};
use super::desc::{
    BodyAttachmentDesc, ColliderDesc, MAX_SOLVER_STEPS, MAX_VERTICES, SoftBodyDesc, SoftDesc,
    SoftModel, SoftShape, XpbdSettings,
};
use super::rigid_bodies::{BodyFrames, NoBodies};
use super::spring_mass::{stability_measure, supports};
use super::system::{Body, Model, Scratch, SoftSystem, Vertices};
use super::topology::{self, Topology};
use crate::math::integration::Integrator;
use crate::math::{Real, Vec3};
use crate::rigid::Shape;
use crate::types::{SceneError, lattice_copies};

/// The largest coordinate, size or speed a scene may use (m, m/s).
const MAX_MAGNITUDE: i32 = 100_000;
/// The stiffest spring a scene may use, N/m.
const MAX_STIFFNESS: i32 = 1_000_000_000;
/// A body with at most this many pinned vertices tethers every free vertex to each of them.
const MAX_TETHERED_PINS: usize = 4;
/// The lightest vertex a scene may make, as the inverse: w ≤ 10⁶ 1/kg (1 mg).
const MAX_INV_MASS: i32 = 1_000_000;

impl<R: Real> SoftSystem<R> {
    /// Checks `desc` and builds the system for a world whose substep is `dt` seconds (used
    /// only to warn about spring-mass networks past their stability bound); the error names
    /// the offending field (relative to the `soft` section).
    pub fn from_desc(desc: &SoftDesc<R>, dt: R) -> Result<Self, SceneError> {
        Self::from_desc_with_bodies(desc, dt, &NoBodies)
    }

    /// [`from_desc`](Self::from_desc) in a world whose rigid bodies are `frames`, which
    /// `body_attachments` name.
    pub(crate) fn from_desc_with_bodies(
        desc: &SoftDesc<R>,
        dt: R,
        frames: &dyn BodyFrames<R>,
    ) -> Result<Self, SceneError> {
        check_settings(&desc.solver).map_err(|e| e.within("solver"))?;
        let mut system = Self {
            settings: desc.solver,
            vertices: Vertices::default(),
            bodies: Vec::new(),
            distances: Default::default(),
            hinges: Default::default(),
            tetrahedra: Default::default(),
            attachments: Default::default(),
            ties: Default::default(),
            tethers: Default::default(),
            springs: Default::default(),
            colliders: Vec::new(),
            has_xpbd: false,
            scratch: Scratch::default(),
            warnings: Vec::new(),
        };
        for (k, collider) in desc.colliders.iter().enumerate() {
            let compiled =
                compile_collider(collider).map_err(|e| e.within(&format!("colliders[{k}]")))?;
            system.colliders.push(compiled);
        }
        for (k, body) in desc.bodies.iter().enumerate() {
            let field = format!("bodies[{k}]");
            system
                .add_body(body, frames)
                .map_err(|e| e.within(&field))?;
            if let Some(warning) = system.stability_warning(system.bodies.len() - 1, dt) {
                system.warnings.push(format!("soft.{field}: {warning}"));
            }
        }
        system.colour_rows();
        Ok(system)
    }

    /// Puts the distance and bending rows in colour order (see [`colour_order`]) and the
    /// tethers in rounds (see [`tether_order`]).
    fn colour_rows(&mut self) {
        let d = &mut self.distances;
        let ends: Vec<[u32; 2]> = d.a.iter().zip(&d.b).map(|(&a, &b)| [a, b]).collect();
        let order = colour_order(&ends, self.vertices.len());
        for rows in [&mut d.a, &mut d.b] {
            permute(rows, &order);
        }
        for rows in [
            &mut d.rest,
            &mut d.inv_length,
            &mut d.compliance,
            &mut d.lambda,
        ] {
            permute(rows, &order);
        }
        if let Some(order) = tether_order(
            &self.tethers.vertex,
            &self.tethers.anchor,
            self.vertices.len(),
        ) {
            let t = &mut self.tethers;
            permute(&mut t.vertex, &order);
            permute(&mut t.anchor, &order);
            permute(&mut t.rest, &order);
        }
        let h = &mut self.hinges;
        let order = colour_order(&h.vertices, self.vertices.len());
        permute(&mut h.vertices, &order);
        permute(&mut h.coefficients, &order);
        permute(&mut h.compliance, &order);
        permute(&mut h.lambda, &order);
    }

    /// Checks and adds one body.
    fn add_body(
        &mut self,
        desc: &SoftBodyDesc<R>,
        frames: &dyn BodyFrames<R>,
    ) -> Result<(), SceneError> {
        let count = check_shape(&desc.shape).map_err(|e| e.within("shape"))?;
        let first = self.vertices.len() as u64;
        if first + count > u64::from(MAX_VERTICES) {
            return Err(SceneError::new(
                "shape",
                format!("more than {MAX_VERTICES} soft vertices in the scene"),
            ));
        }
        let limit = R::from_int(MAX_MAGNITUDE);
        for (name, value) in [
            ("mass", desc.mass),
            ("damping", desc.damping),
            ("radius", desc.radius),
            ("drag", desc.drag),
        ] {
            SceneError::check_range(name, value, R::ZERO, limit, "")?;
        }
        for (name, v) in [("velocity", desc.velocity), ("wind", desc.wind)] {
            if v.abs().max_component() > limit {
                return Err(SceneError::new(
                    name,
                    format!("components must be within ±{MAX_MAGNITUDE}"),
                ));
            }
        }
        let vertex_mass = desc.mass / R::from_int(count as i32);
        let inv_mass = vertex_mass.recip();
        if vertex_mass <= R::ZERO || inv_mass > R::from_int(MAX_INV_MASS) {
            return Err(SceneError::new(
                "mass",
                format!(
                    "each of the {count} vertices must weigh at least 1 mg (got {} kg in all)",
                    desc.mass
                ),
            ));
        }
        let topology = topology::build(&desc.shape);
        let first = first as u32;
        let index = |field: &str, v: u32| -> Result<u32, SceneError> {
            if u64::from(v) < count {
                Ok(first + v)
            } else {
                Err(SceneError::new(
                    field,
                    format!("vertex {v} does not exist (the body has {count})"),
                ))
            }
        };
        let mut pinned = vec![false; count as usize];
        for (k, &p) in desc.pins.iter().enumerate() {
            let global = index(&format!("pins[{k}]"), p)?;
            pinned[(global - first) as usize] = true;
        }
        for (i, &x) in topology.positions.iter().enumerate() {
            self.vertices.position.push(x);
            self.vertices
                .velocity
                .push(if pinned[i] { Vec3::ZERO } else { desc.velocity });
            self.vertices.mass.push(vertex_mass);
            self.vertices
                .inv_mass
                .push(if pinned[i] { R::ZERO } else { inv_mass });
        }
        let model = match &desc.model {
            SoftModel::Xpbd {
                stretch_compliance,
                bend_compliance,
                volume_compliance,
                tethers,
            } => {
                for (name, value) in [
                    ("stretch_compliance", Some(*stretch_compliance)),
                    ("bend_compliance", *bend_compliance),
                    ("volume_compliance", *volume_compliance),
                ] {
                    if value.is_some_and(|v| v < R::ZERO || v > limit) {
                        return Err(SceneError::new(
                            format!("model.Xpbd.{name}"),
                            format!("must be 0 to {MAX_MAGNITUDE}"),
                        ));
                    }
                }
                self.add_xpbd_constraints(
                    &topology,
                    first,
                    *stretch_compliance,
                    *bend_compliance,
                    *volume_compliance,
                );
                for (g, attachment) in desc.attachments.iter().enumerate() {
                    let field = format!("attachments[{g}]");
                    if attachment.compliance < R::ZERO || attachment.compliance > limit {
                        return Err(SceneError::new(
                            format!("{field}.compliance"),
                            format!("must be 0 to {MAX_MAGNITUDE}"),
                        ));
                    }
                    let Some(&head) = attachment.vertices.first() else {
                        return Err(SceneError::new(
                            format!("{field}.vertices"),
                            "must not be empty",
                        ));
                    };
                    index(&format!("{field}.vertices[0]"), head)?;
                    let target = self.attachments.origin.len() as u32;
                    let at = &mut self.attachments;
                    at.origin.push(topology.positions[head as usize]);
                    at.start.push(Vec3::ZERO);
                    at.goal.push(Vec3::ZERO);
                    for (k, &v) in attachment.vertices.iter().enumerate() {
                        let global = index(&format!("{field}.vertices[{k}]"), v)?;
                        let at = &mut self.attachments;
                        at.vertex.push(global);
                        at.target.push(target);
                        at.rest.push(topology.positions[v as usize]);
                        at.compliance.push(attachment.compliance);
                        at.lambda.push(Vec3::ZERO);
                    }
                }
                for (g, tie) in desc.body_attachments.iter().enumerate() {
                    self.add_ties(tie, &topology.positions, frames, &index)
                        .map_err(|e| e.within(&format!("body_attachments[{g}]")))?;
                }
                if *tethers {
                    self.add_tethers(first, &pinned);
                }
                self.has_xpbd = true;
                Model::Xpbd
            }
            SoftModel::SpringMass {
                integrator,
                stiffness,
                damping,
            } => {
                if !supports(*integrator) {
                    return Err(SceneError::new(
                        "model.SpringMass.integrator",
                        format!(
                            "{integrator} keeps state between steps; a spring-mass body takes ExplicitEuler, SemiImplicitEuler, Leapfrog or ImplicitEuler"
                        ),
                    ));
                }
                if *stiffness < R::ZERO || *stiffness > R::from_int(MAX_STIFFNESS) {
                    return Err(SceneError::new(
                        "model.SpringMass.stiffness",
                        format!("must be 0 to {MAX_STIFFNESS} N/m (got {stiffness})"),
                    ));
                }
                if *damping < R::ZERO || *damping > limit {
                    return Err(SceneError::new(
                        "model.SpringMass.damping",
                        format!("must be 0 to {MAX_MAGNITUDE} N·s/m (got {damping})"),
                    ));
                }
                for (field, present) in [
                    ("attachments", !desc.attachments.is_empty()),
                    ("body_attachments", !desc.body_attachments.is_empty()),
                    ("body_contacts", desc.body_contacts.is_some()),
                ] {
                    if present {
                        return Err(SceneError::new(
                            field,
                            "only XPBD bodies have attachments and touch rigid bodies; pin the vertices instead",
                        ));
                    }
                }
                let start = self.springs.a.len() as u32;
                for &[a, b] in &topology.edges {
                    let rest =
                        topology.positions[a as usize].distance(topology.positions[b as usize]);
                    self.springs.a.push(first + a);
                    self.springs.b.push(first + b);
                    self.springs.rest.push(rest);
                }
                Model::SpringMass {
                    integrator: *integrator,
                    stiffness: *stiffness,
                    damping: *damping,
                    springs: (start, self.springs.a.len() as u32),
                }
            }
        };
        self.bodies.push(Body {
            first,
            end: self.vertices.len() as u32,
            model,
            damping: desc.damping,
            radius: desc.radius,
            wind: desc.wind,
            drag: desc.drag,
            contacts: desc
                .body_contacts
                .as_ref()
                .map(|c| -> Result<_, SceneError> {
                    SceneError::check_range("friction", c.friction, R::ZERO, limit, "")
                        .map_err(|e| e.within("body_contacts"))?;
                    Ok(BodyContacts {
                        friction: c.friction,
                        filter: c.filter,
                    })
                })
                .transpose()?,
        });
        Ok(())
    }

    /// The ties of one [`BodyAttachmentDesc`]; `positions` are the body's vertices at rest
    /// and `index` turns a vertex index within the body into a global one (or names it as
    /// missing).
    fn add_ties(
        &mut self,
        tie: &BodyAttachmentDesc<R>,
        positions: &[Vec3<R>],
        frames: &dyn BodyFrames<R>,
        index: &dyn Fn(&str, u32) -> Result<u32, SceneError>,
    ) -> Result<(), SceneError> {
        let limit = R::from_int(MAX_MAGNITUDE);
        SceneError::check_range("compliance", tie.compliance, R::ZERO, limit, "")?;
        let Some((handle, frame)) = frames.frame(tie.body) else {
            return Err(SceneError::new(
                "body",
                format!(
                    "names body {}, but the scene has {} rigid bodies",
                    tie.body,
                    frames.count()
                ),
            ));
        };
        if tie.vertices.is_empty() {
            return Err(SceneError::new("vertices", "must not be empty"));
        }
        for (k, &v) in tie.vertices.iter().enumerate() {
            let global = index(&format!("vertices[{k}]"), v)?;
            self.ties.vertex.push(global);
            self.ties.body.push(handle);
            self.ties
                .local
                .push(frame.inverse_point(positions[v as usize]));
            self.ties.compliance.push(tie.compliance);
        }
        Ok(())
    }

    /// The distance, bending and volume rows of an XPBD body whose first vertex is `first`.
    fn add_xpbd_constraints(
        &mut self,
        topology: &Topology<R>,
        first: u32,
        stretch: R,
        bend: Option<R>,
        volume: Option<R>,
    ) {
        let x = &topology.positions;
        for &[a, b] in &topology.edges {
            let rest = x[a as usize].distance(x[b as usize]);
            if rest > R::ZERO {
                self.distances.push(first + a, first + b, rest, stretch);
            }
        }
        if let Some(compliance) = bend {
            for &hinge in &topology.hinges {
                let corners = hinge.map(|v| x[v as usize]);
                self.hinges
                    .push(hinge.map(|v| first + v), corners, compliance);
            }
        }
        if let Some(compliance) = volume {
            for &tet in &topology.tetrahedra {
                let corners = tet.map(|v| x[v as usize]);
                self.tetrahedra
                    .push(tet.map(|v| first + v), corners, compliance);
            }
        }
    }

    /// Tethers of the body starting at `first` (`pinned` by local index), and of the body
    /// points its vertices are tied to (see [`Ties`](super::body_coupling::Ties)): every
    /// vertex that is neither pinned nor attached, and every tie, is tethered, at its rest distance, to each
    /// pinned vertex when the body has at most [`MAX_TETHERED_PINS`], and otherwise to its
    /// nearest anchor (pinned or attached vertex; the first in order on a tie). Tethering
    /// to every pin keeps the straight line between two pins, which an inextensible sheet
    /// cannot let sag, from stretching where the two nearest-pin regions meet. The body's
    /// attachment rows are the last ones added.
    fn add_tethers(&mut self, first: u32, pinned: &[bool]) {
        let x = &self.vertices.position;
        let mut pins: Vec<(u32, Vec3<R>)> = Vec::new();
        for (i, &p) in pinned.iter().enumerate() {
            if p {
                let v = first + i as u32;
                pins.push((v, x[v as usize]));
            }
        }
        let mut attached: Vec<(u32, Vec3<R>)> = Vec::new();
        let at = &self.attachments;
        for r in 0..at.vertex.len() {
            if at.vertex[r] >= first {
                attached.push((at.vertex[r], at.rest[r]));
            }
        }
        let every_pin = pins.len() <= MAX_TETHERED_PINS;
        let nearest_pool: Vec<(u32, Vec3<R>)> = if every_pin {
            attached.clone()
        } else {
            pins.iter().chain(&attached).copied().collect()
        };
        let choose = |p: Vec3<R>| {
            let mut chosen: Vec<(u32, Vec3<R>)> = Vec::new();
            if every_pin {
                chosen.extend(pins.iter().copied());
            }
            let mut best: Option<(R, usize)> = None;
            for (k, anchor) in nearest_pool.iter().enumerate() {
                let distance = (anchor.1 - p).length_squared();
                if best.is_none_or(|(d, _)| distance < d) {
                    best = Some((distance, k));
                }
            }
            if let Some((_, k)) = best {
                chosen.push(nearest_pool[k]);
            }
            chosen
        };
        for (i, &is_pinned) in pinned.iter().enumerate() {
            let v = first + i as u32;
            if is_pinned || attached.iter().any(|a| a.0 == v) {
                continue;
            }
            let p = x[v as usize];
            for (anchor, at) in choose(p) {
                let t = &mut self.tethers;
                t.vertex.push(v);
                t.anchor.push(anchor);
                t.rest.push(at.distance(p));
            }
        }
        let ties = &mut self.ties;
        for row in 0..ties.vertex.len() {
            if ties.vertex[row] < first {
                continue;
            }
            let p = x[ties.vertex[row] as usize];
            for (anchor, at) in choose(p) {
                ties.tether_row.push(row as u32);
                ties.tether_anchor.push(anchor);
                ties.tether_rest.push(at.distance(p));
            }
        }
    }

    /// The build-time warning for body `b` when it is a spring-mass network past the
    /// [stability bound](super::spring_mass) of its integrator at step `dt`.
    fn stability_warning(&self, b: usize, dt: R) -> Option<String> {
        let Model::SpringMass {
            integrator,
            stiffness,
            damping,
            springs,
        } = self.bodies[b].model
        else {
            return None;
        };
        let range = springs.0 as usize..springs.1 as usize;
        if range.is_empty() || (stiffness == R::ZERO && damping == R::ZERO) {
            return None;
        }
        let measure = stability_measure(
            &self.springs.a[range.clone()],
            &self.springs.b[range],
            &self.vertices.inv_mass,
            stiffness,
            damping,
            dt,
        );
        match integrator {
            Integrator::ImplicitEuler => None,
            Integrator::ExplicitEuler => Some(
                "explicit Euler adds energy to every spring mode at any step; the network will diverge (use SemiImplicitEuler)".to_owned(),
            ),
            _ if measure >= 4.0 => Some(format!(
                "(k·dt² + 2c·dt)·Λ = {measure:.3} is past the {integrator} stability bound 4 \
                 (Λ bounds the stiffest mode's ω²/k); the network will diverge: use more \
                 substeps, softer springs or heavier vertices"
            )),
            _ => None,
        }
    }

    /// Checks the invariants of a state that comes from outside (a snapshot); the error
    /// names the offending field.
    pub fn validate(&self) -> Result<(), SceneError> {
        check_settings(&self.settings).map_err(|e| e.within("solver"))?;
        let v = &self.vertices;
        let n = v.len();
        if [v.velocity.len(), v.mass.len(), v.inv_mass.len()]
            .iter()
            .any(|&len| len != n)
            || n > MAX_VERTICES as usize
        {
            return Err(SceneError::new(
                "vertices",
                "the vertex arrays have different lengths or too many vertices",
            ));
        }
        let in_range = |i: u32| (i as usize) < n;
        let d = &self.distances;
        let rows = d.a.len();
        if [
            d.b.len(),
            d.rest.len(),
            d.inv_length.len(),
            d.compliance.len(),
            d.lambda.len(),
        ]
        .iter()
        .any(|&len| len != rows)
            || !d.a.iter().chain(&d.b).all(|&i| in_range(i))
        {
            return Err(SceneError::new(
                "distances",
                "rows of different lengths or naming missing vertices",
            ));
        }
        let h = &self.hinges;
        if [h.coefficients.len(), h.compliance.len(), h.lambda.len()]
            .iter()
            .any(|&len| len != h.vertices.len())
            || !h.vertices.iter().flatten().all(|&i| in_range(i))
        {
            return Err(SceneError::new(
                "hinges",
                "rows of different lengths or naming missing vertices",
            ));
        }
        let t = &self.tetrahedra;
        if [t.rest_volume.len(), t.compliance.len(), t.lambda.len()]
            .iter()
            .any(|&len| len != t.vertices.len())
            || !t.vertices.iter().flatten().all(|&i| in_range(i))
        {
            return Err(SceneError::new(
                "tetrahedra",
                "rows of different lengths or naming missing vertices",
            ));
        }
        let at = &self.attachments;
        let targets = at.origin.len();
        if at.start.len() != targets
            || at.goal.len() != targets
            || [
                at.target.len(),
                at.rest.len(),
                at.compliance.len(),
                at.lambda.len(),
            ]
            .iter()
            .any(|&len| len != at.vertex.len())
            || !at.vertex.iter().all(|&i| in_range(i))
            || !at.target.iter().all(|&g| (g as usize) < targets)
        {
            return Err(SceneError::new(
                "attachments",
                "rows of different lengths or naming missing vertices or targets",
            ));
        }
        let ties = &self.ties;
        if [ties.body.len(), ties.local.len(), ties.compliance.len()]
            .iter()
            .any(|&len| len != ties.vertex.len())
            || !ties.vertex.iter().all(|&i| in_range(i))
            || [ties.tether_anchor.len(), ties.tether_rest.len()]
                .iter()
                .any(|&len| len != ties.tether_row.len())
            || !ties.tether_anchor.iter().all(|&i| in_range(i))
            || !ties
                .tether_row
                .iter()
                .all(|&r| (r as usize) < ties.vertex.len())
        {
            return Err(SceneError::new(
                "ties",
                "rows of different lengths or naming missing vertices",
            ));
        }
        let tt = &self.tethers;
        if [tt.anchor.len(), tt.rest.len()]
            .iter()
            .any(|&len| len != tt.vertex.len())
            || !tt.vertex.iter().chain(&tt.anchor).all(|&i| in_range(i))
        {
            return Err(SceneError::new(
                "tethers",
                "rows of different lengths or naming missing vertices",
            ));
        }
        let s = &self.springs;
        if s.b.len() != s.a.len()
            || s.rest.len() != s.a.len()
            || !s.a.iter().chain(&s.b).all(|&i| in_range(i))
        {
            return Err(SceneError::new(
                "springs",
                "rows of different lengths or naming missing vertices",
            ));
        }
        let mut end = 0;
        for (k, body) in self.bodies.iter().enumerate() {
            let ok = body.first == end && body.first <= body.end && body.end as usize <= n;
            let springs_ok = match body.model {
                Model::SpringMass {
                    springs,
                    integrator,
                    ..
                } => {
                    springs.0 <= springs.1
                        && springs.1 as usize <= s.a.len()
                        && supports(integrator)
                }
                Model::Xpbd => true,
            };
            if !ok || !springs_ok {
                return Err(SceneError::new(
                    format!("bodies[{k}]"),
                    "vertex or spring range out of order or out of bounds",
                ));
            }
            end = body.end;
        }
        if end as usize != n {
            return Err(SceneError::new(
                "bodies",
                "the bodies do not cover every vertex",
            ));
        }
        if self.has_xpbd != self.bodies.iter().any(|b| b.model == Model::Xpbd) {
            return Err(SceneError::new("has_xpbd", "does not match the bodies"));
        }
        Ok(())
    }
}

/// The most colours [`colour_order`] tells apart; rows past them share the last colour.
const MAX_COLOURS: u32 = 64;

/// A Gauss–Seidel order in which consecutive rows rarely share a vertex, so that the
/// processor can overlap one row's arithmetic with the next one's: rows are coloured
/// greedily in their build order (each takes the lowest colour none of its vertices has yet,
/// up to [`MAX_COLOURS`]), then listed colour by colour, in build order within a colour.
/// The order depends only on the rows, so it is the same on every machine.
fn colour_order<const K: usize>(rows: &[[u32; K]], vertices: usize) -> Vec<usize> {
    let mut used = vec![0u64; vertices];
    let mut colours = Vec::with_capacity(rows.len());
    for row in rows {
        let taken = row.iter().fold(0u64, |mask, &v| mask | used[v as usize]);
        let colour = taken.trailing_ones().min(MAX_COLOURS - 1);
        for &v in row {
            used[v as usize] |= 1 << colour;
        }
        colours.push(colour);
    }
    let mut order: Vec<usize> = (0..rows.len()).collect();
    order.sort_by_key(|&r| (colours[r], r));
    order
}

/// An order of the tethers (tethered vertex `vertex`, anchor `anchor`, both below
/// `vertices`) in which
/// consecutive rows rarely share a vertex, so that the processor can overlap them: each
/// vertex's first tether, then each one's second, and so on, in build order within a round.
/// `None` (keep the build order) unless no anchor is a tethered vertex. Then a pass reads
/// each anchor unchanged and each tether moves only its own vertex, so any order that keeps
/// every vertex's tethers in their build order gives the same positions, bit for bit, as the
/// build order. (The anchors are pinned or attached vertices, which are never tethered, so
/// this always holds for the built bodies.)
fn tether_order(vertex: &[u32], anchor: &[u32], vertices: usize) -> Option<Vec<usize>> {
    let mut tethers = vec![0u32; vertices];
    let rounds: Vec<u32> = vertex
        .iter()
        .map(|&v| {
            tethers[v as usize] += 1;
            tethers[v as usize] - 1
        })
        .collect();
    if anchor.iter().any(|&a| tethers[a as usize] != 0) {
        return None;
    }
    let mut order: Vec<usize> = (0..vertex.len()).collect();
    order.sort_by_key(|&t| (rounds[t], t));
    Some(order)
}

/// `rows` rearranged so that entry k is the old entry `order[k]`.
fn permute<T: Clone>(rows: &mut Vec<T>, order: &[usize]) {
    *rows = order.iter().map(|&k| rows[k].clone()).collect();
}

fn check_settings(s: &XpbdSettings) -> Result<(), SceneError> {
    for (name, value) in [("substeps", s.substeps), ("iterations", s.iterations)] {
        if !(1..=MAX_SOLVER_STEPS).contains(&value) {
            return Err(SceneError::new(
                name,
                format!("must be 1 to {MAX_SOLVER_STEPS} (got {value})"),
            ));
        }
    }
    Ok(())
}

/// Checks a shape's counts and sizes; returns its vertex count.
fn check_shape<R: Real>(shape: &SoftShape<R>) -> Result<u64, SceneError> {
    let limit = R::from_int(MAX_MAGNITUDE);
    let point = |name: &str, v: Vec3<R>| {
        if v.abs().max_component() > limit {
            Err(SceneError::new(
                name,
                format!("components must be within ±{MAX_MAGNITUDE}"),
            ))
        } else {
            Ok(())
        }
    };
    match *shape {
        SoftShape::Cloth {
            origin,
            u,
            v,
            columns,
            rows,
        } => {
            point("Cloth.origin", origin)?;
            point("Cloth.u", u)?;
            point("Cloth.v", v)?;
            if columns < 2 || rows < 2 {
                return Err(SceneError::new(
                    "Cloth",
                    "columns and rows must be at least 2",
                ));
            }
            if u.cross(v).length_squared() == R::ZERO {
                return Err(SceneError::new(
                    "Cloth.v",
                    "must not be parallel to u (or zero)",
                ));
            }
            Ok(u64::from(columns) * u64::from(rows))
        }
        SoftShape::Rope { start, end, links } => {
            point("Rope.start", start)?;
            point("Rope.end", end)?;
            if links == 0 {
                return Err(SceneError::new("Rope.links", "must be at least 1"));
            }
            if start == end {
                return Err(SceneError::new("Rope.end", "must differ from start"));
            }
            Ok(u64::from(links) + 1)
        }
        SoftShape::Lattice {
            origin,
            spacing,
            count,
        } => {
            point("Lattice.origin", origin)?;
            let (nx, ny, nz) = count;
            if nx < 2 || ny < 2 || nz < 2 {
                return Err(SceneError::new(
                    "Lattice.count",
                    "every count must be at least 2",
                ));
            }
            let largest = nx.max(ny).max(nz).min(MAX_VERTICES);
            if spacing <= R::ZERO || spacing * R::from_int(largest as i32) > limit {
                return Err(SceneError::new(
                    "Lattice.spacing",
                    format!("must be above 0, the block within {MAX_MAGNITUDE} m"),
                ));
            }
            Ok(lattice_copies(Some(count)))
        }
    }
    .and_then(|count| {
        if count > u64::from(MAX_VERTICES) {
            Err(SceneError::new(
                "",
                format!("more than {MAX_VERTICES} vertices"),
            ))
        } else {
            Ok(count)
        }
    })
}

/// Checks a collider and places its shape in the world.
fn compile_collider<R: Real>(c: &ColliderDesc<R>) -> Result<Collider<R>, SceneError> {
    let limit = R::from_int(MAX_MAGNITUDE);
    if c.position.abs().max_component() > limit {
        return Err(SceneError::new(
            "position",
            format!("components must be within ±{MAX_MAGNITUDE}"),
        ));
    }
    if c.friction < R::ZERO || c.friction > limit {
        return Err(SceneError::new(
            "friction",
            format!("must be 0 to {MAX_MAGNITUDE}"),
        ));
    }
    let orientation = SceneError::unit_quaternion("orientation", c.orientation)?;
    let size = |name: &str, v: R| {
        if v <= R::ZERO || v > limit {
            Err(SceneError::new(
                name,
                format!("must be above 0 and at most {MAX_MAGNITUDE} m (got {v})"),
            ))
        } else {
            Ok(())
        }
    };
    let geometry = match &c.shape {
        Shape::Plane { normal, offset } => {
            if (normal.length_squared() - R::ONE).abs() > R::from_ratio(1, 1000) {
                return Err(SceneError::new("shape.Plane.normal", "must have length 1"));
            }
            if offset.abs() > limit {
                return Err(SceneError::new(
                    "shape.Plane.offset",
                    format!("must be within ±{MAX_MAGNITUDE} m"),
                ));
            }
            let n = orientation.rotate(*normal);
            Geometry::Plane {
                normal: n,
                offset: *offset + n.dot(c.position),
            }
        }
        Shape::Sphere { radius } => {
            size("shape.Sphere.radius", *radius)?;
            Geometry::Sphere {
                centre: c.position,
                radius: *radius,
            }
        }
        Shape::Box { half_extents } => {
            size("shape.Box.half_extents.x", half_extents.x)?;
            size("shape.Box.half_extents.y", half_extents.y)?;
            size("shape.Box.half_extents.z", half_extents.z)?;
            Geometry::Box {
                rotation: orientation.to_mat3(),
                centre: c.position,
                half_extents: *half_extents,
            }
        }
        Shape::Capsule {
            radius,
            half_height,
        } => {
            size("shape.Capsule.radius", *radius)?;
            if *half_height < R::ZERO || *half_height > limit {
                return Err(SceneError::new(
                    "shape.Capsule.half_height",
                    format!("must be 0 to {MAX_MAGNITUDE} m"),
                ));
            }
            let axis = orientation.rotate(Vec3::Y) * *half_height;
            let length_squared = (axis + axis).length_squared();
            Geometry::Capsule {
                a: c.position - axis,
                b: c.position + axis,
                radius: *radius,
                inv_length_squared: if length_squared == R::ZERO {
                    R::ZERO
                } else {
                    length_squared.recip()
                },
            }
        }
        Shape::Compound { .. }
        | Shape::Cylinder { .. }
        | Shape::Cone { .. }
        | Shape::ConvexHull { .. }
        | Shape::TriMesh { .. }
        | Shape::HeightField { .. } => {
            return Err(SceneError::new(
                "shape",
                "a soft-body collider is a plane, a sphere, a box or a capsule",
            ));
        }
    };
    Ok(Collider {
        geometry,
        friction: c.friction,
    })
}
