//! Stage 1 of the solver for one block: each lane's contact data
//! ([`ContactBlock::prepare_lane`]), then the products every iteration reuses
//! ([`ContactBlock::prepare_products`]): r × n, I⁻¹(r × n), r × t, I⁻¹(r × t), the effective
//! masses and the approach velocities.
//!
//! The products are the costly part (about a hundred multiplies per point); on I32F32 they
//! go to the AVX-512 kernel when the processor has it, which gives the same bits.

use super::ContactBlock;
use crate::math::{Real, Vec3};
use crate::rigid::contact::Contact;
use crate::rigid::manifold::MAX_MANIFOLD_POINTS;
use crate::rigid::solver::body::SolverBody;
use crate::rigid::solver::lanes::Lanes3;

/// The anchors of each point of each lane from the bodies' centres of mass,
/// r_a = p − c_a and r_b = p − c_b (m): what [`ContactBlock::prepare_lane`] leaves for
/// [`ContactBlock::prepare_products`]. Points a lane does not use hold stale values, unread.
#[derive(Clone, Debug)]
pub(crate) struct ContactArms<R: Real> {
    pub r_a: [Lanes3<R>; MAX_MANIFOLD_POINTS],
    pub r_b: [Lanes3<R>; MAX_MANIFOLD_POINTS],
}

impl<R: Real> ContactArms<R> {
    /// Every anchor zero.
    pub const ZERO: Self = Self {
        r_a: [Lanes3::ZERO; MAX_MANIFOLD_POINTS],
        r_b: [Lanes3::ZERO; MAX_MANIFOLD_POINTS],
    };
}

/// 1/k, or 0 when k is not positive (two bodies of infinite mass).
fn inverse_or_zero<R: Real>(k: R) -> R {
    if k > R::ZERO { R::ONE / k } else { R::ZERO }
}

impl<R: Real> ContactBlock<R> {
    /// Takes the next free lane for the constraint of `contact` between solver bodies `a`
    /// and `b` whose centres of mass are at `centre_a`, `centre_b` (m): the bodies, the
    /// normal and its two tangents (t₁ = any unit vector ⟂ n, t₂ = n × t₁), the mixed
    /// friction and restitution, the separations and carried impulses of the points, and
    /// the points' anchors into `arms`. [`prepare_products`](Self::prepare_products)
    /// completes the block. The block must not be full.
    #[allow(clippy::too_many_arguments)]
    pub fn prepare_lane(
        &mut self,
        contact: &Contact<R>,
        index: u32,
        (a, centre_a): (u32, Vec3<R>),
        (b, centre_b): (u32, Vec3<R>),
        bodies: &[SolverBody<R>],
        friction: R,
        restitution: R,
        arms: &mut ContactArms<R>,
    ) {
        let l = self.len;
        self.len += 1;
        let n = contact.normal;
        let t0 = n.any_orthonormal();
        for (p, (cp, point)) in self.points.iter_mut().zip(contact.points()).enumerate() {
            arms.r_a[p].set(l, point.point - centre_a);
            arms.r_b[p].set(l, point.point - centre_b);
            cp.base_separation[l] = point.separation;
            cp.normal_impulse[l] = point.normal_impulse;
            cp.tangent_impulse[0][l] = point.tangent_impulse[0];
            cp.tangent_impulse[1][l] = point.tangent_impulse[1];
            cp.max_normal_impulse[l] = R::ZERO;
        }
        self.a[l] = a;
        self.b[l] = b;
        self.contact[l] = index;
        self.normal.set(l, n);
        self.tangents[0].set(l, t0);
        self.tangents[1].set(l, n.cross(t0));
        self.friction[l] = friction;
        self.restitution[l] = restitution;
        self.rigid_partner[l] =
            bodies[a as usize].inv_mass == R::ZERO || bodies[b as usize].inv_mass == R::ZERO;
        self.count[l] = contact.count;
    }

