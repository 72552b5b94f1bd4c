//! Contact constraints: non-penetration with a soft bias, Coulomb friction on two tangents,
//! and restitution, solved by sequential impulses with accumulated clamping.
//!
//! For a point with anchors r_a, r_b (from each centre of mass, m) and unit normal n (from A
//! to B), the relative normal velocity is
//!
//! ```text
//! v_n = (v_b − v_a)·n + ω_b·(r_b × n) − ω_a·(r_a × n)      (m/s)
//! ```
//!
//! and the effective mass along n is 1/k with
//! k = 1/m_a + 1/m_b + (I_a⁻¹(r_a × n))·(r_a × n) + (I_b⁻¹(r_b × n))·(r_b × n). The same holds
//! along each tangent. The products r × n and I⁻¹(r × n) are computed once per step in
//! [`prepare`], so an iteration costs a few dot products per point.

use super::body::SolverBody;
use super::softness::Softness;
use crate::math::{Real, Vec3};
use crate::rigid::contact::Contact;
use crate::rigid::manifold::MAX_MANIFOLD_POINTS;

/// What the solver keeps for one contact point during a step.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct ConstraintPoint<R: Real> {
    /// r_a × n and r_b × n, m.
    rn_a: Vec3<R>,
    rn_b: Vec3<R>,
    /// I_a⁻¹(r_a × n) and I_b⁻¹(r_b × n): the angular velocity change per unit impulse.
    in_a: Vec3<R>,
    in_b: Vec3<R>,
    /// r × t and I⁻¹(r × t) for the two tangents.
    rt_a: [Vec3<R>; 2],
    rt_b: [Vec3<R>; 2],
    it_a: [Vec3<R>; 2],
    it_b: [Vec3<R>; 2],
    /// Separation at the start of the step, m.
    base_separation: R,
    /// 1/k along the normal and the tangents, kg.
    normal_mass: R,
    tangent_mass: [R; 2],
    /// Accumulated impulses, N·s.
    normal_impulse: R,
    tangent_impulse: [R; 2],
    /// The largest normal impulse of one iteration this step: zero means the point never
    /// pushed, so it does not bounce.
    max_normal_impulse: R,
    /// Normal velocity before the step, m/s (negative: approaching).
    relative_velocity: R,
}

/// One contact's constraint for a step.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ContactConstraint<R: Real> {
    /// Solver indices of the two bodies.
    pub a: u32,
    pub b: u32,
    /// Index of the contact in the world's contact list.
    pub contact: u32,
    normal: Vec3<R>,
    tangents: [Vec3<R>; 2],
    /// n/m_a, n/m_b, t/m_a and t/m_b: the velocity change per unit impulse, 1/kg.
    normal_a: Vec3<R>,
    normal_b: Vec3<R>,
    tangents_a: [Vec3<R>; 2],
    tangents_b: [Vec3<R>; 2],
    friction: R,
    restitution: R,
    /// Contacts with a static or kinematic body are twice as stiff.
    rigid_partner: bool,
    count: usize,
    points: [ConstraintPoint<R>; MAX_MANIFOLD_POINTS],
}

/// Builds the constraint of `contact` between solver bodies `a` and `b` whose centres of
/// mass are at `centre_a`, `centre_b` (m): anchors, effective masses, tangents, and the
/// approach velocity of each point for restitution.
#[allow(clippy::too_many_arguments)]
pub(crate) fn prepare<R: Real>(
    contact: &Contact<R>,
    index: u32,
    (a, centre_a): (u32, Vec3<R>),
    (b, centre_b): (u32, Vec3<R>),
    bodies: &[SolverBody<R>],
    friction: R,
    restitution: R,
) -> ContactConstraint<R> {
    let ba = &bodies[a as usize];
    let bb = &bodies[b as usize];
    let n = contact.normal;
    let t0 = n.any_orthonormal();
    let tangents = [t0, n.cross(t0)];
    let m_sum = ba.inv_mass + bb.inv_mass;
    let mut points = [ConstraintPoint::default(); MAX_MANIFOLD_POINTS];
    for (cp, p) in points.iter_mut().zip(contact.points()) {
        let r_a = p.point - centre_a;
        let r_b = p.point - centre_b;
        let rn_a = r_a.cross(n);
        let rn_b = r_b.cross(n);
        let in_a = ba.inv_inertia * rn_a;
        let in_b = bb.inv_inertia * rn_b;
        let k = m_sum + in_a.dot(rn_a) + in_b.dot(rn_b);
        let mut rt_a = [Vec3::ZERO; 2];
        let mut rt_b = [Vec3::ZERO; 2];
        let mut it_a = [Vec3::ZERO; 2];
        let mut it_b = [Vec3::ZERO; 2];
        let mut tangent_mass = [R::ZERO; 2];
        for j in 0..2 {
            rt_a[j] = r_a.cross(tangents[j]);
            rt_b[j] = r_b.cross(tangents[j]);
            it_a[j] = ba.inv_inertia * rt_a[j];
            it_b[j] = bb.inv_inertia * rt_b[j];
            let kt = m_sum + it_a[j].dot(rt_a[j]) + it_b[j].dot(rt_b[j]);
            tangent_mass[j] = inverse_or_zero(kt);
        }
        let relative_velocity = (bb.v - ba.v).dot(n) + bb.w.dot(rn_b) - ba.w.dot(rn_a);
        *cp = ConstraintPoint {
            rn_a,
            rn_b,
            in_a,
            in_b,
            rt_a,
            rt_b,
            it_a,
            it_b,
            base_separation: p.separation,
            normal_mass: inverse_or_zero(k),
            tangent_mass,
            normal_impulse: p.normal_impulse,
            tangent_impulse: p.tangent_impulse,
            max_normal_impulse: R::ZERO,
            relative_velocity,
        };
    }
    ContactConstraint {
        a,
        b,
        contact: index,
        normal: n,
        tangents,
        normal_a: n * ba.inv_mass,
        normal_b: n * bb.inv_mass,
        tangents_a: tangents.map(|t| t * ba.inv_mass),
        tangents_b: tangents.map(|t| t * bb.inv_mass),
        friction,
        restitution,
        rigid_partner: ba.inv_mass == R::ZERO || bb.inv_mass == R::ZERO,
        count: usize::from(contact.count),
        points,
    }
}

