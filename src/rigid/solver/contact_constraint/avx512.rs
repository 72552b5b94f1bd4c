//! The solve and warm-start passes of an independent block of I32F32 constraints in
//! AVX-512 (F and DQ): the eight lanes side by side, one `i64` lane per constraint, with
//! the bits of [`ContactBlock::solve_lanes`] and [`ContactBlock::warm_start_lanes`].
//!
//! # Why side by side gives the same bits
//!
//! The lanes of an independent block share no moving body, so solving them one after
//! another or together reads and writes the same values; bodies that do not move (the
//! static body, kinematic bodies) have zero inverse mass and inertia, so every lane writes
//! back exactly the value it read, and two lanes writing one such body write the same
//! value.
//!
//! # Exactness
//!
//! The kernel computes every operation of [`ContactBlock::solve_lanes`], in the same
//! order, modulo 2⁶⁴. Every value it loads (body velocities and motions, constraint
//! coefficients, impulses, kept separations) and every value that enters a product is
//! checked to lie in [−2⁴⁶, 2⁴⁶) as raw bits (|x| ≤ 16384 in I32F32): the coefficients,
//! which do not change during a step, once per step ([`KernelFacts`]), the rest in the
//! kernels. Then:
//!
//! * a product a·b of checked values is at most 2⁹² before rounding, 2⁶⁰ after;
//! * a dot product of three is at most 3·2⁹² before rounding, below 2⁶² after;
//! * every sum and difference of the pass has at most four terms, each a checked value or
//!   a product or dot product: below 2⁶³.
//!
//! So no operation leaves the `i64` range: the checked operators saturate nowhere and
//! their results are the exact rounded values, which the kernel's exact residues equal.
//!
//! The linear velocities enter no product themselves, only their difference v_b − v_a,
//! which is checked where it is used; in the warm start kernel no velocity enters a
//! product. Such velocities are checked when loaded, not after each impulse: a pass adds
//! to each at most seven changes (four points' λ n/m or λ I⁻¹(r × n), and two tangent
//! changes and a twist change), each a product of checked values below 2⁶⁰, so they stay
//! below 2⁴⁶ + 7·2⁶⁰ < 2⁶³ and every sum is exact. A velocity left past the bound by a
//! pass fails the next pass's load check.
//! When a check fails in a lane in use, the kernel stops before writing anything and the
//! block takes [`ContactBlock::solve_lanes`], which saturates and counts as usual.
//!
//! # Products
//!
//! The checked `*` and the fused dot product of checked values, exact in `i64` lanes, are
//! those of [`solver::avx512`](crate::rigid::solver::avx512): [`mul`] and [`dot3`].
//!
//! # Narrow products
//!
//! When one factor a lies in [−2³¹, 2³¹) (|a| < ½), it is its own low half (a_h = 0) and
//! the product needs two multiplies of 32-bit halves, both exact in 64 bits:
//! ⌊(a·b + 2³¹)/2³²⌋ = a·b_h + ⌊(a·b_l + 2³¹)/2³²⌋ ([`times`]), about half the work of the
//! wide form. In a contact row one factor of most products is small in SI units: a
//! velocity (the dot products v·n, ω·(r × n), and the motions of the relax pass), or a
//! velocity change per unit impulse (n/m, I⁻¹(r × n) and the like, below ½ for bodies
//! above 2 kg) multiplying an impulse. Each kernel therefore comes twice: a narrow one,
//! tried first when a block's velocity changes per unit impulse are all below ½
//! ([`KernelFacts`]), which checks its velocities against 2³¹ (and the rest against 2⁴⁶)
//! and keeps the wide form for the few products of two large factors (effective mass
//! times biased velocity, friction coefficient times total impulse, squared impulses); and
//! the wide one above, which a block takes when a narrow check fails (it has written
//! nothing then), for the rest of the step. Both compute the same exact values, so the
//! bits are those of the lanes either way. The bounds of the sums above hold a fortiori.
//!
//! # Shared products
//!
//! A product λ n/m_a and λ n/m_b (likewise λ t/m) is the same bits on both sides when
//! the two bodies have the same inverse mass, and zero on a side whose inverse mass is
//! zero; when that holds in every lane of a block ([`KernelFacts`]), the kernels compute
//! it once and apply it to the sides that move.
//!
//! The friction rows are one set per lane (two tangents at the friction centre and a twist
//! about the normal), after the lane's normal rows. The clamp of the tangent impulse to its
//! disc, which needs 1/√x, runs per lane in scalar code with the checked operators, in the
//! few lanes where it applies; the twist clamp is a min and a max.

mod prepare;
mod tangents;
mod twist_arms;

pub(super) use prepare::prepare;
pub(super) use tangents::tangents;
pub(super) use twist_arms::twist_arms;

/// `block` and `arms` as I32F32 values when `R` is I32F32 and the processor has AVX-512F
/// and DQ (the preparation kernels' condition); `None` otherwise.
fn fx_operands<'a, R: Real>(
    block: &'a mut ContactBlock<R>,
    arms: &'a ContactArms<R>,
) -> Option<(&'a mut ContactBlock<Fx>, &'a ContactArms<Fx>)> {
    if !has_kernels() {
        return None;
    }
    Some((
        (block as &mut dyn Any).downcast_mut::<ContactBlock<Fx>>()?,
        (arms as &dyn Any).downcast_ref::<ContactArms<Fx>>()?,
    ))
}

use crate::rigid::solver::avx512::{
    add, add3, dot3, has_kernels, high, load, load3, mul, mul3, out_of_bound, out_of_bound3,
    select, splat, store, store_lanes, sub, sub3,
};

use core::any::Any;
use core::arch::x86_64::{
    __m512i, __mmask8, _mm256_loadu_si256, _mm512_and_si512, _mm512_cmpeq_epi64_mask,
    _mm512_cmpge_epi64_mask, _mm512_cmpge_epu64_mask, _mm512_cmpgt_epi64_mask,
    _mm512_cmpneq_epi64_mask, _mm512_cvtepu32_epi64, _mm512_loadu_si512, _mm512_mask_storeu_epi64,
    _mm512_maskz_loadu_epi64, _mm512_maskz_mov_epi64, _mm512_max_epi64, _mm512_min_epi64,
    _mm512_mul_epi32, _mm512_permutex2var_epi64, _mm512_set_epi64, _mm512_set1_epi64,
    _mm512_setzero_si512, _mm512_srai_epi64, _mm512_unpackhi_epi64, _mm512_unpacklo_epi64,
};
use core::mem::{offset_of, size_of};

