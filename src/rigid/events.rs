//! What happened during a tick: contacts that began and ended, bodies that entered and
//! left sensors, joints that broke.
//!
//! Events are derived from state a snapshot carries (the contact list, the sensor
//! overlaps, the joints), so restoring a snapshot and simulating again raises exactly the
//! events of an uninterrupted run, each once per simulated tick. They come in the
//! canonical order of [`Event`]'s fields: tick, kind, body A, body B (A < B).

use core::fmt;

use super::contact::Contact;
use super::system::RigidSystem;
use crate::math::Real;
use crate::types::Handle;

/// The kinds of event, in their canonical order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum EventKind {
    /// Two bodies came within contact range (their contact has points; a body that
    /// settles on another raises one, however it rocks).
    ContactBegin,
    /// Two bodies that were in contact no longer are, or one of them was removed.
    ContactEnd,
    /// A body began to overlap a sensor.
    SensorEnter,
    /// A body stopped overlapping a sensor, or one of them was removed.
    SensorExit,
    /// A joint broke ([`JointEvent`](super::JointEvent) gives its load).
    JointBreak,
    /// A character ([`crate::character`]) landed: `a` is the character, `b` the body it
    /// landed on.
    CharacterLand,
    /// A character hit a body it did not touch during the previous tick: `a` is the
    /// character, `b` the body.
    CharacterHit,
}

impl EventKind {
    /// The name written in CSV files and JSON: `contact_begin`, `contact_end`,
    /// `sensor_enter`, `sensor_exit`, `joint_break`, `character_land`, `character_hit`.
    pub const fn name(self) -> &'static str {
        match self {
            Self::ContactBegin => "contact_begin",
            Self::ContactEnd => "contact_end",
            Self::SensorEnter => "sensor_enter",
            Self::SensorExit => "sensor_exit",
            Self::JointBreak => "joint_break",
            Self::CharacterLand => "character_land",
            Self::CharacterHit => "character_hit",
        }
    }
}

impl fmt::Display for EventKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// One event. Fields are in canonical order, so sorting events sorts them canonically.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Event {
    /// The tick during which it happened (the world's tick count before the tick ran).
    pub tick: u64,
    /// What happened.
    pub kind: EventKind,
    /// The body of lower slot (for a sensor event, sensor or visitor, whichever is
    /// lower); for [`EventKind::JointBreak`], the joint; for a character event, the
    /// character.
    pub a: Handle,
    /// The body of higher slot; `None` for [`EventKind::JointBreak`].
    pub b: Option<Handle>,
}

impl<R: Real> RigidSystem<R> {
    /// The events of the last tick, in canonical order.
    pub fn events(&self) -> &[Event] {
        &self.scratch.events
    }

    /// Forgets the previous tick's events, broken joints and capped steps; the events to come belong to
    /// `tick`. The world calls it before the tick's inputs, whose removals raise events.
    pub(crate) fn begin_events(&mut self, tick: u64) {
        self.scratch.events.clear();
        self.scratch.event_tick = tick;
        self.scratch.capped_steps = 0;
        self.scratch.spawned.clear();
        self.scratch.spawned_joints.clear();
        self.clear_joint_events();
    }

    /// Records an event of the current tick between slots `a` and `b` (in any order).
    pub(crate) fn push_pair_event(&mut self, kind: EventKind, a: u32, b: u32) {
        let (a, b) = (a.min(b) as usize, a.max(b) as usize);
        let event = Event {
            tick: self.scratch.event_tick,
            kind,
            a: self.bodies.handle(a),
            b: Some(self.bodies.handle(b)),
        };
        self.scratch.events.push(event);
    }

    /// Records the break of `joint`.
    pub(crate) fn push_joint_break(&mut self, joint: Handle) {
        let event = Event {
            tick: self.scratch.event_tick,
            kind: EventKind::JointBreak,
            a: joint,
            b: None,
        };
        self.scratch.events.push(event);
    }

    /// Records a character's event (`a` the character, `b` the body) in the current tick.
    pub(crate) fn push_character_event(
        &mut self,
        kind: EventKind,
        character: Handle,
        body: Handle,
    ) {
        let event = Event {
            tick: self.scratch.event_tick,
            kind,
            a: character,
            b: Some(body),
        };
        self.scratch.events.push(event);
    }

    /// Puts the tick's events in canonical order (several substeps append in turn).
    pub(crate) fn sort_events(&mut self) {
        self.scratch.events.sort_unstable();
    }

    /// After a collide stage: a `contact_begin` for each body pair with a contact now and
    /// none in `old` (last step's contacts), a `contact_end` for each pair the other way.
    /// Both lists are sorted by key, so their body pairs come in ascending order and one
    /// merge finds the differences.
    pub(crate) fn record_contact_events(&mut self, old: &[Contact<R>]) {
        let mut found = Vec::new();
        sorted_difference(
            distinct_pairs(old),
            distinct_pairs(&self.contacts),
            |pair, began| {
                let kind = if began {
                    EventKind::ContactBegin
                } else {
                    EventKind::ContactEnd
                };
                found.push((kind, pair));
            },
        );
        for (kind, (a, b)) in found {
            self.push_pair_event(kind, a, b);
        }
    }
}

/// Walks two ascending lists without repeats in one merge: `changed(item, true)` for each
/// item of `after` missing from `before` (it began), `changed(item, false)` for each item of
/// `before` missing from `after` (it ended), in ascending order.
pub(super) fn sorted_difference<T: Ord + Copy>(
    before: impl Iterator<Item = T>,
    after: impl Iterator<Item = T>,
    mut changed: impl FnMut(T, bool),
) {
    let (mut before, mut after) = (before.peekable(), after.peekable());
    loop {
        let began = match (before.peek(), after.peek()) {
            (None, None) => break,
            (Some(p), Some(q)) if p == q => {
                before.next();
                after.next();
                continue;
            }
            (Some(p), Some(q)) => q < p,
            (Some(_), None) => false,
            (None, Some(_)) => true,
        };
        let item = if began { after.next() } else { before.next() };
        if let Some(item) = item {
            changed(item, began);
        }
    }
}

/// The distinct (body A, body B) pairs of contacts sorted by key, in order.
fn distinct_pairs<R: Real>(contacts: &[Contact<R>]) -> impl Iterator<Item = (u32, u32)> + '_ {
    let mut last = None;
    contacts.iter().filter_map(move |c| {
        let pair = (c.key.body_a, c.key.body_b);
        (last.replace(pair) != Some(pair)).then_some(pair)
    })
}
