//! A CSV file being written: a header, then lines, put in place atomically at the end (a
//! failed run leaves no partial file).

use std::io::Write;
use std::path::Path;

use super::output::write_error;
use super::output_file::OutputFile;

/// A CSV output file, written to a temporary file and renamed into place by
/// [`CsvFile::commit`].
#[derive(Debug)]
pub struct CsvFile {
    file: OutputFile,
}

impl CsvFile {
    /// Starts the file at `path` with `header` as its first line.
    pub fn create(path: &Path, header: &str) -> Result<Self, String> {
        let file = OutputFile::create(path)?;
        let mut csv = Self { file };
        csv.line(header)?;
        Ok(csv)
    }

    /// Writes `line` and a newline.
    pub fn line(&mut self, line: &str) -> Result<(), String> {
        writeln!(self.file, "{line}").map_err(|e| write_error(self.file.path(), &e))
    }

    /// Puts the file in place.
    pub fn commit(self) -> Result<(), String> {
        self.file.commit()
    }
}