use super::{ContactArms, ContactBlock, SolvePass};
use crate::math::{Fx, Real, Vec3};
use crate::rigid::solver::body::SolverBody;
use crate::rigid::solver::lanes::{LANES, Lanes, Lanes3};

/// `SolverBody<Fx>` in `i64` words, and the word offsets of the fields the kernel reads.
const BODY_WORDS: i64 = (size_of::<SolverBody<Fx>>() / 8) as i64;
const V: i64 = (offset_of!(SolverBody<Fx>, v) / 8) as i64;
const W: i64 = (offset_of!(SolverBody<Fx>, w) / 8) as i64;
const DP: i64 = (offset_of!(SolverBody<Fx>, dp) / 8) as i64;
const DTHETA: i64 = (offset_of!(SolverBody<Fx>, dtheta) / 8) as i64;

// The layout the loads and gathers rely on: `Fx` is one `i64`, `Vec3<Fx>` x, y, z in a
// row, the body a whole number of words; v, ω, Δp and Δθ in a row from word 0, so that
// words 0–7 (v, ω, Δp_x, Δp_y) and 8–15 (Δp_z, Δθ, ...) are two rows of eight.
const _: () = {
    assert!(size_of::<Fx>() == 8);
    assert!(size_of::<Vec3<Fx>>() == 24);
    assert!(size_of::<SolverBody<Fx>>().is_multiple_of(8));
    assert!(V == 0 && W == 3 && DP == 6 && DTHETA == 9);
    assert!(BODY_WORDS >= 16);
    assert!(LANES == 8);
};

/// The kernel that took a block: with narrow products, or wide ones ([`times`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kernel {
    Narrow,
    Wide,
}

/// Solves `block` with a kernel when `R` is I32F32, the block is independent and the
/// processor has AVX-512F and DQ, and tells which kernel took it: the narrow one when the
/// block's facts allow it and every value stays within its bound, else the wide one; none
/// (having written nothing) when a value leaves the wide bound too.
pub(super) fn solve<R: Real>(
    block: &mut ContactBlock<R>,
    bodies: &mut [SolverBody<R>],
    pass: &SolvePass<R>,
) -> Option<Kernel> {
    if !has_kernels() || !block.kernel.in_bound {
        return None;
    }
    let (Some(block), Some(pass)) = (
        (block as &mut dyn Any).downcast_mut::<ContactBlock<Fx>>(),
        (pass as &dyn Any).downcast_ref::<SolvePass<Fx>>(),
    ) else {
        return None;
    };
    // SAFETY: `R` is `Fx` (the downcasts succeeded), so the slice's type is unchanged.
    let bodies = unsafe { &mut *(core::ptr::from_mut(bodies) as *mut [SolverBody<Fx>]) };
    // SAFETY: AVX-512F and DQ were detected on this processor just above.
    let narrow = block.kernel.narrow
        && unsafe {
            if pass.use_bias {
                solve_block::<false, true>(block, bodies, pass)
            } else {
                solve_block::<true, true>(block, bodies, pass)
            }
        };
    if narrow {
        return Some(Kernel::Narrow);
    }
    // A block that left the narrow bound (moving fast, pushing hard) is likely to leave it
    // again: the rest of the step goes straight to the wide kernel.
    block.kernel.narrow = false;
    // SAFETY: as above.
    let wide = unsafe {
        if pass.use_bias {
            solve_block::<false, false>(block, bodies, pass)
        } else {
            solve_block::<true, false>(block, bodies, pass)
        }
    };
    wide.then_some(Kernel::Wide)
}

/// Warm starts `block` with a kernel, under the same conditions as [`solve`], and tells
/// which kernel took it (none: nothing was written).
pub(super) fn warm_start<R: Real>(
    block: &mut ContactBlock<R>,
    bodies: &mut [SolverBody<R>],
) -> Option<Kernel> {
    if !has_kernels() || !block.kernel.in_bound {
        return None;
    }
    let block = (block as &mut dyn Any).downcast_mut::<ContactBlock<Fx>>()?;
    // SAFETY: `R` is `Fx` (the downcast succeeded), so the slice's type is unchanged.
    let bodies = unsafe { &mut *(core::ptr::from_mut(bodies) as *mut [SolverBody<Fx>]) };
    // SAFETY: AVX-512F and DQ were detected on this processor just above.
    if block.kernel.narrow && unsafe { warm_start_block::<true>(block, bodies) } {
        return Some(Kernel::Narrow);
    }
    // As in `solve`: the rest of the step goes to the wide kernel.
    block.kernel.narrow = false;
    // SAFETY: as above.
    unsafe { warm_start_block::<false>(block, bodies) }.then_some(Kernel::Wide)
}

/// What the kernels need to know of a block's coefficients, which do not change during a
/// step: found once per step ([`KernelFacts::of`]).
#[derive(Clone, Copy, Debug)]
#[cfg_attr(test, derive(PartialEq))]
pub(super) struct KernelFacts {
    /// Whether every coefficient the passes read lies within the checked bound in the
    /// lanes and points in use (see the module documentation): the normal, tangents and
    /// their per-mass forms, the arms and their inertia products, the effective masses
    /// (rigid and soft), the separations at the start of the step, the twist arms and the
    /// friction coefficients. The kernels take only such blocks, and check only what
    /// changes: velocities, motions, impulses and what they compute.
    in_bound: bool,
    /// Whether, in every lane in use, n/m_a and t/m_a equal n/m_b and t/m_b or one side's
    /// are all zero (bodies of equal mass, or a body that does not move): then one product
    /// λ n/m (and λ t/m) serves both sides, A's where B's are zero.
    pub(super) linear_shared: bool,
    /// The lanes whose side A (B) has a nonzero n/m or t/m: the lanes where a shared
    /// product changes that side's velocity.
    moving_a: __mmask8,
    moving_b: __mmask8,
    /// Whether every velocity change per unit impulse (n/m, t/m, I⁻¹(r × n), I⁻¹(r × t),
    /// I⁻¹n) lies within the narrow bound [−2³¹, 2³¹) in the lanes and points in use
    /// (bodies heavier than 2 kg, with inertias to match): then the kernels try narrow
    /// products ([`times`]) first. Cleared for the rest of the step when they fail.
    narrow: bool,
}

impl KernelFacts {
    /// Facts of a block the kernels do not take.
    pub(super) const NONE: Self = Self {
        in_bound: false,
        linear_shared: false,
        moving_a: 0,
        moving_b: 0,
        narrow: false,
    };

