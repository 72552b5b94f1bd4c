//! Sort-and-sweep broadphase: which pairs of bounding boxes overlap.
//!
//! [`BroadPhase::find_pairs`] takes every body's box and two flags (present, awake) and
//! returns the overlapping pairs with at least one awake member, in ascending order. The
//! answer is a pure function of the input; what the broadphase keeps between calls (a
//! layout and the sort orders of the previous call) only makes the next call cheaper.
//!
//! # How it works
//!
//! **Layout.** Of the three axes, the *sweep axis* is the one along which the fewest boxes
//! overlap, and the *strip axis* the next one (counted on a sample of about [`SAMPLE`]
//! boxes). The strip axis is cut into strips at sampled lower bounds, each between one and
//! two median box sizes beyond the previous one, where it cuts the fewest boxes (in a
//! lattice, between the rows), so that a box usually lies in one strip or two. Each box
//! belongs to the strip of its lower bound along the strip axis. The layout is chosen on
//! the first call, and again when the number of boxes has doubled or halved or the fullest
//! strip has become twice as crowded. Choosing it takes comparisons and, for the sizes,
//! subtractions, which saturate (and count) only for boxes wider than the format's range.
//!
//! **Order.** Boxes are sorted by the total key (strip, lower bound along the sweep axis by
//! [`Real::total_cmp`], index), the same on every machine. Awake boxes and resting boxes
//! (present but not awake: static or sleeping) are kept in two separate sorted lists, and
//! each list also keeps, in the same order, its boxes that reach beyond their own strip.
//!
//! **Pairs.** Two overlapping boxes in strips s < t have t ≤ the strip of the first one's
//! upper bound. So for each strip `t` of awake boxes:
//!
//! - the awake boxes of `t` among themselves: the classic sweep, each box against those
//!   after it whose lower bound is within its upper bound;
//! - the awake boxes of `t` reaching higher strips against the awake and the resting boxes
//!   of those strips;
//! - all the awake boxes of `t` against the resting boxes of `t`, and against the resting
//!   boxes of lower strips that reach `t`.
//!
//! Two runs of boxes are compared by a merged sweep of both, or, when one side has few
//! boxes, by a probe per box: a binary search for its place in the other run, forward
//! while the lower bounds are within reach, and backward from the first entry whose running
//! maximum of the upper bounds reaches it, skipping blocks of [`BLOCK`] entries that all end
//! before it (so a long resting box, a ground slab, does not make every probe walk the
//! whole strip). Every candidate gets the test of [`Aabb::overlaps`], without branches,
//! less the sweep-axis bounds the order already guarantees. Each pair is met exactly once,
//! and the pairs are sorted at the end.
//!
//! **Caching.** The resting list is rebuilt only when its membership or one of its boxes
//! changes, which is checked bit for bit on each call. Both lists are re-sorted by
//! insertion sort from the previous order, which is nearly sorted between frames; when
//! many boxes join at once, or the insertion sort has moved too much, a full sort takes
//! over. Either way the result is the unique order of the total keys. A resting world
//! therefore costs the awake boxes' own sweeps and probes, plus one pass over the flags
//! and one comparison of the resting boxes with their copy.

use core::cmp::Ordering;

use super::aabb::Aabb;
use crate::math::{Fx, Real};

/// Boxes per block of a sorted list; the backward walk skips a block whose boxes all end
/// before the probe starts.
const BLOCK: usize = 32;

/// Largest number of boxes the layout is chosen from.
const SAMPLE: usize = 1024;

/// The layout aims at no more strips than this.
const MAX_STRIPS: usize = 64;

/// Membership of a box index: in neither list (absent, or beyond the input).
const OUT: u8 = 0;
/// Membership of a box index: in the awake list.
const AWAKE: u8 = 1;
/// Membership of a box index: in the resting list.
const RESTING: u8 = 2;

/// The total order of entries: strip, then lower bound along the sweep axis by
/// [`Real::total_cmp`], then index.
#[inline(always)]
fn entry_cmp<R: Real>(a: &Entry<R>, b: &Entry<R>) -> Ordering {
    a.strip
        .cmp(&b.strip)
        .then_with(|| a.bounds.lo[0].total_cmp(&b.bounds.lo[0]))
        .then(a.index.cmp(&b.index))
}

/// True when entry `a` comes strictly before entry `b`.
#[inline(always)]
fn entry_less<R: Real>(a: &Entry<R>, b: &Entry<R>) -> bool {
    entry_cmp(a, b) == Ordering::Less
}

