//! Recording a replay straight to its file: the checkpoints go to a spool file as they are
//! captured, so a long recording holds the world and its inputs in memory, never O(ticks) of
//! checkpoints. The file written is byte for byte the one [`Replay::to_bytes`] gives.
//!
//! [`Replay::to_bytes`]: super::Replay::to_bytes

use core::num::NonZeroU32;
use std::fs::File;
use std::io::{self, BufWriter, Read, Seek, SeekFrom, Write};

use super::encode::check_section_len;
use super::format::Checkpoint;
use super::record::Recorder;
use crate::codec;
use crate::math::Fx;
use crate::scene::{Scene, SceneError};
use crate::world::{TickInput, TickReport, World};

/// A [`Recorder`] whose checkpoints are written to a spool file as they come; at the end,
/// [`StreamingRecorder::finish`] writes the whole replay file.
///
/// The checksums section is the last of a replay file and its length is known only at the
/// end, after the inputs section, so the checkpoints wait in the spool (an empty file opened
/// for reading and writing, such as an anonymous temporary file) rather than in memory.
#[derive(Debug)]
pub struct StreamingRecorder {
    recorder: Recorder,
    spool: Spool,
}

/// The spool file and what was written to it.
#[derive(Debug)]
struct Spool {
    writer: BufWriter<File>,
    /// The checkpoints written so far.
    count: u64,
    /// The bytes written so far.
    len: u64,
    /// The last checkpoint written: its tick and its world checksum.
    last: Option<(u64, u64)>,
}

impl StreamingRecorder {
    /// Builds the scene's world at tick 0, spooling checkpoints to `spool`, which must be
    /// empty and readable. The scene's script is not fed automatically: pass its inputs to
    /// [`StreamingRecorder::step`].
    pub fn new(
        scene: &Scene<Fx>,
        checksum_every: NonZeroU32,
        spool: File,
    ) -> Result<Self, SceneError> {
        Ok(Self {
            recorder: Recorder::new(scene, checksum_every)?,
            spool: Spool {
                writer: BufWriter::new(spool),
                count: 0,
                len: 0,
                last: None,
            },
        })
    }

    /// The world being recorded.
    pub fn world(&self) -> &World<Fx> {
        self.recorder.world()
    }

    /// Starts collecting per-stage timings (they are not recorded).
    pub fn enable_timing(&mut self) {
        self.recorder.enable_timing();
    }

    /// Starts checking the world for divergence every `every` ticks (not recorded).
    pub fn enable_divergence_check(&mut self, every: u64) {
        self.recorder.enable_divergence_check(every);
    }

    /// Runs one tick with `input`, as [`Recorder::step`] does, and spools its checkpoint if
    /// it has one. Fails when the spool cannot be written or the checksums section would
    /// pass the codec's size limit.
    pub fn step(&mut self, input: &TickInput<Fx>) -> io::Result<TickReport> {
        let report = self.recorder.step(input);
        for checkpoint in self.recorder.drain_checkpoints() {
            self.spool.append(&checkpoint)?;
        }
        Ok(report)
    }

    /// Captures the last checkpoint and writes the whole replay file to `out`: the bytes
    /// [`Replay::to_bytes`](super::Replay::to_bytes) gives for the same run. Returns the
    /// world checksum after the last tick.
    pub fn finish(self, out: &mut impl Write) -> io::Result<u64> {
        let Self {
            recorder,
            mut spool,
        } = self;
        let mut replay = recorder.finish();
        let spooled_up_to = spool.last.map(|(tick, _)| tick);
        for checkpoint in core::mem::take(&mut replay.checkpoints) {
            if spooled_up_to.is_none_or(|tick| checkpoint.tick > tick) {
                spool.append(&checkpoint)?;
            }
        }
        out.write_all(&replay.head_bytes().map_err(io::Error::other)?)?;
        spool.copy_section_to(out)?;
        Ok(spool.last.map_or(0, |(_, total)| total))
    }
}

impl Spool {
    /// Appends one checkpoint. Fails when the checksums section would pass the codec's size
    /// limit.
    fn append(&mut self, checkpoint: &Checkpoint) -> io::Result<()> {
        let bytes = codec::encode(checkpoint).map_err(io::Error::other)?;
        let len = self.len + bytes.len() as u64;
        // The section is the checkpoint count (a u64) and then the checkpoints.
        let section_len = usize::try_from(8 + len).unwrap_or(usize::MAX);
        check_section_len("checksums", section_len).map_err(io::Error::other)?;
        self.writer.write_all(&bytes)?;
        self.count += 1;
        self.len = len;
        self.last = Some((checkpoint.tick, checkpoint.total));
        Ok(())
    }

    /// Writes the checksums section to `out`: the checkpoint count, as the codec writes a
    /// vector's length (a u64), then the spooled checkpoints.
    fn copy_section_to(&mut self, out: &mut impl Write) -> io::Result<()> {
        out.write_all(&self.count.to_le_bytes())?;
        self.writer.flush()?;
        let file = self.writer.get_mut();
        file.seek(SeekFrom::Start(0))?;
        let copied = io::copy(&mut Read::take(&mut *file, self.len), out)?;
        if copied != self.len {
            return Err(io::Error::new(
                io::ErrorKind::UnexpectedEof,
                "the checkpoint spool file is shorter than what was written to it",
            ));
        }
        Ok(())
    }
}
