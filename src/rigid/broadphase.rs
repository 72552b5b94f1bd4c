//! Broadphase (being written).