/// Sorts `entries` in the total order, assuming that all but the last `fresh` of them are
/// nearly sorted already. Insertion sort, unless `fresh` is a large share of the list or
/// the insertion sort has moved more than a few times the list's length; then a full sort.
/// Entries are unique (indices differ), so the result does not depend on the method.
fn sort_entries<R: Real>(entries: &mut [Entry<R>], fresh: usize) {
    let n = entries.len();
    if fresh > n / 4 + 8 {
        entries.sort_unstable_by(entry_cmp);
        return;
    }
    let budget = 8 * n + 64;
    let mut moves = 0;
    for i in 1..n {
        if !entry_less(&entries[i], &entries[i - 1]) {
            continue;
        }
        let x = entries[i];
        let mut j = i;
        while j > 0 && entry_less(&x, &entries[j - 1]) {
            entries[j] = entries[j - 1];
            j -= 1;
        }
        entries[j] = x;
        moves += i - j;
        if moves > budget {
            entries.sort_unstable_by(entry_cmp);
            return;
        }
    }
}

/// Sorts the pairs in ascending order. Many pairs (compared with the number of boxes `n`)
/// are sorted by two counting passes, by the second index and then stably by the first,
/// in O(pairs + n); fewer by a comparison sort.
fn sort_pairs(
    pairs: &mut [(u32, u32)],
    n: usize,
    counts: &mut Vec<u32>,
    scratch: &mut Vec<(u32, u32)>,
) {
    if pairs.len() < 256 || pairs.len() < n / 2 {
        pairs.sort_unstable();
        return;
    }
    scratch.clear();
    scratch.resize(pairs.len(), (0, 0));
    counting_pass(pairs, scratch, counts, n, |p| p.1);
    counting_pass(scratch, pairs, counts, n, |p| p.0);
}

/// Copies `from` into `to` (as long) ordered by `digit` (below `n`), stably.
fn counting_pass(
    from: &[(u32, u32)],
    to: &mut [(u32, u32)],
    counts: &mut Vec<u32>,
    n: usize,
    digit: impl Fn(&(u32, u32)) -> u32,
) {
    counts.clear();
    counts.resize(n + 1, 0);
    for p in from {
        counts[digit(p) as usize + 1] += 1;
    }
    for k in 0..n {
        counts[k + 1] += counts[k];
    }
    for p in from {
        let slot = &mut counts[digit(p) as usize];
        to[*slot as usize] = *p;
        *slot += 1;
    }
}

/// True when the two values have the same bits.
#[inline(always)]
fn same<R: Real>(a: R, b: R) -> bool {
    a.canonical_bits() == b.canonical_bits()
}

/// The axes and strips the boxes are sorted by.
#[derive(Clone, Debug)]
struct Layout<R: Real> {
    /// Axis of each lane: sweep axis, strip axis, the remaining axis.
    lanes: [usize; 3],
    /// Strip boundaries along the strip axis, strictly increasing: strip `t` holds the
    /// lower bounds `v` with `bounds[t - 1] ≤ v < bounds[t]`.
    bounds: Vec<R>,
}

impl<R: Real> Layout<R> {
    /// Number of strips.
    #[inline]
    fn strips(&self) -> usize {
        self.bounds.len() + 1
    }

    /// The strip holding the value `v` of the strip axis.
    #[inline(always)]
    fn strip(&self, v: R) -> u32 {
        self.bounds.partition_point(|b| *b <= v) as u32
    }

    /// [`Layout::strip`], checking the strip `hint` first (boxes seldom change strips).
    #[inline(always)]
    fn strip_near(&self, v: R, hint: u32) -> u32 {
        let h = hint as usize;
        let b = &self.bounds;
        if h <= b.len() && (h == 0 || b[h - 1] <= v) && (h == b.len() || v < b[h]) {
            hint
        } else {
            self.strip(v)
        }
    }

    /// True when both layouts are the same bit for bit.
    fn same_as(&self, other: &Self) -> bool {
        self.lanes == other.lanes
            && self.bounds.len() == other.bounds.len()
            && self
                .bounds
                .iter()
                .zip(&other.bounds)
                .all(|(&a, &b)| same(a, b))
    }

