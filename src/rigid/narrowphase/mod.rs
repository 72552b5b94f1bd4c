//! Narrowphase (being written).
