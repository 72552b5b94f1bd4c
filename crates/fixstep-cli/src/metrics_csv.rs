//! The `--metrics` CSV file: a header, a row every K ticks and one after the last tick,
//! written atomically.

use std::io::Write;
use std::path::Path;

use super::output::write_error;
use fixstep::math::Fx;
use fixstep::replay::AtomicFile;
use fixstep::world::{Metrics, World};

/// A metrics file being written.
#[derive(Debug)]
pub struct MetricsCsv {
    file: AtomicFile,
    every: u64,
    last_tick: Option<u64>,
}

impl MetricsCsv {
    /// Starts the file at `path` with the CSV header; a row is due every `every` ticks.
    pub fn create(path: &Path, every: u64) -> Result<Self, String> {
        let file = AtomicFile::create(path).map_err(|e| write_error(path, &e))?;
        let mut csv = Self {
            file,
            every: every.max(1),
            last_tick: None,
        };
        csv.line(Metrics::CSV_HEADER)?;
        Ok(csv)
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
        let path = self.file.path().to_owned();
        self.file.commit().map_err(|e| write_error(&path, &e))
    }

    fn row(&mut self, world: &World<Fx>) -> Result<(), String> {
        self.last_tick = Some(world.tick());
        self.line(&world.metrics().csv_row())
    }

    fn line(&mut self, line: &str) -> Result<(), String> {
        writeln!(self.file, "{line}").map_err(|e| write_error(self.file.path(), &e))
    }
}