    /// Chooses the layout for the present boxes from a sample of about [`SAMPLE`] of them
    /// (all of them when there are no more). For each axis it counts the sampled pairs
    /// overlapping along that axis; the sweep axis has the fewest, the strip axis the next
    /// fewest (ties go to the lower axis). The strip boundaries are sampled lower bounds
    /// along the strip axis: each is the one cutting the fewest sampled boxes among those
    /// between one and two median box sizes beyond the previous boundary, with at least
    /// `max(4, samples / MAX_STRIPS)` sampled boxes between them.
    fn choose(boxes: &[Aabb<R>], present: &[bool], count: usize) -> Self {
        // A pseudo-random choice of indices (a multiplicative hash under a threshold), so
        // that the sample does not alias with a regular arrangement of the bodies.
        let threshold = if count <= SAMPLE {
            u32::MAX
        } else {
            (u64::from(u32::MAX) * SAMPLE as u64 / count as u64) as u32
        };
        let sample: Vec<usize> = (0..boxes.len())
            .filter(|&i| present[i] && (i as u32).wrapping_mul(0x9E37_79B9) <= threshold)
            .collect();
        let mut layout = Self {
            lanes: [0, 1, 2],
            bounds: Vec::new(),
        };
        if sample.len() < 2 {
            return layout;
        }
        let spans = |axis: usize| {
            let mut spans: Vec<(R, R)> = sample
                .iter()
                .map(|&i| (boxes[i].min[axis], boxes[i].max[axis]))
                .collect();
            spans.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
            spans
        };
        let mut overlaps = [0usize; 3];
        for (axis, o) in overlaps.iter_mut().enumerate() {
            let spans = spans(axis);
            *o = spans
                .iter()
                .enumerate()
                .map(|(i, &(_, hi))| {
                    spans
                        .partition_point(|&(lo, _)| lo <= hi)
                        .saturating_sub(i + 1)
                })
                .sum();
        }
        let mut axes = [0, 1, 2];
        axes.sort_by_key(|&a| (overlaps[a], a));
        layout.lanes = axes;

        let spans = spans(axes[1]);
        let mut sizes: Vec<R> = spans.iter().map(|&(lo, hi)| hi - lo).collect();
        let middle = sizes.len() / 2;
        let size = *sizes.select_nth_unstable_by(middle, R::total_cmp).1;
        let mut highs: Vec<R> = spans.iter().map(|&(_, hi)| hi).collect();
        highs.sort_unstable_by(R::total_cmp);
        // Sampled boxes cut by a boundary at `b`: lower bound below it, upper bound not.
        let cut = |b: R| {
            let below = spans.partition_point(|&(lo, _)| lo < b);
            below.saturating_sub(highs.partition_point(|&h| h < b))
        };
        let min_between = (spans.len() / MAX_STRIPS).max(4);
        let (mut last, mut from) = (spans[0].0, 0);
        // The first lower bound that may start a strip, then the one cutting the fewest
        // boxes among those less than one box size beyond it (the earliest on a tie).
        while let Some(first) = (from + min_between..spans.len())
            .find(|&k| spans[k].0 > last && spans[k].0 >= last + size)
        {
            let limit = spans[first].0 + size;
            let mut best = (cut(spans[first].0), first);
            for k in (first + 1..spans.len()).take_while(|&k| spans[k].0 < limit) {
                if spans[k].0 > spans[k - 1].0 {
                    best = best.min((cut(spans[k].0), k));
                }
            }
            last = spans[best.1].0;
            from = best.1;
            layout.bounds.push(last);
        }
        layout
    }
}

/// The components of `v` as an array, x first.
#[inline(always)]
fn components<R: Real>(v: &crate::math::Vec3<R>) -> [R; 3] {
    [v.x, v.y, v.z]
}

/// A box with its bounds in lane order (sweep axis first, strip axis second).
#[derive(Clone, Copy, Debug)]
struct Bounds<R: Real> {
    /// Lower bounds per lane.
    lo: [R; 3],
    /// Upper bounds per lane.
    hi: [R; 3],
}

impl<R: Real> Bounds<R> {
    /// The bounds of `b` in the lane order `lanes`.
    #[inline(always)]
    fn of(b: &Aabb<R>, lanes: [usize; 3]) -> Self {
        let (min, max) = (components(&b.min), components(&b.max));
        Self {
            lo: [min[lanes[0]], min[lanes[1]], min[lanes[2]]],
            hi: [max[lanes[0]], max[lanes[1]], max[lanes[2]]],
        }
    }
}

/// One box of a sorted list: its bounds, index and strips. The list is sorted by
/// [`entry_cmp`].
#[derive(Clone, Copy, Debug)]
struct Entry<R: Real> {
    /// The bounds in lane order.
    bounds: Bounds<R>,
    /// Index of the box in the input.
    index: u32,
    /// Strip of the lower bound along the strip axis.
    strip: u32,
    /// Strip of the upper bound along the strip axis (at least `strip`).
    last: u32,
}