    /// The facts of `block`, complete for the step; [`NONE`](Self::NONE) when `R` is not
    /// I32F32 or the processor has no kernels.
    pub(super) fn of<R: Real>(block: &ContactBlock<R>) -> Self {
        if !has_kernels() {
            return Self::NONE;
        }
        let Some(block) = (block as &dyn Any).downcast_ref::<ContactBlock<Fx>>() else {
            return Self::NONE;
        };
        // SAFETY: AVX-512F and DQ were detected on this processor just above.
        unsafe { facts(block) }
    }
}

/// [`KernelFacts::of`] for I32F32.
///
/// # Safety
/// The processor must have AVX-512F and AVX-512DQ.
#[target_feature(enable = "avx512f,avx512dq")]
unsafe fn facts(block: &ContactBlock<Fx>) -> KernelFacts {
    let active = ((1u16 << block.len) - 1) as __mmask8;
    let vectors = |lanes: &[&Lanes3<Fx>]| {
        lanes
            .iter()
            .fold(0, |bad, &v| bad | out_of_bound3(load3(v)))
    };
    let scalars =
        |lanes: &[&Lanes<Fx>]| lanes.iter().fold(0, |bad, &x| bad | out_of_bound(load(x)));
    let f = &block.friction_rows;
    let mut bad = (vectors(&[
        &block.normal,
        &block.normal_a,
        &block.normal_b,
        &block.tangents[0],
        &block.tangents[1],
        &block.tangents_a[0],
        &block.tangents_a[1],
        &block.tangents_b[0],
        &block.tangents_b[1],
        &f.rt_a[0],
        &f.rt_a[1],
        &f.rt_b[0],
        &f.rt_b[1],
        &f.it_a[0],
        &f.it_a[1],
        &f.it_b[0],
        &f.it_b[1],
        &f.twist_a,
        &f.twist_b,
    ]) | scalars(&[
        &block.friction,
        &f.tangent_mass[0],
        &f.tangent_mass[1],
        &f.twist_mass,
    ])) & active;
    // SAFETY: 64 readable bytes.
    let counts = unsafe { _mm512_loadu_si512(block.count.map(i64::from).as_ptr().cast()) };
    for (k, cp) in block.points.iter().enumerate() {
        let in_use = _mm512_cmpgt_epi64_mask(counts, _mm512_set1_epi64(k as i64)) & active;
        bad |= (vectors(&[&cp.rn_a, &cp.rn_b, &cp.in_a, &cp.in_b])
            | scalars(&[
                &cp.normal_mass,
                &cp.soft_normal_mass,
                &cp.base_separation,
                &cp.twist_arm,
            ]))
            & in_use;
    }
    // The lanes where every component of the side's n/m and t/m is zero, and where the
    // two sides' are equal.
    let per_mass = |normal: &Lanes3<Fx>, tangents: &[Lanes3<Fx>; 2]| {
        [load3(normal), load3(&tangents[0]), load3(&tangents[1])]
    };
    let side_a = per_mass(&block.normal_a, &block.tangents_a);
    let side_b = per_mass(&block.normal_b, &block.tangents_b);
    let zero = _mm512_setzero_si512();
    let mut still_a = active;
    let mut still_b = active;
    let mut equal = active;
    for (a, b) in side_a.iter().flatten().zip(side_b.iter().flatten()) {
        still_a &= _mm512_cmpeq_epi64_mask(*a, zero);
        still_b &= _mm512_cmpeq_epi64_mask(*b, zero);
        equal &= _mm512_cmpeq_epi64_mask(*a, *b);
    }
    // The velocity changes per unit impulse, against the narrow bound.
    let narrow = |lanes: &[&Lanes3<Fx>]| {
        lanes
            .iter()
            .fold(0, |wide, &v| wide | beyond3::<true>(load3(v)))
    };
    let mut wide = narrow(&[
        &block.normal_a,
        &block.normal_b,
        &block.tangents_a[0],
        &block.tangents_a[1],
        &block.tangents_b[0],
        &block.tangents_b[1],
        &f.it_a[0],
        &f.it_a[1],
        &f.it_b[0],
        &f.it_b[1],
        &f.twist_a,
        &f.twist_b,
    ]) & active;
    for (k, cp) in block.points.iter().enumerate() {
        let in_use = _mm512_cmpgt_epi64_mask(counts, _mm512_set1_epi64(k as i64)) & active;
        wide |= narrow(&[&cp.in_a, &cp.in_b]) & in_use;
    }
    KernelFacts {
        in_bound: bad == 0,
        linear_shared: (still_a | still_b | equal) & active == active,
        moving_a: active & !still_a,
        moving_b: active & !still_b,
        narrow: wide == 0,
    }
}

/// The velocity changes per unit impulse of a block's lanes, n/m and t/m, on each side, and
/// how a product with them reaches the two sides.
struct Linear {
    /// n/m_a and n/m_b, or the shared coefficients on both sides.
    normal: [[__m512i; 3]; 2],
    /// t/m_a and t/m_b for the two tangents, likewise.
    tangents: [[[__m512i; 3]; 2]; 2],
    /// The lanes each side moves in when the coefficients are shared
    /// ([`KernelFacts::linear_shared`]).
    shared: Option<(__mmask8, __mmask8)>,
}

impl Linear {
    /// The coefficients of `block`: when they are shared, B's where B moves and A's
    /// elsewhere (where B's are zero), for both sides.
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    fn of(block: &ContactBlock<Fx>) -> Self {
        let (normal_a, normal_b) = (load3(&block.normal_a), load3(&block.normal_b));
        let tangents_a = [load3(&block.tangents_a[0]), load3(&block.tangents_a[1])];
        let tangents_b = [load3(&block.tangents_b[0]), load3(&block.tangents_b[1])];
        let facts = &block.kernel;
        if !facts.linear_shared {
            return Self {
                normal: [normal_a, normal_b],
                tangents: [tangents_a, tangents_b],
                shared: None,
            };
        }
        let pick = |a: [__m512i; 3], b: [__m512i; 3]| {
            [
                select(facts.moving_b, b[0], a[0]),
                select(facts.moving_b, b[1], a[1]),
                select(facts.moving_b, b[2], a[2]),
            ]
        };
        let normal = pick(normal_a, normal_b);
        let tangents = [
            pick(tangents_a[0], tangents_b[0]),
            pick(tangents_a[1], tangents_b[1]),
        ];
        Self {
            normal: [normal; 2],
            tangents: [tangents; 2],
            shared: Some((facts.moving_a, facts.moving_b)),
        }
    }

