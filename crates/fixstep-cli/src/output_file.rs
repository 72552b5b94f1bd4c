//! An output file of a command: written to a temporary file of its own beside its
//! destination, renamed into place by [`OutputFile::commit`], and removed instead if the
//! command fails or a signal stops it (see [`crate::temporaries`]).

use std::io::{self, Write};
use std::path::Path;

use super::output::write_error;
use super::temporaries::Temporaries;
use fixstep::replay::{AtomicFile, folder_of};

/// A file that appears at its path only once complete.
#[derive(Debug)]
pub struct OutputFile {
    /// `None` once committed.
    file: Option<AtomicFile>,
}

impl OutputFile {
    /// Starts the file that will replace `path`.
    pub fn create(path: &Path) -> Result<Self, String> {
        let mut temporaries = Temporaries::lock();
        let file = AtomicFile::create(path).map_err(|e| write_error(path, &e))?;
        temporaries.add(file.temporary_path());
        Ok(Self { file: Some(file) })
    }

    /// Writes the whole file `path` (`bytes`) and puts it in place.
    pub fn write(path: &Path, bytes: &[u8]) -> Result<(), String> {
        let mut file = Self::create(path)?;
        file.write_all(bytes).map_err(|e| write_error(path, &e))?;
        file.commit()
    }

    /// The path the file will have once committed.
    pub fn path(&self) -> &Path {
        self.file().path()
    }

    /// The folder the file is written in (a temporary file beside it can be renamed into
    /// place).
    pub fn folder(&self) -> &Path {
        folder_of(self.path())
    }

    /// Flushes, syncs and renames the file into place.
    pub fn commit(mut self) -> Result<(), String> {
        let mut temporaries = Temporaries::lock();
        let file = self.file.take().expect("an output file is committed once");
        let path = file.path().to_owned();
        let temporary = file.temporary_path().to_owned();
        let result = file.commit().map_err(|e| write_error(&path, &e));
        temporaries.forget(&temporary);
        result
    }

    fn file(&self) -> &AtomicFile {
        self.file
            .as_ref()
            .expect("an output file is used until committed")
    }

    fn file_mut(&mut self) -> io::Result<&mut AtomicFile> {
        self.file
            .as_mut()
            .ok_or_else(|| io::Error::other("file already committed"))
    }
}

impl Write for OutputFile {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.file_mut()?.write(buf)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.file_mut()?.flush()
    }
}

impl Drop for OutputFile {
    /// An output dropped before its commit (the command failed) leaves no temporary file.
    fn drop(&mut self) {
        if let Some(file) = self.file.take() {
            let mut temporaries = Temporaries::lock();
            let temporary = file.temporary_path().to_owned();
            drop(file);
            temporaries.forget(&temporary);
        }
    }
}
