//! Why a replay file cannot be used: one line that names the file, the section and, where it
//! applies, the byte offset.

use core::fmt;

use super::format::{FORMAT_VERSION, MAGIC, Section};
use crate::math::{Fx, Real};
use crate::world::STATE_VERSION;

/// A replay that cannot be read, written or simulated.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReplayError {
    /// The file (or other origin) the bytes came from.
    pub origin: String,
    /// What is wrong.
    pub kind: ReplayErrorKind,
}

/// What is wrong with a replay.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ReplayErrorKind {
    /// The file could not be opened or read; the text says why.
    Unreadable(String),
    /// The file is larger than any replay this build writes.
    TooLarge {
        /// File length in bytes.
        len: u64,
        /// The largest accepted length.
        limit: u64,
    },
    /// The file has no bytes at all.
    Empty,
    /// The first eight bytes are not [`MAGIC`].
    NotAReplay {
        /// The bytes found (up to eight).
        magic: Vec<u8>,
    },
    /// A format version other than [`FORMAT_VERSION`].
    FormatVersion(u32),
    /// The file ends before `section` does.
    Truncated {
        /// The section that is cut short.
        section: Section,
        /// Where the file ends.
        offset: u64,
        /// How many more bytes were needed, as text ("8 more bytes needed").
        needed: String,
    },
    /// A section's content hash does not match the header.
    Corrupted {
        /// The damaged section.
        section: Section,
        /// First byte of the section.
        start: u64,
        /// One past its last byte.
        end: u64,
    },
    /// A section decodes to something invalid.
    Malformed {
        /// The section.
        section: Section,
        /// Byte offset of the problem (the section start when not known more precisely).
        offset: u64,
        /// What is wrong.
        detail: String,
    },
    /// The replay was recorded by an engine with another state version.
    StateVersion {
        /// The version in the file.
        recorded: u32,
    },
    /// The replay was recorded with another scalar format.
    Scalar {
        /// The format named in the file.
        recorded: String,
    },
    /// The replay's scene does not build a world.
    Scene(String),
    /// The replay could not be encoded or written.
    Write(String),
}

impl ReplayError {
    /// An error about `origin`.
    pub fn new(origin: impl Into<String>, kind: ReplayErrorKind) -> Self {
        Self {
            origin: origin.into(),
            kind,
        }
    }
}

impl fmt::Display for ReplayError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.origin, self.kind)
    }
}

impl fmt::Display for ReplayErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Unreadable(why) => write!(f, "cannot read: {why}"),
            Self::TooLarge { len, limit } => write!(
                f,
                "file is {len} bytes, larger than any replay ({limit} bytes at most)"
            ),
            Self::Empty => f.write_str("empty file, not a fixstep replay"),
            Self::NotAReplay { magic } => write!(
                f,
                "not a fixstep replay (magic \"{}\", expected \"{}\")",
                magic.escape_ascii(),
                MAGIC.escape_ascii()
            ),
            Self::FormatVersion(version) => write!(
                f,
                "replay format version {version}; this build reads version {FORMAT_VERSION}"
            ),
            Self::Truncated {
                section,
                offset,
                needed,
            } => write!(
                f,
                "truncated in the {section} at byte offset {offset}: {needed}"
            ),
            Self::Corrupted {
                section,
                start,
                end,
            } => write!(
                f,
                "{section} is corrupted (content hash mismatch), bytes {start}..{end}"
            ),
            Self::Malformed {
                section,
                offset,
                detail,
            } => write!(f, "{section} at byte offset {offset}: {detail}"),
            Self::StateVersion { recorded } if *recorded > STATE_VERSION => write!(
                f,
                "recorded with engine state version {recorded}; this build simulates version \
                 {STATE_VERSION} — it needs a newer fixstep"
            ),
            Self::StateVersion { recorded } => write!(
                f,
                "recorded with engine state version {recorded}; this build simulates version \
                 {STATE_VERSION} — re-record it (scripts/rerecord.sh)"
            ),
            Self::Scalar { recorded } => write!(
                f,
                "recorded with scalar format {recorded:?}; this build simulates {:?}",
                Fx::NAME
            ),
            Self::Scene(why) => write!(f, "scene section: {why}"),
            Self::Write(why) => write!(f, "cannot write: {why}"),
        }
    }
}

impl std::error::Error for ReplayError {}