    /// (Δv_a, Δv_b) = (λ n/m_a, λ n/m_b), each product rounded as `Vec3 * R`.
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    fn along_normal<const NARROW: bool>(&self, impulse: __m512i) -> ([__m512i; 3], [__m512i; 3]) {
        match self.shared {
            Some((moving_a, moving_b)) => {
                let change = times3::<NARROW>(self.normal[0], impulse);
                (keep3(moving_a, change), keep3(moving_b, change))
            }
            None => (
                times3::<NARROW>(self.normal[0], impulse),
                times3::<NARROW>(self.normal[1], impulse),
            ),
        }
    }

    /// (Δv_a, Δv_b) = (λ₁ t₁/m_a + λ₂ t₂/m_a, λ₁ t₁/m_b + λ₂ t₂/m_b).
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    fn along_tangents<const NARROW: bool>(
        &self,
        impulses: [__m512i; 2],
    ) -> ([__m512i; 3], [__m512i; 3]) {
        let along = |t: &[[__m512i; 3]; 2]| {
            add3(
                times3::<NARROW>(t[0], impulses[0]),
                times3::<NARROW>(t[1], impulses[1]),
            )
        };
        match self.shared {
            Some((moving_a, moving_b)) => {
                let change = along(&self.tangents[0]);
                (keep3(moving_a, change), keep3(moving_b, change))
            }
            None => (along(&self.tangents[0]), along(&self.tangents[1])),
        }
    }
}

/// The warm start kernel: per point, v_a −= λ_n n/m_a, ω_a −= λ_n I_a⁻¹(r_a × n), and the
/// opposite on B; then per lane the friction impulses, v_a −= λ₁ t₁/m_a + λ₂ t₂/m_a,
/// ω_a −= λ₁ I_a⁻¹(r_a × t₁) + λ₂ I_a⁻¹(r_a × t₂) + λ_twist I_a⁻¹n, and the opposite on B,
/// as in [`ContactBlock::warm_start`] (zero impulses add zero, the same as skipping them).
/// Narrow or wide products ([`times`]); the velocities, which enter no product here, are
/// checked against the wide bound when loaded, either way, and not after each impulse (see
/// the module documentation). Returns false, having written nothing, when a value leaves
/// its checked bound in a lane in use.
///
/// # Safety
/// The processor must have AVX-512F and AVX-512DQ.
#[target_feature(enable = "avx512f,avx512dq")]
unsafe fn warm_start_block<const NARROW: bool>(
    block: &ContactBlock<Fx>,
    bodies: &mut [SolverBody<Fx>],
) -> bool {
    let Some(lanes) = BodyLanes::new(block, bodies) else {
        return false;
    };
    let active = lanes.active;
    // SAFETY: `BodyLanes::new` checked every active lane's index.
    let (mut side_a, mut side_b) = unsafe { lanes.load(false) };
    // Warm starting only adds to the velocities: they need the wide bound, whatever the
    // products.
    let mut bad = side_a.beyond::<false>() | side_b.beyond::<false>();
    let zero = _mm512_setzero_si512();
    let linear = Linear::of(block);
    // SAFETY: 64 readable bytes.
    let counts = unsafe { _mm512_loadu_si512(block.count.map(i64::from).as_ptr().cast()) };
    for (k, cp) in block.points.iter().enumerate() {
        let in_use = _mm512_cmpgt_epi64_mask(counts, _mm512_set1_epi64(k as i64)) & active;
        if in_use == 0 {
            continue;
        }
        let n = select(in_use, load(&cp.normal_impulse), zero);
        let (in_a, in_b) = (load3(&cp.in_a), load3(&cp.in_b));
        bad |= out_of_bound(n) & in_use;
        let (dv_a, dv_b) = linear.along_normal::<NARROW>(n);
        Side::exchange(
            (&mut side_a, &mut side_b),
            [
                dv_a,
                times3::<NARROW>(in_a, n),
                dv_b,
                times3::<NARROW>(in_b, n),
            ],
        );
        if bad != 0 {
            return false;
        }
    }
    let f = &block.friction_rows;
    let it_a = [load3(&f.it_a[0]), load3(&f.it_a[1])];
    let it_b = [load3(&f.it_b[0]), load3(&f.it_b[1])];
    let (twist_a, twist_b) = (load3(&f.twist_a), load3(&f.twist_b));
    let t = [
        select(active, load(&f.tangent_impulse[0]), zero),
        select(active, load(&f.tangent_impulse[1]), zero),
    ];
    let twist = select(active, load(&f.twist_impulse), zero);
    bad |= (out_of_bound(t[0]) | out_of_bound(t[1]) | out_of_bound(twist)) & active;
    let along =
        |a: [[__m512i; 3]; 2]| add3(times3::<NARROW>(a[0], t[0]), times3::<NARROW>(a[1], t[1]));
    let (dv_a, dv_b) = linear.along_tangents::<NARROW>(t);
    Side::exchange(
        (&mut side_a, &mut side_b),
        [
            dv_a,
            add3(along(it_a), times3::<NARROW>(twist_a, twist)),
            dv_b,
            add3(along(it_b), times3::<NARROW>(twist_b, twist)),
        ],
    );
    if bad != 0 {
        return false;
    }
    // SAFETY: `BodyLanes::new` checked every active lane's index.
    unsafe { lanes.store(&side_a, &side_b) };
    true
}

/// The lanes where x, a velocity-like value that changes during the step (a velocity or
/// motion, a separation, a relative velocity along a row), lies outside the bound the
/// kernel's products need: [−2³¹, 2³¹) for narrow products, [−2⁴⁶, 2⁴⁶) for wide ones
/// ([`times`]). Impulses are always checked against the wide bound: the narrow operand of
/// their products is the coefficient.
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn beyond<const NARROW: bool>(x: __m512i) -> __mmask8 {
    if NARROW {
        _mm512_cmpge_epu64_mask(
            add(x, _mm512_set1_epi64(1 << 31)),
            _mm512_set1_epi64(1 << 32),
        )
    } else {
        out_of_bound(x)
    }
}

#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn beyond3<const NARROW: bool>(x: [__m512i; 3]) -> __mmask8 {
    beyond::<NARROW>(x[0]) | beyond::<NARROW>(x[1]) | beyond::<NARROW>(x[2])
}

