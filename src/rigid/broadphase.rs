//! Sort-and-sweep broadphase: which pairs of bounding boxes overlap.
//!
//! [`BroadPhase::find_pairs`] takes every body's box and two flags (present, awake) and
//! returns the overlapping pairs with at least one awake member, in ascending order. The
//! answer is a pure function of the input; what the broadphase keeps between calls (the
//! sort orders of the previous call) only makes the next call cheaper.
//!
//! # How it works
//!
//! Boxes are sorted by their lower bound along one sweep axis, ties broken by index, so the
//! order is total and the same on every machine. Awake boxes and resting boxes (present but
//! not awake: static or sleeping) are kept in two separate sorted lists:
//!
//! - awake × awake: the classic sweep. For each awake box, the boxes after it in the list
//!   whose lower bound is within its upper bound are tested on all three axes.
//! - awake × resting: for each awake box, a binary search finds its place in the resting
//!   list. The resting boxes after that place are walked forward while their lower bound is
//!   within reach; the ones before it are walked backward, in blocks of [`BLOCK`], while
//!   the running maximum of their upper bounds (and the block's own maximum) still reaches
//!   the awake box. So a long resting box (a ground slab) does not make every query walk
//!   the whole list.
//!
//! The resting list is re-sorted only when its membership or one of its boxes changes,
//! which is checked bit for bit each call. Both lists are re-sorted by insertion sort
//! starting from the previous order, which is nearly sorted between frames; when many
//! boxes join at once, or the insertion sort has moved too much, a full sort takes over.
//! Either way the result is the unique order of the total keys.
//!
//! A resting world therefore costs the awake boxes' own sweep and queries, plus one pass
//! over the flags and one bitwise comparison of the resting boxes.

use core::cmp::Ordering;
use core::ops::Range;

use super::aabb::Aabb;
use crate::math::{Fx, Real};

/// Boxes per block of the resting list; the backward walk skips a block whose boxes all end
/// before the query box starts.
const BLOCK: usize = 32;

/// Membership of a box index: in neither list (absent, or beyond the input).
const OUT: u8 = 0;
/// Membership of a box index: in the awake list.
const AWAKE: u8 = 1;
/// Membership of a box index: in the resting list.
const RESTING: u8 = 2;

/// A sort key: the box's lower bound along the sweep axis, then its index.
type Key<R> = (R, u32);

/// The total order of keys: lower bound by [`Real::total_cmp`], then index.
#[inline(always)]
fn key_cmp<R: Real>(a: &Key<R>, b: &Key<R>) -> Ordering {
    a.0.total_cmp(&b.0).then(a.1.cmp(&b.1))
}

/// True when key `a` comes strictly before key `b`.
#[inline(always)]
fn key_less<R: Real>(a: &Key<R>, b: &Key<R>) -> bool {
    key_cmp(a, b) == Ordering::Less
}

/// Sorts `keys` in the total key order, assuming that all but the last `fresh` entries
/// are nearly sorted already. Insertion sort, unless `fresh` is a large share of the list or
/// the insertion sort has moved more than a few times the list's length; then a full sort.
/// Keys are unique (indices differ), so the result does not depend on the method.
fn sort_keys<R: Real>(keys: &mut [Key<R>], fresh: usize) {
    let n = keys.len();
    if fresh > n / 4 + 8 {
        keys.sort_unstable_by(key_cmp);
        return;
    }
    let budget = 8 * n + 64;
    let mut moves = 0;
    for i in 1..n {
        let x = keys[i];
        if !key_less(&x, &keys[i - 1]) {
            continue;
        }
        let mut j = i;
        while j > 0 && key_less(&x, &keys[j - 1]) {
            keys[j] = keys[j - 1];
            j -= 1;
        }
        keys[j] = x;
        moves += i - j;
        if moves > budget {
            keys.sort_unstable_by(key_cmp);
            return;
        }
    }
}

/// The three axes in lane order: the sweep axis first, then the two others.
#[inline(always)]
fn lanes(axis: usize) -> [usize; 3] {
    [axis, (axis + 1) % 3, (axis + 2) % 3]
}

