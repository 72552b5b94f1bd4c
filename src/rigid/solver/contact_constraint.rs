//! Contact constraints: non-penetration with a soft bias at each point, Coulomb friction
//! per contact (two tangent rows at the centre of the points and a twist row about the
//! normal, the model Rapier and PhysX use by default), and restitution, solved by
//! sequential impulses with accumulated clamping.
//!
//! For a point with anchors r_a, r_b (from each centre of mass, m) and unit normal n (from A
//! to B), the relative normal velocity is
//!
//! ```text
//! v_n = (v_b − v_a)·n + ω_b·(r_b × n) − ω_a·(r_a × n)      (m/s)
//! ```
//!
//! and the effective mass along n is 1/k with
//! k = 1/m_a + 1/m_b + (I_a⁻¹(r_a × n))·(r_a × n) + (I_b⁻¹(r_b × n))·(r_b × n) (1/kg).
//!
//! Friction acts once per contact, at the centre c of its points (the mean, m), with the
//! anchors c − x_a and c − x_b: the same velocity and effective mass along each tangent t₁,
//! t₂, and a twist row about n with relative angular velocity ω_n = (ω_b − ω_a)·n (rad/s)
//! and effective mass 1/k_twist, k_twist = n·I_a⁻¹n + n·I_b⁻¹n (1/(kg·m²)). With Λ = Σ λ_n,k
//! the contact's total normal impulse (N·s) and d_k = |p_k − c| (m) each point's distance
//! from the centre, the limits are
//!
//! ```text
//! |λ_t| ≤ μ Λ            (N·s, a disc on the 2D tangent impulse)
//! |λ_twist| ≤ μ Σ λ_n,k d_k   (N·m·s)
//! ```
//!
//! the twist limit being Rapier's: the torque the points' own friction discs could resist
//! about the centre if they all slid around it. Five rows per contact instead of two
//! per point.
//!
//! The products r × n, I⁻¹(r × n), r × t, I⁻¹(r × t) and I⁻¹n are computed once per step
//! in [`ContactBlock::prepare_products`], so an iteration costs a few dot products per row.
//!
//! Constraints are stored [`LANES`] to a [`ContactBlock`], field by field (structure of
//! arrays); a lane is one contact. The solver visits the lanes of a block in order and the
//! blocks in order, so the block layout is storage only: it changes no result.

use super::body::{SolverBody, pair};
use super::bounce::BouncePass;
use super::lanes::{LANES, Lanes, Lanes3};
use super::softness::Softness;
use crate::math::Real;
#[cfg(vector_kernels)]
use crate::math::over_real::OverReal;
use crate::rigid::contact::Contact;
use crate::rigid::manifold::MAX_MANIFOLD_POINTS;

/// What the solver keeps for one contact point of each lane during a step.
#[derive(Clone, Copy, Debug)]
#[cfg_attr(test, derive(PartialEq))]
struct PointLanes<R: Real> {
    /// r_a × n and r_b × n, m.
    rn_a: Lanes3<R>,
    rn_b: Lanes3<R>,
    /// I_a⁻¹(r_a × n) and I_b⁻¹(r_b × n): the angular velocity change per unit impulse.
    in_a: Lanes3<R>,
    in_b: Lanes3<R>,
    /// Separation at the start of the step, m.
    base_separation: Lanes<R>,
    /// Separation at the bodies' current positions, m: `base_separation` at the start of
    /// the step, then refreshed by each relax pass, which follows a position update, for
    /// the next solve pass (the positions do not move in between).
    separation: Lanes<R>,
    /// Distance from the lane's friction centre, m: the point's lever arm in the twist
    /// limit.
    twist_arm: Lanes<R>,
    /// 1/k along the normal, kg.
    normal_mass: Lanes<R>,
    /// `normal_mass` times the lane's soft mass scale (kg): the effective mass of an
    /// overlapping point in a biased pass, set once per step by
    /// [`ContactBlock::soften`].
    soft_normal_mass: Lanes<R>,
    /// Accumulated impulse, N·s.
    normal_impulse: Lanes<R>,
    /// The largest normal impulse of one iteration this step: zero means the point never
    /// pushed, so it does not bounce.
    max_normal_impulse: Lanes<R>,
    /// Normal velocity before the step, m/s (negative: approaching).
    relative_velocity: Lanes<R>,
    /// The normal impulse the point applied over the whole step, N·s: the sum of the
    /// accumulated impulse after each substep (each substep re-applies it by its warm
    /// start, then changes it by its passes). Kept only in steps that may bounce
    /// ([`ContactBlock::add_substep_impulses`]), for the chains' restitution pass.
    step_impulse: Lanes<R>,
}