/// The checked `*` of `small`, within the narrow bound [−2³¹, 2³¹) when `NARROW` (and the
/// wide one otherwise), and `other`, within the wide bound [−2⁴⁶, 2⁴⁶).
///
/// Narrow: a value a in [−2³¹, 2³¹) is its own low half, so
/// ⌊(a·b + 2³¹)/2³²⌋ = a·b_h + ⌊(a·b_l + 2³¹)/2³²⌋, two products of 32-bit halves (a·b_h
/// below 2⁴⁵, a·b_l below 2⁶²) where [`mul`] needs three, one of them 64 × 64 bits.
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn times<const NARROW: bool>(small: __m512i, other: __m512i) -> __m512i {
    if NARROW {
        let upper = _mm512_mul_epi32(small, high(other));
        add(upper, high(_mm512_mul_epi32(small, other)))
    } else {
        mul(small, other)
    }
}

/// Each of the small `coefficients` (a velocity change per unit impulse, within the
/// narrow bound when `NARROW`: [`KernelFacts::narrow`]) times the same impulse
/// ([`times`]).
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn times3<const NARROW: bool>(coefficients: [__m512i; 3], impulse: __m512i) -> [__m512i; 3] {
    [
        times::<NARROW>(coefficients[0], impulse),
        times::<NARROW>(coefficients[1], impulse),
        times::<NARROW>(coefficients[2], impulse),
    ]
}

/// The fused dot product of velocity-like values within their bound ([`beyond`]) and
/// coefficients, the exact Σ aᵢbᵢ rounded once ([`dot3`]). Narrow: Σ aᵢb_h,ᵢ plus the low
/// products aᵢb_l,ᵢ, each split into q·2³² + r as in [`dot3`].
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn dot<const NARROW: bool>(values: [__m512i; 3], coefficients: [__m512i; 3]) -> __m512i {
    if !NARROW {
        return dot3(values, coefficients);
    }
    let mask = _mm512_set1_epi64(0xffff_ffff);
    let mut whole = _mm512_setzero_si512();
    let mut remainders = _mm512_setzero_si512();
    for (a, b) in values.into_iter().zip(coefficients) {
        let low = _mm512_mul_epi32(a, b);
        let upper = _mm512_mul_epi32(a, high(b));
        whole = add(whole, add(upper, _mm512_srai_epi64::<32>(low)));
        remainders = add(remainders, _mm512_and_si512(low, mask));
    }
    add(whole, high(remainders))
}

/// `value` in the lanes of `mask`, zero elsewhere.
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn keep3(mask: __mmask8, value: [__m512i; 3]) -> [__m512i; 3] {
    value.map(|x| _mm512_maskz_mov_epi64(mask, x))
}

/// The velocities and motions of the lanes' bodies on one side.
struct Side {
    v: [__m512i; 3],
    w: [__m512i; 3],
    dp: [__m512i; 3],
    dtheta: [__m512i; 3],
}

impl Side {
    /// Loads the bodies of `indices` in the lanes of `active` (zero elsewhere): one 64-byte
    /// row per body, v, ω, Δp_x and Δp_y, turned into one vector per component; with the
    /// motions Δp and Δθ when `with_motion` (zero otherwise), from the next row. One masked load per lane, all eight unrolled, so that the rows stay
    /// in registers; a lane outside `active` loads nothing.
    ///
    /// # Safety
    /// The index of each lane of `active` must be that of a body of the array at `bodies`.
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    unsafe fn load(
        bodies: *const i64,
        indices: &[u32; LANES],
        active: __mmask8,
        with_motion: bool,
    ) -> Self {
        let zero = _mm512_setzero_si512();
        let rows = |offset: usize| {
            transpose(core::array::from_fn(|l| {
                let at = bodies.wrapping_add(first_word(indices[l]) + offset);
                // SAFETY: in a lane of `active`, words `offset` to `offset + 7` of the
                // body lie in it (the caller's promise and the layout checked above);
                // elsewhere the mask is empty and nothing is read.
                unsafe { _mm512_maskz_loadu_epi64(lane_mask(active, l), at.cast()) }
            }))
        };
        let [vx, vy, vz, wx, wy, wz, px, py] = rows(V as usize);
        let (dp, dtheta) = if with_motion {
            let [pz, tx, ty, tz, ..] = rows(DP as usize + 2);
            ([px, py, pz], [tx, ty, tz])
        } else {
            ([zero; 3], [zero; 3])
        };
        Self {
            v: [vx, vy, vz],
            w: [wx, wy, wz],
            dp,
            dtheta,
        }
    }

    /// Applies an impulse's velocity changes, A losing and B gaining:
    /// v_a −= Δv_a, ω_a −= Δω_a, v_b += Δv_b, ω_b += Δω_b. The new velocities are not
    /// checked: a velocity that enters products later is checked there ([`Side::spin_beyond`]
    /// and the relative velocity), and the sums are exact (see the module documentation).
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    fn exchange((a, b): (&mut Side, &mut Side), [dv_a, dw_a, dv_b, dw_b]: [[__m512i; 3]; 4]) {
        a.v = sub3(a.v, dv_a);
        a.w = sub3(a.w, dw_a);
        b.v = add3(b.v, dv_b);
        b.w = add3(b.w, dw_b);
    }

    /// The lanes where an angular velocity of either side, a factor of the next row's
    /// products ω·(r × n) and ω·(r × t), lies outside the bound of changing values
    /// ([`beyond`]).
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    fn spin_beyond<const NARROW: bool>(a: &Side, b: &Side) -> __mmask8 {
        beyond3::<NARROW>(a.w) | beyond3::<NARROW>(b.w)
    }

    /// Writes the velocities back: the first six words of each body's first row, in the
    /// lanes of `active`. Lanes that share a body share it only when it does not move, and
    /// then write the values they read.
    ///
    /// # Safety
    /// As for [`Side::load`], with `bodies` writable.
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    unsafe fn store_velocities(&self, bodies: *mut i64, indices: &[u32; LANES], active: __mmask8) {
        let [vx, vy, vz] = self.v;
        let [wx, wy, wz] = self.w;
        let zero = _mm512_setzero_si512();
        let rows = transpose([vx, vy, vz, wx, wy, wz, zero, zero]);
        for (l, row) in rows.into_iter().enumerate() {
            let at = bodies.wrapping_add(first_word(indices[l]) + V as usize);
            // SAFETY: as in `load`; six words, none outside `active`.
            unsafe { _mm512_mask_storeu_epi64(at.cast(), lane_mask(active, l) & 0b11_1111, row) };
        }
    }

    /// The lanes where a value lies outside the bound of changing values ([`beyond`]).
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    fn beyond<const NARROW: bool>(&self) -> __mmask8 {
        beyond3::<NARROW>(self.v)
            | beyond3::<NARROW>(self.w)
            | beyond3::<NARROW>(self.dp)
            | beyond3::<NARROW>(self.dtheta)
    }
}

