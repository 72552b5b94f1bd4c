//! The query index: the bounding-volume tree of the bodies, kept current step by step.
//!
//! It lives in the system's scratch (it is a cache, not state). Each body with a finite
//! box has a leaf whose fat box is its tight box grown by [`fat_margin`] and stretched
//! along its velocity ([`fat_box`]); bodies without
//! one (planes) are listed apart, to be tested by every query. At the end of each step
//! ([`QueryIndex::sync`]) only the bodies that moved are looked at, and a leaf is
//! re-inserted only when the body's tight box has left its fat box; bodies added or
//! removed since the last step are found by their slot's alive flag and generation.
//!
//! The index is *current* when every live body's tight box lies in its leaf's fat box;
//! queries use it only then, and test every live body otherwise (after a restore, or after
//! a body was added, until the next step), with the same answers.

use super::tree::AabbTree;
use crate::math::{Real, Vec3};
use crate::rigid::aabb::Aabb;
use crate::rigid::bodies::Bodies;
use crate::rigid::transform::Transform;

/// What the index holds for a slot: no entry.
const ABSENT: u32 = u32::MAX;
/// What the index holds for a slot: a body without a finite box (a plane).
const UNBOUNDED: u32 = u32::MAX - 1;

/// How far a leaf's fat box reaches past the body's tight box on every side, m: 2⁻³ m.
/// A body re-enters the tree only after moving this far.
pub(crate) fn fat_margin<R: Real>() -> R {
    R::from_ratio(1, 8)
}

/// The tree of the bodies' fat boxes and the list of the bodies without a box.
#[derive(Debug, Default)]
pub(crate) struct QueryIndex<R: Real> {
    tree: AabbTree<R>,
    /// For each slot: its leaf node, [`UNBOUNDED`] or [`ABSENT`].
    entry: Vec<u32>,
    /// For each slot with an entry, the generation of the body it was made for.
    generation: Vec<u32>,
    /// Slots of the live bodies without a box, ascending.
    unbounded: Vec<u32>,
    /// Whether `entry` describes a tree built for this system (false after a restore).
    built: bool,
    /// Whether every live body is in the index with its current box.
    current: bool,
}

impl<R: Real> QueryIndex<R> {
    /// The index may be missing bodies added since the last step: queries test every body
    /// until the next [`sync`](Self::sync) adds them.
    pub fn invalidate(&mut self) {
        self.current = false;
    }

    /// The index no longer describes the bodies (a restore, a body placed by hand): the
    /// next [`sync`](Self::sync) rebuilds it.
    pub fn discard(&mut self) {
        self.built = false;
        self.current = false;
    }

    /// Whether queries may use the index for a system of `slots` slots.
    pub fn is_current(&self, slots: usize) -> bool {
        self.current && self.entry.len() == slots
    }

    /// Brings the index up to date with `bodies`, where `moved(i)` is true for every slot
    /// whose body may have moved since the last sync (ignored when the index is rebuilt).
    pub fn sync(&mut self, bodies: &Bodies<R>, moved: impl Fn(usize) -> bool) {
        let n = bodies.len();
        let rebuild = !self.built;
        if rebuild {
            self.tree.clear();
            self.entry.clear();
            self.generation.clear();
            self.built = true;
        }
        self.entry.resize(n, ABSENT);
        self.generation.resize(n, 0);
        self.unbounded.clear();
        let margin = fat_margin::<R>();
        for i in 0..n {
            let entry = self.entry[i];
            if !bodies.alive[i] {
                if entry != ABSENT {
                    self.forget(i);
                }
                continue;
            }
            let same_body = entry != ABSENT && self.generation[i] == bodies.generation[i];
            if same_body && (entry == UNBOUNDED || !moved(i)) {
                if entry == UNBOUNDED {
                    self.unbounded.push(i as u32);
                }
                continue;
            }
            let xf = Transform::from_pose(bodies.position[i], bodies.orientation[i]);
            let tight = Aabb::of_shape(&bodies.shape[i], &xf);
            match (same_body, tight) {
                (true, Some(tight)) => {
                    if !contains(self.tree.fat_box(entry), &tight) {
                        let fat = fat_box(&tight, margin, bodies.linear_velocity[i]);
                        self.tree.reinsert(entry, fat);
                    }
                }
                (_, tight) => {
                    if entry != ABSENT {
                        self.forget(i);
                    }
                    self.generation[i] = bodies.generation[i];
                    self.entry[i] = match tight {
                        Some(tight) => {
                            let fat = fat_box(&tight, margin, bodies.linear_velocity[i]);
                            self.tree.insert(i as u32, fat)
                        }
                        None => {
                            self.unbounded.push(i as u32);
                            UNBOUNDED
                        }
                    };
                }
            }
        }
        self.current = true;
    }