    /// Completes every lane set up by [`prepare_lane`](Self::prepare_lane), from the
    /// anchors in `arms` and the solver bodies:
    ///
    /// * n/m_a, n/m_b, t/m_a, t/m_b (1/kg), the velocity change per unit impulse;
    /// * per point, r × n and I⁻¹(r × n) on each side, and the same for both tangents;
    /// * the effective masses 1/k (kg), k = 1/m_a + 1/m_b + (I_a⁻¹(r_a × n))·(r_a × n)
    ///   + (I_b⁻¹(r_b × n))·(r_b × n), and likewise along each tangent;
    /// * the approach velocity v_n = (v_b − v_a)·n + ω_b·(r_b × n) − ω_a·(r_a × n) (m/s),
    ///   for restitution.
    ///
    /// On I32F32 the AVX-512 kernel computes the products when the processor has it and
    /// every value lies within its bound; otherwise, and on other formats, lane by lane.
    /// Both give the same bits.
    pub fn prepare_products(&mut self, arms: &ContactArms<R>, bodies: &[SolverBody<R>]) {
        #[cfg(target_arch = "x86_64")]
        let done = super::avx512::prepare(self, arms, bodies);
        #[cfg(not(target_arch = "x86_64"))]
        let done = false;
        if !done {
            self.prepare_products_lanes(arms, bodies);
        }
        self.invert_effective_masses();
    }

    /// The products of [`prepare_products`](Self::prepare_products), one lane after
    /// another, leaving k (not yet 1/k) in the mass fields.
    pub fn prepare_products_lanes(&mut self, arms: &ContactArms<R>, bodies: &[SolverBody<R>]) {
        for l in 0..self.len {
            let ba = &bodies[self.a[l] as usize];
            let bb = &bodies[self.b[l] as usize];
            let n = self.normal.get(l);
            let tangents = [self.tangents[0].get(l), self.tangents[1].get(l)];
            let m_sum = ba.inv_mass + bb.inv_mass;
            let count = usize::from(self.count[l]);
            for (p, cp) in self.points.iter_mut().enumerate().take(count) {
                let r_a = arms.r_a[p].get(l);
                let r_b = arms.r_b[p].get(l);
                let rn_a = r_a.cross(n);
                let rn_b = r_b.cross(n);
                let in_a = ba.inv_inertia * rn_a;
                let in_b = bb.inv_inertia * rn_b;
                cp.rn_a.set(l, rn_a);
                cp.rn_b.set(l, rn_b);
                cp.in_a.set(l, in_a);
                cp.in_b.set(l, in_b);
                cp.normal_mass[l] = m_sum + in_a.dot(rn_a) + in_b.dot(rn_b);
                for (j, &t) in tangents.iter().enumerate() {
                    let rt_a = r_a.cross(t);
                    let rt_b = r_b.cross(t);
                    let it_a = ba.inv_inertia * rt_a;
                    let it_b = bb.inv_inertia * rt_b;
                    cp.rt_a[j].set(l, rt_a);
                    cp.rt_b[j].set(l, rt_b);
                    cp.it_a[j].set(l, it_a);
                    cp.it_b[j].set(l, it_b);
                    cp.tangent_mass[j][l] = m_sum + it_a.dot(rt_a) + it_b.dot(rt_b);
                }
                cp.relative_velocity[l] = (bb.v - ba.v).dot(n) + bb.w.dot(rn_b) - ba.w.dot(rn_a);
            }
            self.normal_a.set(l, n * ba.inv_mass);
            self.normal_b.set(l, n * bb.inv_mass);
            for (j, t) in tangents.into_iter().enumerate() {
                self.tangents_a[j].set(l, t * ba.inv_mass);
                self.tangents_b[j].set(l, t * bb.inv_mass);
            }
        }
    }

    /// Turns the k left in the mass fields into the effective masses 1/k (0 for k ≤ 0):
    /// three divisions per point, which stay scalar.
    pub(super) fn invert_effective_masses(&mut self) {
        for l in 0..self.len {
            let count = usize::from(self.count[l]);
            for cp in self.points.iter_mut().take(count) {
                cp.normal_mass[l] = inverse_or_zero(cp.normal_mass[l]);
                for mass in &mut cp.tangent_mass {
                    mass[l] = inverse_or_zero(mass[l]);
                }
            }
        }
    }
}
