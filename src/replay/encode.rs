//! Writing replays: the exact inverse of [`decode`](super::decode), byte for byte.

use super::file::Replay;
use super::format::{FORMAT_VERSION, MAGIC, ReplayHeader, content_hash};
use super::scene_section::encode_scene;
use crate::codec::{self, CodecError, SIZE_LIMIT};
use crate::math::{Fx, Real};

/// The encoded sections of a replay that the header describes (the checksums section follows
/// them and is not in the header).
struct Sections {
    scene: Vec<u8>,
    inputs: Vec<u8>,
}

impl Replay {
    /// The file's bytes (layout in [`format`](super::format)). Fails when a section would
    /// exceed the codec's size limit, since no reader would accept it.
    pub fn to_bytes(&self) -> Result<Vec<u8>, CodecError> {
        let mut bytes = self.head_bytes()?;
        let checksums = codec::encode(&self.checkpoints)?;
        check_section_len("checksums", checksums.len())?;
        bytes.extend_from_slice(&checksums);
        Ok(bytes)
    }

    /// The bytes before the checksums section: preamble, header, header hash, scene and
    /// inputs. None of them depends on the checkpoints.
    pub(super) fn head_bytes(&self) -> Result<Vec<u8>, CodecError> {
        let sections = self.sections()?;
        let header = codec::encode(&self.header_for(&sections))?;
        let mut bytes = Vec::with_capacity(
            MAGIC.len() + 4 + header.len() + 8 + sections.scene.len() + sections.inputs.len(),
        );
        bytes.extend_from_slice(&MAGIC);
        bytes.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
        bytes.extend_from_slice(&header);
        let header_hash = content_hash(&bytes);
        bytes.extend_from_slice(&header_hash.to_le_bytes());
        bytes.extend_from_slice(&sections.scene);
        bytes.extend_from_slice(&sections.inputs);
        Ok(bytes)
    }

    /// The header this replay's file has.
    pub fn header(&self) -> Result<ReplayHeader, CodecError> {
        Ok(self.header_for(&self.sections()?))
    }

    fn header_for(&self, sections: &Sections) -> ReplayHeader {
        ReplayHeader {
            state_version: self.state_version,
            scalar: Fx::NAME.to_owned(),
            tick_rate: self.scene.tick_rate,
            seed: self.scene.seed,
            ticks: self.ticks,
            checksum_every: self.checksum_every.get(),
            scene_len: sections.scene.len() as u64,
            scene_hash: content_hash(&sections.scene),
            inputs_len: sections.inputs.len() as u64,
            inputs_hash: content_hash(&sections.inputs),
        }
    }

    fn sections(&self) -> Result<Sections, CodecError> {
        let sections = Sections {
            scene: encode_scene(&self.scene)?,
            inputs: codec::encode(&self.inputs)?,
        };
        check_section_len("scene", sections.scene.len())?;
        check_section_len("inputs", sections.inputs.len())?;
        Ok(sections)
    }
}

/// Refuses a section of `len` bytes over the codec's size limit, naming it.
pub(super) fn check_section_len(name: &str, len: usize) -> Result<(), CodecError> {
    if len > SIZE_LIMIT {
        return Err(CodecError(format!(
            "the {name} section would be {len} bytes, over the {SIZE_LIMIT}-byte limit"
        )));
    }
    Ok(())
}