/// 1/k, or 0 when k is not positive (two bodies of infinite mass).
fn inverse_or_zero<R: Real>(k: R) -> R {
    if k > R::ZERO { R::ONE / k } else { R::ZERO }
}

/// Two distinct bodies of the solver array, mutably. Index [`STATIC_BODY`] is never written
/// (its inverse mass is zero, so the impulses applied to it are zero), which lets a
/// constraint against a static body use a scratch copy.
///
/// [`STATIC_BODY`]: super::body::STATIC_BODY
fn pair<R: Real>(
    bodies: &mut [SolverBody<R>],
    a: u32,
    b: u32,
) -> (&mut SolverBody<R>, &mut SolverBody<R>) {
    let (a, b) = (a as usize, b as usize);
    debug_assert_ne!(a, b);
    if a < b {
        let (lo, hi) = bodies.split_at_mut(b);
        (&mut lo[a], &mut hi[0])
    } else {
        let (lo, hi) = bodies.split_at_mut(a);
        (&mut hi[0], &mut lo[b])
    }
}

impl<R: Real> ContactConstraint<R> {
    /// Applies the impulses carried from the last step: v_a −= P/m_a, ω_a −= I_a⁻¹(r_a × P),
    /// and the opposite on B, with P = λ_n n + λ₁ t₁ + λ₂ t₂.
    pub fn warm_start(&self, bodies: &mut [SolverBody<R>]) {
        let (ba, bb) = pair(bodies, self.a, self.b);
        for cp in &self.points[..self.count] {
            let [t0, t1] = cp.tangent_impulse;
            if cp.normal_impulse == R::ZERO && t0 == R::ZERO && t1 == R::ZERO {
                continue;
            }
            let n = cp.normal_impulse;
            ba.v -= self.normal_a * n + self.tangents_a[0] * t0 + self.tangents_a[1] * t1;
            ba.w -= cp.in_a * n + cp.it_a[0] * t0 + cp.it_a[1] * t1;
            bb.v += self.normal_b * n + self.tangents_b[0] * t0 + self.tangents_b[1] * t1;
            bb.w += cp.in_b * n + cp.it_b[0] * t0 + cp.it_b[1] * t1;
        }
    }

    /// The relative normal velocity of point `cp`, v_n (m/s).
    #[inline(always)]
    fn normal_velocity(
        &self,
        cp: &ConstraintPoint<R>,
        ba: &SolverBody<R>,
        bb: &SolverBody<R>,
    ) -> R {
        (bb.v - ba.v).dot_fused(self.normal) + bb.w.dot_fused(cp.rn_b) - ba.w.dot_fused(cp.rn_a)
    }

    /// Applies the normal impulse `applied` (N·s) at point `cp`.
    #[inline(always)]
    fn apply_normal(
        &self,
        cp: &ConstraintPoint<R>,
        ba: &mut SolverBody<R>,
        bb: &mut SolverBody<R>,
        applied: R,
    ) {
        ba.v -= self.normal_a * applied;
        ba.w -= cp.in_a * applied;
        bb.v += self.normal_b * applied;
        bb.w += cp.in_b * applied;
    }

