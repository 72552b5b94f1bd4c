//! The `--metrics` CSV file: a header, a row every K ticks and one after the last tick,
//! written atomically.

use std::path::Path;

use super::csv_file::CsvFile;
use fixstep::math::Fx;
use fixstep::world::{Metrics, World};

/// A metrics file being written.
#[derive(Debug)]
pub struct MetricsCsv {
    file: CsvFile,
    every: u64,
    last_tick: Option<u64>,
}

impl MetricsCsv {
    /// Starts the file at `path` with the CSV header; a row is due every `every` ticks.
    pub fn create(path: &Path, every: u64) -> Result<Self, String> {
        Ok(Self {
            file: CsvFile::create(path, Metrics::CSV_HEADER)?,
            every: every.max(1),
            last_tick: None,
        })
    }

    /// Writes a row if one is due at the world's tick.
    pub fn tick(&mut self, world: &World<Fx>) -> Result<(), String> {
        if world.tick().is_multiple_of(self.every) {
            self.row(world)?;
        }
        Ok(())
    }

    /// Writes the last row (unless already written) and puts the file in place.
    pub fn finish(mut self, world: &World<Fx>) -> Result<(), String> {
        if self.last_tick != Some(world.tick()) {
            self.row(world)?;
        }
        self.file.commit()
    }

    fn row(&mut self, world: &World<Fx>) -> Result<(), String> {
        self.last_tick = Some(world.tick());
        self.file.line(&world.metrics().csv_row())
    }
}
