//! The products of constraint preparation for a block of I32F32 constraints as a kernel:
//! the eight lanes side by side, with the bits of
//! [`ContactBlock::prepare_products_lanes`], written once against [`Wide`] and run with
//! the backend [`backend`] picks (AVX-512 or AVX2).
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
//! products of [`Wide::mul`], gives its exact results. When a check fails in a point in use, the
//! kernel returns false and the caller recomputes every lane with the scalar form, which
//! overwrites whatever the kernel wrote.

use core::mem::{offset_of, size_of};

use super::kernel::{Kernels, counts_of, points_in_use};
use super::{ContactArms, ContactArmsOf, ContactBlock, ContactBlockOf};
use crate::math::wide::{Wide, backend, on_backend};
use crate::math::{Fx, Mat3, Real, Vec3};
use crate::rigid::solver::body::{SolverBodiesOf, SolverBody};
use crate::rigid::solver::lanes::LANES;
use crate::rigid::solver::wide_bodies::WideBodies;
use crate::rigid::solver::wide_bodies::{BODY_WORDS, V, W};

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
/// has a backend ([`backend`]); returns whether it did (if not, the caller must compute
/// them all).
pub(super) fn prepare<R: Real>(
    block: &mut ContactBlock<R>,
    arms: &ContactArms<R>,
    bodies: &[SolverBody<R>],
) -> bool {
    let (Some(block), Some(arms), Some(bodies)) = (
        R::as_fixed_mut::<ContactBlockOf>(block),
        R::as_fixed::<ContactArmsOf>(arms),
        R::as_fixed::<SolverBodiesOf>(bodies),
    ) else {
        return false;
    };
    match backend() {
        Some(backend) => on_backend!(backend, wide => wide.prepare_block(block, arms, bodies)),
        None => false,
    }
}

/// The first word of each lane's body, A's and B's, in the lanes in use; `None` if an
/// index is out of bounds.
#[inline(always)]
fn lane_words<W: WideBodies>(
    w: W,
    block: &ContactBlock<Fx>,
    body_count: usize,
) -> Option<(W::V, W::V)> {
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
    Some((w.load_words(words_a), w.load_words(words_b)))
}

/// Word `offset` of each lane's body, whose first words are `words`.
///
/// # Safety
/// `words` must be the first words of bodies of `bodies` in the lanes of `active`, and
/// `offset` a word inside a body.
#[inline(always)]
unsafe fn field<W: WideBodies>(
    w: W,
    bodies: &[SolverBody<Fx>],
    words: W::V,
    offset: i64,
    active: u8,
) -> W::V {
    // SAFETY: the caller's promise.
    unsafe {
        w.gather_words(
            bodies.as_ptr().cast(),
            w.add(words, w.splat(offset)),
            active,
        )
    }
}

/// Words `offset` to `offset + 2` of each lane's body: a vector.
///
/// # Safety
/// As for [`field`], for all three words.
#[inline(always)]
unsafe fn vector<W: WideBodies>(
    w: W,
    bodies: &[SolverBody<Fx>],
    words: W::V,
    offset: i64,
    active: u8,
) -> [W::V; 3] {
    // SAFETY: the caller's promise.
    unsafe {
        [
            field(w, bodies, words, offset, active),
            field(w, bodies, words, offset + 1, active),
            field(w, bodies, words, offset + 2, active),
        ]
    }
}

/// The inverse inertia of each lane's body, by columns.
///
/// # Safety
/// As for [`field`], with `words` the first words of the bodies.
#[inline(always)]
unsafe fn inertia<W: WideBodies>(
    w: W,
    bodies: &[SolverBody<Fx>],
    words: W::V,
    active: u8,
) -> Columns<W> {
    // SAFETY: the caller's promise; the inertia lies inside the body (checked above).
    unsafe {
        [
            vector(w, bodies, words, INV_INERTIA, active),
            vector(w, bodies, words, INV_INERTIA + 3, active),
            vector(w, bodies, words, INV_INERTIA + 6, active),
        ]
    }
}