impl<R: Real> Entry<R> {
    /// Fills in the bounds and strips of box `index` of `boxes`; the strips already in the
    /// entry serve as hints.
    #[inline(always)]
    fn set(&mut self, boxes: &[Aabb<R>], index: u32, layout: &Layout<R>) {
        self.bounds = Bounds::of(&boxes[index as usize], layout.lanes);
        self.index = index;
        self.strip = layout.strip_near(self.bounds.lo[1], self.strip);
        self.last = layout
            .strip_near(self.bounds.hi[1], self.last)
            .max(self.strip);
    }
}

/// Boxes sorted by [`entry_cmp`], with per-strip offsets and the summaries the probes use.
#[derive(Clone, Debug, Default)]
struct Runs<R: Real> {
    /// The boxes, in order.
    entries: Vec<Entry<R>>,
    /// Start of each strip's run of entries, and the end: `strips + 1` offsets.
    seg: Vec<u32>,
    /// Running maximum of the upper bound along the sweep axis within each strip.
    prefix_hi: Vec<R>,
    /// Maximum of the upper bound along the sweep axis per [`BLOCK`] of entries.
    block_hi: Vec<R>,
}

impl<R: Real> Runs<R> {
    /// Rebuilds the offsets and summaries for `strips` strips from the sorted entries.
    fn summarize(&mut self, strips: usize) {
        self.seg.clear();
        self.seg.resize(strips + 1, 0);
        self.prefix_hi.clear();
        let mut running = R::MIN;
        let mut strip = u32::MAX;
        for e in &self.entries {
            if e.strip != strip {
                strip = e.strip;
                running = e.bounds.hi[0];
            }
            running = running.max(e.bounds.hi[0]);
            self.prefix_hi.push(running);
            self.seg[e.strip as usize + 1] += 1;
        }
        for t in 0..strips {
            self.seg[t + 1] += self.seg[t];
        }
        self.block_hi.clear();
        self.block_hi
            .extend(self.entries.chunks(BLOCK).map(|block| {
                block
                    .iter()
                    .skip(1)
                    .fold(block[0].bounds.hi[0], |m, e| m.max(e.bounds.hi[0]))
            }));
    }

    /// The run of strip `t`.
    #[inline(always)]
    fn run(&self, t: usize) -> Run<'_, R> {
        let (start, end) = (self.seg[t] as usize, self.seg[t + 1] as usize);
        Run {
            entries: &self.entries[start..end],
            prefix_hi: &self.prefix_hi[start..end],
            block_hi: &self.block_hi,
            offset: start,
        }
    }
}

/// The boxes of one strip, sorted, with their summaries.
#[derive(Clone, Copy, Debug)]
struct Run<'a, R: Real> {
    /// The boxes, in order.
    entries: &'a [Entry<R>],
    /// Running maximum of the upper bound along the sweep axis.
    prefix_hi: &'a [R],
    /// Maximum of the upper bound along the sweep axis per [`BLOCK`] of the whole list.
    block_hi: &'a [R],
    /// Position of the run's first entry in the whole list.
    offset: usize,
}

impl<R: Real> Run<'_, R> {
    /// Every box of the run that overlaps `q` (a box not in the run): a binary search for
    /// `q`'s place, then forward while the lower bounds are within `q`'s reach, and
    /// backward over the entries from the first one whose running maximum of the upper
    /// bounds reaches `q`, skipping the blocks that all end before it.
    fn probe(&self, q: &Entry<R>, sink: &mut Sink<'_>) {
        if sink.full() {
            return;
        }
        let (lo, hi) = (q.bounds.lo[0], q.bounds.hi[0]);
        let place = self.entries.partition_point(|e| comes_before(e, q));
        let after = &self.entries[place..];
        scan(&after[..window(after, hi)], q, false, sink);
        let mut k = self.prefix_hi[..place].partition_point(|h| *h < lo);
        while k < place && !sink.full() {
            let block = (self.offset + k) / BLOCK;
            let to = place.min((block + 1) * BLOCK - self.offset);
            if self.block_hi[block] >= lo {
                scan(&self.entries[k..to], q, true, sink);
            }
            k = to;
        }
    }

    /// Every overlapping pair between the boxes of two runs of different boxes: a probe
    /// of `other` per box of `self` when they are few enough for the binary searches to
    /// cost less than a merged sweep, otherwise [`cross_sweep`].
    fn cross(&self, other: &Run<'_, R>, sink: &mut Sink<'_>) {
        let (mine, theirs) = (self.entries.len(), other.entries.len());
        if mine == 0 || theirs == 0 {
            return;
        }
        if mine * (theirs.ilog2() as usize + 8) < mine + theirs {
            for q in self.entries {
                other.probe(q, sink);
            }
        } else {
            cross_sweep(self.entries, other.entries, sink);
        }
    }
}

