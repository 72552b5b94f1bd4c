//! Rigid bodies in the fluid, two-way: their volumes sampled as boundary particles
//! (Akinci et al. 2012, "Versatile rigid–fluid coupling for incompressible SPH"), and the
//! fluid's pressure pushing them back.
//!
//! **Sampling**, once per body, in its own frame: the sites of a lattice one fluid spacing
//! apart, offset half a spacing from the body's centre, that lie in the shape within the
//! kernel's reach of its surface (a site ⌈H/spacing⌉ sites or fewer along an axis from one
//! outside). This is Akinci's boundary with uniform sampling, as the tank's walls have:
//! each sample has the volume V₀ of a fluid particle (ψ = ρ₀V₀), and a fluid particle
//! beside a flat face sees the kernel sum of the fluid it replaces, so its density is right
//! at the face. Akinci's volume weighting V_b = 1/Σₖ W_bk is for a shell one sample thick;
//! on this kernel it gives a particle one spacing off a face 33 % more than the missing
//! fluid (0.164 against 0.124 of ρ₀ at a support of 2 spacings), which held the water a
//! fraction of a spacing off the body and floated an 8 × 4 × 8 cm box of 500 kg/m³ with a
//! 1.26 cm draft against 2.0. With sites half a spacing off the centre, a box a whole
//! number of spacings wide has its outermost samples half a spacing inside its faces, as
//! the tank's are outside its walls. Planes, meshes and heightfields are not sampled (the
//! tank is the fluid's level), nor bodies of more than [`MAX_BODY_SITES`] lattice sites.
//!
//! **Each fluid substep** the samples are placed where the body is at the substep's start,
//! with the velocity of the body's material point v_b = v + ω × (x_b − c), and listed as
//! the fluid particles' neighbours with V₀W and V₀∇W:
//! - density: ρ̃ᵢ += Σ_b V₀W_ib;
//! - WCSPH: aᵢ −= Σ_b (P̃ᵢ/ρ̃ᵢ² − α c min((vᵢ − v_b)·d_ib, 0)) V₀∇W_ib, and the body takes
//!   the opposite, m aᵢ's share Δt at the sample (m = ρ₀V₀);
//! - DFSPH: the compression rate takes Σ_b (vᵢ − v_b)·V₀∇W_ib, the corrections
//!   −Δt kᵢ Σ_b V₀∇W_ib, and each iteration gives the body the opposite,
//!   J = m Δt kᵢ V₀∇W_ib at each sample, at once: the next iteration sees the body move
//!   ([`BodiesInFluid::push_iteration`]). So the fluid and a light body converge together;
//!   pushed once per substep instead, a box of 500 kg/m³ (lighter than the water it sets
//!   moving) took twice the push it needed and chattered at 0.1 m/s. In each particle's
//!   factor the body counts with its mass shared among the particles touching it
//!   ([`BodiesInFluid::mobility`]), so the iterations do not overshoot.
//! - XSPH smoothing (both solvers): vᵢ += ε Σ_b V₀W_ib (v_b − vᵢ), the body taking the
//!   opposite momentum: the water's friction on it ([`BodiesInFluid::drag`]).
//!
//! The pushes of a substep are summed into an impulse and a moment about the body's
//! centre, and the drift they caused over the substep (h J/m, h I⁻¹L), which the world
//! applies.

use super::grid::CellGrid;
use super::kernel::Kernel;
use super::neighbours::NeighbourLists;
use crate::math::{Mat3, Quat, Real, Vec3};
use crate::rigid::query::shape_contains;
use crate::rigid::{Aabb, Shape, Transform};
use crate::types::Handle;

/// The most lattice sites a body's box may hold for it to be sampled: 2²².
pub const MAX_BODY_SITES: u64 = 1 << 22;

/// A rigid body as the fluid sees it during one fluid substep.
#[derive(Clone, Copy, Debug)]
pub(crate) struct BodyView<'a, R: Real> {
    pub handle: Handle,
    pub shape: &'a Shape<R>,
    /// Centre of mass, m, and orientation at the start of the fluid substep.
    pub position: Vec3<R>,
    pub orientation: Quat<R>,
    /// v (m/s) and ω (rad/s).
    pub velocity: Vec3<R>,
    pub angular_velocity: Vec3<R>,
    /// 1/m (1/kg) and I⁻¹ in the world frame (1/(kg·m²)); zero for a body the fluid does
    /// not move (static, kinematic, asleep).
    pub inv_mass: R,
    pub inv_inertia: Mat3<R>,
}

