//! Stage 1 of a rigid step: find the touching shape pairs and their manifolds.
//!
//! 1. The placement and bounding box (grown by the speculative distance) of every moving
//!    body is recomputed; those of static and sleeping bodies are cached.
//! 2. The broadphase lists overlapping boxes with at least one moving body, in ascending
//!    (a, b) order; static planes, which have no box, are tested against each moving body's
//!    box directly. When more than [`MAX_PAIRS`](super::broadphase::MAX_PAIRS) boxes overlap
//!    (bodies piled on one spot), the broadphase stops, so that memory and time stay
//!    bounded, and the step keeps only the pairs of a moving body and a static body
//!    ([`super::capped_pairs`]) and the planes' pairs; it is counted
//!    ([`RigidSystem::capped_steps`]), and the world reports it
//!    ([`crate::world::TickReport::capped_contact_steps`]).
//!    Pairs of bodies joined by a joint that does not let them collide are dropped.
//! 3. A box or capsule pair that has moved less than the contact recycle distance relative
//!    to its last narrowphase carries last step's contact with the bodies
//!    ([`super::recycle`]). For every other pair the narrowphase computes its manifold
//!    (part by part for compounds); each point takes the impulses of the point with the
//!    same feature id in last step's contact of the same key. A mesh or a heightfield
//!    collides triangle by triangle: each triangle under the other shape's box, from the
//!    mesh's tree, is a part of its own ([`for_each_manifold`]). Box–box pairs have their
//!    separating-axis tests done up to [`LANES`] at a time, with the same results as one by
//!    one.
//! 4. Contacts between two bodies that do not move (sleeping or static) are kept as they
//!    are, impulses included, so a sleeping island wakes with its contacts warm.
//!
//! The result is sorted by key.

use super::aabb::Aabb;
use super::bodies::Bodies;
use super::capped_pairs::static_pairs;
use super::contact::{Contact, ContactKey};
use super::desc::BodyKind;
use super::filter::CollisionFilter;
use super::manifold::Manifold;
use super::mesh::TriMesh;
use super::narrowphase::{
    BoxPair, box_box_contact, collide as collide_convex, collide_triangle, separating_axes_batch,
};
use super::recycle::{PairFrame, PairPose, recyclable};
use super::shape::Shape;
use super::solver::LANES;
use super::system::RigidSystem;
use super::transform::Transform;
use crate::math::{Real, Vec3};
use crate::parallel::{map_collect, splits};