/// A box being tested against a list: its bounds in lane order and its index.
#[derive(Clone, Copy, Debug)]
struct Probe<R: Real> {
    /// Lower bounds, sweep axis first.
    lo: [R; 3],
    /// Upper bounds, sweep axis first.
    hi: [R; 3],
    /// Index of the box in the input.
    index: u32,
}

/// A sorted list of boxes: the keys (the order) and the boxes in that order, one array per
/// bound so that the inner loops read memory in sequence.
#[derive(Clone, Debug, Default)]
struct SortedList<R: Real> {
    /// Sort keys, in order.
    keys: Vec<Key<R>>,
    /// Index of each box, in order.
    index: Vec<u32>,
    /// Lower bounds per lane (sweep axis first), in order.
    lo: [Vec<R>; 3],
    /// Upper bounds per lane, in order.
    hi: [Vec<R>; 3],
}

impl<R: Real> SortedList<R> {
    /// Number of boxes in the list.
    #[inline]
    fn len(&self) -> usize {
        self.index.len()
    }

    /// Brings the list up to date: keeps the entries whose index still has membership
    /// `tag` in `state`, refreshes their keys from `boxes`, appends `added`, re-sorts from
    /// the previous order and copies the boxes out in the new order.
    fn refresh(&mut self, boxes: &[Aabb<R>], state: &[u8], tag: u8, added: &[u32], axis: usize) {
        let n = boxes.len();
        self.keys.retain_mut(|key| {
            let i = key.1 as usize;
            let keep = i < n && state[i] == tag;
            if keep {
                key.0 = boxes[i].min[axis];
            }
            keep
        });
        self.keys
            .extend(added.iter().map(|&i| (boxes[i as usize].min[axis], i)));
        sort_keys(&mut self.keys, added.len());
        self.gather(boxes, axis);
    }

    /// Copies the boxes into the per-bound arrays in key order.
    fn gather(&mut self, boxes: &[Aabb<R>], axis: usize) {
        let lane = lanes(axis);
        self.index.clear();
        for v in self.lo.iter_mut().chain(self.hi.iter_mut()) {
            v.clear();
        }
        for &(_, i) in &self.keys {
            let b = &boxes[i as usize];
            self.index.push(i);
            for (l, &a) in lane.iter().enumerate() {
                self.lo[l].push(b.min[a]);
                self.hi[l].push(b.max[a]);
            }
        }
    }

    /// True when every box of the list is bit for bit the box at its index in `boxes`
    /// (every index is assumed to be in range).
    fn unchanged(&self, boxes: &[Aabb<R>], axis: usize) -> bool {
        let lane = lanes(axis);
        let same = |x: R, y: R| x.canonical_bits() == y.canonical_bits();
        (0..self.len()).all(|k| {
            let b = &boxes[self.index[k] as usize];
            lane.iter()
                .enumerate()
                .all(|(l, &a)| same(self.lo[l][k], b.min[a]) && same(self.hi[l][k], b.max[a]))
        })
    }

    /// The box at position `k` as a probe.
    #[inline(always)]
    fn probe(&self, k: usize) -> Probe<R> {
        Probe {
            lo: [self.lo[0][k], self.lo[1][k], self.lo[2][k]],
            hi: [self.hi[0][k], self.hi[1][k], self.hi[2][k]],
            index: self.index[k],
        }
    }

    /// The end of the forward window from position `start`: the first position at or after
    /// it whose lower bound along the sweep axis is beyond `reach`.
    #[inline(always)]
    fn window_end(&self, start: usize, reach: R) -> usize {
        start
            + self.lo[0][start..]
                .iter()
                .take_while(|&&lo| lo <= reach)
                .count()
    }