/// What a fluid substep did to the bodies in view, per view: the impulse (N·s) and moment
/// about its centre (N·m·s) it gave, and how far those moved (m) and turned (rotation
/// vector, rad) the body during the substep.
pub(crate) struct FluidPushes<'a, R: Real> {
    pub pushes: &'a [(Vec3<R>, Vec3<R>)],
    pub drifts: &'a [(Vec3<R>, Vec3<R>)],
}

/// A body's samples in its own frame.
#[derive(Debug)]
struct Sampled<R: Real> {
    handle: Handle,
    local: Vec<Vec3<R>>,
}

/// The bodies in the fluid: their samples (kept while the bodies live) and, for the current
/// fluid substep, the placed samples, their neighbour lists and the pushes gathered.
#[derive(Debug, Default)]
pub(crate) struct BodiesInFluid<R: Real> {
    /// Samples by body, in ascending handle order.
    sampled: Vec<Sampled<R>>,
    /// Whether the current substep has samples near the fluid.
    pub active: bool,
    /// The placed samples: position (m), velocity (m/s), and the view they belong to.
    points: Vec<Vec3<R>>,
    velocities: Vec<Vec3<R>>,
    owner: Vec<u32>,
    /// Each view's motion at the current substep.
    motions: Vec<Motion<R>>,
    grid: Option<CellGrid<R>>,
    /// The placed bodies' boxes, grown by the kernel's support: the particles that may have
    /// samples among their neighbours.
    near: Vec<Aabb<R>>,
    /// The fluid particles' neighbours among the samples, values V₀W and gradients V₀∇W.
    pub lists: NeighbourLists<R>,
    /// Σ_b v_b·V₀∇W_ib of each fluid particle, 1/s (DFSPH).
    pub rate: Vec<R>,
    /// Per view: impulse (N·s) and moment about its centre (N·m·s) over the substep.
    pub pushes: Vec<(Vec3<R>, Vec3<R>)>,
    /// Per view: how far the substep's pushes moved it (m) and turned it (rotation
    /// vector, rad) beyond its path along its velocities.
    pub drifts: Vec<(Vec3<R>, Vec3<R>)>,
}

/// A view's motion during a fluid substep.
#[derive(Clone, Copy, Debug)]
struct Motion<R: Real> {
    /// Centre of mass, m.
    centre: Vec3<R>,
    /// v (m/s) and ω (rad/s) before the substep's pushes.
    velocity: Vec3<R>,
    angular_velocity: Vec3<R>,
    /// 1/m (1/kg) and I⁻¹ (1/(kg·m²)), zero for a body the fluid does not move.
    inv_mass: R,
    inv_inertia: Mat3<R>,
    /// The fluid particles with a sample of this body among their neighbours.
    touching: u32,
}

impl<R: Real> Motion<R> {
    /// The velocities once the pushes `(J, L)` are applied: v + J/m and ω + I⁻¹L, so that
    /// the fluid's later iterations and substeps see the body respond.
    fn pushed(&self, (impulse, moment): (Vec3<R>, Vec3<R>)) -> (Vec3<R>, Vec3<R>) {
        (
            self.velocity.add_scaled(impulse, self.inv_mass),
            self.angular_velocity + self.inv_inertia * moment,
        )
    }
}

