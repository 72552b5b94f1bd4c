//! Continuous collision: the step's last stage, which keeps fast dynamic bodies from
//! tunnelling through thin static and kinematic bodies (Box2D v3's `b2SolveContinuous`).
//!
//! The solver moves a body by its velocity in substeps and only sees contacts the collide
//! stage found at the start of the step, within the speculative distance. A body that moves
//! farther in one step than its own thickness can therefore pass a wall it was not yet near.
//! This stage, after the solve and the sleep update, looks at every awake dynamic body
//! that is not a sensor, nor held by a joint unless it is a bullet (moving a jointed body
//! back alone would stretch its joints: in the committed `ragdolls`, a forearm stopped on
//! a stair pulled 7 cm off its elbow):
//!
//! 1. **Fast?** With p₀ its centre of mass at the start of the step (where the collide stage
//!    placed it) and p₁ at the end, Δp = p₁ − p₀, the body is *fast* when
//!    |Δp| > ½ e, where e (m) is its core extent: the radius of the ball inscribed in its
//!    shape about the shape's centre, the smallest over a compound's parts ([`core_of`]).
//!    No fast body: the stage ends there, after one comparison per moving body.
//! 2. **Sweep.** The body's shape, at its *end* orientation (rotation during the step is
//!    not swept), is translated from p₀ along the unit direction d = Δp/|Δp| over the
//!    length L = |Δp| (m), against every candidate whose box meets the swept box (the
//!    union of the body's box at p₀ and at p₁, found with the query tree, then checked on
//!    the candidate's tight box): static and kinematic bodies at their end-of-step poses
//!    and, for a [bullet](super::BodyDesc::bullet), the dynamic bodies that are not
//!    bullets. Sensors, bodies whose layers do not interact, and jointed pairs that do not
//!    collide are skipped, as in the collide stage. The sweep is the query module's
//!    shape cast (conservative advancement with the narrowphase), so every convex shape
//!    the narrowphase handles is swept.
//! 3. **Time of impact.** A cast that first touches at distance D (m) with unit normal n
//!    (out of the target) gives, to first order, the body's gap along n at the start,
//!    g₀ = D c, and how deep its end pose lies, g₁ = (L − D) c, with c = −n·d > 0 the
//!    closing rate. With the slop σ = ¼ × the speculative distance (5 mm by default, Box2D's
//!    linear slop), the hit counts when g₀ > σ (the body started clear) and
//!    g₁ > δ = max(σ, e) (it would end deeper than its core extent inside): the body's
//!    travel is then cut to T = D − σ/c ≥ 0, which leaves it σ outside along n. A
//!    shallower end pose keeps the body's centre on the near side of the target's surface
//!    (its inscribed ball, of radius e, lies at least e behind its leading point), so the
//!    contacts push it back out on the side it came from: it is left to them, as is a body
//!    the solver stopped on a surface. So ordinary scenes are hardly disturbed: at δ = ½ e
//!    a box of the committed `falling_hinges` driven 0.21 m into the floor by its hinges
//!    and a `shooter` projectile landing 8.8 cm deep, both pushed back out by their
//!    contacts, were moved back; at δ = e neither is. (Box2D moves a body back as soon as
//!    it would end within its slop.)
//! 4. **Core.** A body that starts within the slop of a target (g₀ ≤ σ: resting on it,
//!    sliding along it) would always hit at once. As Box2D, it sweeps instead its core, a
//!    ball of radius ¼ e about each part's centre, with the same rule but the depth
//!    max(σ, ¼ e) (the core's leading point is ¼ e ahead of its centre): a body sliding fast
//!    over the ground is not held back, but one driven through a thin plate it touches is
//!    stopped with its core σ short of the plate (the shape then overlaps, and the contact
//!    pushes it out over the next steps). A core already within the slop is left to the
//!    contacts.
//! 5. **Move back.** The body moves to p₀ + T d, T the smallest travel over its parts and
//!    candidates, keeping its end orientation and its velocity: next step's collide stage
//!    finds the target within the speculative distance, and the speculative contact
//!    (separation σ > 0, solved as a hard constraint) stops it.
//!
//! Bodies that are not bullets are swept first, in slot order, against static and
//! kinematic bodies, which this stage never moves; then the bullets, against the others'
//! final poses and never against each other. So no result depends on the order of the
//! sweeps, nor on the shape of the query tree: each sweep keeps the smallest travel over
//! all its candidates. The query tree is brought up to date with the bodies moved back
//! after each pass that moved one. The stage keeps no state between steps.