impl<R: Real> RigidSystem<R> {
    /// Stage 1: recomputes the contact list (see the [module](self) documentation).
    pub(crate) fn collide(&mut self) {
        self.update_bounds();
        let scratch = &mut self.scratch;
        let complete = scratch.broadphase.find_pairs(
            &scratch.aabbs,
            &scratch.active,
            &scratch.present,
            &mut scratch.pairs,
        );
        if !complete {
            // More than MAX_PAIRS boxes overlap: only the contacts with static bodies are
            // looked for this step, and the world reports the cap.
            scratch.capped_steps += 1;
            static_pairs(
                &scratch.aabbs,
                &scratch.active,
                &scratch.present,
                &self.bodies.kind,
                &mut scratch.pairs,
            );
        }
        for &plane in &scratch.planes {
            let p = plane as usize;
            for (i, aabb) in scratch.aabbs.iter().enumerate() {
                if scratch.active[i]
                    && scratch.present[i]
                    && below_plane(&self.bodies.shape[p], aabb)
                {
                    let (a, b) = if p < i { (p, i) } else { (i, p) };
                    scratch.pairs.push((a as u32, b as u32));
                }
            }
        }

        // The broadphase's pairs are in order; the planes' pairs join them here, so that
        // the contacts below come out in key order (one run for the sort to find).
        scratch.pairs.sort();

        if !scratch.joint_filter_valid {
            scratch.joint_filter = self.joints.non_colliding_pairs();
            scratch.joint_filter_valid = true;
        }
        if !scratch.joint_filter.is_empty() {
            let filter = &scratch.joint_filter;
            scratch
                .pairs
                .retain(|pair| filter.binary_search(pair).is_err());
        }
        scratch.sensor_pairs.clear();
        if scratch.layered {
            let filter = &self.bodies.filter;
            scratch
                .pairs
                .retain(|&(a, b)| filter[a as usize].interacts(filter[b as usize]));
        }
        if scratch.sensing {
            let (sensor, sensor_pairs) = (&self.bodies.sensor, &mut scratch.sensor_pairs);
            scratch.pairs.retain(|&(a, b)| {
                let (sa, sb) = (sensor[a as usize], sensor[b as usize]);
                if sa != sb {
                    sensor_pairs.push((a, b));
                }
                !(sa || sb)
            });
        }

        // Last step's lists are read while the new ones are filled, in the storage of the
        // step before (no allocation once it has grown).
        let mut contacts = core::mem::take(&mut scratch.spare_contacts);
        let mut frames = core::mem::take(&mut scratch.spare_frames);
        contacts.clear();
        frames.clear();
        let old = core::mem::take(&mut self.contacts);
        let old_frames = core::mem::take(&mut self.frames);
        let bodies = &self.bodies;
        // A contact keeps its frame, which moves to the new list of frames.
        let keep_frame = |frames: &mut Vec<PairFrame<R>>, mut contact: Contact<R>| {
            if let Some(frame) = old_frames.get(contact.frame as usize) {
                contact.frame = frames.len() as u32;
                frames.push(*frame);
            }
            contact
        };
        for c in &old {
            let (a, b) = (c.key.body_a as usize, c.key.body_b as usize);
            if bodies.alive[a] && bodies.alive[b] && !bodies.is_moving(a) && !bodies.is_moving(b) {
                contacts.push(keep_frame(&mut frames, *c));
            }
        }
        let margin = self.settings.speculative_distance;
        let recycle_distance = self.settings.contact_recycle_distance;
        let pairs = &scratch.pairs;
        let transforms = &scratch.transforms;
        let pose = |a: u32, b: u32| PairPose {
            xf_a: &transforms[a as usize],
            q_a: bodies.orientation[a as usize],
            xf_b: &transforms[b as usize],
            q_b: bodies.orientation[b as usize],
        };
        let collides = |(a, b): (u32, u32)| {
            bodies.kind[a as usize] == BodyKind::Dynamic
                || bodies.kind[b as usize] == BodyKind::Dynamic
        };
        let recycles = |(a, b): (u32, u32)| {
            recycle_distance > R::ZERO
                && recyclable(&bodies.shape[a as usize], &bodies.shape[b as usize])
        };
        find_carried(
            &mut scratch.carried,
            pairs,
            &old,
            |pair| collides(pair) && recycles(pair),
            |c: &Contact<R>| {
                let (a, b) = (c.key.body_a, c.key.body_b);
                old_frames.get(c.frame as usize).is_some_and(|frame| {
                    pose(a, b).near(frame, &bodies.shape[b as usize], recycle_distance)
                })
            },
        );
        let carried = &scratch.carried;
        // The manifolds come in ascending key order (pairs sorted, parts in order), as do
        // last step's contacts: the contacts before `cursor` have keys below every key to
        // come, so finding a manifold's previous contact is a walk, not a search.
        let mut cursor = 0;
        let mut push = |key: ContactKey, found: Found<'_, R>| {
            let pose = pose(key.body_a, key.body_b);
            let contact = match found {
                Found::Carried(index) => {
                    let contact = &old[index as usize];
                    let frame = &old_frames[contact.frame as usize];
                    keep_frame(&mut frames, pose.carried(contact, frame))
                }
                Found::Fresh(manifold) => {
                    while old.get(cursor).is_some_and(|c| c.key < key) {
                        cursor += 1;
                    }
                    let previous = old.get(cursor).filter(|c| c.key == key);
                    let mut contact = Contact::from_manifold(key, manifold, previous);
                    if recycles((key.body_a, key.body_b)) {
                        contact.frame = frames.len() as u32;
                        frames.push(pose.frame(manifold));
                    }
                    contact
                }
            };
            contacts.push(contact);
        };
        let narrowphase = Narrowphase {
            pairs,
            carried,
            bodies,
            transforms,
            margin,
        };
        if splits() && pairs.len() > NARROWPHASE_CHUNK {
            // On the workers: each chunk of pairs finds its manifolds into a list of its own;
            // the lists are then taken in chunk order, so the contacts come in the order the
            // one-thread loop gives them.
            let found = map_collect(pairs.len().div_ceil(NARROWPHASE_CHUNK), 1, |c| {
                let start = c * NARROWPHASE_CHUNK;
                let mut found = Vec::new();
                narrowphase.run(
                    start..(start + NARROWPHASE_CHUNK).min(pairs.len()),
                    |key, f| found.push((key, f.to_owned())),
                );
                found
            });
            for (key, f) in found.iter().flatten() {
                push(*key, f.borrowed());
            }
        } else {
            narrowphase.run(0..pairs.len(), &mut push);
        }
        // Two runs, each in key order (the contacts kept, then the new ones), with distinct
        // keys: the stable sort merges them in one pass and leaves a single run untouched.
        contacts.sort_by_key(|c| c.key);
        self.contacts = contacts;
        self.frames = frames;
        self.record_contact_events(&old);
        if self.scratch.sensing || !self.sensor_overlaps.is_empty() {
            self.update_sensor_overlaps();
        }
        self.scratch.spare_contacts = old;
        self.scratch.spare_frames = old_frames;
    }

    /// The rigid steps of the current tick whose broadphase found more than
    /// [`MAX_PAIRS`](super::broadphase::MAX_PAIRS) overlapping boxes and so kept only the
    /// contacts with static bodies: bodies piled on one spot may then pass through each
    /// other. Not state: it is reset when a tick begins.
    pub fn capped_steps(&self) -> u32 {
        self.scratch.capped_steps
    }

    /// Recomputes placements and boxes: all of them when the cache is not valid, otherwise
    /// those of the moving bodies.
    fn update_bounds(&mut self) {
        let n = self.bodies.len();
        let rebuild = !self.scratch.cache_valid || self.scratch.transforms.len() != n;
        if rebuild {
            let scratch = &mut self.scratch;
            scratch.transforms.clear();
            scratch.transforms.resize(n, Transform::IDENTITY);
            scratch.aabbs.clear();
            scratch.aabbs.resize(n, Aabb::default());
            scratch.present.clear();
            scratch.present.resize(n, false);
            scratch.active.clear();
            scratch.active.resize(n, false);
            scratch.planes.clear();
        }
        let margin = self.settings.speculative_distance;
        for i in 0..n {
            let moving = self.bodies.is_moving(i);
            self.scratch.active[i] = moving;
            if moving || rebuild {
                self.refresh_bounds_of(i, margin);
            }
        }
        if rebuild {
            let b = &self.bodies;
            self.scratch.layered =
                (0..n).any(|i| b.alive[i] && b.filter[i] != CollisionFilter::ALL);
            self.scratch.sensing = (0..n).any(|i| b.alive[i] && b.sensor[i]);
            self.scratch.planes = (0..n)
                .filter(|&i| {
                    self.bodies.alive[i] && matches!(self.bodies.shape[i], Shape::Plane { .. })
                })
                .map(|i| i as u32)
                .collect();
            self.scratch.cache_valid = true;
        }
    }

    /// Recomputes the placement and bounding box of slot `i`.
    pub(crate) fn refresh_bounds_of(&mut self, i: usize, margin: R) {
        let scratch = &mut self.scratch;
        if !self.bodies.alive[i] {
            scratch.present[i] = false;
            return;
        }
        let xf = Transform::from_pose(self.bodies.position[i], self.bodies.orientation[i]);
        scratch.transforms[i] = xf;
        match Aabb::of_shape(&self.bodies.shape[i], &xf) {
            Some(aabb) => {
                scratch.aabbs[i] = aabb.expanded(margin);
                scratch.present[i] = true;
            }
            None => scratch.present[i] = false,
        }
    }
}

