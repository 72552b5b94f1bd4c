//! The characters as obstacles to one another during a tick: where each one is now (those
//! that have moved this tick at their new place, the others at their old one), and shape
//! casts against them.
//!
//! A cast only tests the characters whose boxes its swept box reaches along x: the crowd
//! keeps the characters sorted by (centre x, index), so those are one contiguous run found
//! by binary search, and a character that moves is slid to its new place in the order.
//! The answer is the first character touched, ties to the lower index: the same whatever
//! the order of the candidates.

use crate::math::{Quat, Real, Vec3};
use crate::rigid::query::{cast_shape, unit_direction};
use crate::rigid::{Aabb, CollisionFilter, Shape, Transform};

use super::system::Character;

/// Where a cast meets another character.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CrowdHit<R: Real> {
    /// The character met (its index).
    pub index: usize,
    /// Travel along the unit direction at impact, m.
    pub distance: R,
    /// The contact point, m.
    pub point: Vec3<R>,
    /// Unit normal from the character met towards the cast shape.
    pub normal: Vec3<R>,
}

/// One character as an obstacle.
#[derive(Clone, Debug)]
struct Member<R: Real> {
    shape: Shape<R>,
    position: Vec3<R>,
    /// The half extents of its box, m.
    half: Vec3<R>,
    filter: CollisionFilter,
}

/// Every character's current place, for the casts of the others.
#[derive(Clone, Debug, Default)]
pub struct Crowd<R: Real> {
    members: Vec<Member<R>>,
    /// Indices sorted by (centre x, index).
    order: Vec<usize>,
    /// Each index's place in `order`.
    place: Vec<usize>,
    /// The largest half extent along x of any member, m.
    widest: R,
}

/// The half extents of the box of an unrotated `shape`.
fn half_extents<R: Real>(shape: &Shape<R>) -> Vec3<R> {
    Aabb::of_shape(shape, &Transform::from_pose(Vec3::ZERO, Quat::IDENTITY))
        .map_or(Vec3::ZERO, |b| (b.max - b.min) * R::HALF)
}

impl<R: Real> Crowd<R> {
    /// The crowd of `characters` where they are now.
    pub fn new(characters: &[Character<R>]) -> Self {
        let members: Vec<Member<R>> = characters
            .iter()
            .map(|c| Member {
                shape: c.shape.clone(),
                position: c.position,
                half: half_extents(&c.shape),
                filter: c.settings.filter,
            })
            .collect();
        let widest = members.iter().fold(R::ZERO, |w, m| w.max(m.half.x));
        let mut order: Vec<usize> = (0..members.len()).collect();
        order.sort_unstable_by(|&a, &b| {
            members[a]
                .position
                .x
                .total_cmp(&members[b].position.x)
                .then(a.cmp(&b))
        });
        let mut place = vec![0; members.len()];
        for (k, &i) in order.iter().enumerate() {
            place[i] = k;
        }
        Self {
            members,
            order,
            place,
            widest,
        }
    }

    /// Whether member `a` comes before member `b` in the order.
    fn before(&self, a: usize, b: usize) -> bool {
        let (pa, pb) = (self.members[a].position.x, self.members[b].position.x);
        pa < pb || (pa == pb && a < b)
    }

    /// Character `index` is now at `position` (m).
    pub fn moved(&mut self, index: usize, position: Vec3<R>) {
        self.members[index].position = position;
        let mut k = self.place[index];
        while k > 0 && self.before(index, self.order[k - 1]) {
            self.order[k] = self.order[k - 1];
            self.place[self.order[k]] = k;
            k -= 1;
        }
        while k + 1 < self.order.len() && self.before(self.order[k + 1], index) {
            self.order[k] = self.order[k + 1];
            self.place[self.order[k]] = k;
            k += 1;
        }
        self.order[k] = index;
        self.place[index] = k;
    }

    /// The first character other than `me` and those in `exclude` that `shape` at
    /// `position` (m), unrotated, touches when moved along `motion` by up to `max` m (along
    /// its unit direction), among those whose filter interacts with `filter`; ties to the
    /// lower index. A shape touching or overlapping one at the start hits it at distance 0.
    #[allow(clippy::too_many_arguments)]
    pub fn cast(
        &self,
        me: usize,
        shape: &Shape<R>,
        position: Vec3<R>,
        motion: Vec3<R>,
        max: R,
        filter: CollisionFilter,
        exclude: &[usize],
    ) -> Option<CrowdHit<R>> {
        if self.members.len() < 2 {
            return None;
        }
        let direction = unit_direction(motion)?;
        let end = position.add_scaled(direction, max);
        let half = half_extents(shape);
        let pad = R::from_ratio(1, 1 << 10);
        let low = position.min_elem(end) - half - Vec3::splat(pad);
        let high = position.max_elem(end) + half + Vec3::splat(pad);
        let start = Transform::from_pose(position, Quat::IDENTITY);
        let first = self
            .order
            .partition_point(|&i| self.members[i].position.x < low.x - self.widest);
        let mut best: Option<CrowdHit<R>> = None;
        for &i in &self.order[first..] {
            let m = &self.members[i];
            if m.position.x > high.x + self.widest {
                break;
            }
            if i == me || exclude.contains(&i) || !filter.interacts(m.filter) {
                continue;
            }
            let (lo, hi) = (m.position - m.half, m.position + m.half);
            if hi.x < low.x || lo.x > high.x || hi.y < low.y || lo.y > high.y {
                continue;
            }
            if hi.z < low.z || lo.z > high.z {
                continue;
            }
            let xf = Transform::from_pose(m.position, Quat::IDENTITY);
            let Some(hit) = cast_shape(shape, &start, direction, max, &m.shape, &xf) else {
                continue;
            };
            if best.is_none_or(|b| {
                hit.distance < b.distance || (hit.distance == b.distance && i < b.index)
            }) {
                best = Some(CrowdHit {
                    index: i,
                    distance: hit.distance,
                    point: hit.point,
                    normal: hit.normal,
                });
            }
        }
        best
    }
}