impl<R: Real> BodiesInFluid<R> {
    /// Starts a fluid substep with `views` in view: no push yet, and the samples of bodies
    /// no longer in view (removed) forgotten.
    pub fn begin(&mut self, views: &[BodyView<'_, R>]) {
        let count = views.len();
        let mut next = 0;
        self.sampled.retain(|s| {
            while next < count && views[next].handle < s.handle {
                next += 1;
            }
            next < count && views[next].handle == s.handle
        });
        self.pushes.clear();
        self.pushes.resize(count, (Vec3::ZERO, Vec3::ZERO));
        self.drifts.clear();
        self.drifts.resize(count, (Vec3::ZERO, Vec3::ZERO));
    }

    /// Ends a fluid substep of `h` seconds: each view moves on by its pushes,
    /// Δx = h J/m and Δθ = h I⁻¹L, as the velocities it now has would have moved it.
    pub fn drift(&mut self, h: R) {
        for (k, motion) in self.motions.iter().enumerate() {
            let (impulse, moment) = self.pushes[k];
            self.drifts[k] = (
                impulse * (motion.inv_mass * h),
                (motion.inv_inertia * moment) * h,
            );
        }
    }

    /// Places the samples of `views`,
    /// for fluid particles at `positions` and a fluid grid from `lower` to `upper` (m), and
    /// lists the particles' neighbours among them.
    #[allow(clippy::too_many_arguments)]
    pub fn place(
        &mut self,
        views: &[BodyView<'_, R>],
        positions: &[Vec3<R>],
        (lower, upper): (Vec3<R>, Vec3<R>),
        kernel: &Kernel<R>,
        spacing: R,
    ) {
        self.points.clear();
        self.velocities.clear();
        self.owner.clear();
        self.motions.clear();
        self.near.clear();
        let reach = Aabb {
            min: lower,
            max: upper,
        };
        for (k, view) in views.iter().enumerate() {
            let centre = view.position;
            self.motions.push(Motion {
                centre,
                velocity: view.velocity,
                angular_velocity: view.angular_velocity,
                inv_mass: view.inv_mass,
                inv_inertia: view.inv_inertia,
                touching: 0,
            });
            let placement = Transform::from_pose(centre, view.orientation);
            let Some(near) = Aabb::of_shape(view.shape, &placement)
                .map(|b| b.expanded(kernel.support))
                .filter(|b| b.overlaps(&reach))
            else {
                continue;
            };
            self.near.push(near);
            let at = match self
                .sampled
                .binary_search_by_key(&view.handle, |s| s.handle)
            {
                Ok(at) => at,
                Err(at) => {
                    let local = sample(view.shape, spacing, kernel);
                    self.sampled.insert(
                        at,
                        Sampled {
                            handle: view.handle,
                            local,
                        },
                    );
                    at
                }
            };
            let sampled = &self.sampled[at];
            for &p in &sampled.local {
                self.points.push(placement.point(p));
                self.owner.push(k as u32);
            }
        }
        self.active = !self.points.is_empty();
        if !self.active {
            return;
        }
        let grid = self
            .grid
            .get_or_insert_with(|| CellGrid::new(lower, upper, kernel.support));
        grid.fill(&self.points);
        let near = &self.near;
        self.lists
            .build_where(positions, &self.points, grid, kernel, |x| {
                near.iter().any(|b| b.contains_point(x))
            });
        for i in 0..positions.len() {
            let mut last = None;
            for e in self.lists.range(i) {
                let k = self.owner[self.lists.index[e] as usize];
                if last != Some(k) {
                    self.motions[k as usize].touching += 1;
                    last = Some(k);
                }
            }
        }
        self.update_velocities();
    }

    /// The samples' velocities v_b = v + ω × (x_b − c) with the pushes so far (m/s).
    fn update_velocities(&mut self) {
        self.velocities.clear();
        for (&x, &k) in self.points.iter().zip(&self.owner) {
            let motion = &self.motions[k as usize];
            let (v, w) = motion.pushed(self.pushes[k as usize]);
            self.velocities.push(v + w.cross(x - motion.centre));
        }
    }

    /// The bodies' share of fluid particle i's DFSPH factor (1/m², added to Dᵢ), at `x`
    /// (m), of mass `mass` (kg): the body moves too when i pushes it, by a share of its
    /// mass split over the n particles touching it (Tonge et al. 2012), so per body
    /// n m w |Bᵢ|² with Bᵢ = Σ_b V₀∇W_ib over its samples and w = 1/M + (r × B̂)·I⁻¹(r × B̂)
    /// its inverse mass along B̂ at r = x − c (1/kg). n m w is capped at 64: a body 64 times
    /// lighter than the fluid touching it is pushed as if it were that heavy.
    pub fn mobility(&self, i: usize, x: Vec3<R>, mass: R) -> R {
        let cap = R::from_int(64);
        let mut total = R::ZERO;
        let mut range = self.lists.range(i).peekable();
        while let Some(e) = range.next() {
            let k = self.owner[self.lists.index[e] as usize] as usize;
            let mut b = self.lists.gradient(e);
            while let Some(&next) = range.peek() {
                if self.owner[self.lists.index[next] as usize] as usize != k {
                    break;
                }
                b += self.lists.gradient(next);
                range.next();
            }
            let motion = &self.motions[k];
            if motion.inv_mass == R::ZERO {
                continue;
            }
            let length_squared = b.length_squared();
            let arm = (x - motion.centre).cross(b.normalize_or_zero());
            let w = motion.inv_mass + arm.dot(motion.inv_inertia * arm);
            let shared = mass * R::from_int(motion.touching as i32);
            let ratio = if w >= cap / shared { cap } else { shared * w };
            total += ratio * length_squared;
        }
        total
    }

    /// One iteration's pushes: particle i's correction −Δt kᵢ Σ_b V₀∇W_ib gives each
    /// body the impulse m Δt kᵢ V₀∇W_ib at each sample b (`scale` = m Δt, kg·s); then the
    /// samples' velocities and the compression rates follow.
    pub fn push_iteration(&mut self, stiffness: &[R], scale: R) {
        for (i, &k) in stiffness.iter().enumerate() {
            if k == R::ZERO {
                continue;
            }
            for e in self.lists.range(i) {
                let impulse = self.lists.gradient(e) * (k * scale);
                self.push(e, impulse);
            }
        }
        self.update_velocities();
        self.compression_rates(stiffness.len());
    }

    /// The bodies' share of XSPH smoothing, the water's friction on them: adds
    /// Σ_b V₀W_ib (v_b − vᵢ) (m/s) to each fluid particle's `sums` (before they are scaled
    /// by ε), and gives each body the opposite of the change ε Σ_b V₀W_ib (v_b − vᵢ) of a
    /// particle of mass m at the sample, `scale` = m ε (kg); then the samples' velocities
    /// and the compression rates follow.
    pub fn drag(&mut self, velocities: &[Vec3<R>], sums: &mut [Vec3<R>], scale: R) {
        for (i, (&vi, sum)) in velocities.iter().zip(sums.iter_mut()).enumerate() {
            for e in self.lists.range(i) {
                let pull = (self.velocity(e) - vi) * self.lists.value[e];
                *sum += pull;
                self.push(e, pull * -scale);
            }
        }
        self.update_velocities();
        self.compression_rates(velocities.len());
    }

    /// Σ_b v_b·V₀∇W_ib of each fluid particle into `rate` (DFSPH).
    pub fn compression_rates(&mut self, particles: usize) {
        self.rate.clear();
        for i in 0..particles {
            let mut rate = R::ZERO;
            for e in self.lists.range(i) {
                let b = self.lists.index[e] as usize;
                rate += self.velocities[b].dot(self.lists.gradient(e));
            }
            self.rate.push(rate);
        }
    }

    /// Gives the body of sample entry `e` (of a fluid particle) the impulse `impulse` (N·s)
    /// at the sample.
    #[inline]
    pub fn push(&mut self, e: usize, impulse: Vec3<R>) {
        let b = self.lists.index[e] as usize;
        let k = self.owner[b] as usize;
        let (total, moment) = &mut self.pushes[k];
        *total += impulse;
        *moment += (self.points[b] - self.motions[k].centre).cross(impulse);
    }

    /// The velocity of sample entry `e`'s sample, m/s.
    #[inline]
    pub fn velocity(&self, e: usize) -> Vec3<R> {
        self.velocities[self.lists.index[e] as usize]
    }

    /// The position of sample entry `e`'s sample, m.
    #[inline]
    pub fn point(&self, e: usize) -> Vec3<R> {
        self.points[self.lists.index[e] as usize]
    }
}

/// The samples of `shape` (its own frame) at `spacing` (m) (see the [module](self)); none for a plane, a mesh, a heightfield or a body of more than
/// [`MAX_BODY_SITES`] sites.
fn sample<R: Real>(shape: &Shape<R>, spacing: R, kernel: &Kernel<R>) -> Vec<Vec3<R>> {
    let kernel_layers = super::kernel::lattice_reach(kernel.support / spacing);
    if shape.triangles().is_some() {
        return Vec::new();
    }
    let Some(bounds) = Aabb::of_shape(shape, &Transform::IDENTITY) else {
        return Vec::new();
    };
    let Some(axes) = [
        sites_around(bounds.min.x, bounds.max.x, spacing),
        sites_around(bounds.min.y, bounds.max.y, spacing),
        sites_around(bounds.min.z, bounds.max.z, spacing),
    ]
    .into_iter()
    .collect::<Option<Vec<_>>>() else {
        return Vec::new();
    };
    let sites: u64 = axes.iter().map(|&(a, b)| (b - a + 1) as u64).product();
    if sites > MAX_BODY_SITES {
        return Vec::new();
    }
    let offset = lattice_offset(shape, spacing, &axes);
    let site = |i: i32, j: i32, k: i32| {
        Vec3::new(
            spacing * R::from_int(i) + offset,
            spacing * R::from_int(j) + offset,
            spacing * R::from_int(k) + offset,
        )
    };
    let mut points = Vec::new();
    for k in axes[2].0..=axes[2].1 {
        for j in axes[1].0..=axes[1].1 {
            for i in axes[0].0..=axes[0].1 {
                if !shape_contains(shape, site(i, j, k)) {
                    continue;
                }
                // Within the kernel's reach of the surface along an axis: the layers the
                // tank's walls have.
                let near_surface = (1..=kernel_layers).any(|d| {
                    [
                        (i - d, j, k),
                        (i + d, j, k),
                        (i, j - d, k),
                        (i, j + d, k),
                        (i, j, k - d),
                        (i, j, k + d),
                    ]
                    .iter()
                    .any(|&(a, b, c)| !shape_contains(shape, site(a, b, c)))
                });
                if near_surface {
                    points.push(site(i, j, k));
                }
            }
        }
    }
    points
}

/// The lattice's offset from the body's centre along each axis (m): half a spacing, as the
/// tank's boundary lies half a spacing outside its walls (a box a whole number of spacings
/// wide then has its outermost samples half a spacing inside its faces), unless sites on
/// the centre give a count of sites inside the shape nearer its volume over V₀. A ball
/// 1.6 spacings in radius holds 8 sites of the first lattice (half its volume: it floated
/// 3.5 cm too deep) and 19 of the second (1.1 times its volume).
fn lattice_offset<R: Real>(shape: &Shape<R>, spacing: R, axes: &[(i32, i32)]) -> R {
    let sites = spacing * spacing * spacing;
    let volume = shape.mass_properties(R::ONE).mass;
    let mismatch = |offset: R| {
        let mut inside = R::ZERO;
        for k in axes[2].0..=axes[2].1 {
            for j in axes[1].0..=axes[1].1 {
                for i in axes[0].0..=axes[0].1 {
                    let site = Vec3::new(
                        spacing * R::from_int(i) + offset,
                        spacing * R::from_int(j) + offset,
                        spacing * R::from_int(k) + offset,
                    );
                    if shape_contains(shape, site) {
                        inside += sites;
                    }
                }
            }
        }
        (inside - volume).abs()
    };
    let half = spacing * R::HALF;
    if mismatch(R::ZERO) < mismatch(half) {
        R::ZERO
    } else {
        half
    }
}

/// The lattice indices i whose site i·`spacing` lies within one spacing of [`lo`, `hi`]
/// (m), as (first, last); `None` beyond 2¹² sites.
fn sites_around<R: Real>(lo: R, hi: R, spacing: R) -> Option<(i32, i32)> {
    let limit = 1 << 12;
    let (mut first, mut last) = (0i32, 0i32);
    while R::from_int(first) * spacing > lo - spacing {
        first -= 1;
        if -first > limit {
            return None;
        }
    }
    while R::from_int(first) * spacing < lo - spacing {
        first += 1;
    }
    while R::from_int(last) * spacing < hi + spacing {
        last += 1;
        if last > limit {
            return None;
        }
    }
    (first <= last).then_some((first, last))
}