/// A sorted list of boxes: all of them by strip, and those reaching beyond their strip.
#[derive(Clone, Debug, Default)]
struct SortedList<R: Real> {
    /// All the boxes of the list.
    all: Runs<R>,
    /// The boxes whose upper bound along the strip axis lies in a higher strip than their
    /// lower bound (in the same order).
    up: Runs<R>,
    /// Per strip, the highest strip reached by the upper bound of one of its boxes (at
    /// least the strip itself).
    reach: Vec<u32>,
    /// Per strip `s`, the lowest strip `t ≤ s` whose reach is at least `s`.
    down: Vec<u32>,
    /// Number of boxes without `min ≤ max` along the sweep axis.
    inverted: usize,
}

impl<R: Real> SortedList<R> {
    /// Number of boxes in the list.
    #[inline]
    fn len(&self) -> usize {
        self.all.entries.len()
    }

    /// Brings the list up to date: keeps the entries whose index still has membership
    /// `tag` in `state`, refreshes their bounds from `boxes`, appends `added`, re-sorts
    /// (from the previous order unless `full`) and rebuilds the summaries.
    fn refresh(
        &mut self,
        boxes: &[Aabb<R>],
        state: &[u8],
        tag: u8,
        added: &[u32],
        layout: &Layout<R>,
        full: bool,
    ) {
        let n = boxes.len();
        let entries = &mut self.all.entries;
        entries.retain_mut(|e| {
            let i = e.index;
            let keep = (i as usize) < n && state[i as usize] == tag;
            if keep {
                e.set(boxes, i, layout);
            }
            keep
        });
        entries.extend(added.iter().map(|&i| {
            let mut e = Entry {
                bounds: Bounds::of(&boxes[i as usize], layout.lanes),
                index: i,
                strip: 0,
                last: 0,
            };
            e.set(boxes, i, layout);
            e
        }));
        let fresh = if full { entries.len() } else { added.len() };
        sort_entries(entries, fresh);
        self.summarize(layout.strips());
    }

    /// Rebuilds the reaching sub-list and the per-strip and per-block summaries from the
    /// sorted entries.
    fn summarize(&mut self, strips: usize) {
        self.all.summarize(strips);
        self.inverted = self
            .all
            .entries
            .iter()
            .filter(|e| {
                !matches!(
                    e.bounds.lo[0].partial_cmp(&e.bounds.hi[0]),
                    Some(Ordering::Less | Ordering::Equal)
                )
            })
            .count();
        self.up.entries.clear();
        self.up
            .entries
            .extend(self.all.entries.iter().filter(|e| e.last > e.strip));
        self.up.summarize(strips);
        self.reach.clear();
        self.reach.extend(0..strips as u32);
        for e in &self.up.entries {
            let reach = &mut self.reach[e.strip as usize];
            *reach = (*reach).max(e.last);
        }
        self.down.clear();
        self.down.extend(0..strips as u32);
        for t in 0..strips {
            for s in t + 1..=self.reach[t] as usize {
                self.down[s] = self.down[s].min(t as u32);
            }
        }
    }
}

/// True when `a` comes before `b` in the order within a strip: lower bound along the sweep
/// axis by [`Real::total_cmp`], then index.
#[inline(always)]
fn comes_before<R: Real>(a: &Entry<R>, b: &Entry<R>) -> bool {
    match a.bounds.lo[0].total_cmp(&b.bounds.lo[0]) {
        Ordering::Less => true,
        Ordering::Greater => false,
        Ordering::Equal => a.index < b.index,
    }
}

/// The length of the forward window of `entries` (sorted): how many of the first entries
/// have their lower bound along the sweep axis within `reach`.
#[inline(always)]
fn window<R: Real>(entries: &[Entry<R>], reach: R) -> usize {
    entries
        .iter()
        .take_while(|e| e.bounds.lo[0] <= reach)
        .count()
}

/// Where the pairs go, and what the tests need to know.
struct Sink<'a> {
    /// The pairs found, unordered.
    out: &'a mut Vec<(u32, u32)>,
    /// Scanning stops once `out` holds more than this many pairs.
    limit: usize,
    /// Every box has `min ≤ max` along the sweep axis (see [`scan`]).
    valid: bool,
}