/// The kernel. Returns false when a value leaves the checked bound in a point in use.
#[inline(always)]
pub(super) fn prepare_block<W: WideBodies>(
    w: W,
    block: &mut ContactBlock<Fx>,
    arms: &ContactArms<Fx>,
    bodies: &[SolverBody<Fx>],
) -> bool {
    let Some((words_a, words_b)) = lane_words(w, block, bodies.len()) else {
        return false;
    };
    let active = ((1u16 << block.len) - 1) as u8;
    // SAFETY: `lane_words` checked every active lane's body index, and each offset is a
    // word inside a body.
    let (inv_mass_a, inv_mass_b, inertia_a, inertia_b, v_a, v_b, w_a, w_b) = unsafe {
        (
            field(w, bodies, words_a, INV_MASS, active),
            field(w, bodies, words_b, INV_MASS, active),
            inertia(w, bodies, words_a, active),
            inertia(w, bodies, words_b, active),
            vector(w, bodies, words_a, V, active),
            vector(w, bodies, words_b, V, active),
            vector(w, bodies, words_a, W, active),
            vector(w, bodies, words_b, W, active),
        )
    };
    let normal = w.load3(&block.normal);
    let tangents = [w.load3(&block.tangents[0]), w.load3(&block.tangents[1])];
    let mut bad = w.out_of_bound(inv_mass_a)
        | w.out_of_bound(inv_mass_b)
        | out_of_bound_matrix(w, inertia_a)
        | out_of_bound_matrix(w, inertia_b)
        | w.out_of_bound3(v_a)
        | w.out_of_bound3(v_b)
        | w.out_of_bound3(w_a)
        | w.out_of_bound3(w_b)
        | w.out_of_bound3(normal)
        | w.out_of_bound3(tangents[0])
        | w.out_of_bound3(tangents[1]);
    let dv = w.sub3(v_b, v_a);
    bad |= w.out_of_bound3(dv);
    let m_sum = w.add(inv_mass_a, inv_mass_b);
    if bad & active != 0 {
        return false;
    }

    let counts = counts_of(w, block);
    for (p, cp) in block.points.iter_mut().enumerate() {
        let in_use = points_in_use(w, counts, active, p);
        if in_use == 0 {
            continue;
        }
        let r_a = w.load3(&arms.r_a[p]);
        let r_b = w.load3(&arms.r_b[p]);
        let row = Row::along(w, (r_a, r_b), normal, (inertia_a, inertia_b), m_sum);
        let (rn_a, rn_b) = row.arms;
        let mut bad = w.out_of_bound3(r_a) | w.out_of_bound3(r_b) | row.bad;
        let approach = w.add(w.rounded_dot(dv, normal), w.rounded_dot(w_b, rn_b));
        bad |= w.out_of_bound(approach);
        let approach = w.sub(approach, w.rounded_dot(w_a, rn_a));
        if bad & in_use != 0 {
            return false;
        }
        w.store_lanes3(&mut cp.rn_a, in_use, rn_a);
        w.store_lanes3(&mut cp.rn_b, in_use, rn_b);
        w.store_lanes3(&mut cp.in_a, in_use, row.turns.0);
        w.store_lanes3(&mut cp.in_b, in_use, row.turns.1);
        w.store_lanes(&mut cp.normal_mass, in_use, row.k);
        w.store_lanes(&mut cp.relative_velocity, in_use, approach);
    }

    // Friction, at the centre of each lane's points.
    let r_a = w.load3(&arms.centre_a);
    let r_b = w.load3(&arms.centre_b);
    let mut bad = w.out_of_bound3(r_a) | w.out_of_bound3(r_b);
    // Each row is stored as soon as it is computed (a failed check later leaves the block
    // to the scalar form, which overwrites it), so that no row holds registers after.
    let f = &mut block.friction_rows;
    for (j, &tangent) in tangents.iter().enumerate() {
        let row = Row::along(w, (r_a, r_b), tangent, (inertia_a, inertia_b), m_sum);
        bad |= row.bad;
        w.store_lanes3(&mut f.rt_a[j], active, row.arms.0);
        w.store_lanes3(&mut f.rt_b[j], active, row.arms.1);
        w.store_lanes3(&mut f.it_a[j], active, row.turns.0);
        w.store_lanes3(&mut f.it_b[j], active, row.turns.1);
        w.store_lanes(&mut f.tangent_mass[j], active, row.k);
    }
    let twist_a = mat_vec(w, inertia_a, normal);
    let twist_b = mat_vec(w, inertia_b, normal);
    bad |= w.out_of_bound3(twist_a) | w.out_of_bound3(twist_b);
    let k_twist = w.add(
        w.rounded_dot(twist_a, normal),
        w.rounded_dot(twist_b, normal),
    );
    if bad & active != 0 {
        return false;
    }
    w.store_lanes3(&mut f.twist_a, active, twist_a);
    w.store_lanes3(&mut f.twist_b, active, twist_b);
    w.store_lanes(&mut f.twist_mass, active, k_twist);
    w.store_lanes3(
        &mut block.normal_a,
        active,
        w.times3::<false>(normal, inv_mass_a),
    );
    w.store_lanes3(
        &mut block.normal_b,
        active,
        w.times3::<false>(normal, inv_mass_b),
    );
    for (j, tangent) in tangents.into_iter().enumerate() {
        w.store_lanes3(
            &mut block.tangents_a[j],
            active,
            w.times3::<false>(tangent, inv_mass_a),
        );
        w.store_lanes3(
            &mut block.tangents_b[j],
            active,
            w.times3::<false>(tangent, inv_mass_b),
        );
    }
    true
}

