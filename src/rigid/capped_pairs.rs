//! The pairs a rigid step keeps when the broadphase hits its cap
//! (more than [`MAX_PAIRS`] overlapping boxes, bodies piled on one
//! spot): each moving body against each static body whose box it overlaps, so that a pile
//! still rests on the ground even when its bodies pass through each other.
//!
//! Which pairs are kept is decided from the data alone: every static × moving overlap,
//! visited statics in slot order and moving bodies in ascending (lower x bound, slot) order,
//! up to the cap. The pairs among moving bodies the broadphase found before it stopped are
//! not kept: which ones it finds first depends on its sweep layout, a cache that depends on
//! the history of the run (a world restored from a snapshot may have another), so keeping
//! them would break determinism. Finding the pairs the cap leaves out in a fixed order would
//! cost a test per pair of piled bodies, which the cap is there to bound.

use super::aabb::Aabb;
use super::broadphase::MAX_PAIRS;
use super::desc::BodyKind;
use crate::math::Real;

/// Fills `out` (cleared first) with the pairs (lower, higher slot) of a moving body
/// (`active[i]`) and a static body (`kind[s]` static) whose boxes overlap, both `present`,
/// at most [`MAX_PAIRS`] of them, in ascending order.
pub(crate) fn static_pairs<R: Real>(
    boxes: &[Aabb<R>],
    active: &[bool],
    present: &[bool],
    kind: &[BodyKind],
    out: &mut Vec<(u32, u32)>,
) {
    out.clear();
    let mut moving: Vec<u32> = (0..boxes.len())
        .filter(|&i| active[i] && present[i])
        .map(|i| i as u32)
        .collect();
    moving.sort_unstable_by(|&a, &b| {
        let x = |i: u32| boxes[i as usize].min.x;
        x(a).total_cmp(&x(b)).then(a.cmp(&b))
    });
    let statics = (0..boxes.len()).filter(|&s| present[s] && kind[s] == BodyKind::Static);
    'statics: for s in statics {
        let bounds = &boxes[s];
        // The moving bodies whose lower x bound is not past the static box's upper one.
        let reach = moving.partition_point(|&i| boxes[i as usize].min.x <= bounds.max.x);
        for &i in &moving[..reach] {
            if boxes[i as usize].overlaps(bounds) {
                if out.len() == MAX_PAIRS {
                    break 'statics;
                }
                let s = s as u32;
                out.push((s.min(i), s.max(i)));
            }
        }
    }
    out.sort_unstable();
}
