//! Reading replay files: every check of the format, in file order, with one clear error.
//!
//! Nothing is allocated from a length field before it is checked: section lengths are
//! compared with the section limit and with the bytes left in the file, and each section is
//! decoded from a slice of exactly its length. Inside a section, the codec refuses strings
//! longer than [`SIZE_LIMIT`]; bincode's serde path does not check sequence lengths against
//! that limit, but serde preallocates at most 1 MiB for a sequence and then decodes element
//! by element, so a bogus count runs out of section bytes instead of memory.

use core::num::NonZeroU32;
use std::path::Path;

use serde::de::DeserializeOwned;

use super::error::{ReplayError, ReplayErrorKind};
use super::file::Replay;
use super::format::{
    Checkpoint, FORMAT_VERSION, MAGIC, PREAMBLE_LEN, ReplayHeader, Section, content_hash,
};
use super::scene_section::{SceneSectionError, decode_scene};
use crate::codec::{self, CodecError, SIZE_LIMIT};
use crate::math::{Fx, Real};
use crate::scene::Scene;
use crate::types::{InputFileError, read_input_file};
use crate::world::{STATE_VERSION, TickInput};

/// The largest file accepted: three sections at the codec limit plus room for the header.
pub const MAX_FILE_LEN: u64 = 4 * SIZE_LIMIT as u64;

/// Distances from header fields to the end of the header (every field after `scalar` has a
/// fixed size), for naming their byte offsets.
const CHECKSUM_EVERY_FROM_END: usize = 36;
const SCENE_LEN_FROM_END: usize = 32;
const INPUTS_LEN_FROM_END: usize = 16;

/// The longest scalar name a header may hold; longer is damage, not a format.
const MAX_SCALAR_NAME_LEN: u64 = 32;

/// Which engine state versions a read accepts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StateVersionCheck {
    /// Only [`STATE_VERSION`]: the replay can be verified by this build.
    Current,
    /// [`STATE_VERSION`] or older: the replay's scene and inputs can be re-recorded.
    CurrentOrOlder,
}

impl Replay {
    /// Reads and checks a replay file recorded with this build's state version.
    pub fn read(path: &Path) -> Result<Replay, ReplayError> {
        Self::read_with(path, StateVersionCheck::Current)
    }

    /// Reads and checks a replay file, accepting the state versions `check` allows.
    pub fn read_with(path: &Path, check: StateVersionCheck) -> Result<Replay, ReplayError> {
        let origin = path.display().to_string();
        let bytes = read_file(path, &origin)?;
        Self::from_bytes_with(&bytes, &origin, check)
    }

    /// Decodes and checks a replay recorded with this build's state version. `origin`
    /// names the bytes in error messages.
    pub fn from_bytes(bytes: &[u8], origin: &str) -> Result<Replay, ReplayError> {
        Self::from_bytes_with(bytes, origin, StateVersionCheck::Current)
    }

    /// Decodes and checks a replay, accepting the state versions `check` allows.
    pub fn from_bytes_with(
        bytes: &[u8],
        origin: &str,
        check: StateVersionCheck,
    ) -> Result<Replay, ReplayError> {
        Decoder { bytes, origin }.replay(check)
    }
}

/// Reads a whole regular file of at most [`MAX_FILE_LEN`] bytes.
fn read_file(path: &Path, origin: &str) -> Result<Vec<u8>, ReplayError> {
    read_input_file(path, MAX_FILE_LEN, "a replay file").map_err(|e| {
        let kind = match e {
            InputFileError::TooLarge { len, limit, .. } => ReplayErrorKind::TooLarge { len, limit },
            InputFileError::Unreadable(why) => ReplayErrorKind::Unreadable(why),
            other @ InputFileError::NotAFile { .. } => {
                ReplayErrorKind::Unreadable(other.to_string())
            }
        };
        ReplayError::new(origin, kind)
    })
}

/// The bytes of one file being decoded, and their name for messages.
struct Decoder<'a> {
    bytes: &'a [u8],
    origin: &'a str,
}