    /// One Gauss–Seidel pass over the points: the normal impulses, then friction.
    ///
    /// Normal: with the current separation s = s₀ + (Δp_b − Δp_a)·n + Δθ_b·(r_b × n) −
    /// Δθ_a·(r_a × n), a point still apart (s > 0) only stops the approach that would close
    /// the gap within this substep (bias s/h, speculative contact); an overlapping point
    /// gets the soft bias max(bias_rate·s, −max_push) when `use_bias`, and no bias in the
    /// relax pass. The accumulated impulse stays ≥ 0.
    ///
    /// Friction: each tangent's impulse −m_t v_t is added, then the accumulated tangent
    /// impulse is clamped to the disc |λ_t| ≤ μ λ_n (Coulomb's cone, not a box, so sliding
    /// speed does not depend on the direction). A point with no normal and no tangent
    /// impulse is skipped: its cone has radius 0, so nothing would change.
    pub fn solve(
        &mut self,
        bodies: &mut [SolverBody<R>],
        softness: &Softness<R>,
        inv_h: R,
        max_push: R,
        use_bias: bool,
    ) {
        let (ba, bb) = pair(bodies, self.a, self.b);
        let moved_apart = (bb.dp - ba.dp).dot_fused(self.normal);
        for k in 0..self.count {
            let cp = &self.points[k];
            let s = cp.base_separation + moved_apart + bb.dtheta.dot_fused(cp.rn_b)
                - ba.dtheta.dot_fused(cp.rn_a);
            let (bias, mass_scale, impulse_scale) = if s > R::ZERO {
                (s * inv_h, R::ONE, R::ZERO)
            } else if use_bias {
                (
                    (softness.bias_rate * s).max(-max_push),
                    softness.mass_scale,
                    softness.impulse_scale,
                )
            } else {
                (R::ZERO, R::ONE, R::ZERO)
            };
            let vn = self.normal_velocity(cp, ba, bb);
            let impulse =
                -(cp.normal_mass * mass_scale * (vn + bias)) - impulse_scale * cp.normal_impulse;
            let new_impulse = (cp.normal_impulse + impulse).max(R::ZERO);
            let applied = new_impulse - cp.normal_impulse;
            self.apply_normal(&self.points[k], ba, bb, applied);
            let cp = &mut self.points[k];
            cp.normal_impulse = new_impulse;
            cp.max_normal_impulse = cp.max_normal_impulse.max(applied);
        }
        let friction = self.friction;
        for cp in &mut self.points[..self.count] {
            if cp.normal_impulse == R::ZERO && cp.tangent_impulse == [R::ZERO; 2] {
                continue;
            }
            let dv = bb.v - ba.v;
            let mut new_impulse = cp.tangent_impulse;
            for (j, impulse) in new_impulse.iter_mut().enumerate() {
                let vt = dv.dot_fused(self.tangents[j]) + bb.w.dot_fused(cp.rt_b[j])
                    - ba.w.dot_fused(cp.rt_a[j]);
                *impulse -= cp.tangent_mass[j] * vt;
            }
            let limit = friction * cp.normal_impulse;
            let length_squared = new_impulse[0] * new_impulse[0] + new_impulse[1] * new_impulse[1];
            if length_squared > limit * limit {
                let scale = limit * length_squared.rsqrt();
                new_impulse = [new_impulse[0] * scale, new_impulse[1] * scale];
            }
            let [a0, a1] = [
                new_impulse[0] - cp.tangent_impulse[0],
                new_impulse[1] - cp.tangent_impulse[1],
            ];
            cp.tangent_impulse = new_impulse;
            ba.v -= self.tangents_a[0] * a0 + self.tangents_a[1] * a1;
            ba.w -= cp.it_a[0] * a0 + cp.it_a[1] * a1;
            bb.v += self.tangents_b[0] * a0 + self.tangents_b[1] * a1;
            bb.w += cp.it_b[0] * a0 + cp.it_b[1] * a1;
        }
    }

    /// Restitution, after the substeps: a point that approached faster than `threshold`
    /// (m/s) and pushed during the step gets the normal impulse that makes it separate at
    /// e times its approach speed, λ = −m_n (v_n + e v_n,before), accumulated and kept ≥ 0.
    pub fn apply_restitution(&mut self, bodies: &mut [SolverBody<R>], threshold: R) {
        if self.restitution == R::ZERO {
            return;
        }
        let (ba, bb) = pair(bodies, self.a, self.b);
        for k in 0..self.count {
            let cp = &self.points[k];
            if cp.relative_velocity > -threshold || cp.max_normal_impulse == R::ZERO {
                continue;
            }
            let vn = self.normal_velocity(cp, ba, bb);
            let impulse = -(cp.normal_mass * (vn + self.restitution * cp.relative_velocity));
            let new_impulse = (cp.normal_impulse + impulse).max(R::ZERO);
            let applied = new_impulse - cp.normal_impulse;
            self.apply_normal(cp, ba, bb, applied);
            self.points[k].normal_impulse = new_impulse;
        }
    }

    /// Whether the pair's partner is static or kinematic (it gets the stiffer softness).
    pub fn has_rigid_partner(&self) -> bool {
        self.rigid_partner
    }

    /// Copies the accumulated impulses back into the persistent contact, for warm starting
    /// the next step.
    pub fn store_impulses(&self, contact: &mut Contact<R>) {
        for (p, cp) in contact
            .points_mut()
            .iter_mut()
            .zip(&self.points[..self.count])
        {
            p.normal_impulse = cp.normal_impulse;
            p.tangent_impulse = cp.tangent_impulse;
        }
    }
}
