//! Restitution through touching bodies: the notes' iterative resolver (Millington, "Game
//! Physics Engine Development", ch. 14), run on the bodies a bounce reaches through
//! contacts that pushed during the step.
//!
//! The substeps solve all the contacts of a step together, as one inelastic collision:
//! a ball striking a row of touching balls leaves the whole row moving at the common
//! speed, and restitution applied to the striking contact alone then splits the row in
//! two instead of passing the impulse along (measured: the last of five touching balls
//! left at 0.34 v). Real touching bodies pass an impulse on as a sequence of two-body
//! collisions, and that is what this pass computes.
//!
//! A **chain** is a set of moving bodies joined by contacts between two moving bodies that
//! pushed during the step (a point with a nonzero normal impulse), with every pushing
//! contact of those bodies, static and kinematic partners included. A chain is resolved
//! here when one of its contacts between two moving bodies bounces (restitution e > 0, an
//! approach faster than the threshold when the step began), it has at least two
//! contacts, and at most [`MAX_CHAIN_POINTS`] points; other bounces keep the one-contact
//! pass ([`ContactBlock::apply_restitution`]). For a chain:
//!
//! 1. **Undo** the normal impulse P each of its points applied over the step (the sum of
//!    the substeps' accumulated impulses): the bodies get back the velocities the step
//!    gave them without those contacts (gravity, friction and joints stay).
//! 2. **Resolve**, one point at a time: take the point with the largest closing speed
//!    c = −v_n (m/s; the first in block, lane, point order among equals) and give it the
//!    impulse that makes it separate at u,
//!
//!    ```text
//!    λ = m_n (u + c) ≥ 0      (N·s),   u = e·c if c > threshold, else 0      (m/s)
//!    ```
//!
//!    with m_n the point's effective mass; stop when no point closes faster than
//!    [`resolved_speed`] (2⁻¹⁶ m/s), or after 4 resolutions per point. A closing that
//!    remains is the next step's contact solver's.
//!
//! Each resolution changes the kinetic energy by ½ λ (v_n before + v_n after) =
//! ½ λ (u − c) ≤ 0, so the pass never adds energy; with e = 1 each is an elastic
//! two-body collision. Slow closings (below the threshold) are resolved without bounce, so
//! resting contacts stay quiet, and a chain with no bounce is never touched, so stacks
//! solve as before. The points' stored impulses (the next step's warm start) are zeroed
//! where the pass leaves them separating.

use super::super::body::{SolverBody, pair};
use super::super::bounce::BouncePass;
use super::ContactBlock;
use crate::math::Real;

/// The most points a chain may have for this pass to resolve it (its cost grows as the
/// square of the points: each resolution looks for the fastest closing among them).
pub(crate) const MAX_CHAIN_POINTS: usize = 128;

/// Closing speeds at or below this are resolved, m/s (2⁻¹⁶).
fn resolved_speed<R: Real>() -> R {
    R::from_ratio(1, 1 << 16)
}

/// One point of a chain: where it is stored, the bodies it joins, and its closing speed.
#[derive(Clone, Copy, Debug)]
struct ChainPoint<R: Real> {
    /// The chain it belongs to (the smallest solver index of its moving bodies), then its
    /// place in block, lane, point order: the sort key that groups the chains.
    chain: u32,
    order: u32,
    block: u32,
    lane: u8,
    point: u8,
    a: u32,
    b: u32,
    /// c = −v_n, m/s.
    closing: R,
}

/// The chain pass's buffers, reused from step to step (no state between steps).
#[derive(Clone, Debug, Default)]
pub(crate) struct BounceChains<R: Real> {
    /// Union–find parents over solver bodies (each chain's root is its smallest index).
    parent: Vec<u32>,
    /// Per chain root: its pushing lanes, its pushing points, whether a contact between
    /// two moving bodies bounces.
    lanes: Vec<u32>,
    points: Vec<u32>,
    bounces: Vec<bool>,
    chain_points: Vec<ChainPoint<R>>,
}

fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let up = parent[parent[x as usize] as usize];
        parent[x as usize] = up;
        x = up;
    }
    x
}

impl<R: Real> BounceChains<R> {
    /// Resolves the chains of this step's `blocks` that a bounce reaches (see the module
    /// documentation), marking their lanes chained for
    /// [`ContactBlock::apply_restitution`].
    pub fn resolve(
        &mut self,
        blocks: &mut [ContactBlock<R>],
        bodies: &mut [SolverBody<R>],
        pass: &BouncePass<R>,
    ) {
        let n = bodies.len();
        let moving = |bodies: &[SolverBody<R>], i: u32| bodies[i as usize].inv_mass > R::ZERO;
        self.parent.clear();
        self.parent.extend(0..n as u32);
        for block in blocks.iter() {
            for l in 0..block.len {
                let (a, b) = (block.a[l], block.b[l]);
                if block.pushed(l) && moving(bodies, a) && moving(bodies, b) {
                    let (ra, rb) = (find(&mut self.parent, a), find(&mut self.parent, b));
                    let (low, high) = (ra.min(rb), ra.max(rb));
                    self.parent[high as usize] = low;
                }
            }
        }
        self.lanes.clear();
        self.lanes.resize(n, 0);
        self.points.clear();
        self.points.resize(n, 0);
        self.bounces.clear();
        self.bounces.resize(n, false);
        for block in blocks.iter() {
            for l in 0..block.len {
                if !block.pushed(l) {
                    continue;
                }
                let (a, b) = (block.a[l], block.b[l]);
                let root = find(&mut self.parent, if moving(bodies, a) { a } else { b }) as usize;
                self.lanes[root] += 1;
                self.points[root] += block.pushed_points(l) as u32;
                if moving(bodies, a) && moving(bodies, b) && block.bounces(l, pass.threshold) {
                    self.bounces[root] = true;
                }
            }
        }
        let resolved = |chains: &Self, root: usize| {
            chains.bounces[root]
                && chains.lanes[root] >= 2
                && chains.points[root] as usize <= MAX_CHAIN_POINTS
        };
        if !(0..n).any(|root| resolved(self, root)) {
            return;
        }
        self.chain_points.clear();
        let mut order = 0u32;
        for (bi, block) in blocks.iter_mut().enumerate() {
            for l in 0..block.len {
                if !block.pushed(l) {
                    continue;
                }
                let (a, b) = (block.a[l], block.b[l]);
                let root = find(&mut self.parent, if moving(bodies, a) { a } else { b });
                if !resolved(self, root as usize) {
                    continue;
                }
                block.chained[l] = true;
                for p in 0..usize::from(block.count[l]) {
                    if block.points[p].max_normal_impulse[l] == R::ZERO {
                        continue;
                    }
                    self.chain_points.push(ChainPoint {
                        chain: root,
                        order,
                        block: bi as u32,
                        lane: l as u8,
                        point: p as u8,
                        a,
                        b,
                        closing: R::ZERO,
                    });
                    order += 1;
                }
            }
        }
        self.chain_points
            .sort_unstable_by_key(|cp| (cp.chain, cp.order));
        let mut start = 0;
        while start < self.chain_points.len() {
            let chain = self.chain_points[start].chain;
            let end = start
                + self.chain_points[start..]
                    .iter()
                    .take_while(|cp| cp.chain == chain)
                    .count();
            resolve_chain(&mut self.chain_points[start..end], blocks, bodies, pass);
            start = end;
        }
    }
}