    /// Removes slot `i`'s entry.
    fn forget(&mut self, i: usize) {
        let entry = self.entry[i];
        if entry != UNBOUNDED && entry != ABSENT {
            self.tree.remove(entry);
        }
        self.entry[i] = ABSENT;
    }

    /// Calls `visit(slot)` for every body whose fat box passes `keep` (called on the boxes
    /// of the tree's nodes, top down: a node that fails prunes its subtree) and for every
    /// body without a box. A slot may name a body removed since the last sync.
    pub fn candidates(&self, keep: impl FnMut(&Aabb<R>) -> bool, visit: impl FnMut(usize)) {
        self.candidates_with(&mut Vec::new(), keep, visit);
    }

    /// [`candidates`](Self::candidates) with `stack` as the traversal's memory, for callers
    /// that query many times in a row.
    pub fn candidates_with(
        &self,
        stack: &mut Vec<u32>,
        mut keep: impl FnMut(&Aabb<R>) -> bool,
        mut visit: impl FnMut(usize),
    ) {
        self.tree.traverse(stack, |aabb, leaf| {
            let pass = keep(aabb);
            if let Some(slot) = leaf
                && pass
            {
                visit(slot as usize);
            }
            pass
        });
        for &slot in &self.unbounded {
            visit(slot as usize);
        }
    }

    /// Calls `visit(slot)` for the bodies whose fat box `enter` keeps, nearest entry
    /// first (see [`AabbTree::traverse_nearest`]: a box whose entry exceeds `reach()` when
    /// its turn comes is skipped), then for every body without a box.
    pub fn candidates_nearest(
        &self,
        enter: impl FnMut(&Aabb<R>) -> Option<R>,
        reach: impl Fn() -> R,
        mut visit: impl FnMut(usize),
    ) {
        let mut stack = Vec::new();
        self.tree
            .traverse_nearest(&mut stack, enter, reach, |slot| visit(slot as usize));
        for &slot in &self.unbounded {
            visit(slot as usize);
        }
    }

    /// The tree, for tests.
    #[cfg(test)]
    pub fn tree(&self) -> &AabbTree<R> {
        &self.tree
    }
}

/// How far ahead a leaf's fat box reaches along the body's velocity, s: 2⁻⁴ s (a few
/// steps at 60 Hz), as Box2D stretches its fat boxes along the displacement.
fn lookahead<R: Real>() -> R {
    R::from_ratio(1, 16)
}

/// The fat box of a body with tight box `tight` and velocity `velocity` (m/s): `tight`
/// grown by `margin` (m) on every side, and stretched by velocity × [`lookahead`] on the
/// side each velocity component points to, so a moving body stays in its leaf longer.
fn fat_box<R: Real>(tight: &Aabb<R>, margin: R, velocity: Vec3<R>) -> Aabb<R> {
    let fat = tight.expanded(margin);
    let ahead = velocity * lookahead::<R>();
    let zero = Vec3::ZERO;
    Aabb {
        min: fat.min + ahead.min_elem(zero),
        max: fat.max + ahead.max_elem(zero),
    }
}

/// Whether `inner` lies within `outer` (boundaries included).
fn contains<R: Real>(outer: &Aabb<R>, inner: &Aabb<R>) -> bool {
    outer.min.x <= inner.min.x
        && outer.min.y <= inner.min.y
        && outer.min.z <= inner.min.z
        && inner.max.x <= outer.max.x
        && inner.max.y <= outer.max.y
        && inner.max.z <= outer.max.z
}
