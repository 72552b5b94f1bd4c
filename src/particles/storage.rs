//! Structure-of-arrays particle storage: one `Vec` per attribute, indexed by slot.
//!
//! # Slots
//!
//! The arrays grow one slot at a time up to the capacity and never shrink. A slot is alive
//! or dead. Killing a particle bumps its slot's generation, so every [`Handle`] to it goes
//! stale at once, and zeroes its inverse mass, so the integrators skip dead and pinned
//! slots with one test (`inv_mass == 0`).
//!
//! # Recycling order
//!
//! A new particle takes the **lowest-index dead slot**; only when no slot is dead does the
//! storage grow by one slot at the end. `lowest_free` caches that index (it is always the
//! lowest dead index, or the slot count when none is dead), so it is a function of the alive
//! flags and the same on every peer.

use serde::{Deserialize, Serialize};

use crate::math::{Real, Vec3};
use crate::types::Handle;
use crate::types::Target;

/// The attributes integrators change: positions, velocities and their history.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Kinematics<R: Real> {
    /// x, m.
    pub positions: Vec<Vec3<R>>,
    /// v, m/s.
    pub velocities: Vec<Vec3<R>>,
    /// x at the previous step, m (Störmer–Verlet only).
    pub previous_positions: Vec<Vec3<R>>,
    /// Whether `previous_positions` holds the previous step's position. False after a spawn
    /// or a velocity change; Störmer–Verlet then starts over from (x, v).
    pub has_previous_position: Vec<bool>,
    /// a(x, v) at the end of the last step, m/s² (velocity Verlet only).
    pub accelerations: Vec<Vec3<R>>,
}

/// The attributes integrators read but do not change.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Attributes<R: Real> {
    /// 1/m, 1/kg; 0 for pinned and dead slots.
    pub inv_masses: Vec<R>,
    /// m, kg; 0 for pinned and dead slots.
    pub masses: Vec<R>,
    /// Force applied by commands during the current tick, N.
    pub external_forces: Vec<Vec3<R>>,
    /// Seconds left to live; 0 means immortal.
    pub lifetimes: Vec<R>,
    /// Group of each particle.
    pub groups: Vec<u16>,
    /// Whether the slot holds a particle.
    pub alive: Vec<bool>,
    /// Bumped every time the slot's particle dies.
    pub generations: Vec<u32>,
}

impl<R: Real> Attributes<R> {
    /// True when slot `i` holds a particle that forces can move.
    #[inline(always)]
    pub fn is_movable(&self, i: usize) -> bool {
        self.inv_masses[i] != R::ZERO
    }

    /// True when slot `i` holds a pinned particle.
    #[inline(always)]
    pub fn is_pinned(&self, i: usize) -> bool {
        self.alive[i] && self.inv_masses[i] == R::ZERO
    }

    /// The slot `handle` refers to, if its particle is still alive.
    #[inline]
    pub fn resolve(&self, handle: Handle) -> Option<usize> {
        let i = handle.index as usize;
        (i < self.alive.len() && self.alive[i] && self.generations[i] == handle.generation)
            .then_some(i)
    }
}

/// A particle about to be created.
#[derive(Clone, Copy, Debug)]
pub(crate) struct NewParticle<R: Real> {
    pub position: Vec3<R>,
    pub velocity: Vec3<R>,
    pub mass: R,
    /// 1/mass, or 0 when `mass` is 0 (pinned).
    pub inv_mass: R,
    pub group: u16,
    /// Seconds; 0 means immortal.
    pub lifetime: R,
}

/// The particle arrays and the slot allocator.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct ParticleStorage<R: Real> {
    pub kinematics: Kinematics<R>,
    pub attributes: Attributes<R>,
    capacity: u32,
    /// The lowest dead slot, or the slot count when every slot is alive.
    lowest_free: u32,
    live_count: u32,
}

impl<R: Real> ParticleStorage<R> {
    /// Empty storage that will hold at most `capacity` particles at once.
    pub fn new(capacity: u32) -> Self {
        Self {
            kinematics: Kinematics::default(),
            attributes: Attributes::default(),
            capacity,
            lowest_free: 0,
            live_count: 0,
        }
    }

    /// Slots in use or recyclable (the length of every array).
    #[inline]
    pub fn slot_count(&self) -> usize {
        self.attributes.alive.len()
    }

    /// The most particles alive at once.
    pub fn capacity(&self) -> u32 {
        self.capacity
    }

    /// Particles alive.
    pub fn live_count(&self) -> u32 {
        self.live_count
    }

    /// The lowest dead slot, or the slot count when every slot is alive.
    pub fn lowest_free(&self) -> u32 {
        self.lowest_free
    }

    /// True when a new particle would not fit.
    #[inline]
    pub fn is_full(&self) -> bool {
        self.live_count >= self.capacity
    }