/// Undoes the step's normal impulses of one chain's points and resolves them one at a
/// time, the fastest closing first (the module documentation's steps 1 and 2).
fn resolve_chain<R: Real>(
    points: &mut [ChainPoint<R>],
    blocks: &mut [ContactBlock<R>],
    bodies: &mut [SolverBody<R>],
    pass: &BouncePass<R>,
) {
    for cp in points.iter() {
        let block = &blocks[cp.block as usize];
        let undo = -block.points[usize::from(cp.point)].step_impulse[usize::from(cp.lane)];
        block.push_point(bodies, cp.lane.into(), cp.point.into(), undo);
    }
    for cp in points.iter_mut() {
        cp.closing =
            -blocks[cp.block as usize].normal_speed(bodies, cp.lane.into(), cp.point.into());
    }
    let settled = resolved_speed::<R>();
    for _ in 0..4 * points.len() {
        let mut fastest = 0;
        for (k, cp) in points.iter().enumerate() {
            if cp.closing > points[fastest].closing {
                fastest = k;
            }
        }
        let cp = points[fastest];
        if cp.closing <= settled {
            break;
        }
        let block = &blocks[cp.block as usize];
        let (l, p) = (usize::from(cp.lane), usize::from(cp.point));
        let restitution = block.restitution[l];
        let leaving = if cp.closing > pass.threshold {
            restitution * cp.closing
        } else {
            R::ZERO
        };
        let impulse = block.points[p].normal_mass[l] * (leaving + cp.closing);
        block.push_point(bodies, l, p, impulse);
        let touched = |i: u32| i == cp.a || i == cp.b;
        for other in points.iter_mut() {
            let shares = (touched(other.a) && bodies[other.a as usize].inv_mass > R::ZERO)
                || (touched(other.b) && bodies[other.b as usize].inv_mass > R::ZERO);
            if shares {
                other.closing = -blocks[other.block as usize].normal_speed(
                    bodies,
                    other.lane.into(),
                    other.point.into(),
                );
            }
        }
    }
    for cp in points.iter() {
        if cp.closing < -settled {
            blocks[cp.block as usize].points[usize::from(cp.point)].normal_impulse
                [usize::from(cp.lane)] = R::ZERO;
        }
    }
}

impl<R: Real> ContactBlock<R> {
    /// Whether a point of lane `l` pushed during the step.
    fn pushed(&self, l: usize) -> bool {
        self.pushed_points(l) > 0
    }

    /// How many points of lane `l` pushed during the step.
    fn pushed_points(&self, l: usize) -> usize {
        self.points[..usize::from(self.count[l])]
            .iter()
            .filter(|cp| cp.max_normal_impulse[l] > R::ZERO)
            .count()
    }

    /// Whether a point of lane `l` bounces: restitution, a push, and an approach faster
    /// than `threshold` (m/s) when the step began.
    fn bounces(&self, l: usize, threshold: R) -> bool {
        self.restitution[l] > R::ZERO
            && self.points[..usize::from(self.count[l])].iter().any(|cp| {
                cp.max_normal_impulse[l] > R::ZERO && cp.relative_velocity[l] < -threshold
            })
    }

    /// The normal velocity of point `p` of lane `l`, m/s:
    /// v_n = (v_b − v_a)·n + ω_b·(r_b × n) − ω_a·(r_a × n).
    fn normal_speed(&self, bodies: &[SolverBody<R>], l: usize, p: usize) -> R {
        let (ba, bb) = (&bodies[self.a[l] as usize], &bodies[self.b[l] as usize]);
        let cp = &self.points[p];
        (bb.v - ba.v).dot_fused(self.normal.get(l)) + bb.w.dot_fused(cp.rn_b.get(l))
            - ba.w.dot_fused(cp.rn_a.get(l))
    }

    /// Applies the normal impulse `impulse` (N·s) at point `p` of lane `l`:
    /// v_a −= λ n/m_a, ω_a −= λ I_a⁻¹(r_a × n), and the opposite on B.
    fn push_point(&self, bodies: &mut [SolverBody<R>], l: usize, p: usize, impulse: R) {
        let (ba, bb) = pair(bodies, self.a[l], self.b[l]);
        let cp = &self.points[p];
        ba.v -= self.normal_a.get(l) * impulse;
        ba.w -= cp.in_a.get(l) * impulse;
        bb.v += self.normal_b.get(l) * impulse;
        bb.w += cp.in_b.get(l) * impulse;
    }
}