/// The first word of body `index` in an array of solver bodies taken as words:
/// index · [`BODY_WORDS`].
#[inline]
fn first_word(index: u32) -> usize {
    index as usize * BODY_WORDS as usize
}

/// The mask of a 64-byte load or store of lane `l`'s row: all eight words when `l` is
/// one of the lanes of `active`, none otherwise.
#[inline]
fn lane_mask(active: __mmask8, l: usize) -> __mmask8 {
    0u8.wrapping_sub((active >> l) & 1)
}

/// The transpose of an 8 × 8 matrix of words given by rows: row i of the result holds
/// word i of every input row. Three rounds of two-source permutes, 24 in all.
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn transpose(rows: [__m512i; 8]) -> [__m512i; 8] {
    let pairs = |a: __m512i, b: __m512i| (_mm512_unpacklo_epi64(a, b), _mm512_unpackhi_epi64(a, b));
    let (a0, a1) = pairs(rows[0], rows[1]);
    let (a2, a3) = pairs(rows[2], rows[3]);
    let (a4, a5) = pairs(rows[4], rows[5]);
    let (a6, a7) = pairs(rows[6], rows[7]);
    // Words 0 and 1 of each 256-bit half from the first source, then from the second
    // (indices 8 and up), and likewise words 2 and 3.
    let low = _mm512_set_epi64(13, 12, 5, 4, 9, 8, 1, 0);
    let high = _mm512_set_epi64(15, 14, 7, 6, 11, 10, 3, 2);
    let quads = |a: __m512i, b: __m512i| {
        (
            _mm512_permutex2var_epi64(a, low, b),
            _mm512_permutex2var_epi64(a, high, b),
        )
    };
    let (b0, b2) = quads(a0, a2);
    let (b1, b3) = quads(a1, a3);
    let (b4, b6) = quads(a4, a6);
    let (b5, b7) = quads(a5, a7);
    // The low 256 bits of each, then the high 256 bits.
    let first = _mm512_set_epi64(11, 10, 9, 8, 3, 2, 1, 0);
    let second = _mm512_set_epi64(15, 14, 13, 12, 7, 6, 5, 4);
    let halves = |a: __m512i, b: __m512i| {
        (
            _mm512_permutex2var_epi64(a, first, b),
            _mm512_permutex2var_epi64(a, second, b),
        )
    };
    let (r0, r4) = halves(b0, b4);
    let (r1, r5) = halves(b1, b5);
    let (r2, r6) = halves(b2, b6);
    let (r3, r7) = halves(b3, b7);
    [r0, r1, r2, r3, r4, r5, r6, r7]
}

/// The lanes in use of `block`, and the first word of each lane's body A and body B in
/// an array of `body_count` solver bodies; `None` if an index is out of bounds.
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn lane_words(block: &ContactBlock<Fx>, body_count: usize) -> Option<(__mmask8, __m512i, __m512i)> {
    let mut words_a = [0i64; LANES];
    let mut words_b = [0i64; LANES];
    for l in 0..block.len {
        let (a, b) = (block.a[l] as usize, block.b[l] as usize);
        if a >= body_count || b >= body_count {
            return None;
        }
        words_a[l] = a as i64 * BODY_WORDS;
        words_b[l] = b as i64 * BODY_WORDS;
    }
    // SAFETY: 64 readable bytes each.
    let (words_a, words_b) = unsafe {
        (
            _mm512_loadu_si512(words_a.as_ptr().cast()),
            _mm512_loadu_si512(words_b.as_ptr().cast()),
        )
    };
    Some((((1u16 << block.len) - 1) as __mmask8, words_a, words_b))
}

/// Where the bodies of a block's lanes are.
struct BodyLanes {
    /// The lanes in use: the first `len` of the block.
    active: __mmask8,
    /// The indices of each lane's body A and body B (checked in the lanes in use).
    a: [u32; LANES],
    b: [u32; LANES],
    /// The solver bodies, as words.
    base: *mut i64,
}

impl BodyLanes {
    /// The bodies of `block`'s lanes in `bodies`, or `None` if the index of a lane in use
    /// is out of bounds.
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    fn new(block: &ContactBlock<Fx>, bodies: &mut [SolverBody<Fx>]) -> Option<Self> {
        let active = ((1u16 << block.len) - 1) as __mmask8;
        let count = _mm512_set1_epi64(bodies.len() as i64);
        // The lanes' indices, widened; the lanes in use must be below the body count.
        let outside = |indices: &[u32; LANES]| {
            // SAFETY: eight `u32`: 32 readable bytes.
            let indices =
                _mm512_cvtepu32_epi64(unsafe { _mm256_loadu_si256(indices.as_ptr().cast()) });
            _mm512_cmpge_epi64_mask(indices, count) & active
        };
        if outside(&block.a) | outside(&block.b) != 0 {
            return None;
        }
        Some(Self {
            active,
            a: block.a,
            b: block.b,
            base: bodies.as_mut_ptr().cast::<i64>(),
        })
    }

    /// The two sides' bodies, with their motions when `with_motion`.
    ///
    /// # Safety
    /// The bodies must still be those `new` was given, alive and not otherwise borrowed.
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    unsafe fn load(&self, with_motion: bool) -> (Side, Side) {
        // SAFETY: every lane's index was checked in `new`.
        unsafe {
            (
                Side::load(self.base, &self.a, self.active, with_motion),
                Side::load(self.base, &self.b, self.active, with_motion),
            )
        }
    }

    /// Writes both sides' velocities back.
    ///
    /// # Safety
    /// As for [`BodyLanes::load`].
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    unsafe fn store(&self, a: &Side, b: &Side) {
        // SAFETY: every lane's index was checked in `new`.
        unsafe {
            a.store_velocities(self.base, &self.a, self.active);
            b.store_velocities(self.base, &self.b, self.active);
        }
    }
}