impl Sink<'_> {
    /// Whether more than `limit` pairs were found: the call's answer is then known (none),
    /// and the sweeps stop, so that boxes piled on one spot cost O(`limit`) tests rather
    /// than one per pair of them.
    #[inline(always)]
    fn full(&self) -> bool {
        self.out.len() > self.limit
    }
}

/// Tests the box `q` against `entries` with the full overlap test, less what is known, and
/// pushes each overlapping pair as (smaller, larger index).
///
/// The entries come before `q` in the order when `before`, otherwise after it and within
/// its reach. When every box has `min ≤ max` along the sweep axis, the entries after `q`
/// overlap it along that axis, and those before it start within its reach; then only the
/// remaining bounds are compared.
#[inline(always)]
fn scan<R: Real>(entries: &[Entry<R>], q: &Entry<R>, before: bool, sink: &mut Sink<'_>) {
    match (sink.valid, before) {
        (true, false) => scan_with::<R, false, false>(entries, q, sink.out, sink.limit),
        (true, true) => scan_with::<R, true, false>(entries, q, sink.out, sink.limit),
        (false, _) => scan_with::<R, true, true>(entries, q, sink.out, sink.limit),
    }
}

/// [`scan`], comparing the candidate's upper bound along the sweep axis with `q`'s lower
/// bound when `UPPER`, and its lower bound with `q`'s upper bound when `LOWER`.
///
/// Whether a candidate overlaps is not predictable, so there is no branch on it: each
/// chunk of 64 candidates is tested into a bit mask, then the set bits are pushed.
#[inline(always)]
fn scan_with<R: Real, const UPPER: bool, const LOWER: bool>(
    entries: &[Entry<R>],
    q: &Entry<R>,
    out: &mut Vec<(u32, u32)>,
    limit: usize,
) {
    let b = &q.bounds;
    for chunk in entries.chunks(64) {
        if out.len() > limit {
            return;
        }
        let mut mask = 0u64;
        for (k, e) in chunk.iter().enumerate() {
            let o = &e.bounds;
            let mut hit = u8::from(o.lo[1] <= b.hi[1])
                & u8::from(b.lo[1] <= o.hi[1])
                & u8::from(o.lo[2] <= b.hi[2])
                & u8::from(b.lo[2] <= o.hi[2]);
            if UPPER {
                hit &= u8::from(b.lo[0] <= o.hi[0]);
            }
            if LOWER {
                hit &= u8::from(o.lo[0] <= b.hi[0]);
            }
            mask |= u64::from(hit) << k;
        }
        while mask != 0 {
            let other = chunk[mask.trailing_zeros() as usize].index;
            mask &= mask - 1;
            out.push(if q.index < other {
                (q.index, other)
            } else {
                (other, q.index)
            });
        }
    }
}

/// Every overlapping pair within one strip (sorted): each box against the boxes after it
/// whose lower bound is within its reach.
fn self_sweep<R: Real>(entries: &[Entry<R>], sink: &mut Sink<'_>) {
    for (i, q) in entries.iter().enumerate() {
        if sink.full() {
            return;
        }
        let after = &entries[i + 1..];
        scan(&after[..window(after, q.bounds.hi[0])], q, false, sink);
    }
}

/// Every overlapping pair between two sorted runs of different boxes: a merged sweep in
/// which each box, when its turn comes, is tested against the boxes of the other run that
/// come after it and start within its reach. Each pair overlapping along the sweep axis is
/// tested once, by whichever of the two comes first.
fn cross_sweep<R: Real>(xs: &[Entry<R>], ys: &[Entry<R>], sink: &mut Sink<'_>) {
    let (mut i, mut j) = (0, 0);
    while i < xs.len() && j < ys.len() && !sink.full() {
        if comes_before(&xs[i], &ys[j]) {
            let (q, rest) = (&xs[i], &ys[j..]);
            scan(&rest[..window(rest, q.bounds.hi[0])], q, false, sink);
            i += 1;
        } else {
            let (q, rest) = (&ys[j], &xs[i..]);
            scan(&rest[..window(rest, q.bounds.hi[0])], q, false, sink);
            j += 1;
        }
    }
}

/// The most overlapping pairs one call reports (2¹⁸, about 260,000; the 4096-ball pile has
/// about 13,000). Beyond it the bodies are piled so densely that every pair's manifold and
/// constraint would not fit in memory; see [`BroadPhase::find_pairs`].
pub const MAX_PAIRS: usize = 1 << 18;