    /// Tests the probe against the boxes at positions `range` with the full overlap test
    /// ([`Aabb::overlaps`]) and pushes each overlapping pair as (smaller, larger index).
    #[inline(always)]
    fn scan(&self, range: Range<usize>, q: &Probe<R>, out: &mut Vec<(u32, u32)>) {
        let index = &self.index[range.clone()];
        let m = index.len();
        let lo0 = &self.lo[0][range.clone()][..m];
        let hi0 = &self.hi[0][range.clone()][..m];
        let lo1 = &self.lo[1][range.clone()][..m];
        let hi1 = &self.hi[1][range.clone()][..m];
        let lo2 = &self.lo[2][range.clone()][..m];
        let hi2 = &self.hi[2][range][..m];
        for k in 0..m {
            let hit = (lo0[k] <= q.hi[0])
                & (q.lo[0] <= hi0[k])
                & (lo1[k] <= q.hi[1])
                & (q.lo[1] <= hi1[k])
                & (lo2[k] <= q.hi[2])
                & (q.lo[2] <= hi2[k]);
            if hit {
                let other = index[k];
                out.push(if q.index < other {
                    (q.index, other)
                } else {
                    (other, q.index)
                });
            }
        }
    }
}

/// Sort-and-sweep broadphase. Its internal state (the remembered sort orders) is a cache:
/// the pairs it returns depend only on the boxes and flags passed in, never on history, so
/// snapshots, restores and different peers get identical pairs.
#[derive(Clone, Debug)]
pub struct BroadPhase<R: Real = Fx> {
    /// Sweep axis (0 = x) of the lists.
    axis: usize,
    /// Membership of each box index ([`OUT`], [`AWAKE`] or [`RESTING`]) as of the last call.
    state: Vec<u8>,
    /// Awake boxes.
    awake: SortedList<R>,
    /// Resting boxes (present, not awake).
    resting: SortedList<R>,
    /// Running maximum of the resting boxes' upper bounds along the sweep axis.
    resting_prefix_hi: Vec<R>,
    /// Maximum of the resting boxes' upper bounds along the sweep axis, per [`BLOCK`].
    resting_block_hi: Vec<R>,
    /// Scratch: indices that joined the awake list this call.
    awake_added: Vec<u32>,
    /// Scratch: indices that joined the resting list this call.
    resting_added: Vec<u32>,
}

impl<R: Real> Default for BroadPhase<R> {
    /// An empty broadphase; see [`BroadPhase::new`].
    fn default() -> Self {
        Self::new()
    }
}

impl<R: Real> BroadPhase<R> {
    /// An empty broadphase with nothing cached.
    pub fn new() -> Self {
        Self {
            axis: 0,
            state: Vec::new(),
            awake: SortedList::default(),
            resting: SortedList::default(),
            resting_prefix_hi: Vec::new(),
            resting_block_hi: Vec::new(),
            awake_added: Vec::new(),
            resting_added: Vec::new(),
        }
    }

    /// Every pair `(a, b)`, `a < b` (indices into `boxes`), whose boxes overlap
    /// ([`Aabb::overlaps`], touching included) and where at least one of the two is
    /// `active[i]` (awake); pairs of two inactive boxes (static or sleeping) are never
    /// reported. Boxes with `present[i] == false` (empty slots, planes) are skipped.
    /// `out` is cleared and filled in ascending `(a, b)` order, without duplicates.
    ///
    /// The result depends only on the arguments, not on earlier calls.
    ///
    /// # Panics
    ///
    /// If `active` or `present` is not as long as `boxes`, or there are more than
    /// `u32::MAX` boxes.
    pub fn find_pairs(
        &mut self,
        boxes: &[Aabb<R>],
        active: &[bool],
        present: &[bool],
        out: &mut Vec<(u32, u32)>,
    ) {
        let n = boxes.len();
        assert_eq!(active.len(), n, "find_pairs: one active flag per box");
        assert_eq!(present.len(), n, "find_pairs: one present flag per box");
        assert!(u32::try_from(n).is_ok(), "find_pairs: too many boxes");
        out.clear();

        let mut resting_dirty = self.update_membership(active, present);

        let axis = self.axis;
        if !resting_dirty {
            resting_dirty = !self.resting.unchanged(boxes, axis);
        }
        if resting_dirty {
            self.resting
                .refresh(boxes, &self.state, RESTING, &self.resting_added, axis);
            self.build_resting_maxima();
        }
        self.awake
            .refresh(boxes, &self.state, AWAKE, &self.awake_added, axis);

        self.sweep(out);
        out.sort_unstable();
        debug_assert!(out.windows(2).all(|w| w[0] < w[1]));
    }