impl<R: Real> PointLanes<R> {
    const ZERO: Self = Self {
        rn_a: Lanes3::ZERO,
        rn_b: Lanes3::ZERO,
        in_a: Lanes3::ZERO,
        in_b: Lanes3::ZERO,
        base_separation: [R::ZERO; LANES],
        separation: [R::ZERO; LANES],
        twist_arm: [R::ZERO; LANES],
        normal_mass: [R::ZERO; LANES],
        soft_normal_mass: [R::ZERO; LANES],
        normal_impulse: [R::ZERO; LANES],
        max_normal_impulse: [R::ZERO; LANES],
        relative_velocity: [R::ZERO; LANES],
        step_impulse: [R::ZERO; LANES],
    };
}

/// What the solver keeps for the friction of each lane during a step: the two tangent rows
/// at the friction centre and the twist row about the normal.
#[derive(Clone, Copy, Debug)]
#[cfg_attr(test, derive(PartialEq))]
struct FrictionLanes<R: Real> {
    /// r_a × t and r_b × t for the two tangents, with the anchors of the centre, m.
    rt_a: [Lanes3<R>; 2],
    rt_b: [Lanes3<R>; 2],
    /// I_a⁻¹(r_a × t) and I_b⁻¹(r_b × t).
    it_a: [Lanes3<R>; 2],
    it_b: [Lanes3<R>; 2],
    /// I_a⁻¹n and I_b⁻¹n: the angular velocity change per unit twist impulse, 1/(kg·m²).
    twist_a: Lanes3<R>,
    twist_b: Lanes3<R>,
    /// 1/k along the tangents (kg) and about the normal (kg·m²).
    tangent_mass: [Lanes<R>; 2],
    twist_mass: Lanes<R>,
    /// Accumulated impulses: along the tangents (N·s) and about the normal (N·m·s).
    tangent_impulse: [Lanes<R>; 2],
    twist_impulse: Lanes<R>,
}

impl<R: Real> FrictionLanes<R> {
    const ZERO: Self = Self {
        rt_a: [Lanes3::ZERO; 2],
        rt_b: [Lanes3::ZERO; 2],
        it_a: [Lanes3::ZERO; 2],
        it_b: [Lanes3::ZERO; 2],
        twist_a: Lanes3::ZERO,
        twist_b: Lanes3::ZERO,
        tangent_mass: [[R::ZERO; LANES]; 2],
        twist_mass: [R::ZERO; LANES],
        tangent_impulse: [[R::ZERO; LANES]; 2],
        twist_impulse: [R::ZERO; LANES],
    };
}

mod chains;
#[cfg(vector_kernels)]
mod kernel;
mod prepare;
#[cfg(vector_kernels)]
mod prepare_kernel;
#[cfg(vector_kernels)]
mod roots_kernel;
#[cfg(test)]
mod tests;

pub(crate) use chains::BounceChains;
pub(crate) use prepare::ContactArms;
#[cfg(vector_kernels)]
use prepare::ContactArmsOf;

/// The family of [`ContactBlock`]s, for [`Real::as_fixed`].
#[cfg(vector_kernels)]
struct ContactBlockOf;

#[cfg(vector_kernels)]
impl OverReal for ContactBlockOf {
    type Of<R: Real> = ContactBlock<R>;
}

/// The family of [`SolvePass`]es, for [`Real::as_fixed`].
#[cfg(vector_kernels)]
struct SolvePassOf;

#[cfg(vector_kernels)]
impl OverReal for SolvePassOf {
    type Of<R: Real> = SolvePass<R>;
}