impl Decoder<'_> {
    fn error(&self, kind: ReplayErrorKind) -> ReplayError {
        ReplayError::new(self.origin, kind)
    }

    fn malformed(&self, section: Section, offset: usize, detail: String) -> ReplayError {
        self.error(ReplayErrorKind::Malformed {
            section,
            offset: offset as u64,
            detail,
        })
    }

    /// The little-endian `u64` at byte `at`, if the file is long enough.
    fn u64_at(&self, at: usize) -> Option<u64> {
        let raw = self.bytes.get(at..at.checked_add(8)?)?;
        let mut value = [0; 8];
        value.copy_from_slice(raw);
        Some(u64::from_le_bytes(value))
    }

    /// The file ends inside `section`.
    fn truncated(&self, section: Section, needed: String) -> ReplayError {
        self.error(ReplayErrorKind::Truncated {
            section,
            offset: self.bytes.len() as u64,
            needed,
        })
    }

    fn replay(&self, check: StateVersionCheck) -> Result<Replay, ReplayError> {
        self.preamble()?;
        let (header, header_end) = self.header()?;
        self.check_versions(&header, check)?;
        let checksum_every = NonZeroU32::new(header.checksum_every).ok_or_else(|| {
            self.malformed(
                Section::Header,
                header_end - CHECKSUM_EVERY_FROM_END,
                "checksum_every is 0".to_owned(),
            )
        })?;

        let scene_start = header_end + 8;
        let scene_bytes = self.section(
            Section::Scene,
            scene_start,
            header.scene_len,
            header.scene_hash,
            header_end - SCENE_LEN_FROM_END,
        )?;
        let scene = self.scene_section(scene_start, scene_bytes)?;
        self.check_scene(&scene, &header, scene_start)?;

        let inputs_start = scene_start + scene_bytes.len();
        let inputs_bytes = self.section(
            Section::Inputs,
            inputs_start,
            header.inputs_len,
            header.inputs_hash,
            header_end - INPUTS_LEN_FROM_END,
        )?;
        let inputs: Vec<TickInput<Fx>> =
            self.decode_section(Section::Inputs, inputs_start, inputs_bytes)?;
        self.check_inputs(&inputs, header.ticks, inputs_start)?;

        let checksums_start = inputs_start + inputs_bytes.len();
        let checkpoints = self.checkpoints(checksums_start)?;
        self.check_checkpoints(&checkpoints, header.ticks, checksum_every, checksums_start)?;

        Ok(Replay {
            state_version: header.state_version,
            scene,
            inputs,
            ticks: header.ticks,
            checksum_every,
            checkpoints,
        })
    }

    /// Magic and format version, read raw.
    fn preamble(&self) -> Result<(), ReplayError> {
        let bytes = self.bytes;
        if bytes.is_empty() {
            return Err(self.error(ReplayErrorKind::Empty));
        }
        let magic = &bytes[..bytes.len().min(MAGIC.len())];
        if magic != &MAGIC[..magic.len()] {
            return Err(self.error(ReplayErrorKind::NotAReplay {
                magic: magic.to_vec(),
            }));
        }
        if bytes.len() < PREAMBLE_LEN {
            return Err(self.truncated(
                Section::Preamble,
                format!("{} more bytes needed", PREAMBLE_LEN - bytes.len()),
            ));
        }
        let mut version = [0; 4];
        version.copy_from_slice(&bytes[MAGIC.len()..PREAMBLE_LEN]);
        match u32::from_le_bytes(version) {
            FORMAT_VERSION => Ok(()),
            other => Err(self.error(ReplayErrorKind::FormatVersion(other))),
        }
    }

    /// The header and its hash; returns the header and the offset where it ends (where the
    /// header hash starts).
    fn header(&self) -> Result<(ReplayHeader, usize), ReplayError> {
        // The scalar name's length, read raw so that a damaged one cannot make the codec
        // allocate up to its limit before the header hash is checked.
        let scalar_len_at = PREAMBLE_LEN + 4;
        if let Some(len) = self.u64_at(scalar_len_at)
            && len > MAX_SCALAR_NAME_LEN
        {
            return Err(self.malformed(
                Section::Header,
                scalar_len_at,
                format!(
                    "scalar name length {len} is not plausible (at most {MAX_SCALAR_NAME_LEN})"
                ),
            ));
        }
        let (header, used) = codec::decode_prefix::<ReplayHeader>(&self.bytes[PREAMBLE_LEN..])
            .map_err(|e| match truncation(&e) {
                Some(needed) => self.truncated(Section::Header, needed.to_owned()),
                None => self.malformed(Section::Header, PREAMBLE_LEN, e.0),
            })?;
        let header_end = PREAMBLE_LEN + used;
        let Some(stored) = self.u64_at(header_end) else {
            let needed = header_end + 8 - self.bytes.len();
            return Err(self.truncated(Section::Header, format!("{needed} more bytes needed")));
        };
        if stored != content_hash(&self.bytes[..header_end]) {
            return Err(self.error(ReplayErrorKind::Corrupted {
                section: Section::Header,
                start: 0,
                end: header_end as u64 + 8,
            }));
        }
        Ok((header, header_end))
    }

    fn check_versions(
        &self,
        header: &ReplayHeader,
        check: StateVersionCheck,
    ) -> Result<(), ReplayError> {
        if header.scalar != Fx::NAME {
            return Err(self.error(ReplayErrorKind::Scalar {
                recorded: header.scalar.clone(),
            }));
        }
        let accepted = match check {
            StateVersionCheck::Current => header.state_version == STATE_VERSION,
            StateVersionCheck::CurrentOrOlder => header.state_version <= STATE_VERSION,
        };
        if accepted {
            Ok(())
        } else {
            Err(self.error(ReplayErrorKind::StateVersion {
                recorded: header.state_version,
            }))
        }
    }

    /// The `len` bytes of `section` from `start`, after checking the length (whose field is
    /// at `len_field_at`) and the content hash.
    fn section(
        &self,
        section: Section,
        start: usize,
        len: u64,
        hash: u64,
        len_field_at: usize,
    ) -> Result<&[u8], ReplayError> {
        if len > SIZE_LIMIT as u64 {
            return Err(self.malformed(
                Section::Header,
                len_field_at,
                format!("the {section} length {len} exceeds the {SIZE_LIMIT}-byte limit"),
            ));
        }
        let available = self.bytes.len().saturating_sub(start);
        let len = len as usize;
        if len > available {
            return Err(self.truncated(section, format!("{} more bytes needed", len - available)));
        }
        let bytes = &self.bytes[start..start + len];
        if content_hash(bytes) != hash {
            return Err(self.error(ReplayErrorKind::Corrupted {
                section,
                start: start as u64,
                end: (start + len) as u64,
            }));
        }
        Ok(bytes)
    }

    /// Decodes a value that fills exactly the section's bytes.
    /// The scene section (see [`scene_section`](super::scene_section)).
    fn scene_section(&self, start: usize, bytes: &[u8]) -> Result<Scene<Fx>, ReplayError> {
        decode_scene(bytes).map_err(|(at, e)| {
            let detail = match e {
                SceneSectionError::Codec(e) => match truncation(&e) {
                    Some(needed) => format!(
                        "does not decode: a length or value runs past the end of the section \
                         ({needed})"
                    ),
                    None => format!("does not decode: {e}"),
                },
                SceneSectionError::Trailing(n) => {
                    format!("{n} bytes left over after the section's value")
                }
                SceneSectionError::NotCanonical(what) => format!("not canonical: {what}"),
            };
            self.malformed(Section::Scene, start + at, detail)
        })
    }

    fn decode_section<T: DeserializeOwned>(
        &self,
        section: Section,
        start: usize,
        bytes: &[u8],
    ) -> Result<T, ReplayError> {
        let (value, used) = codec::decode_prefix::<T>(bytes).map_err(|e| {
            let detail = match truncation(&e) {
                Some(needed) => format!(
                    "does not decode: a length or value runs past the end of the section \
                     ({needed})"
                ),
                None => format!("does not decode: {e}"),
            };
            self.malformed(section, start, detail)
        })?;
        if used != bytes.len() {
            return Err(self.malformed(
                section,
                start + used,
                format!(
                    "{} bytes left over after the section's value",
                    bytes.len() - used
                ),
            ));
        }
        Ok(value)
    }

    fn check_scene(
        &self,
        scene: &Scene<Fx>,
        header: &ReplayHeader,
        start: usize,
    ) -> Result<(), ReplayError> {
        let detail = if !scene.script.is_empty() {
            "the scene has a script; its inputs belong in the inputs section".to_owned()
        } else if scene.tick_rate != header.tick_rate {
            format!(
                "the scene's tick_rate {} disagrees with the header's {}",
                scene.tick_rate, header.tick_rate
            )
        } else if scene.seed != header.seed {
            format!(
                "the scene's seed {} disagrees with the header's {}",
                scene.seed, header.seed
            )
        } else {
            return Ok(());
        };
        Err(self.malformed(Section::Scene, start, detail))
    }

    /// Inputs must be canonical (see [`input_problem`]).
    fn check_inputs(
        &self,
        inputs: &[TickInput<Fx>],
        ticks: u64,
        start: usize,
    ) -> Result<(), ReplayError> {
        let mut previous: Option<u64> = None;
        for (i, input) in inputs.iter().enumerate() {
            if let Some(problem) = input_problem(input, previous, ticks) {
                return Err(self.malformed(
                    Section::Inputs,
                    start,
                    format!("input {i}: {problem}"),
                ));
            }
            previous = Some(input.tick);
        }
        Ok(())
    }

    /// The checksums section: everything from `start` to the end of the file.
    fn checkpoints(&self, start: usize) -> Result<Vec<Checkpoint>, ReplayError> {
        let bytes = &self.bytes[start..];
        let (checkpoints, used) =
            codec::decode_prefix::<Vec<Checkpoint>>(bytes).map_err(|e| match truncation(&e) {
                Some(needed) => self.truncated(Section::Checksums, needed.to_owned()),
                None => self.malformed(Section::Checksums, start, format!("does not decode: {e}")),
            })?;
        if used != bytes.len() {
            return Err(self.malformed(
                Section::Checksums,
                start + used,
                format!(
                    "{} unexpected bytes after the end of the file's last section",
                    bytes.len() - used
                ),
            ));
        }
        Ok(checkpoints)
    }

    /// Checkpoints must sit at tick 0, every multiple of `every`, and `ticks`.
    fn check_checkpoints(
        &self,
        checkpoints: &[Checkpoint],
        ticks: u64,
        every: NonZeroU32,
        start: usize,
    ) -> Result<(), ReplayError> {
        let expected = Replay::checkpoint_count(ticks, every);
        if checkpoints.len() as u64 != expected {
            return Err(self.malformed(
                Section::Checksums,
                start,
                format!(
                    "{} checkpoints, expected {expected} for {ticks} ticks with one every {every}",
                    checkpoints.len()
                ),
            ));
        }
        for (i, checkpoint) in checkpoints.iter().enumerate() {
            let tick = Replay::checkpoint_tick(i as u64, ticks, every);
            if checkpoint.tick != tick {
                return Err(self.malformed(
                    Section::Checksums,
                    start,
                    format!(
                        "checkpoint {i} is at tick {}, expected tick {tick}",
                        checkpoint.tick
                    ),
                ));
            }
        }
        Ok(())
    }
}

/// What keeps an input from being canonical: its tick must be after the `previous` input's
/// and below `ticks`, its players in strictly ascending index, each with a command.
fn input_problem(input: &TickInput<Fx>, previous: Option<u64>, ticks: u64) -> Option<String> {
    if previous.is_some_and(|p| input.tick <= p) {
        return Some(format!(
            "tick {} is not after the previous input's",
            input.tick
        ));
    }
    if input.tick >= ticks {
        return Some(format!(
            "tick {} is not below the replay's {ticks} ticks",
            input.tick
        ));
    }
    if input.players.is_empty() {
        return Some("it has no players".to_owned());
    }
    if !input.players.is_sorted_by(|a, b| a.player < b.player) {
        return Some("players are not in strictly ascending order".to_owned());
    }
    input
        .players
        .iter()
        .find(|p| p.commands.is_empty())
        .map(|p| format!("player {} has no commands", p.player))
}

/// The "N more bytes needed" part of a codec error that says the bytes ran out.
fn truncation(error: &CodecError) -> Option<&str> {
    error.0.strip_prefix("truncated: ")
}
