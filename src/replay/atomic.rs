//! Atomic file output: readers see the old file or the complete new one, never a part.
//!
//! The bytes go to a temporary file of their own in the same directory,
//! `.<name>.tmp-<pid>-<k>` (`k` counts the files this process has opened, so two outputs that
//! name one file by different spellings never share a temporary file), are flushed and synced
//! to disk, and the temporary file is then renamed over `path` (an atomic replacement on the
//! same file system), after which the directory is synced so the rename itself survives a
//! crash. A file that is dropped before [`AtomicFile::commit`], or whose commit fails, is
//! removed and `path` is left untouched.

use std::ffi::OsString;
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// An output file that appears at its path only once complete.
#[derive(Debug)]
pub struct AtomicFile {
    path: PathBuf,
    temporary: PathBuf,
    writer: Option<BufWriter<File>>,
}

impl AtomicFile {
    /// Starts writing the file that will replace `path`.
    pub fn create(path: &Path) -> io::Result<Self> {
        let temporary = temporary_path_for(path)?;
        let file = File::create_new(&temporary)?;
        Ok(Self {
            path: path.to_owned(),
            temporary,
            writer: Some(BufWriter::new(file)),
        })
    }

    /// The path the file will have once committed.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The temporary file the bytes go to until [`AtomicFile::commit`].
    pub fn temporary_path(&self) -> &Path {
        &self.temporary
    }

    /// Flushes, syncs and renames the file into place.
    pub fn commit(mut self) -> io::Result<()> {
        let Some(writer) = self.writer.take() else {
            return Err(io::Error::other("file already closed"));
        };
        let result = finish(writer, &self.temporary, &self.path);
        if result.is_err() {
            // Best effort: the temporary file must not outlive a failed commit.
            let _ = std::fs::remove_file(&self.temporary);
        }
        result
    }

    fn writer(&mut self) -> io::Result<&mut BufWriter<File>> {
        self.writer
            .as_mut()
            .ok_or_else(|| io::Error::other("file already closed"))
    }
}

/// A fresh temporary path beside `path`: `.<name>.tmp-<pid>-<k>`, `k` unique in this process.
/// Fails when `path` names no file (it ends in `..` or is a root).
pub fn temporary_path_for(path: &Path) -> io::Result<PathBuf> {
    static OPENED: AtomicU64 = AtomicU64::new(0);
    let name = path
        .file_name()
        .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "the path names no file"))?;
    let k = OPENED.fetch_add(1, Ordering::Relaxed);
    let mut temporary = OsString::from(".");
    temporary.push(name);
    temporary.push(format!(".tmp-{}-{k}", std::process::id()));
    Ok(path.with_file_name(temporary))
}

/// Flush, sync, rename, sync the directory.
fn finish(writer: BufWriter<File>, temporary: &Path, path: &Path) -> io::Result<()> {
    let file = writer
        .into_inner()
        .map_err(io::IntoInnerError::into_error)?;
    file.sync_all()?;
    drop(file);
    std::fs::rename(temporary, path)?;
    sync_directory(path);
    Ok(())
}

/// Syncs the directory holding `path` so a completed rename is durable. Best effort: some
/// platforms and file systems cannot open or sync a directory, and the file itself is
/// already complete.
fn sync_directory(path: &Path) {
    if let Ok(dir) = File::open(folder_of(path)) {
        let _ = dir.sync_all();
    }
}

impl Write for AtomicFile {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.writer()?.write(buf)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.writer()?.flush()
    }
}

impl Drop for AtomicFile {
    fn drop(&mut self) {
        if self.writer.take().is_some() {
            let _ = std::fs::remove_file(&self.temporary);
        }
    }
}

/// The folder that holds `path`: its parent, or `.` for a bare file name.
pub fn folder_of(path: &Path) -> &Path {
    match path.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent,
        _ => Path::new("."),
    }
}

/// Writes `bytes` to `path` atomically.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let mut file = AtomicFile::create(path)?;
    file.write_all(bytes)?;
    file.commit()
}