/// The constraints of up to [`LANES`] contacts for a step, one per lane.
#[derive(Clone, Debug)]
#[cfg_attr(test, derive(PartialEq))]
pub(crate) struct ContactBlock<R: Real> {
    /// Lanes in use, from lane 0.
    len: usize,
    /// Whether the lanes share no moving body, so that they may be solved side by side.
    independent: bool,
    /// What the solve and warm-start kernels need to know of the block's coefficients,
    /// found once per step by [`soften`](Self::soften).
    #[cfg(vector_kernels)]
    kernel: kernel::KernelFacts,
    /// Solver indices of the two bodies.
    a: [u32; LANES],
    b: [u32; LANES],
    /// Index of the contact in the world's contact list.
    contact: [u32; LANES],
    normal: Lanes3<R>,
    tangents: [Lanes3<R>; 2],
    /// n/m_a, n/m_b, t/m_a and t/m_b: the velocity change per unit impulse, 1/kg.
    normal_a: Lanes3<R>,
    normal_b: Lanes3<R>,
    tangents_a: [Lanes3<R>; 2],
    tangents_b: [Lanes3<R>; 2],
    friction: Lanes<R>,
    restitution: Lanes<R>,
    /// Contacts with a static or kinematic body are twice as stiff.
    rigid_partner: [bool; LANES],
    /// Lanes whose restitution this step's chain pass ([`BounceChains`]) resolved, which
    /// [`apply_restitution`](Self::apply_restitution) then leaves alone.
    chained: [bool; LANES],
    /// Points in use per lane.
    count: [u8; LANES],
    points: [PointLanes<R>; MAX_MANIFOLD_POINTS],
    friction_rows: FrictionLanes<R>,
}

/// The coefficients a lane's solve uses: the step's softness for contacts between two
/// moving bodies and for contacts with a static or kinematic body, the inverse substep
/// (1/s), the largest push-out speed (m/s), and whether the soft bias applies (false in
/// the relax pass).
#[derive(Clone, Copy, Debug)]
pub(crate) struct SolvePass<R: Real> {
    pub soft: Softness<R>,
    pub soft_static: Softness<R>,
    pub inv_h: R,
    pub max_push: R,
    pub use_bias: bool,
}

impl<R: Real> ContactBlock<R> {
    /// A block with no lane in use.
    pub fn empty() -> Self {
        Self {
            len: 0,
            independent: false,
            #[cfg(vector_kernels)]
            kernel: kernel::KernelFacts::NONE,
            a: [0; LANES],
            b: [0; LANES],
            contact: [0; LANES],
            normal: Lanes3::ZERO,
            tangents: [Lanes3::ZERO; 2],
            normal_a: Lanes3::ZERO,
            normal_b: Lanes3::ZERO,
            tangents_a: [Lanes3::ZERO; 2],
            tangents_b: [Lanes3::ZERO; 2],
            friction: [R::ZERO; LANES],
            restitution: [R::ZERO; LANES],
            rigid_partner: [false; LANES],
            chained: [false; LANES],
            count: [0; LANES],
            points: [PointLanes::ZERO; MAX_MANIFOLD_POINTS],
            friction_rows: FrictionLanes::ZERO,
        }
    }

    /// Frees every lane (their old contents stay, unread); the lanes to come share no
    /// moving body when `independent`.
    pub fn clear(&mut self, independent: bool) {
        self.len = 0;
        self.independent = independent;
        self.chained = [false; LANES];
        #[cfg(vector_kernels)]
        {
            self.kernel = kernel::KernelFacts::NONE;
        }
    }

    /// Applies the impulses carried from the last step, lane by lane: per point
    /// v_a −= λ_n n/m_a, ω_a −= λ_n I_a⁻¹(r_a × n), then the friction at the centre
    /// v_a −= λ₁ t₁/m_a + λ₂ t₂/m_a, ω_a −= λ₁ I_a⁻¹(r_a × t₁) + λ₂ I_a⁻¹(r_a × t₂) +
    /// λ_twist I_a⁻¹n, and the opposite on B.
    ///
    /// An independent block of I32F32 constraints goes to a kernel ([`kernel`]) when the
    /// processor has AVX-512 or AVX2, which gives the same bits.
    pub fn warm_start(&mut self, bodies: &mut [SolverBody<R>]) {
        #[cfg(vector_kernels)]
        if self.independent && kernel::warm_start(self, bodies).is_some() {
            return;
        }
        self.warm_start_lanes(bodies);
    }

