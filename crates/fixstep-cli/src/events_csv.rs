//! The `--events` CSV file: every event of every tick, in the engine's canonical order,
//! written atomically.

use std::path::Path;

use super::csv_file::CsvFile;
use fixstep::rigid::Event;

/// The columns: the tick during which it happened, the event's name (`contact_begin`,
/// `contact_end`, `sensor_enter`, `sensor_exit`, `joint_break`) and the two handles (`b`
/// empty for `joint_break`, whose `a` is the joint).
pub const EVENTS_CSV_HEADER: &str = "tick,event,a,b";

/// An events file being written.
#[derive(Debug)]
pub struct EventsCsv {
    file: CsvFile,
}

impl EventsCsv {
    /// Starts the file at `path` with the CSV header.
    pub fn create(path: &Path) -> Result<Self, String> {
        Ok(Self {
            file: CsvFile::create(path, EVENTS_CSV_HEADER)?,
        })
    }

    /// Writes a row per event of a tick.
    pub fn events(&mut self, events: &[Event]) -> Result<(), String> {
        for event in events {
            let b = event.b.map(|b| b.to_string()).unwrap_or_default();
            self.file.line(&format!(
                "{},{},{},{b}",
                event.tick,
                event.kind.name(),
                event.a
            ))?;
        }
        Ok(())
    }

    /// Puts the file in place.
    pub fn finish(self) -> Result<(), String> {
        self.file.commit()
    }
}