/// The kernel, for the biased pass or (`RELAX`) the relax pass, with narrow or wide
/// products ([`times`]). Returns false, having written nothing, when a value leaves its
/// checked bound in a lane in use.
///
/// The biased pass reads the separations the block keeps; the relax pass computes them
/// from the bodies' motions and keeps them (as [`ContactBlock::solve_lanes`] does).
///
/// # Safety
/// The processor must have AVX-512F and AVX-512DQ.
#[target_feature(enable = "avx512f,avx512dq")]
unsafe fn solve_block<const RELAX: bool, const NARROW: bool>(
    block: &mut ContactBlock<Fx>,
    bodies: &mut [SolverBody<Fx>],
    pass: &SolvePass<Fx>,
) -> bool {
    let Some(lanes) = BodyLanes::new(block, bodies) else {
        return false;
    };
    let active = lanes.active;
    // SAFETY: `BodyLanes::new` checked every active lane's index.
    let (mut side_a, mut side_b) = unsafe { lanes.load(RELAX) };
    let mut bad = side_a.beyond::<NARROW>() | side_b.beyond::<NARROW>();
    if bad != 0 {
        return false;
    }

    let zero = _mm512_setzero_si512();
    let rigid_partner = block
        .rigid_partner
        .iter()
        .enumerate()
        .fold(0u8, |mask, (l, &rigid)| mask | (u8::from(rigid) << l));
    let soft = |pick: fn(&crate::rigid::solver::Softness<Fx>) -> Fx| {
        select(
            rigid_partner,
            splat(pick(&pass.soft_static)),
            splat(pick(&pass.soft)),
        )
    };
    let bias_rate = soft(|s| s.bias_rate);
    let impulse_scale = soft(|s| s.impulse_scale);
    let inv_h = splat(pass.inv_h);
    let lowest_bias = splat(-pass.max_push);
    bad |= (out_of_bound(bias_rate)
        | beyond::<NARROW>(impulse_scale)
        | out_of_bound(inv_h)
        | out_of_bound(lowest_bias))
        & active;

    let normal = load3(&block.normal);
    let linear = Linear::of(block);
    let counts = block.count.map(i64::from);
    // SAFETY: 64 readable bytes.
    let counts = unsafe { _mm512_loadu_si512(counts.as_ptr().cast()) };
    let points_in_use =
        |k: usize| _mm512_cmpgt_epi64_mask(counts, _mm512_set1_epi64(k as i64)) & active;

    // Normal impulses. The separations first: kept by the block in the biased pass,
    // computed from the motions in the relax pass, which then no longer needs them.
    let mut separations = [zero; 4];
    if RELAX {
        let moved = sub3(side_b.dp, side_a.dp);
        bad |= beyond3::<NARROW>(moved) & active;
        let moved_apart = dot::<NARROW>(moved, normal);
        for (k, cp) in block.points.iter().enumerate() {
            let in_use = points_in_use(k);
            if in_use == 0 {
                continue;
            }
            let (rn_a, rn_b) = (load3(&cp.rn_a), load3(&cp.rn_b));
            let base_separation = load(&cp.base_separation);
            let s = sub(
                add(
                    add(base_separation, moved_apart),
                    dot::<NARROW>(side_b.dtheta, rn_b),
                ),
                dot::<NARROW>(side_a.dtheta, rn_a),
            );
            bad |= beyond::<NARROW>(s) & in_use;
            separations[k] = s;
        }
    } else {
        for (k, cp) in block.points.iter().enumerate() {
            let in_use = points_in_use(k);
            if in_use == 0 {
                continue;
            }
            let s = load(&cp.separation);
            bad |= beyond::<NARROW>(s) & in_use;
            separations[k] = s;
        }
    }
    let mut normal_impulses = [zero; 4];
    let mut max_normal_impulses = [zero; 4];
    for (k, cp) in block.points.iter().enumerate() {
        let in_use = points_in_use(k);
        if in_use == 0 {
            // No lane has this point (nor the next ones): nothing to solve or store.
            continue;
        }
        let (rn_a, rn_b) = (load3(&cp.rn_a), load3(&cp.rn_b));
        let (in_a, in_b) = (load3(&cp.in_a), load3(&cp.in_b));
        let normal_mass = load(&cp.normal_mass);
        let old = load(&cp.normal_impulse);
        let old_max = load(&cp.max_normal_impulse);
        bad |= (out_of_bound(old) | out_of_bound(old_max)) & in_use;
        let s = separations[k];
        let apart = _mm512_cmpgt_epi64_mask(s, zero);
        // s/h for the points still apart (s·inv_h is only computed when there are some).
        let speculative_bias = if apart & in_use != 0 {
            times::<NARROW>(s, inv_h)
        } else {
            zero
        };
        let dv = sub3(side_b.v, side_a.v);
        bad |= beyond3::<NARROW>(dv) & in_use;
        let vn = sub(
            add(dot::<NARROW>(dv, normal), dot::<NARROW>(side_b.w, rn_b)),
            dot::<NARROW>(side_a.w, rn_a),
        );
        let impulse = if RELAX {
            let biased = add(vn, select(apart, speculative_bias, zero));
            bad |= out_of_bound(biased) & in_use;
            sub(zero, mul(normal_mass, biased))
        } else {
            let soft_mass = load(&cp.soft_normal_mass);
            let soft_bias = _mm512_max_epi64(times::<NARROW>(s, bias_rate), lowest_bias);
            let biased = add(vn, select(apart, speculative_bias, soft_bias));
            let mass = select(apart, normal_mass, soft_mass);
            let scale_impulse = select(apart, zero, impulse_scale);
            bad |= out_of_bound(biased) & in_use;
            sub(
                sub(zero, mul(mass, biased)),
                times::<NARROW>(scale_impulse, old),
            )
        };
        let new = _mm512_max_epi64(add(old, impulse), zero);
        let applied = select(in_use, sub(new, old), zero);
        bad |= out_of_bound(applied) & in_use;
        let (dv_a, dv_b) = linear.along_normal::<NARROW>(applied);
        Side::exchange(
            (&mut side_a, &mut side_b),
            [
                dv_a,
                times3::<NARROW>(in_a, applied),
                dv_b,
                times3::<NARROW>(in_b, applied),
            ],
        );
        bad |= Side::spin_beyond::<NARROW>(&side_a, &side_b) & active;
        normal_impulses[k] = select(in_use, new, old);
        max_normal_impulses[k] = select(in_use, _mm512_max_epi64(old_max, applied), old_max);
        if bad != 0 {
            return false;
        }
    }

    // Friction: the lane's total normal impulse Λ = Σ λ_n,k and Σ λ_n,k d_k, then the two
    // tangent rows and the twist row.
    let f = &block.friction_rows;
    // Lanes of one point have no twist row.
    let twisting = points_in_use(1);
    let mut normal_sum = zero;
    let mut twist_sum = zero;
    for (k, cp) in block.points.iter().enumerate() {
        let in_use = points_in_use(k);
        if in_use == 0 {
            continue;
        }
        let impulse = select(in_use, normal_impulses[k], zero);
        bad |= out_of_bound(impulse) & in_use;
        normal_sum = add(normal_sum, impulse);
        if twisting != 0 {
            let arm = select(in_use, load(&cp.twist_arm), zero);
            twist_sum = add(twist_sum, mul(impulse, arm));
        }
    }
    let tangents = [load3(&block.tangents[0]), load3(&block.tangents[1])];
    let friction = load(&block.friction);
    let old = [load(&f.tangent_impulse[0]), load(&f.tangent_impulse[1])];
    let old_twist = load(&f.twist_impulse);
    let pushing = _mm512_cmpneq_epi64_mask(normal_sum, zero)
        | _mm512_cmpneq_epi64_mask(old[0], zero)
        | _mm512_cmpneq_epi64_mask(old[1], zero)
        | _mm512_cmpneq_epi64_mask(old_twist, zero);
    let in_use = active & pushing;
    let mut tangent_impulses = old;
    let mut twist_impulses = old_twist;
    if in_use != 0 {
        let rt_a = [load3(&f.rt_a[0]), load3(&f.rt_a[1])];
        let rt_b = [load3(&f.rt_b[0]), load3(&f.rt_b[1])];
        let it_a = [load3(&f.it_a[0]), load3(&f.it_a[1])];
        let it_b = [load3(&f.it_b[0]), load3(&f.it_b[1])];
        let (twist_a, twist_b) = (load3(&f.twist_a), load3(&f.twist_b));
        let tangent_mass = [load(&f.tangent_mass[0]), load(&f.tangent_mass[1])];
        let twist_mass = load(&f.twist_mass);
        bad |= (out_of_bound(normal_sum)
            | out_of_bound(twist_sum)
            | out_of_bound(old[0])
            | out_of_bound(old[1])
            | out_of_bound(old_twist))
            & in_use;
        let dv = sub3(side_b.v, side_a.v);
        bad |= beyond3::<NARROW>(dv) & in_use;
        let mut new = [zero; 2];
        for j in 0..2 {
            let vt = sub(
                add(
                    dot::<NARROW>(dv, tangents[j]),
                    dot::<NARROW>(side_b.w, rt_b[j]),
                ),
                dot::<NARROW>(side_a.w, rt_a[j]),
            );
            bad |= out_of_bound(vt) & in_use;
            new[j] = sub(old[j], mul(tangent_mass[j], vt));
        }
        let limit = mul(friction, normal_sum);
        bad |= (out_of_bound(new[0]) | out_of_bound(new[1]) | out_of_bound(limit)) & in_use;
        if bad != 0 {
            return false;
        }
        let length_squared = add(mul(new[0], new[0]), mul(new[1], new[1]));
        let outside = _mm512_cmpgt_epi64_mask(length_squared, mul(limit, limit)) & in_use;
        if outside != 0 {
            new = clamp_to_cone(outside, new, limit, length_squared);
        }
        let applied = [
            select(in_use, sub(new[0], old[0]), zero),
            select(in_use, sub(new[1], old[1]), zero),
        ];
        bad |= (out_of_bound(applied[0]) | out_of_bound(applied[1])) & in_use;
        let along = |a: [[__m512i; 3]; 2]| {
            add3(
                times3::<NARROW>(a[0], applied[0]),
                times3::<NARROW>(a[1], applied[1]),
            )
        };
        let (dv_a, dv_b) = linear.along_tangents::<NARROW>(applied);
        Side::exchange(
            (&mut side_a, &mut side_b),
            [dv_a, along(it_a), dv_b, along(it_b)],
        );
        // The twist row reads the angular velocities only through ω_b − ω_a, checked there.
        tangent_impulses = [
            select(in_use, new[0], old[0]),
            select(in_use, new[1], old[1]),
        ];

        let in_use = in_use & twisting;
        if in_use != 0 {
            let twist_limit = mul(friction, twist_sum);
            let spin_rate = sub3(side_b.w, side_a.w);
            bad |= (out_of_bound(twist_limit) | beyond3::<NARROW>(spin_rate)) & in_use;
            let spin = dot::<NARROW>(spin_rate, normal);
            bad |= out_of_bound(spin) & in_use;
            let unclamped = sub(old_twist, mul(twist_mass, spin));
            let new_twist = _mm512_min_epi64(
                _mm512_max_epi64(unclamped, sub(zero, twist_limit)),
                twist_limit,
            );
            let applied = select(in_use, sub(new_twist, old_twist), zero);
            bad |= out_of_bound(applied) & in_use;
            // The last row: its velocities enter no product in this pass.
            Side::exchange(
                (&mut side_a, &mut side_b),
                [
                    [zero; 3],
                    times3::<NARROW>(twist_a, applied),
                    [zero; 3],
                    times3::<NARROW>(twist_b, applied),
                ],
            );
            if bad != 0 {
                return false;
            }
            twist_impulses = select(in_use, new_twist, old_twist);
        }
    }
    if bad != 0 {
        return false;
    }

    for (k, cp) in block.points.iter_mut().enumerate() {
        let in_use = points_in_use(k);
        if in_use == 0 {
            continue;
        }
        store(&mut cp.normal_impulse, normal_impulses[k]);
        store(&mut cp.max_normal_impulse, max_normal_impulses[k]);
        if RELAX {
            store_lanes(&mut cp.separation, in_use, separations[k]);
        }
    }
    let f = &mut block.friction_rows;
    store(&mut f.tangent_impulse[0], tangent_impulses[0]);
    store(&mut f.tangent_impulse[1], tangent_impulses[1]);
    store(&mut f.twist_impulse, twist_impulses);
    // SAFETY: `BodyLanes::new` checked every active lane's index.
    unsafe { lanes.store(&side_a, &side_b) };
    true
}

/// The tangent impulses of the `outside` lanes scaled back onto the cone's edge, λ ←
/// λ · (limit / |λ|), with the checked operators as in the lane-by-lane solve.
#[target_feature(enable = "avx512f,avx512dq")]
fn clamp_to_cone(
    outside: __mmask8,
    new: [__m512i; 2],
    limit: __m512i,
    length_squared: __m512i,
) -> [__m512i; 2] {
    let [mut first, mut second, mut limits, mut lengths] = [[Fx::ZERO; LANES]; 4];
    store(&mut first, new[0]);
    store(&mut second, new[1]);
    store(&mut limits, limit);
    store(&mut lengths, length_squared);
    let lanes = first
        .iter_mut()
        .zip(second.iter_mut())
        .zip(limits.iter().zip(&lengths));
    for (l, ((first, second), (&limit, &length_squared))) in lanes.enumerate() {
        if outside & (1 << l) != 0 {
            let scale = limit * length_squared.rsqrt();
            *first *= scale;
            *second *= scale;
        }
    }
    [load(&first), load(&second)]
}