    /// [`warm_start`](Self::warm_start), one lane after another.
    pub fn warm_start_lanes(&self, bodies: &mut [SolverBody<R>]) {
        let f = &self.friction_rows;
        for l in 0..self.len {
            let (ba, bb) = pair(bodies, self.a[l], self.b[l]);
            let (normal_a, normal_b) = (self.normal_a.get(l), self.normal_b.get(l));
            for cp in &self.points[..usize::from(self.count[l])] {
                let n = cp.normal_impulse[l];
                if n == R::ZERO {
                    continue;
                }
                ba.v -= normal_a * n;
                ba.w -= cp.in_a.get(l) * n;
                bb.v += normal_b * n;
                bb.w += cp.in_b.get(l) * n;
            }
            let [t0, t1] = [f.tangent_impulse[0][l], f.tangent_impulse[1][l]];
            let twist = f.twist_impulse[l];
            if t0 == R::ZERO && t1 == R::ZERO && twist == R::ZERO {
                continue;
            }
            ba.v -= self.tangents_a[0].get(l) * t0 + self.tangents_a[1].get(l) * t1;
            ba.w -= f.it_a[0].get(l) * t0 + f.it_a[1].get(l) * t1 + f.twist_a.get(l) * twist;
            bb.v += self.tangents_b[0].get(l) * t0 + self.tangents_b[1].get(l) * t1;
            bb.w += f.it_b[0].get(l) * t0 + f.it_b[1].get(l) * t1 + f.twist_b.get(l) * twist;
        }
    }

    /// One Gauss–Seidel pass over the block, lane by lane: for each lane the normal
    /// impulses of its points, then its friction rows.
    ///
    /// Normal: with the current separation s = s₀ + (Δp_b − Δp_a)·n + Δθ_b·(r_b × n) −
    /// Δθ_a·(r_a × n), a point still apart (s > 0) only stops the approach that would close
    /// the gap within this substep (bias s/h, speculative contact); an overlapping point
    /// gets the soft bias max(bias_rate·s, −max_push) and the soft effective mass when
    /// `use_bias`, and no bias in the relax pass. The accumulated impulse stays ≥ 0.
    ///
    /// The biased pass comes before the substep's position update and the relax pass after
    /// it (Box2D v3's order), so s changes only between a biased pass and the relax pass
    /// that follows: the relax pass computes it and keeps it for the next biased pass,
    /// which reads it (the first one reads s₀).
    ///
    /// Friction, at the lane's centre: each tangent's impulse −m_t v_t is added, then the
    /// accumulated tangent impulse is clamped to the disc |λ_t| ≤ μ Λ, Λ = Σ λ_n,k (Coulomb's
    /// cone, not a box, so sliding speed does not depend on the direction); then the twist
    /// impulse −m_twist ω_n is added and the accumulated twist impulse clamped to
    /// |λ_twist| ≤ μ Σ λ_n,k d_k; a lane of one point has no twist row (its limit is 0). A
    /// lane with no normal and no friction impulse is skipped: both limits are 0, so
    /// nothing would change.
    ///
    /// An independent block of I32F32 constraints goes to a kernel ([`kernel`]) when the
    /// processor has AVX-512 or AVX2, which gives the same bits.
    pub fn solve(&mut self, bodies: &mut [SolverBody<R>], pass: &SolvePass<R>) {
        #[cfg(vector_kernels)]
        if self.independent && kernel::solve(self, bodies, pass).is_some() {
            return;
        }
        self.solve_lanes(bodies, pass);
    }

    /// [`solve`](Self::solve), one lane after another.
    pub fn solve_lanes(&mut self, bodies: &mut [SolverBody<R>], pass: &SolvePass<R>) {
        for l in 0..self.len {
            self.solve_lane(l, bodies, pass);
        }
    }

