//! The one error of reading and building a scene: which file, line and field (or which field
//! of a snapshot's state) is wrong, and how.

use core::fmt;

use crate::math::{Quat, Real};

/// A scene that cannot be read or built: the file it came from and the line and column
/// where reading stopped (when known), the field that is wrong (a path such as
/// `particles.emitters[2].rate`, empty when the error is not about one field) and what is
/// wrong. Its `Display` is one line: `FILE: line L, column C: field `F`: MESSAGE`, each part
/// present only when known.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SceneError {
    /// The file (or other origin, such as `inline`) the scene was read from; `None` for a
    /// scene built in code.
    pub file: Option<String>,
    /// Line and column (from 1) where reading the file stopped; `None` for an error found
    /// after reading, when building.
    pub line: Option<(usize, usize)>,
    /// Path of the offending field from the scene root; empty when the error is about the
    /// file as a whole.
    pub field: String,
    /// What is wrong with it.
    pub message: String,
}

impl SceneError {
    /// An error about `field`.
    pub fn new(field: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            file: None,
            line: None,
            field: field.into(),
            message: message.into(),
        }
    }

    /// An error about the file `file` as a whole (it cannot be read, it is not text, …).
    pub fn in_file(file: impl Into<String>, message: impl Into<String>) -> Self {
        Self::new("", message).with_file(file)
    }

    /// The same error, found in the file `file`.
    pub fn with_file(mut self, file: impl Into<String>) -> Self {
        self.file = Some(file.into());
        self
    }

    /// The same error, found where reading stopped: `line` and `column`, from 1.
    pub fn at_line(mut self, line: usize, column: usize) -> Self {
        self.line = Some((line, column));
        self
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
        if let Some(file) = &self.file {
            write!(f, "{file}: ")?;
        }
        if let Some((line, column)) = self.line {
            write!(f, "line {line}, column {column}: ")?;
        }
        if !self.field.is_empty() {
            write!(f, "field `{}`: ", self.field)?;
        }
        f.write_str(&self.message)
    }
}

impl std::error::Error for SceneError {}
