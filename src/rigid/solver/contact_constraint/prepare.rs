//! Stage 1 of the solver for one block: each lane's contact data
//! ([`ContactBlock::prepare_lane`]), then the products every iteration reuses
//! ([`ContactBlock::prepare_products`]): per point r × n, I⁻¹(r × n), the normal effective
//! mass and the approach velocity; per contact, at the friction centre, r × t, I⁻¹(r × t),
//! I⁻¹n and the tangent and twist effective masses.
//!
//! The products are the costly part (about forty multiplies per point and a hundred per
//! contact); on I32F32 they go to a kernel when the processor has AVX-512 or AVX2, which gives
//! the same bits.

use super::{ContactBlock, SolvePass};
#[cfg(vector_kernels)]
use crate::math::over_real::OverReal;
use crate::math::{Real, Vec3};
use crate::rigid::contact::Contact;
use crate::rigid::manifold::MAX_MANIFOLD_POINTS;
use crate::rigid::solver::body::SolverBody;
use crate::rigid::solver::lanes::{LANES, Lanes, Lanes3};

/// The anchors of each point of each lane from the bodies' centres of mass,
/// r_a = p − x_a and r_b = p − x_b (m), and those of each lane's friction centre c,
/// c − x_a and c − x_b: what [`ContactBlock::prepare_lane`] leaves for
/// [`ContactBlock::prepare_products`], with the squares of the points' twist arms,
/// |p_k − c|² (m²), whose square roots that stage takes for the whole block at once.
/// Points a lane does not use hold stale values, unread.
#[derive(Clone, Debug)]
pub(crate) struct ContactArms<R: Real> {
    pub r_a: [Lanes3<R>; MAX_MANIFOLD_POINTS],
    pub r_b: [Lanes3<R>; MAX_MANIFOLD_POINTS],
    pub centre_a: Lanes3<R>,
    pub centre_b: Lanes3<R>,
    pub twist_arm_squared: [Lanes<R>; MAX_MANIFOLD_POINTS],
}

/// The family of [`ContactArms`], for [`Real::as_fixed`].
#[cfg(vector_kernels)]
pub(crate) struct ContactArmsOf;

#[cfg(vector_kernels)]
impl OverReal for ContactArmsOf {
    type Of<R: Real> = ContactArms<R>;
}

impl<R: Real> ContactArms<R> {
    /// Every anchor zero.
    pub const ZERO: Self = Self {
        r_a: [Lanes3::ZERO; MAX_MANIFOLD_POINTS],
        r_b: [Lanes3::ZERO; MAX_MANIFOLD_POINTS],
        centre_a: Lanes3::ZERO,
        centre_b: Lanes3::ZERO,
        twist_arm_squared: [[R::ZERO; LANES]; MAX_MANIFOLD_POINTS],
    };
}

/// The friction centre of a contact's points, their mean c = (Σ p_k)/N (m), and the
/// square of each point's distance from it, d_k² = |p_k − c|² (m²). No points give the
/// origin.
fn friction_centre<R: Real>(
    points: &[crate::rigid::contact::ContactPoint<R>],
) -> (Vec3<R>, [R; MAX_MANIFOLD_POINTS]) {
    let mut distances = [R::ZERO; MAX_MANIFOLD_POINTS];
    let Some(first) = points.first() else {
        return (Vec3::ZERO, distances);
    };
    if points.len() == 1 {
        return (first.point, distances);
    }
    // Offsets from the first point keep the sum small wherever the contact is.
    let mut offset_sum = Vec3::ZERO;
    for p in &points[1..] {
        offset_sum += p.point - first.point;
    }
    let centre = first.point + offset_sum / R::from_int(points.len() as i32);
    for (d, p) in distances.iter_mut().zip(points) {
        *d = (p.point - centre).length_squared();
    }
    (centre, distances)
}

/// 1/k, or 0 when k is not positive (two bodies of infinite mass).
fn inverse_or_zero<R: Real>(k: R) -> R {
    if k > R::ZERO { R::ONE / k } else { R::ZERO }
}