    /// [`solve`](Self::solve) for lane `l`.
    fn solve_lane(&mut self, l: usize, bodies: &mut [SolverBody<R>], pass: &SolvePass<R>) {
        let (ba, bb) = pair(bodies, self.a[l], self.b[l]);
        let count = usize::from(self.count[l]);
        let normal = self.normal.get(l);
        let (normal_a, normal_b) = (self.normal_a.get(l), self.normal_b.get(l));
        let impulse_scale = if self.rigid_partner[l] {
            pass.soft_static.impulse_scale
        } else {
            pass.soft.impulse_scale
        };
        let bias_rate = if self.rigid_partner[l] {
            pass.soft_static.bias_rate
        } else {
            pass.soft.bias_rate
        };
        let moved_apart = if pass.use_bias {
            R::ZERO
        } else {
            (bb.dp - ba.dp).dot_fused(normal)
        };
        for cp in &mut self.points[..count] {
            let s = if pass.use_bias {
                cp.separation[l]
            } else {
                let (rn_a, rn_b) = (cp.rn_a.get(l), cp.rn_b.get(l));
                let s = cp.base_separation[l] + moved_apart + bb.dtheta.dot_fused(rn_b)
                    - ba.dtheta.dot_fused(rn_a);
                cp.separation[l] = s;
                s
            };
            let (bias, mass, impulse_scale) = if s > R::ZERO {
                (s * pass.inv_h, cp.normal_mass[l], R::ZERO)
            } else if pass.use_bias {
                (
                    (bias_rate * s).max(-pass.max_push),
                    cp.soft_normal_mass[l],
                    impulse_scale,
                )
            } else {
                (R::ZERO, cp.normal_mass[l], R::ZERO)
            };
            let (rn_a, rn_b) = (cp.rn_a.get(l), cp.rn_b.get(l));
            let vn = (bb.v - ba.v).dot_fused(normal) + bb.w.dot_fused(rn_b) - ba.w.dot_fused(rn_a);
            let old_impulse = cp.normal_impulse[l];
            let impulse = -(mass * (vn + bias)) - impulse_scale * old_impulse;
            let new_impulse = (old_impulse + impulse).max(R::ZERO);
            let applied = new_impulse - old_impulse;
            ba.v -= normal_a * applied;
            ba.w -= cp.in_a.get(l) * applied;
            bb.v += normal_b * applied;
            bb.w += cp.in_b.get(l) * applied;
            cp.normal_impulse[l] = new_impulse;
            cp.max_normal_impulse[l] = cp.max_normal_impulse[l].max(applied);
        }
        self.solve_friction(l, ba, bb);
    }

    /// The friction rows of lane `l` between its bodies `ba` and `bb`
    /// ([`solve`](Self::solve)).
    fn solve_friction(&mut self, l: usize, ba: &mut SolverBody<R>, bb: &mut SolverBody<R>) {
        let count = usize::from(self.count[l]);
        let mut normal_sum = R::ZERO;
        let mut twist_sum = R::ZERO;
        for cp in &self.points[..count] {
            normal_sum += cp.normal_impulse[l];
            twist_sum += cp.normal_impulse[l] * cp.twist_arm[l];
        }
        let f = &mut self.friction_rows;
        let old_impulse = [f.tangent_impulse[0][l], f.tangent_impulse[1][l]];
        let old_twist = f.twist_impulse[l];
        if normal_sum == R::ZERO && old_impulse == [R::ZERO; 2] && old_twist == R::ZERO {
            return;
        }
        let friction = self.friction[l];
        let tangents = [self.tangents[0].get(l), self.tangents[1].get(l)];
        let dv = bb.v - ba.v;
        let mut new_impulse = old_impulse;
        for (j, impulse) in new_impulse.iter_mut().enumerate() {
            let vt = dv.dot_fused(tangents[j]) + bb.w.dot_fused(f.rt_b[j].get(l))
                - ba.w.dot_fused(f.rt_a[j].get(l));
            *impulse -= f.tangent_mass[j][l] * vt;
        }
        let limit = friction * normal_sum;
        let length_squared = new_impulse[0] * new_impulse[0] + new_impulse[1] * new_impulse[1];
        if length_squared > limit * limit {
            let scale = limit * length_squared.rsqrt();
            new_impulse = [new_impulse[0] * scale, new_impulse[1] * scale];
        }
        let [a0, a1] = [
            new_impulse[0] - old_impulse[0],
            new_impulse[1] - old_impulse[1],
        ];
        f.tangent_impulse[0][l] = new_impulse[0];
        f.tangent_impulse[1][l] = new_impulse[1];
        ba.v -= self.tangents_a[0].get(l) * a0 + self.tangents_a[1].get(l) * a1;
        ba.w -= f.it_a[0].get(l) * a0 + f.it_a[1].get(l) * a1;
        bb.v += self.tangents_b[0].get(l) * a0 + self.tangents_b[1].get(l) * a1;
        bb.w += f.it_b[0].get(l) * a0 + f.it_b[1].get(l) * a1;

        if count < 2 {
            // One point has no lever arm: no twist friction (its impulse stays zero).
            return;
        }
        let twist_limit = friction * twist_sum;
        let spin = (bb.w - ba.w).dot_fused(self.normal.get(l));
        let new_twist = (old_twist - f.twist_mass[l] * spin).clamp(-twist_limit, twist_limit);
        let applied = new_twist - old_twist;
        f.twist_impulse[l] = new_twist;
        ba.w -= f.twist_a.get(l) * applied;
        bb.w += f.twist_b.get(l) * applied;
    }

