//! The products of constraint preparation for a block of I32F32 constraints in AVX-512:
//! the eight lanes side by side, with the bits of
//! [`ContactBlock::prepare_products_lanes`].
//!
//! Preparation only reads the bodies, so any block may take it, independent or not.
//!
//! # Exactness
//!
//! The scalar form rounds every product on its own (the checked `*`: to nearest, ties
//! toward +∞) and adds with saturation: r × n component by component, I⁻¹v as
//! Σⱼ Mᵢⱼvⱼ, a·b as Σ aᵢbᵢ. Every value the kernel loads (anchors of the points and of the
//! friction centre, normal, tangents, the bodies' inverse masses, inverse inertias,
//! velocities) and every value that enters a product (r × n, r × t, I⁻¹(r × n),
//! I⁻¹(r × t), I⁻¹n, v_b − v_a) is checked to lie in
//! [−2⁴⁶, 2⁴⁶) as raw bits. Then each rounded product is below 2⁶⁰ in magnitude, a sum of
//! three below 2⁶², k = 1/m_a + 1/m_b + two such sums below 2⁶³ (k_twist is two such
//! sums), and the approach velocity,
//! whose first two sums are checked against 2⁴⁶ before the third is subtracted, too. So the
//! scalar form saturates nowhere, and the kernel's wrapping `i64` arithmetic, with the
//! products of [`mul`], gives its exact results. When a check fails in a point in use, the
//! kernel returns false and the caller recomputes every lane with the scalar form, which
//! overwrites whatever the kernel wrote.

use core::arch::x86_64::{
    __m512i, __mmask8, _mm512_cmpgt_epi64_mask, _mm512_loadu_si512, _mm512_mask_i64gather_epi64,
    _mm512_set1_epi64, _mm512_setzero_si512,
};
use core::mem::{offset_of, size_of};

use super::{
    BODY_WORDS, V, W, add, fx_operands, lane_words, load3, mul, mul3, out_of_bound, out_of_bound3,
    store_lanes, sub, sub3,
};
use crate::math::{Fx, Mat3, Real, Vec3};
use crate::rigid::solver::body::SolverBody;
use crate::rigid::solver::contact_constraint::{ContactArms, ContactBlock};
use crate::rigid::solver::lanes::Lanes3;

/// Word offsets of the inverse mass and of the inverse inertia's first column in a
/// `SolverBody<Fx>`; element (i, j) of the inertia is word `INV_INERTIA + 3j + i`.
const INV_MASS: i64 = (offset_of!(SolverBody<Fx>, inv_mass) / 8) as i64;
const INV_INERTIA: i64 = (offset_of!(SolverBody<Fx>, inv_inertia) / 8) as i64;

// The layout the gathers rely on: a `Mat3<Fx>` is its three columns in a row.
const _: () = {
    assert!(offset_of!(Mat3<Fx>, cols) == 0);
    assert!(size_of::<Mat3<Fx>>() == 3 * size_of::<Vec3<Fx>>());
    assert!(INV_INERTIA + 9 <= BODY_WORDS);
};

/// Computes the products of `block` with the kernel when `R` is I32F32 and the processor
/// has AVX-512F and DQ; returns whether it did (if not, the caller must compute them all).
pub(in crate::rigid::solver::contact_constraint) fn prepare<R: Real>(
    block: &mut ContactBlock<R>,
    arms: &ContactArms<R>,
    bodies: &[SolverBody<R>],
) -> bool {
    let Some((block, arms)) = fx_operands(block, arms) else {
        return false;
    };
    // SAFETY: `R` is `Fx` (the downcasts succeeded), so the slice's type is unchanged.
    let bodies = unsafe { &*(core::ptr::from_ref(bodies) as *const [SolverBody<Fx>]) };
    // SAFETY: `fx_operands` detected AVX-512F and DQ on this processor.
    unsafe { prepare_block(block, arms, bodies) }
}