/// True when some point of `aabb` lies within the half-space of `plane` (n·x ≤ offset):
/// min over the box of n·x = n·c − |n|·e ≤ offset, with c the centre and e the half extents.
fn below_plane<R: Real>(plane: &Shape<R>, aabb: &Aabb<R>) -> bool {
    let Shape::Plane { normal, offset } = plane else {
        return false;
    };
    let centre = (aabb.min + aabb.max) * R::HALF;
    let half = (aabb.max - aabb.min) * R::HALF;
    normal.dot(centre) - normal.abs().dot(half) <= *offset
}

/// Calls `emit(part_a, part_b, manifold)` for every part pair of the two shapes that has
/// contact points, in ascending (part_a, part_b) order; a compound's parts and a mesh's or
/// heightfield's triangles are numbered, any other shape is part 0. Two meshes never
/// collide.
pub(super) fn for_each_manifold<R: Real>(
    a: &Shape<R>,
    xf_a: &Transform<R>,
    b: &Shape<R>,
    xf_b: &Transform<R>,
    margin: R,
    mut emit: impl FnMut(u32, u32, &Manifold<R>),
) {
    match (a.triangles(), b.triangles()) {
        (Some(_), Some(_)) => return,
        (Some(mesh), None) if !matches!(b, Shape::Compound { .. }) => {
            triangle_manifolds(mesh, xf_a, b, xf_b, margin, |t, manifold| {
                emit(t, 0, &manifold);
            });
            return;
        }
        (Some(mesh), None) => {
            // Triangle-major keys, while B's parts come part by part: sorted here.
            let mut found = Vec::new();
            for_each_part(b, xf_b, |part, shape, placed| {
                triangle_manifolds(mesh, xf_a, shape, placed, margin, |t, manifold| {
                    found.push((t, part, manifold));
                });
            });
            found.sort_unstable_by_key(|&(t, part, _)| (t, part));
            for (t, part, manifold) in &found {
                emit(*t, *part, manifold);
            }
            return;
        }
        (None, Some(mesh)) => {
            for_each_part(a, xf_a, |part, shape, placed| {
                triangle_manifolds(mesh, xf_b, shape, placed, margin, |t, manifold| {
                    emit(part, t, &manifold.flipped());
                });
            });
            return;
        }
        (None, None) => {}
    }
    for_each_part(a, xf_a, |part_a, shape_a, placed_a| {
        for_each_part(b, xf_b, |part_b, shape_b, placed_b| {
            let manifold = collide_convex(shape_a, placed_a, shape_b, placed_b, margin);
            if manifold.count > 0 {
                emit(part_a, part_b, &manifold);
            }
        });
    });
}