    /// Restitution, after the substeps, lane by lane: a point that approached faster than
    /// the pass's threshold (m/s) and pushed during the step gets the normal impulse that
    /// makes it separate at the speed [`BouncePass::leaving_speed`] gives (e times the
    /// impact speed, gravity's share of the step included), λ = m_n (u − v_n), accumulated
    /// and kept ≥ 0.
    /// Lanes the chain pass resolved ([`BounceChains`]) are skipped.
    pub fn apply_restitution(&mut self, bodies: &mut [SolverBody<R>], pass: &BouncePass<R>) {
        for l in 0..self.len {
            let restitution = self.restitution[l];
            if restitution == R::ZERO || self.chained[l] {
                continue;
            }
            let (ba, bb) = pair(bodies, self.a[l], self.b[l]);
            let normal = self.normal.get(l);
            let (normal_a, normal_b) = (self.normal_a.get(l), self.normal_b.get(l));
            let falls = |body: &SolverBody<R>| body.inv_mass > R::ZERO;
            let separating = match (falls(ba), falls(bb)) {
                (true, false) => -pass.gravity.dot(normal),
                (false, true) => pass.gravity.dot(normal),
                _ => R::ZERO,
            };
            for cp in &mut self.points[..usize::from(self.count[l])] {
                let v0 = cp.relative_velocity[l];
                if v0 > -pass.threshold || cp.max_normal_impulse[l] == R::ZERO {
                    continue;
                }
                let separations = (cp.base_separation[l], cp.separation[l]);
                let u = pass.leaving_speed(restitution, v0, separations, separating);
                let (rn_a, rn_b) = (cp.rn_a.get(l), cp.rn_b.get(l));
                let vn =
                    (bb.v - ba.v).dot_fused(normal) + bb.w.dot_fused(rn_b) - ba.w.dot_fused(rn_a);
                let impulse = cp.normal_mass[l] * (u - vn);
                let old_impulse = cp.normal_impulse[l];
                let new_impulse = (old_impulse + impulse).max(R::ZERO);
                let applied = new_impulse - old_impulse;
                ba.v -= normal_a * applied;
                ba.w -= cp.in_a.get(l) * applied;
                bb.v += normal_b * applied;
                bb.w += cp.in_b.get(l) * applied;
                cp.normal_impulse[l] = new_impulse;
            }
        }
    }

    /// Whether a point of the block may bounce this step: a lane with restitution whose
    /// point approached faster than `threshold` (m/s) when the step began.
    pub fn may_bounce(&self, threshold: R) -> bool {
        (0..self.len).any(|l| {
            self.restitution[l] > R::ZERO
                && self.points[..usize::from(self.count[l])]
                    .iter()
                    .any(|cp| cp.relative_velocity[l] < -threshold)
        })
    }

    /// Adds each point's accumulated normal impulse, as it stands after a substep's relax
    /// pass, to the impulse it applied over the step (N·s), starting the sum at the
    /// `first` substep.
    pub fn add_substep_impulses(&mut self, first: bool) {
        for cp in &mut self.points {
            for l in 0..self.len {
                cp.step_impulse[l] = if first {
                    cp.normal_impulse[l]
                } else {
                    cp.step_impulse[l] + cp.normal_impulse[l]
                };
            }
        }
    }

    /// Copies the accumulated impulses back into the persistent contacts, for warm
    /// starting the next step.
    pub fn store_impulses(&self, contacts: &mut [Contact<R>]) {
        for l in 0..self.len {
            let contact = &mut contacts[self.contact[l] as usize];
            for (p, cp) in contact.points_mut().iter_mut().zip(&self.points) {
                p.normal_impulse = cp.normal_impulse[l];
            }
            let f = &self.friction_rows;
            contact.friction_impulse = [f.tangent_impulse[0][l], f.tangent_impulse[1][l]];
            contact.twist_impulse = f.twist_impulse[l];
        }
    }
}