/// A 3 × 3 matrix in lanes, by columns.
type Columns<W> = [[<W as Wide>::V; 3]; 3];

/// The products of a constraint row along a unit direction d at anchors r_a and r_b (m):
/// the arms r × d (m) and I⁻¹(r × d) (1/(kg·m)) on each side, and
/// k = 1/m_a + 1/m_b + (I_a⁻¹(r_a × d))·(r_a × d) + (I_b⁻¹(r_b × d))·(r_b × d) (1/kg), each
/// product rounded as the scalar form rounds it.
struct Row<W: WideBodies> {
    arms: ([W::V; 3], [W::V; 3]),
    turns: ([W::V; 3], [W::V; 3]),
    k: W::V,
    /// The lanes where an arm or a turn leaves the checked bound (k is then not exact).
    bad: u8,
}

impl<W: WideBodies> Row<W> {
    /// The row along `direction`, with the bodies' inverse inertias (by columns) and
    /// m_sum = 1/m_a + 1/m_b.
    #[inline(always)]
    fn along(
        w: W,
        (r_a, r_b): ([W::V; 3], [W::V; 3]),
        direction: [W::V; 3],
        (inertia_a, inertia_b): (Columns<W>, Columns<W>),
        m_sum: W::V,
    ) -> Self {
        let arms = (w.cross(r_a, direction), w.cross(r_b, direction));
        let turns = (mat_vec(w, inertia_a, arms.0), mat_vec(w, inertia_b, arms.1));
        let bad = w.out_of_bound3(arms.0)
            | w.out_of_bound3(arms.1)
            | w.out_of_bound3(turns.0)
            | w.out_of_bound3(turns.1);
        let k = w.add(
            w.add(m_sum, w.rounded_dot(turns.0, arms.0)),
            w.rounded_dot(turns.1, arms.1),
        );
        Self {
            arms,
            turns,
            k,
            bad,
        }
    }
}

/// M v for M given by columns, as `Mat3 * Vec3`: row i is Σⱼ Mᵢⱼvⱼ.
#[inline(always)]
fn mat_vec<W: WideBodies>(w: W, columns: Columns<W>, v: [W::V; 3]) -> [W::V; 3] {
    let mut rows = [w.zero(); 3];
    for (i, row) in rows.iter_mut().enumerate() {
        *row = w.add(
            w.add(w.mul(columns[0][i], v[0]), w.mul(columns[1][i], v[1])),
            w.mul(columns[2][i], v[2]),
        );
    }
    rows
}

/// The lanes where an element of the matrix lies outside the checked bound.
#[inline(always)]
fn out_of_bound_matrix<W: WideBodies>(w: W, columns: Columns<W>) -> u8 {
    w.out_of_bound3(columns[0]) | w.out_of_bound3(columns[1]) | w.out_of_bound3(columns[2])
}