/// The kernel. Returns false when a value leaves the checked bound in a point in use.
///
/// # Safety
/// The processor must have AVX-512F and AVX-512DQ.
#[target_feature(enable = "avx512f,avx512dq")]
unsafe fn prepare_block(
    block: &mut ContactBlock<Fx>,
    arms: &ContactArms<Fx>,
    bodies: &[SolverBody<Fx>],
) -> bool {
    let Some((active, words_a, words_b)) = lane_words(block, bodies.len()) else {
        return false;
    };
    let base = bodies.as_ptr().cast::<i64>();
    let zero = _mm512_setzero_si512();
    let field = |words: __m512i, offset: i64| {
        let at = add(words, _mm512_set1_epi64(offset));
        // SAFETY: `lane_words` checked every active lane's body index, and each offset is
        // a word inside a body.
        unsafe { _mm512_mask_i64gather_epi64::<8>(zero, active, at, base) }
    };
    let vector = |words: __m512i, offset: i64| {
        [
            field(words, offset),
            field(words, offset + 1),
            field(words, offset + 2),
        ]
    };
    let inertia = |words: __m512i| {
        [
            vector(words, INV_INERTIA),
            vector(words, INV_INERTIA + 3),
            vector(words, INV_INERTIA + 6),
        ]
    };
    let (inv_mass_a, inv_mass_b) = (field(words_a, INV_MASS), field(words_b, INV_MASS));
    let (inertia_a, inertia_b) = (inertia(words_a), inertia(words_b));
    let (v_a, v_b) = (vector(words_a, V), vector(words_b, V));
    let (w_a, w_b) = (vector(words_a, W), vector(words_b, W));
    let normal = load3(&block.normal);
    let tangents = [load3(&block.tangents[0]), load3(&block.tangents[1])];
    let mut bad = out_of_bound(inv_mass_a)
        | out_of_bound(inv_mass_b)
        | out_of_bound_matrix(inertia_a)
        | out_of_bound_matrix(inertia_b)
        | out_of_bound3(v_a)
        | out_of_bound3(v_b)
        | out_of_bound3(w_a)
        | out_of_bound3(w_b)
        | out_of_bound3(normal)
        | out_of_bound3(tangents[0])
        | out_of_bound3(tangents[1]);
    let dv = sub3(v_b, v_a);
    bad |= out_of_bound3(dv);
    let m_sum = add(inv_mass_a, inv_mass_b);
    if bad & active != 0 {
        return false;
    }

    // SAFETY: 64 readable bytes.
    let counts = unsafe { _mm512_loadu_si512(block.count.map(i64::from).as_ptr().cast()) };
    for (p, cp) in block.points.iter_mut().enumerate() {
        let in_use = _mm512_cmpgt_epi64_mask(counts, _mm512_set1_epi64(p as i64)) & active;
        if in_use == 0 {
            continue;
        }
        let r_a = load3(&arms.r_a[p]);
        let r_b = load3(&arms.r_b[p]);
        let rn_a = cross(r_a, normal);
        let rn_b = cross(r_b, normal);
        let in_a = mat_vec(inertia_a, rn_a);
        let in_b = mat_vec(inertia_b, rn_b);
        let mut bad = out_of_bound3(r_a)
            | out_of_bound3(r_b)
            | out_of_bound3(rn_a)
            | out_of_bound3(rn_b)
            | out_of_bound3(in_a)
            | out_of_bound3(in_b);
        let k = add(add(m_sum, dot(in_a, rn_a)), dot(in_b, rn_b));
        let approach = add(dot(dv, normal), dot(w_b, rn_b));
        bad |= out_of_bound(approach);
        let approach = sub(approach, dot(w_a, rn_a));
        if bad & in_use != 0 {
            return false;
        }
        store3(&mut cp.rn_a, in_use, rn_a);
        store3(&mut cp.rn_b, in_use, rn_b);
        store3(&mut cp.in_a, in_use, in_a);
        store3(&mut cp.in_b, in_use, in_b);
        store_lanes(&mut cp.normal_mass, in_use, k);
        store_lanes(&mut cp.relative_velocity, in_use, approach);
    }

    // Friction, at the centre of each lane's points.
    let r_a = load3(&arms.centre_a);
    let r_b = load3(&arms.centre_b);
    let mut bad = out_of_bound3(r_a) | out_of_bound3(r_b);
    let mut rt_a = [[zero; 3]; 2];
    let mut rt_b = [[zero; 3]; 2];
    let mut it_a = [[zero; 3]; 2];
    let mut it_b = [[zero; 3]; 2];
    let mut kt = [zero; 2];
    for j in 0..2 {
        rt_a[j] = cross(r_a, tangents[j]);
        rt_b[j] = cross(r_b, tangents[j]);
        it_a[j] = mat_vec(inertia_a, rt_a[j]);
        it_b[j] = mat_vec(inertia_b, rt_b[j]);
        bad |= out_of_bound3(rt_a[j])
            | out_of_bound3(rt_b[j])
            | out_of_bound3(it_a[j])
            | out_of_bound3(it_b[j]);
        kt[j] = add(add(m_sum, dot(it_a[j], rt_a[j])), dot(it_b[j], rt_b[j]));
    }
    let twist_a = mat_vec(inertia_a, normal);
    let twist_b = mat_vec(inertia_b, normal);
    bad |= out_of_bound3(twist_a) | out_of_bound3(twist_b);
    let k_twist = add(dot(twist_a, normal), dot(twist_b, normal));
    if bad & active != 0 {
        return false;
    }
    let f = &mut block.friction_rows;
    for j in 0..2 {
        store3(&mut f.rt_a[j], active, rt_a[j]);
        store3(&mut f.rt_b[j], active, rt_b[j]);
        store3(&mut f.it_a[j], active, it_a[j]);
        store3(&mut f.it_b[j], active, it_b[j]);
        store_lanes(&mut f.tangent_mass[j], active, kt[j]);
    }
    store3(&mut f.twist_a, active, twist_a);
    store3(&mut f.twist_b, active, twist_b);
    store_lanes(&mut f.twist_mass, active, k_twist);
    store3(&mut block.normal_a, active, mul3(normal, inv_mass_a));
    store3(&mut block.normal_b, active, mul3(normal, inv_mass_b));
    for (j, tangent) in tangents.into_iter().enumerate() {
        store3(&mut block.tangents_a[j], active, mul3(tangent, inv_mass_a));
        store3(&mut block.tangents_b[j], active, mul3(tangent, inv_mass_b));
    }
    true
}