    /// Compares the wanted membership of every index (from the flags) with the remembered
    /// one and records the changes: indices joining a list go to the `*_added` scratch
    /// lists, and the state is updated (the lists drop their leavers themselves, in
    /// [`SortedList::refresh`]). Returns whether the resting list's membership changed.
    fn update_membership(&mut self, active: &[bool], present: &[bool]) -> bool {
        let n = active.len();
        let mut resting_changed = false;
        if self.state.len() > n {
            resting_changed |= self.state[n..].contains(&RESTING);
            self.state.truncate(n);
        }
        self.state.resize(n, OUT);
        self.awake_added.clear();
        self.resting_added.clear();

        // 1 when present and awake, 2 when present and resting, 0 when absent.
        let want = |a: bool, p: bool| u8::from(p) * (1 + u8::from(!a));
        const CHUNK: usize = 64;
        let chunks = self
            .state
            .chunks_mut(CHUNK)
            .zip(active.chunks(CHUNK))
            .zip(present.chunks(CHUNK));
        for (c, ((state, active), present)) in chunks.enumerate() {
            let differs = state
                .iter()
                .zip(active)
                .zip(present)
                .fold(false, |d, ((&s, &a), &p)| d | (s != want(a, p)));
            if !differs {
                continue;
            }
            for (k, ((s, &a), &p)) in state.iter_mut().zip(active).zip(present).enumerate() {
                let w = want(a, p);
                if *s == w {
                    continue;
                }
                resting_changed |= *s == RESTING || w == RESTING;
                let i = (c * CHUNK + k) as u32;
                match w {
                    AWAKE => self.awake_added.push(i),
                    RESTING => self.resting_added.push(i),
                    _ => {}
                }
                *s = w;
            }
        }
        resting_changed
    }

    /// Rebuilds the running and per-block maxima of the resting list's upper bounds along
    /// the sweep axis.
    fn build_resting_maxima(&mut self) {
        let hi = &self.resting.hi[0];
        self.resting_prefix_hi.clear();
        self.resting_block_hi.clear();
        let mut running: Option<R> = None;
        for &h in hi {
            let m = running.map_or(h, |r| r.max(h));
            running = Some(m);
            self.resting_prefix_hi.push(m);
        }
        for block in hi.chunks(BLOCK) {
            let m = block.iter().skip(1).fold(block[0], |m, &h| m.max(h));
            self.resting_block_hi.push(m);
        }
    }

    /// Finds the pairs awake × awake and awake × resting, unordered, into `out`.
    fn sweep(&self, out: &mut Vec<(u32, u32)>) {
        let awake = &self.awake;
        let resting = &self.resting;
        let mut place = 0;
        for i in 0..awake.len() {
            let q = awake.probe(i);
            let end = awake.window_end(i + 1, q.hi[0]);
            awake.scan(i + 1..end, &q, out);
            if resting.len() > 0 {
                let key = (q.lo[0], q.index);
                place += resting.keys[place..].partition_point(|k| key_less(k, &key));
                self.probe_resting(&q, place, out);
            }
        }
    }

    /// Tests an awake box against the resting list, where `place` is its position in the
    /// resting list's key order: forward while the resting boxes start within its reach,
    /// backward while some earlier resting box still reaches its lower bound.
    fn probe_resting(&self, q: &Probe<R>, place: usize, out: &mut Vec<(u32, u32)>) {
        let resting = &self.resting;
        let end = resting.window_end(place, q.hi[0]);
        resting.scan(place..end, q, out);
        let mut k = place;
        while k > 0 && self.resting_prefix_hi[k - 1] >= q.lo[0] {
            let start = (k - 1) / BLOCK * BLOCK;
            if self.resting_block_hi[start / BLOCK] >= q.lo[0] {
                resting.scan(start..k, q, out);
            }
            k = start;
        }
    }
}
