//! Islands and sleeping.
//!
//! An island is a set of dynamic bodies linked by touching contacts and by joints (static
//! and kinematic bodies do not link islands). A body is *slow* while |v| ≤ the linear sleep speed and
//! |ω| ≤ the angular sleep speed; its sleep time counts the seconds it has been slow. After
//! each step, an island whose bodies have all been slow for at least `time_to_sleep` goes
//! to sleep: velocities are zeroed, and its bodies leave the broadphase's active set and
//! the solver, so a resting island costs nothing until something wakes it.
//!
//! An island wakes as a whole when a moving body touches one of its bodies or is jointed to
//! one, when a command acts on one of its bodies or joints, when one of its joints breaks,
//! or when gravity changes.
//!
//! Islands are found each step with a union-find over the touching contacts in key order
//! and the joints in slot order;
//! each set's root is its lowest slot, so the partition and the roots do not depend on the
//! order of the unions.

use super::desc::BodyKind;
use super::system::RigidSystem;
use crate::math::{Real, Vec3};

impl<R: Real> RigidSystem<R> {
    /// Stage 2: wakes every sleeping island that a moving body touches or is jointed to.
    pub(crate) fn wake_touched(&mut self) {
        let bodies = &self.bodies;
        let joints = &self.joints;
        let sleeping_partner = |a: usize, b: usize| {
            if bodies.is_moving(a) && bodies.asleep[b] {
                Some(bodies.island[b])
            } else if bodies.is_moving(b) && bodies.asleep[a] {
                Some(bodies.island[a])
            } else {
                None
            }
        };
        let mut islands: Vec<u32> = self
            .contacts
            .iter()
            .filter(|c| c.count > 0)
            .filter_map(|c| sleeping_partner(c.key.body_a as usize, c.key.body_b as usize))
            .chain(joints.live().filter_map(|j| {
                sleeping_partner(joints.body_a[j] as usize, joints.body_b[j] as usize)
            }))
            .collect();
        self.wake_islands(&mut islands);
    }

    /// Wakes the islands whose roots are listed (in any order, with repeats).
    pub(crate) fn wake_islands(&mut self, islands: &mut Vec<u32>) {
        if islands.is_empty() {
            return;
        }
        islands.sort_unstable();
        islands.dedup();
        let bodies = &mut self.bodies;
        for i in 0..bodies.len() {
            if bodies.asleep[i] && islands.binary_search(&bodies.island[i]).is_ok() {
                bodies.asleep[i] = false;
                bodies.sleep_time[i] = R::ZERO;
            }
        }
    }

    /// Wakes the island of slot `i`, if it sleeps.
    pub(crate) fn wake_body(&mut self, i: usize) {
        if self.bodies.asleep[i] {
            let mut islands = vec![self.bodies.island[i]];
            self.wake_islands(&mut islands);
        }
        self.bodies.sleep_time[i] = R::ZERO;
    }

    /// Wakes every body.
    pub fn wake_all(&mut self) {
        for i in 0..self.bodies.len() {
            self.bodies.asleep[i] = false;
            self.bodies.sleep_time[i] = R::ZERO;
        }
    }

    /// Stage 4: updates sleep times and puts islands to sleep (see the
    /// [module](self) documentation). `dt` is the step length, s.
    pub(crate) fn update_sleep(&mut self, dt: R) {
        let n = self.bodies.len();
        if !self.settings.sleeping {
            return;
        }
        let lin2 = self.settings.linear_sleep_speed * self.settings.linear_sleep_speed;
        let ang2 = self.settings.angular_sleep_speed * self.settings.angular_sleep_speed;
        let bodies = &mut self.bodies;
        let scratch = &mut self.scratch;
        for i in 0..n {
            if !bodies.is_awake_dynamic(i) {
                continue;
            }
            let slow = bodies.linear_velocity[i].length_squared() <= lin2
                && bodies.angular_velocity[i].length_squared() <= ang2;
            bodies.sleep_time[i] = if slow {
                bodies.sleep_time[i] + dt
            } else {
                R::ZERO
            };
        }

        // Union-find over touching contacts and joints between awake dynamic bodies; a body
        // touching or jointed to a moving kinematic body stays awake.
        let parent = &mut scratch.island_parent;
        parent.clear();
        parent.extend(0..n as u32);
        let touching = self
            .contacts
            .iter()
            .filter(|c| c.count > 0)
            .map(|c| (c.key.body_a as usize, c.key.body_b as usize));
        let joints = &self.joints;
        let jointed = joints
            .live()
            .map(|j| (joints.body_a[j] as usize, joints.body_b[j] as usize));
        for (a, b) in touching.chain(jointed) {
            let (dyn_a, dyn_b) = (bodies.is_awake_dynamic(a), bodies.is_awake_dynamic(b));
            if dyn_a && dyn_b {
                union(parent, a, b);
            } else if dyn_a && kinematic_moving(bodies, b) {
                bodies.sleep_time[a] = R::ZERO;
            } else if dyn_b && kinematic_moving(bodies, a) {
                bodies.sleep_time[b] = R::ZERO;
            }
        }

        // The shortest sleep time of each island, held at its root.
        let island_time = &mut scratch.island_time;
        island_time.clear();
        island_time.resize(n, R::MAX);
        for i in 0..n {
            if bodies.is_awake_dynamic(i) {
                let root = find(parent, i);
                island_time[root] = island_time[root].min(bodies.sleep_time[i]);
            }
        }
        let time_to_sleep = self.settings.time_to_sleep;
        let mut fell_asleep = Vec::new();
        for i in 0..n {
            if bodies.is_awake_dynamic(i) {
                let root = find(parent, i);
                if island_time[root] >= time_to_sleep {
                    bodies.asleep[i] = true;
                    bodies.island[i] = root as u32;
                    bodies.linear_velocity[i] = Vec3::ZERO;
                    bodies.angular_velocity[i] = Vec3::ZERO;
                    fell_asleep.push(i);
                }
            }
        }
        let margin = self.settings.speculative_distance;
        if self.scratch.cache_valid {
            for i in fell_asleep {
                self.refresh_bounds_of(i, margin);
            }
        }
    }
}

fn kinematic_moving<R: Real>(bodies: &super::bodies::Bodies<R>, i: usize) -> bool {
    bodies.alive[i]
        && bodies.kind[i] == BodyKind::Kinematic
        && (bodies.linear_velocity[i] != Vec3::ZERO || bodies.angular_velocity[i] != Vec3::ZERO)
}

/// The root of `i`'s set, halving the path on the way.
fn find(parent: &mut [u32], mut i: usize) -> usize {
    while parent[i] as usize != i {
        let grandparent = parent[parent[i] as usize];
        parent[i] = grandparent;
        i = grandparent as usize;
    }
    i
}

/// Joins the sets of `a` and `b`; the lower root becomes the root of both.
fn union(parent: &mut [u32], a: usize, b: usize) {
    let (ra, rb) = (find(parent, a), find(parent, b));
    if ra < rb {
        parent[rb] = ra as u32;
    } else if rb < ra {
        parent[ra] = rb as u32;
    }
}