/// Calls `emit(t, manifold)` for each triangle t of `mesh` placed by `xf_mesh` whose box
/// overlaps the box of the convex `shape` placed by `xf` grown by `margin` (m), and that
/// touches it within `margin`, in ascending t; the normal points from the triangle to the
/// shape.
fn triangle_manifolds<R: Real>(
    mesh: &TriMesh<R>,
    xf_mesh: &Transform<R>,
    shape: &Shape<R>,
    xf: &Transform<R>,
    margin: R,
    mut emit: impl FnMut(u32, Manifold<R>),
) {
    let Some(aabb) = Aabb::of_shape(shape, xf) else {
        return;
    };
    // The triangles under the box, on the stack unless there are many.
    const FEW: usize = 64;
    let (mut few, mut count, mut many) = ([0u32; FEW], 0, Vec::new());
    mesh.for_each_triangle_in(&aabb.expanded(margin).seen_from(xf_mesh), |t| {
        if count < FEW {
            few[count] = t;
            count += 1;
        } else {
            many.push(t);
        }
    });
    let triangles = if many.is_empty() {
        &mut few[..count]
    } else {
        many.extend_from_slice(&few);
        &mut many[..]
    };
    triangles.sort_unstable();
    for &t in triangles.iter() {
        let manifold = collide_triangle(mesh, t, xf_mesh, shape, xf, margin, true);
        if manifold.count > 0 {
            emit(t, manifold);
        }
    }
}