use super::collide::for_each_part;
use super::desc::BodyKind;
use super::query::{CastHit, cast_tolerance, sweep_shape, unit_direction};
use super::shape::Shape;
use super::system::RigidSystem;
use super::transform::Transform;
use crate::math::{Real, Vec3};

/// The motion, as a fraction of the core extent, beyond which a body is fast (Box2D's
/// safety factor ½).
fn fast_fraction<R: Real>() -> R {
    R::HALF
}

/// The radius of the core ball swept for a body that starts in contact, as a fraction of
/// the core extent (Box2D's `B2_CORE_FRACTION`, ¼).
fn core_fraction<R: Real>() -> R {
    R::from_ratio(1, 4)
}

/// The ball inscribed in a convex shape, in its own frame: its centre (m) and radius (m).
/// Sphere: r about the centre; box: the smallest half extent; capsule: r; cylinder: the
/// smaller of r and h; cone (apex at (0, h, 0), base at y = −h): about its centre of mass
/// (0, −h/2, 0), the smaller of its height above the base, h/2, and its distance to the
/// side, 3rh/(2√(r² + 4h²)), bounded below by 3rh/(2(r + 2h)) (√(r² + 4h²) ≤ r + 2h);
/// hull: about its origin (its centre of mass once in a dynamic body), the nearest face
/// offset, 0 when the origin is outside or the hull has no faces. `None` for a plane, a
/// compound, a mesh or a heightfield.
fn core_of<R: Real>(shape: &Shape<R>) -> Option<(Vec3<R>, R)> {
    let centred = |radius: R| Some((Vec3::ZERO, radius));
    match shape {
        Shape::Sphere { radius } | Shape::Capsule { radius, .. } => centred(*radius),
        Shape::Box { half_extents } => {
            centred(half_extents.x.min(half_extents.y).min(half_extents.z))
        }
        Shape::Cylinder {
            radius,
            half_height,
        } => centred(radius.min(*half_height)),
        Shape::Cone {
            radius,
            half_height,
        } => {
            let (r, h) = (*radius, *half_height);
            // r + 2h > 0: a checked cone has positive sizes.
            let side = (R::from_int(3) * r * h) / (R::TWO * (r + R::TWO * h));
            Some((
                Vec3::new(R::ZERO, -h * R::HALF, R::ZERO),
                side.min(h * R::HALF),
            ))
        }
        Shape::ConvexHull { hull } => {
            let nearest = hull
                .faces()
                .iter()
                .map(|f| f.offset)
                .reduce(|a, b| a.min(b));
            centred(nearest.unwrap_or(R::ZERO).max(R::ZERO))
        }
        Shape::Plane { .. }
        | Shape::Compound { .. }
        | Shape::TriMesh { .. }
        | Shape::HeightField { .. } => None,
    }
}

/// The core extent e of a body's shape (m): the smallest inscribed radius over its parts
/// ([`core_of`]); `None` for a shape without one (a plane).
fn core_extent<R: Real>(shape: &Shape<R>) -> Option<R> {
    let radius = |part: &Shape<R>| core_of(part).map(|(_, radius)| radius);
    match shape {
        // Parts are never compounds (the scene checks refuse them).
        Shape::Compound { parts } => parts
            .iter()
            .filter_map(|part| radius(&part.shape))
            .reduce(R::min),
        other => radius(other),
    }
}