impl<R: Real> ContactBlock<R> {
    /// Takes the next free lane for the constraint of `contact` between solver bodies `a`
    /// and `b` whose centres of mass are at `centre_a`, `centre_b` (m): the bodies, the
    /// normal and a vector ⟂ n ([`Vec3::any_orthogonal`], which [`tangents`](Self::tangents)
    /// turns into the two unit tangents), the mixed friction and restitution, the
    /// separations and normal impulses of the points, the contact's carried friction
    /// impulses, and the anchors of the points and of the friction centre and the squares
    /// of the points' twist lever arms into `arms`.
    /// [`prepare_products`](Self::prepare_products) completes the block. The block must not
    /// be full.
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
        let (centre, twist_arms_squared) = friction_centre(contact.points());
        for (p, (cp, point)) in self.points.iter_mut().zip(contact.points()).enumerate() {
            arms.r_a[p].set(l, point.point - centre_a);
            arms.r_b[p].set(l, point.point - centre_b);
            cp.base_separation[l] = point.separation;
            cp.separation[l] = point.separation;
            arms.twist_arm_squared[p][l] = twist_arms_squared[p];
            cp.normal_impulse[l] = point.normal_impulse;
            cp.max_normal_impulse[l] = R::ZERO;
        }
        arms.centre_a.set(l, centre - centre_a);
        arms.centre_b.set(l, centre - centre_b);
        let f = &mut self.friction_rows;
        f.tangent_impulse[0][l] = contact.friction_impulse[0];
        f.tangent_impulse[1][l] = contact.friction_impulse[1];
        // One point has no twist row ([`ContactBlock::solve`]), so nothing to carry.
        f.twist_impulse[l] = if contact.count > 1 {
            contact.twist_impulse
        } else {
            R::ZERO
        };
        self.a[l] = a;
        self.b[l] = b;
        self.contact[l] = index;
        self.normal.set(l, n);
        self.tangents[0].set(l, n.any_orthogonal());
        self.friction[l] = friction;
        self.restitution[l] = restitution;
        self.rigid_partner[l] =
            bodies[a as usize].inv_mass == R::ZERO || bodies[b as usize].inv_mass == R::ZERO;
        self.count[l] = contact.count;
    }

    /// Completes every lane set up by [`prepare_lane`](Self::prepare_lane), from the
    /// anchors in `arms` and the solver bodies:
    ///
    /// * the tangents t₁ = o/|o| for the vector o ⟂ n left in the first tangent (0 for
    ///   o = 0) and t₂ = n × t₁ ([`tangents`](Self::tangents)), so that t₁ = `n.any_orthonormal()`;
    /// * per point, the twist lever arm d_k = √(d_k²) (m) ([`twist_arms`](Self::twist_arms));
    /// * n/m_a, n/m_b, t/m_a, t/m_b (1/kg), the velocity change per unit impulse;
    /// * per point, r × n and I⁻¹(r × n) on each side, the effective mass 1/k (kg),
    ///   k = 1/m_a + 1/m_b + (I_a⁻¹(r_a × n))·(r_a × n) + (I_b⁻¹(r_b × n))·(r_b × n), and the
    ///   approach velocity v_n = (v_b − v_a)·n + ω_b·(r_b × n) − ω_a·(r_a × n) (m/s), for
    ///   restitution;
    /// * per lane, with the anchors of the friction centre, r × t and I⁻¹(r × t) on each
    ///   side for both tangents and their effective masses (kg) as above, I_a⁻¹n, I_b⁻¹n and
    ///   the twist effective mass 1/k_twist (kg·m²), k_twist = (I_a⁻¹n)·n + (I_b⁻¹n)·n.
    ///
    /// On I32F32 a kernel computes the products when the processor has AVX-512 or AVX2
    /// ([`prepare_kernel`](super::prepare_kernel)) and every value lies within its bound;
    /// otherwise, and on other formats, lane by lane. Both give the same bits.
    pub fn prepare_products(&mut self, arms: &ContactArms<R>, bodies: &[SolverBody<R>]) {
        self.tangents();
        self.twist_arms(arms);
        #[cfg(vector_kernels)]
        let done = super::prepare_kernel::prepare(self, arms, bodies);
        #[cfg(not(vector_kernels))]
        let done = false;
        if !done {
            self.prepare_products_lanes(arms, bodies);
        }
        self.invert_effective_masses();
    }

    /// Each lane's unit tangents (dimensionless) from the vector o ⟂ n that
    /// [`prepare_lane`](Self::prepare_lane) left in the first: t₁ = o/|o| as
    /// [`Vec3::normalize_or_zero`] computes it (|o| = √(o·o), then o·(1/|o|)), and
    /// t₂ = n × t₁. On I32F32 a kernel takes the whole block when the processor has
    /// AVX-512 or AVX2 ([`roots_kernel`](super::roots_kernel)) and every value lies within
    /// its bound; otherwise, and on other formats, one
    /// lane after another. Both give the same bits.
    pub(super) fn tangents(&mut self) {
        #[cfg(vector_kernels)]
        if super::roots_kernel::tangents(self) {
            return;
        }
        self.tangents_lanes();
    }

    /// [`tangents`](Self::tangents) one lane after another.
    pub(super) fn tangents_lanes(&mut self) {
        for l in 0..self.len {
            let t0 = self.tangents[0].get(l).normalize_or_zero();
            self.tangents[0].set(l, t0);
            self.tangents[1].set(l, self.normal.get(l).cross(t0));
        }
    }

    /// Each point's twist lever arm, d_k = √(d_k²) (m), from the squares in `arms`. On
    /// I32F32 a kernel's square roots take the whole block when the processor has AVX-512 or
    /// AVX2;
    /// otherwise, and on other formats, one point after another with [`Real::sqrt`]. Both
    /// give the same bits.
    fn twist_arms(&mut self, arms: &ContactArms<R>) {
        #[cfg(vector_kernels)]
        if super::roots_kernel::twist_arms(self, arms) {
            return;
        }
        self.twist_arms_lanes(arms);
    }

    /// [`twist_arms`](Self::twist_arms) one point after another.
    pub(super) fn twist_arms_lanes(&mut self, arms: &ContactArms<R>) {
        for l in 0..self.len {
            let count = usize::from(self.count[l]);
            for (cp, squared) in self
                .points
                .iter_mut()
                .zip(&arms.twist_arm_squared)
                .take(count)
            {
                cp.twist_arm[l] = squared[l].sqrt();
            }
        }
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
                let rn_a = arms.r_a[p].get(l).cross(n);
                let rn_b = arms.r_b[p].get(l).cross(n);
                let in_a = ba.inv_inertia * rn_a;
                let in_b = bb.inv_inertia * rn_b;
                cp.rn_a.set(l, rn_a);
                cp.rn_b.set(l, rn_b);
                cp.in_a.set(l, in_a);
                cp.in_b.set(l, in_b);
                cp.normal_mass[l] = m_sum + in_a.dot(rn_a) + in_b.dot(rn_b);
                cp.relative_velocity[l] = (bb.v - ba.v).dot(n) + bb.w.dot(rn_b) - ba.w.dot(rn_a);
            }
            let f = &mut self.friction_rows;
            let (r_a, r_b) = (arms.centre_a.get(l), arms.centre_b.get(l));
            for (j, &t) in tangents.iter().enumerate() {
                let rt_a = r_a.cross(t);
                let rt_b = r_b.cross(t);
                let it_a = ba.inv_inertia * rt_a;
                let it_b = bb.inv_inertia * rt_b;
                f.rt_a[j].set(l, rt_a);
                f.rt_b[j].set(l, rt_b);
                f.it_a[j].set(l, it_a);
                f.it_b[j].set(l, it_b);
                f.tangent_mass[j][l] = m_sum + it_a.dot(rt_a) + it_b.dot(rt_b);
            }
            let twist_a = ba.inv_inertia * n;
            let twist_b = bb.inv_inertia * n;
            f.twist_a.set(l, twist_a);
            f.twist_b.set(l, twist_b);
            f.twist_mass[l] = twist_a.dot(n) + twist_b.dot(n);
            self.normal_a.set(l, n * ba.inv_mass);
            self.normal_b.set(l, n * bb.inv_mass);
            for (j, t) in tangents.into_iter().enumerate() {
                self.tangents_a[j].set(l, t * ba.inv_mass);
                self.tangents_b[j].set(l, t * bb.inv_mass);
            }
        }
    }

    /// The soft effective masses of the step's biased passes: m_n · mass_scale (kg) for
    /// every point in use, with the mass scale of `pass`'s softness for the lane (the
    /// stiffer one for contacts with a static or kinematic body). Then, the block being
    /// complete, whether the kernels may take it.
    pub fn soften(&mut self, pass: &SolvePass<R>) {
        for l in 0..self.len {
            let scale = if self.rigid_partner[l] {
                pass.soft_static.mass_scale
            } else {
                pass.soft.mass_scale
            };
            for cp in self.points.iter_mut().take(usize::from(self.count[l])) {
                cp.soft_normal_mass[l] = cp.normal_mass[l] * scale;
            }
        }
        #[cfg(vector_kernels)]
        {
            self.kernel = super::kernel::KernelFacts::of(self);
        }
    }

    /// Turns the k left in the mass fields into the effective masses 1/k (0 for k ≤ 0):
    /// one division per point and three per lane, which stay scalar.
    pub(super) fn invert_effective_masses(&mut self) {
        for l in 0..self.len {
            let count = usize::from(self.count[l]);
            for cp in self.points.iter_mut().take(count) {
                cp.normal_mass[l] = inverse_or_zero(cp.normal_mass[l]);
            }
            let f = &mut self.friction_rows;
            for mass in &mut f.tangent_mass {
                mass[l] = inverse_or_zero(mass[l]);
            }
            f.twist_mass[l] = inverse_or_zero(f.twist_mass[l]);
        }
    }
}
