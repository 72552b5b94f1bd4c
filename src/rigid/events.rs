//! What happened during a tick: contacts that began and ended, bodies that entered and
//! left sensors, joints that broke.
//!
//! Events are derived from state a snapshot carries (the contact list, the sensor
//! overlaps, the joints), so restoring a snapshot and simulating again raises exactly the
//! events of an uninterrupted run, each once per simulated tick. They come in the
//! canonical order of [`Event`]'s fields: tick, kind, body A, body B (A < B).

use core::fmt;

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
}

impl EventKind {
    /// The name written in CSV files and JSON: `contact_begin`, `contact_end`,
    /// `sensor_enter`, `sensor_exit`, `joint_break`.
    pub const fn name(self) -> &'static str {
        match self {
            Self::ContactBegin => "contact_begin",
            Self::ContactEnd => "contact_end",
            Self::SensorEnter => "sensor_enter",
            Self::SensorExit => "sensor_exit",
            Self::JointBreak => "joint_break",
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
    /// lower); for [`EventKind::JointBreak`], the joint.
    pub a: Handle,
    /// The body of higher slot; `None` for [`EventKind::JointBreak`].
    pub b: Option<Handle>,
}