/// Whether a displacement `delta` (m) is longer than `threshold` (m ≥ 0), without squaring
/// a large vector: |Δ| ≥ max |Δᵢ|, and |Δ| ≤ √3 max |Δᵢ| < 2 max |Δᵢ|.
fn longer_than<R: Real>(delta: Vec3<R>, threshold: R) -> bool {
    let largest = delta.abs().max_component();
    if largest > threshold {
        return true;
    }
    if largest * R::TWO <= threshold {
        return false;
    }
    // Here every |Δᵢ| ≤ threshold: the square cannot saturate.
    delta.length_squared() > threshold * threshold
}

/// What one cast says about the body's travel (see the [module](self), steps 3 and 4).
enum Impact<R: Real> {
    /// No hit, or a hit the end pose does not pass by more than the slop.
    Clear,
    /// The shape starts within the slop of the target.
    Starts,
    /// The travel cut to T (m).
    Travel(R),
}

/// The impact rule of a cast `hit` along unit `direction` over `length` (m), with slop
/// `slop` (m) and depth `depth` (m): see the [module](self), step 3.
fn impact<R: Real>(
    hit: Option<CastHit<R>>,
    direction: Vec3<R>,
    length: R,
    slop: R,
    depth: R,
) -> Impact<R> {
    let Some(hit) = hit else {
        return Impact::Clear;
    };
    let closing = -hit.normal.dot(direction);
    if hit.distance * closing <= slop {
        return Impact::Starts;
    }
    if (length - hit.distance) * closing <= depth {
        return Impact::Clear;
    }
    // D c > σ ≥ 0 with D ≥ 0, so c > 0: the quotient is defined and below D.
    Impact::Travel((hit.distance - slop / closing).max(R::ZERO))
}

/// One fast body's sweep: where it starts, which way and how far it goes.
struct Sweep<R: Real> {
    slot: usize,
    /// The body's placement at the start of the step with its end orientation.
    start: Transform<R>,
    direction: Vec3<R>,
    length: R,
    /// The core extent e, m.
    extent: R,
    bullet: bool,
}

impl<R: Real> RigidSystem<R> {
    /// The continuous stage (see the [module](self)); runs after the query index is
    /// current.
    pub(crate) fn solve_continuous(&mut self) {
        let bodies = &self.bodies;
        let transforms = &self.scratch.transforms;
        let mut sweeps: Vec<Sweep<R>> = Vec::new();
        let mut bullets = false;
        for (i, placement) in transforms.iter().enumerate().take(bodies.len()) {
            if !bodies.is_awake_dynamic(i) || bodies.sensor[i] {
                continue;
            }
            let Some(extent) = core_extent(&bodies.shape[i]) else {
                continue;
            };
            let start = placement.translation;
            let delta = bodies.position[i] - start;
            if !longer_than(delta, extent * fast_fraction::<R>()) {
                continue;
            }
            let Some(direction) = unit_direction(delta) else {
                continue;
            };
            bullets |= bodies.bullet[i];
            sweeps.push(Sweep {
                bullet: bodies.bullet[i],
                slot: i,
                start: Transform::from_pose(start, bodies.orientation[i]),
                direction,
                length: delta.dot(direction).max(R::ZERO),
                extent,
            });
        }
        if !sweeps.is_empty() && !self.joints.is_empty() {
            // A jointed body is swept only when it is a bullet: moving it back alone would
            // stretch its joints, which with its contacts keep it out of what it meets.
            let joints = &self.joints;
            let mut jointed: Vec<u32> = joints
                .live()
                .flat_map(|j| [joints.body_a[j], joints.body_b[j]])
                .collect();
            jointed.sort_unstable();
            sweeps.retain(|s| s.bullet || jointed.binary_search(&(s.slot as u32)).is_err());
            bullets = sweeps.iter().any(|s| s.bullet);
        }
        if sweeps.is_empty() {
            return;
        }
        if !self.scratch.joint_filter_valid {
            self.scratch.joint_filter = self.joints.non_colliding_pairs();
            self.scratch.joint_filter_valid = true;
        }
        let passes: &[bool] = if bullets { &[false, true] } else { &[false] };
        for &bullet_pass in passes {
            let mut moved: Vec<u32> = Vec::new();
            for sweep in sweeps.iter().filter(|s| s.bullet == bullet_pass) {
                if let Some(travel) = self.sweep_travel(sweep) {
                    let i = sweep.slot;
                    self.bodies.position[i] =
                        sweep.start.translation.add_scaled(sweep.direction, travel);
                    moved.push(i as u32);
                }
            }
            if !moved.is_empty() {
                let bodies = &self.bodies;
                self.scratch
                    .query
                    .sync(bodies, |i| moved.binary_search(&(i as u32)).is_ok());
            }
        }
    }