    /// The handle of the particle in slot `i` (alive or not).
    #[inline]
    pub fn handle(&self, i: usize) -> Handle {
        Handle::new(i as u32, self.attributes.generations[i])
    }

    /// Creates a particle in the lowest dead slot (or a new slot at the end) and returns its
    /// handle; `None` when the storage is full.
    pub fn allocate(&mut self, particle: NewParticle<R>) -> Option<Handle> {
        if self.is_full() {
            return None;
        }
        let i = self.lowest_free as usize;
        if i == self.slot_count() {
            self.push_dead_slot();
        }
        let k = &mut self.kinematics;
        k.positions[i] = particle.position;
        k.velocities[i] = particle.velocity;
        k.previous_positions[i] = particle.position;
        k.has_previous_position[i] = false;
        k.accelerations[i] = Vec3::ZERO;
        let a = &mut self.attributes;
        a.inv_masses[i] = particle.inv_mass;
        a.masses[i] = particle.mass;
        a.external_forces[i] = Vec3::ZERO;
        a.lifetimes[i] = particle.lifetime;
        a.groups[i] = particle.group;
        a.alive[i] = true;
        self.live_count += 1;
        self.lowest_free = self.next_dead_slot_from(i + 1);
        Some(self.handle(i))
    }

    /// Kills the particle in slot `i` (which must be alive): its handles go stale and the
    /// slot becomes the first candidate for reuse if it is the lowest dead one.
    pub fn kill(&mut self, i: usize) {
        let a = &mut self.attributes;
        debug_assert!(a.alive[i], "killing dead slot {i}");
        a.alive[i] = false;
        a.generations[i] = a.generations[i].wrapping_add(1);
        a.inv_masses[i] = R::ZERO;
        a.masses[i] = R::ZERO;
        a.external_forces[i] = Vec3::ZERO;
        a.lifetimes[i] = R::ZERO;
        self.live_count -= 1;
        self.lowest_free = self.lowest_free.min(i as u32);
    }

    /// Ages every mortal particle by `dt` seconds and kills those whose remaining lifetime
    /// drops to `dt/2` or less (so a lifetime of L seconds lasts round(L/dt) steps). Returns
    /// how many died.
    pub fn age(&mut self, dt: R) -> u32 {
        let half_dt = dt * R::HALF;
        let mut expired = 0;
        for i in 0..self.slot_count() {
            let lifetime = self.attributes.lifetimes[i];
            if lifetime == R::ZERO {
                continue;
            }
            let remaining = lifetime - dt;
            if remaining <= half_dt {
                self.kill(i);
                expired += 1;
            } else {
                self.attributes.lifetimes[i] = remaining;
            }
        }
        expired
    }

    /// The slots a command target can match: one slot for a live particle handle (none for a
    /// stale one), every slot for a group. Filter with [`ParticleStorage::matches`].
    pub fn candidate_slots(&self, target: Target) -> core::ops::Range<usize> {
        match target {
            Target::Particle(handle) => match self.attributes.resolve(handle) {
                Some(i) => i..i + 1,
                None => 0..0,
            },
            Target::ParticleGroup(_) => 0..self.slot_count(),
            Target::Body(_) | Target::SoftAttachment(_) | Target::Joint(_) => 0..0,
        }
    }

    /// True when the live particle in slot `i` is (in) `target`.
    #[inline]
    pub fn matches(&self, i: usize, target: Target) -> bool {
        let a = &self.attributes;
        a.alive[i]
            && match target {
                Target::Particle(handle) => a.generations[i] == handle.generation,
                Target::ParticleGroup(group) => a.groups[i] == group,
                Target::Body(_) | Target::SoftAttachment(_) | Target::Joint(_) => false,
            }
    }

    /// Appends a dead slot with generation 0 to every array.
    fn push_dead_slot(&mut self) {
        let k = &mut self.kinematics;
        k.positions.push(Vec3::ZERO);
        k.velocities.push(Vec3::ZERO);
        k.previous_positions.push(Vec3::ZERO);
        k.has_previous_position.push(false);
        k.accelerations.push(Vec3::ZERO);
        let a = &mut self.attributes;
        a.inv_masses.push(R::ZERO);
        a.masses.push(R::ZERO);
        a.external_forces.push(Vec3::ZERO);
        a.lifetimes.push(R::ZERO);
        a.groups.push(0);
        a.alive.push(false);
        a.generations.push(0);
    }

    /// The first dead slot at or after `start`, or the slot count.
    fn next_dead_slot_from(&self, start: usize) -> u32 {
        let alive = &self.attributes.alive;
        (start..alive.len())
            .find(|&i| !alive[i])
            .unwrap_or(alive.len()) as u32
    }
}