/// a × b with each product rounded on its own, as [`Vec3::cross`].
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
pub(super) fn cross(a: [__m512i; 3], b: [__m512i; 3]) -> [__m512i; 3] {
    [
        sub(mul(a[1], b[2]), mul(a[2], b[1])),
        sub(mul(a[2], b[0]), mul(a[0], b[2])),
        sub(mul(a[0], b[1]), mul(a[1], b[0])),
    ]
}

/// a·b with each product rounded on its own, as [`Vec3::dot`].
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
pub(super) fn dot(a: [__m512i; 3], b: [__m512i; 3]) -> __m512i {
    add(add(mul(a[0], b[0]), mul(a[1], b[1])), mul(a[2], b[2]))
}

/// M v for M given by columns, as `Mat3 * Vec3`: row i is Σⱼ Mᵢⱼvⱼ.
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn mat_vec(columns: [[__m512i; 3]; 3], v: [__m512i; 3]) -> [__m512i; 3] {
    let row = |i: usize| {
        add(
            add(mul(columns[0][i], v[0]), mul(columns[1][i], v[1])),
            mul(columns[2][i], v[2]),
        )
    };
    [row(0), row(1), row(2)]
}

/// The lanes where an element of the matrix lies outside the checked bound.
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn out_of_bound_matrix(columns: [[__m512i; 3]; 3]) -> __mmask8 {
    out_of_bound3(columns[0]) | out_of_bound3(columns[1]) | out_of_bound3(columns[2])
}

#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
pub(super) fn store3(lanes: &mut Lanes3<Fx>, mask: __mmask8, value: [__m512i; 3]) {
    store_lanes(&mut lanes.x, mask, value[0]);
    store_lanes(&mut lanes.y, mask, value[1]);
    store_lanes(&mut lanes.z, mask, value[2]);
}
