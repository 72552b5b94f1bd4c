//! Build errors: which field of a scene (or of a snapshot's state) is wrong, and how.

use core::fmt;

use crate::math::{Quat, Real};

/// A scene that cannot be built. `field` is a path such as `particles.emitters[2].rate`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SceneError {
    /// Path of the offending field from the scene root.
    pub field: String,
    /// What is wrong with it.
    pub message: String,
}

impl SceneError {
    /// An error about `field`.
    pub fn new(field: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            field: field.into(),
            message: message.into(),
        }
    }

    /// An error about `field` unless `lo ≤ value ≤ hi`: "must be lo to hi unit (got value)",
    /// `unit` left out when empty.
    pub fn check_range<R: Real>(
        field: impl Into<String>,
        value: R,
        lo: R,
        hi: R,
        unit: &str,
    ) -> Result<(), Self> {
        if lo <= value && value <= hi {
            return Ok(());
        }
        let unit = if unit.is_empty() {
            String::new()
        } else {
            format!(" {unit}")
        };
        Err(Self::new(
            field,
            format!("must be {lo} to {hi}{unit} (got {value})"),
        ))
    }

    /// `q` normalised, or an error about `field` when it is zero. Orientations from a scene
    /// are normalised here, so that every orientation and every joint frame built from one
    /// is a rotation (a snapshot of the world then passes its decoder's checks); any
    /// nonzero q normalises, however long or short ([`Quat::try_normalize`]).
    pub fn unit_quaternion<R: Real>(field: impl Into<String>, q: Quat<R>) -> Result<Quat<R>, Self> {
        q.try_normalize()
            .ok_or_else(|| Self::new(field, "must not be zero"))
    }

    /// The same error seen from one level up: `prefix.field`.
    pub fn within(mut self, prefix: &str) -> Self {
        self.field = if self.field.is_empty() {
            prefix.to_owned()
        } else if self.field.starts_with('[') {
            format!("{prefix}{}", self.field)
        } else {
            format!("{prefix}.{}", self.field)
        };
        self
    }
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "field `{}`: {}", self.field, self.message)
    }
}

impl std::error::Error for SceneError {}