    /// The smallest travel (m) over the sweep's parts and candidates, when some hit cuts
    /// it short.
    fn sweep_travel(&self, sweep: &Sweep<R>) -> Option<R> {
        let bodies = &self.bodies;
        let i = sweep.slot;
        let shape = &bodies.shape[i];
        let end = Transform {
            translation: bodies.position[i],
            ..sweep.start
        };
        let (Some(at_start), Some(at_end)) = (
            super::Aabb::of_shape(shape, &sweep.start),
            super::Aabb::of_shape(shape, &end),
        ) else {
            return None;
        };
        let swept = at_start
            .union(&at_end)
            .expanded(cast_tolerance::<R>() * R::TWO);
        let mut candidates: Vec<usize> = Vec::new();
        debug_assert!(self.scratch.query.is_current(bodies.len()));
        self.scratch
            .query
            .candidates(|aabb| aabb.overlaps(&swept), |j| candidates.push(j));
        candidates.sort_unstable();
        candidates.dedup();

        let slop = self.settings.speculative_distance * R::from_ratio(1, 4);
        let core_radius = sweep.extent * core_fraction::<R>();
        let depth = slop.max(sweep.extent);
        let core_depth = slop.max(core_radius);
        let mut best: Option<R> = None;
        for j in candidates {
            if !self.sweeps_against(i, j) {
                continue;
            }
            let target = &bodies.shape[j];
            let xf = Transform::from_pose(bodies.position[j], bodies.orientation[j]);
            // The same tight-box test whatever the tree looks like.
            if super::Aabb::of_shape(target, &xf).is_some_and(|b| !b.overlaps(&swept)) {
                continue;
            }
            let centre_path = (sweep.start.translation, end.translation);
            for_each_part(shape, &sweep.start, |_, part, placed| {
                let cast = |cast: &Shape<R>, from: &Transform<R>, depth: R| {
                    let hit = sweep_shape(
                        cast,
                        from,
                        sweep.direction,
                        sweep.length,
                        target,
                        &xf,
                        centre_path,
                    );
                    impact(hit, sweep.direction, sweep.length, slop, depth)
                };
                let travel = match cast(part, placed, depth) {
                    Impact::Travel(t) => Some(t),
                    Impact::Clear => None,
                    Impact::Starts => core_of(part).and_then(|(centre, _)| {
                        let core = Shape::Sphere {
                            radius: core_radius,
                        };
                        let from = Transform {
                            translation: placed.point(centre),
                            ..*placed
                        };
                        match cast(&core, &from, core_depth) {
                            Impact::Travel(t) => Some(t),
                            Impact::Clear | Impact::Starts => None,
                        }
                    }),
                };
                if let Some(t) = travel {
                    best = Some(best.map_or(t, |b| b.min(t)));
                }
            });
        }
        best
    }

    /// Whether fast body `i` is swept against body `j`: a live body other than `i`, not a
    /// sensor, static or kinematic (or a dynamic body that is not a bullet, when `i` is
    /// one), whose layers interact with `i`'s and which no joint keeps from colliding with
    /// it.
    fn sweeps_against(&self, i: usize, j: usize) -> bool {
        let b = &self.bodies;
        if j == i || j >= b.len() || !b.alive[j] || b.sensor[j] {
            return false;
        }
        let kind_ok = match b.kind[j] {
            BodyKind::Static | BodyKind::Kinematic => true,
            BodyKind::Dynamic => b.bullet[i] && !b.bullet[j],
        };
        if !kind_ok || !b.filter[i].interacts(b.filter[j]) {
            return false;
        }
        let pair = (i.min(j) as u32, i.max(j) as u32);
        self.scratch.joint_filter.binary_search(&pair).is_err()
    }
}