/// Calls `f(part, shape, placement)` for each convex part of `shape` placed by `xf`.
pub(super) fn for_each_part<R: Real>(
    shape: &Shape<R>,
    xf: &Transform<R>,
    mut f: impl FnMut(u32, &Shape<R>, &Transform<R>),
) {
    match shape {
        Shape::Compound { parts } => {
            for (k, part) in parts.iter().enumerate() {
                let local = Transform::from_pose(part.translation, part.rotation);
                f(k as u32, &part.shape, &xf.compose(&local));
            }
        }
        _ => f(0, shape, xf),
    }
}

/// Where a contact comes from: the narrowphase, or last step's contact at this index,
/// carried ([`super::recycle`]).
enum Found<'a, R: Real> {
    Fresh(&'a Manifold<R>),
    Carried(u32),
}

impl<R: Real> Found<'_, R> {
    /// The same, holding its manifold (to pass it from a worker).
    fn to_owned(&self) -> FoundOwned<R> {
        match *self {
            Found::Fresh(manifold) => FoundOwned::Fresh(*manifold),
            Found::Carried(index) => FoundOwned::Carried(index),
        }
    }
}

/// [`Found`], holding its manifold.
enum FoundOwned<R: Real> {
    Fresh(Manifold<R>),
    Carried(u32),
}

impl<R: Real> FoundOwned<R> {
    fn borrowed(&self) -> Found<'_, R> {
        match self {
            FoundOwned::Fresh(manifold) => Found::Fresh(manifold),
            FoundOwned::Carried(index) => Found::Carried(*index),
        }
    }
}

/// Pairs a worker takes at a time in the narrowphase: enough that a chunk's work (a few
/// microseconds at least) outweighs handing it over.
const NARROWPHASE_CHUNK: usize = 256;

/// What the narrowphase of one step reads: the pairs in key order, which of them carry last
/// step's contact (`u32::MAX`: none), the bodies and their placements, the speculative
/// margin (m).
struct Narrowphase<'a, R: Real> {
    pairs: &'a [(u32, u32)],
    carried: &'a [u32],
    bodies: &'a Bodies<R>,
    transforms: &'a [Transform<R>],
    margin: R,
}