/// Sort-and-sweep broadphase. Its internal state (the layout and the remembered sort
/// orders) is a cache: the pairs it returns depend only on the boxes and flags passed in,
/// never on history, so snapshots, restores and different peers get identical pairs.
#[derive(Clone, Debug)]
pub struct BroadPhase<R: Real = Fx> {
    /// Axes and strips, once chosen.
    layout: Option<Layout<R>>,
    /// Number of present boxes when the layout was chosen.
    layout_count: usize,
    /// Entries in the fullest strip (both lists) on the first call with the layout.
    layout_crowding: Option<usize>,
    /// Entries in the fullest strip (both lists) on the last call.
    crowding: usize,
    /// Membership of each box index ([`OUT`], [`AWAKE`] or [`RESTING`]) as of the last call.
    state: Vec<u8>,
    /// Number of present boxes as of the last call.
    count: usize,
    /// Awake boxes.
    awake: SortedList<R>,
    /// Resting boxes (present, not awake).
    resting: SortedList<R>,
    /// The resting boxes in index order, as they were when the resting list was last
    /// rebuilt.
    resting_boxes: Vec<Aabb<R>>,
    /// Scratch: indices that joined the awake list this call.
    awake_added: Vec<u32>,
    /// Scratch: indices that joined the resting list this call.
    resting_added: Vec<u32>,
    /// Scratch for sorting the pairs: counts per index.
    counts: Vec<u32>,
    /// Scratch for sorting the pairs: the pairs sorted by their second index.
    pair_scratch: Vec<(u32, u32)>,
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
            layout: None,
            layout_count: 0,
            layout_crowding: None,
            crowding: 0,
            state: Vec::new(),
            count: 0,
            awake: SortedList::default(),
            resting: SortedList::default(),
            resting_boxes: Vec::new(),
            awake_added: Vec::new(),
            resting_added: Vec::new(),
            counts: Vec::new(),
            pair_scratch: Vec::new(),
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
    /// Returns false, with `out` empty, when more than [`MAX_PAIRS`] pairs overlap (boxes
    /// piled on one spot): the scan stops there, so memory and time stay bounded. Whether that
    /// happens depends only on the number of overlapping pairs, not on the order they are
    /// found in, so it is the same on every machine.
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
    ) -> bool {
        let n = boxes.len();
        assert_eq!(active.len(), n, "find_pairs: one active flag per box");
        assert_eq!(present.len(), n, "find_pairs: one present flag per box");
        assert!(u32::try_from(n).is_ok(), "find_pairs: too many boxes");
        out.clear();

        let mut resting_dirty = self.update_membership(active, present);
        let full = self.update_layout(boxes, present);
        let layout = self.layout.as_ref().expect("a layout is chosen");
        if !resting_dirty && !full {
            resting_dirty = !self.resting_unchanged(boxes);
        }
        if resting_dirty || full {
            self.resting.refresh(
                boxes,
                &self.state,
                RESTING,
                &self.resting_added,
                layout,
                full,
            );
            self.resting_boxes.clear();
            self.resting_boxes.extend(
                self.state
                    .iter()
                    .zip(boxes)
                    .filter(|&(&s, _)| s == RESTING)
                    .map(|(_, b)| *b),
            );
        }
        self.awake
            .refresh(boxes, &self.state, AWAKE, &self.awake_added, layout, full);
        self.crowding = (0..layout.strips())
            .map(|t| {
                let size = |l: &SortedList<R>| (l.all.seg[t + 1] - l.all.seg[t]) as usize;
                size(&self.awake) + size(&self.resting)
            })
            .max()
            .unwrap_or(0);
        if self.layout_crowding.is_none() {
            self.layout_crowding = Some(self.crowding);
        }

        let mut sink = Sink {
            out,
            limit: MAX_PAIRS,
            valid: self.awake.inverted == 0 && self.resting.inverted == 0,
        };
        self.sweep(&mut sink);
        if out.len() > MAX_PAIRS {
            out.clear();
            return false;
        }
        sort_pairs(out, n, &mut self.counts, &mut self.pair_scratch);
        debug_assert!(out.windows(2).all(|w| w[0] < w[1]));
        true
    }

    /// True when every resting box is bit for bit the box it was when the resting list
    /// was last rebuilt: one pass over the boxes in index order. Assumes the membership
    /// has not changed since.
    fn resting_unchanged(&self, boxes: &[Aabb<R>]) -> bool {
        let same = |a: &Aabb<R>, b: &Aabb<R>| {
            let eq = |x: R, y: R| x.canonical_bits() == y.canonical_bits();
            eq(a.min.x, b.min.x)
                & eq(a.min.y, b.min.y)
                & eq(a.min.z, b.min.z)
                & eq(a.max.x, b.max.x)
                & eq(a.max.y, b.max.y)
                & eq(a.max.z, b.max.z)
        };
        let mut kept = self.resting_boxes.iter();
        self.state
            .iter()
            .zip(boxes)
            .filter(|&(&s, _)| s == RESTING)
            .all(|(_, b)| kept.next().is_some_and(|k| same(b, k)))
    }

    /// Compares the wanted membership of every index (from the flags) with the remembered
    /// one and records the changes: indices joining a list go to the `*_added` scratch
    /// lists, and the state and the present count are updated (the lists drop their
    /// leavers themselves, in [`SortedList::refresh`]). Returns whether the resting list's
    /// membership changed.
    fn update_membership(&mut self, active: &[bool], present: &[bool]) -> bool {
        let n = active.len();
        let mut resting_changed = false;
        if self.state.len() > n {
            resting_changed |= self.state[n..].contains(&RESTING);
            self.count -= self.state[n..].iter().filter(|&&s| s != OUT).count();
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
                self.count = self.count + usize::from(w != OUT) - usize::from(*s != OUT);
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

    /// Chooses the layout on the first call, and again when the number of present boxes
    /// has more than doubled or halved, or the fullest strip on the last call held more than
    /// twice as many entries as on the first call with the layout. Returns true when the
    /// layout changed, so that both lists must be rebuilt.
    fn update_layout(&mut self, boxes: &[Aabb<R>], present: &[bool]) -> bool {
        if let Some(layout) = &self.layout {
            let grown = self.count > 2 * self.layout_count + 64;
            let shrunk = 2 * self.count + 64 < self.layout_count;
            let crowded = self
                .layout_crowding
                .is_some_and(|c| self.crowding > 2 * c + 64);
            if !(grown || shrunk || crowded) {
                return false;
            }
            let new = Layout::choose(boxes, present, self.count);
            self.layout_count = self.count;
            self.layout_crowding = None;
            if new.same_as(layout) {
                return false;
            }
            self.layout = Some(new);
        } else {
            self.layout = Some(Layout::choose(boxes, present, self.count));
            self.layout_count = self.count;
            self.layout_crowding = None;
        }
        true
    }

    /// Finds the pairs awake × awake and awake × resting, unordered, into `out`.
    ///
    /// For each strip `t` of awake boxes: a sweep within the strip; its boxes reaching
    /// higher strips against the awake and resting boxes there; and all its boxes against
    /// the resting boxes of the strip and the resting boxes of lower strips that reach it.
    /// Each pair of strips is handled by a merged sweep, or by a probe per box when the
    /// boxes on one side are few (see [`Run::cross`]).
    ///
    /// On a pool's workers ([`crate::parallel::splits`]) each strip's pairs are found into
    /// a list of their own, and the lists are joined in strip order: the pairs are the
    /// one-thread pairs in the one-thread order (and are sorted afterwards anyway), and
    /// more than the limit are found on some thread exactly when more than the limit
    /// overlap.
    fn sweep(&self, sink: &mut Sink<'_>) {
        let strips = self.awake.reach.len();
        if crate::parallel::splits() {
            let (limit, valid) = (sink.limit, sink.valid);
            let parts = crate::parallel::map_collect(strips, 1, |t| {
                let mut out = Vec::new();
                self.sweep_strip(
                    t,
                    &mut Sink {
                        out: &mut out,
                        limit,
                        valid,
                    },
                );
                out
            });
            for part in parts {
                sink.out.extend_from_slice(&part);
            }
            return;
        }
        for t in 0..strips {
            if sink.full() {
                return;
            }
            self.sweep_strip(t, sink);
        }
    }

    /// The pairs of strip `t` of awake boxes (see [`BroadPhase::sweep`]).
    fn sweep_strip(&self, t: usize, sink: &mut Sink<'_>) {
        let (awake, resting) = (&self.awake, &self.resting);
        let here = awake.all.run(t);
        if here.entries.is_empty() {
            return;
        }
        self_sweep(here.entries, sink);
        let up = awake.up.run(t);
        let reach = awake.reach[t] as usize;
        for s in t + 1..=reach {
            up.cross(&awake.all.run(s), sink);
        }
        if resting.len() == 0 {
            return;
        }
        for s in resting.down[t] as usize..t {
            if resting.reach[s] as usize >= t {
                here.cross(&resting.up.run(s), sink);
            }
        }
        here.cross(&resting.all.run(t), sink);
        for s in t + 1..=reach {
            up.cross(&resting.all.run(s), sink);
        }
    }
}