impl<R: Real> Narrowphase<'_, R> {
    /// Whether the pair has a dynamic body (otherwise it has no contact to solve).
    fn collides(&self, (a, b): (u32, u32)) -> bool {
        self.bodies.kind[a as usize] == BodyKind::Dynamic
            || self.bodies.kind[b as usize] == BodyKind::Dynamic
    }

    /// The pair at `index` as a box–box pair, when it is one to test (not carried).
    fn box_pair(&self, index: usize) -> Option<BoxPair<'_, R>> {
        let (a, b) = self.pairs[index];
        if self.carried[index] != u32::MAX {
            // Carried, not recomputed: no separating-axis test.
            return None;
        }
        let (ia, ib) = (a as usize, b as usize);
        match (&self.bodies.shape[ia], &self.bodies.shape[ib]) {
            (Shape::Box { half_extents: ha }, Shape::Box { half_extents: hb })
                if self.collides((a, b)) =>
            {
                Some(BoxPair {
                    half_a: *ha,
                    xf_a: &self.transforms[ia],
                    half_b: *hb,
                    xf_b: &self.transforms[ib],
                })
            }
            _ => None,
        }
    }

    /// Calls `emit(key, found)` for each contact of the pairs `range`, in key order: the
    /// carried ones, and the manifolds with points. Each pair's contacts depend on that pair
    /// alone, so a range gives the contacts the whole list gives for its pairs.
    fn run(&self, range: core::ops::Range<usize>, mut emit: impl FnMut(ContactKey, Found<'_, R>)) {
        let (pairs, carried, margin) = (self.pairs, self.carried, self.margin);
        // Pairs go in runs: from a box–box pair, up to LANES of them, whose separating-axis
        // tests are done together, and the other pairs among them; otherwise the one pair.
        // Every pair of a run, in order, then gets its manifold.
        let unused = BoxPair {
            half_a: Vec3::ZERO,
            xf_a: &Transform::IDENTITY,
            half_b: Vec3::ZERO,
            xf_b: &Transform::IDENTITY,
        };
        let mut boxes = [unused; LANES];
        let mut indices = [usize::MAX; LANES];
        let mut next = range.start;
        while next < range.end {
            let mut count = 0;
            let mut end = next;
            while end < range.end && count < LANES {
                if let Some(pair) = self.box_pair(end) {
                    boxes[count] = pair;
                    indices[count] = end;
                    count += 1;
                } else if count == 0 {
                    end += 1;
                    break;
                }
                end += 1;
            }
            let axes = if count > 0 {
                separating_axes_batch(&boxes[..count], margin)
            } else {
                [None; LANES]
            };
            let mut lane = 0;
            for (index, &(a, b)) in pairs.iter().enumerate().take(end).skip(next) {
                if !self.collides((a, b)) {
                    continue;
                }
                let key = |part_a, part_b| ContactKey {
                    body_a: a,
                    body_b: b,
                    part_a,
                    part_b,
                };
                if carried[index] != u32::MAX {
                    emit(key(0, 0), Found::Carried(carried[index]));
                    continue;
                }
                if lane < count && indices[lane] == index {
                    if let Some(axes) = &axes[lane] {
                        let manifold = box_box_contact(&boxes[lane], axes, margin);
                        if manifold.count > 0 {
                            emit(key(0, 0), Found::Fresh(&manifold));
                        }
                    }
                    lane += 1;
                    continue;
                }
                let (ia, ib) = (a as usize, b as usize);
                let shape = &self.bodies.shape;
                for_each_manifold(
                    &shape[ia],
                    &self.transforms[ia],
                    &shape[ib],
                    &self.transforms[ib],
                    margin,
                    |part_a, part_b, manifold| emit(key(part_a, part_b), Found::Fresh(manifold)),
                );
            }
            next = end;
        }
    }
}

/// Fills `carried` with, for each of `pairs` (in key order, as `old`), the index in `old`
/// of the contact it carries, or `u32::MAX`: the pair must be `recyclable` and last step's
/// contact of its key (parts 0 and 0: the pair is not a compound) must be `near` the pair's
/// pose now (which needs a frame).
fn find_carried<R: Real>(
    carried: &mut Vec<u32>,
    pairs: &[(u32, u32)],
    old: &[Contact<R>],
    recyclable: impl Fn((u32, u32)) -> bool,
    near: impl Fn(&Contact<R>) -> bool,
) {
    carried.clear();
    let mut cursor = 0;
    for &(a, b) in pairs {
        let key = ContactKey {
            body_a: a,
            body_b: b,
            part_a: 0,
            part_b: 0,
        };
        while old.get(cursor).is_some_and(|c| c.key < key) {
            cursor += 1;
        }
        let kept = old
            .get(cursor)
            .is_some_and(|c| c.key == key && recyclable((a, b)) && near(c));
        carried.push(if kept { cursor as u32 } else { u32::MAX });
    }
}
