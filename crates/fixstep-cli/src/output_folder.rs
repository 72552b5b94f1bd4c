//! The output folder of `fixstep render`: written as a fresh temporary folder beside its
//! destination and renamed over it at the end, so that a render's folder holds that render's
//! files only, and a failed or stopped render leaves the destination as it was.
//!
//! A destination that holds anything but a render's files (`tick-*.png`, the GIF, the page)
//! is refused, since it would be replaced whole.

use std::path::{Path, PathBuf};

use super::temporaries::Temporaries;
use fixstep::replay::{folder_of, temporary_path_for};
use fixstep_viewer::{GIF_NAME, PAGE_NAME};

/// A folder that appears at its path only once complete.
#[derive(Debug)]
pub struct OutputFolder {
    /// The destination, as given (for messages).
    given: PathBuf,
    /// The destination, absolute, ending in its name.
    destination: PathBuf,
    /// The folder being written; `None` once committed.
    temporary: Option<PathBuf>,
}

impl OutputFolder {
    /// Checks that `destination` is missing, empty or an earlier render's folder, and
    /// creates the temporary folder beside it (and the folders above it if missing).
    pub fn create(destination: &Path) -> Result<Self, String> {
        let given = destination.to_owned();
        let shown = destination.display();
        if destination.exists() {
            if !destination.is_dir() {
                return Err(format!("--out {shown} is not a directory"));
            }
            refuse_foreign_files(destination)?;
        } else if let Some(parent) = destination.parent()
            && !parent.as_os_str().is_empty()
        {
            std::fs::create_dir_all(parent)
                .map_err(|e| format!("--out {shown}: cannot create the directory: {e}"))?;
        }
        let destination = absolute_destination(destination)
            .map_err(|e| format!("--out {shown}: cannot resolve the directory: {e}"))?;
        let temporary = temporary_path_for(&destination)
            .map_err(|e| format!("--out {shown}: cannot name a temporary folder: {e}"))?;
        let mut temporaries = Temporaries::lock();
        std::fs::create_dir(&temporary).map_err(|e| {
            format!(
                "--out {shown}: cannot create the temporary folder {}: {e}",
                temporary.display()
            )
        })?;
        temporaries.add(&temporary);
        Ok(Self {
            given,
            destination,
            temporary: Some(temporary),
        })
    }

    /// The folder to write into until [`OutputFolder::commit`].
    pub fn path(&self) -> &Path {
        self.temporary
            .as_deref()
            .expect("an output folder is used until committed")
    }

    /// Puts the folder in place: an earlier render's folder there is moved aside, replaced
    /// and then removed.
    pub fn commit(mut self) -> Result<(), String> {
        let temporary = self
            .temporary
            .take()
            .expect("an output folder is committed once");
        let shown = self.given.display();
        let mut temporaries = Temporaries::lock();
        let aside = if self.destination.exists() {
            let aside = temporary_path_for(&self.destination)
                .map_err(|e| format!("--out {shown}: cannot name a temporary folder: {e}"))?;
            std::fs::rename(&self.destination, &aside)
                .map_err(|e| format!("--out {shown}: cannot move the earlier render aside: {e}"))?;
            Some(aside)
        } else {
            None
        };
        if let Err(e) = std::fs::rename(&temporary, &self.destination) {
            if let Some(aside) = &aside {
                let _ = std::fs::rename(aside, &self.destination);
            }
            let _ = std::fs::remove_dir_all(&temporary);
            temporaries.forget(&temporary);
            return Err(format!(
                "--out {shown}: cannot put the render in place: {e}"
            ));
        }
        temporaries.forget(&temporary);
        if let Some(aside) = aside {
            // The earlier render, now replaced: removed like a temporary folder.
            temporaries.add(&aside);
            drop(temporaries);
            let _ = std::fs::remove_dir_all(&aside);
            Temporaries::lock().forget(&aside);
        }
        Ok(())
    }
}

impl Drop for OutputFolder {
    /// A folder dropped before its commit (the render failed) is removed.
    fn drop(&mut self) {
        if let Some(temporary) = self.temporary.take() {
            let mut temporaries = Temporaries::lock();
            let _ = std::fs::remove_dir_all(&temporary);
            temporaries.forget(&temporary);
        }
    }
}

/// Whether a file named `name` is one a render writes.
fn is_render_file(name: &str) -> bool {
    name == GIF_NAME || name == PAGE_NAME || (name.starts_with("tick-") && name.ends_with(".png"))
}

/// Refuses a folder holding anything a render does not write.
fn refuse_foreign_files(folder: &Path) -> Result<(), String> {
    let shown = folder.display();
    let entries =
        std::fs::read_dir(folder).map_err(|e| format!("--out {shown}: cannot read: {e}"))?;
    for entry in entries {
        let entry = entry.map_err(|e| format!("--out {shown}: cannot read: {e}"))?;
        let name = entry.file_name();
        let is_file = entry.file_type().is_ok_and(|t| t.is_file());
        if !is_file || !name.to_str().is_some_and(is_render_file) {
            return Err(format!(
                "--out {shown} holds {}, which is not a render's file: a render replaces \
                 its whole folder, so give a new or empty folder, or an earlier render's",
                entry.path().display()
            ));
        }
    }
    Ok(())
}

/// `destination` made absolute, ending in a name (`.` and `..` are resolved, the folder
/// above must exist).
fn absolute_destination(destination: &Path) -> std::io::Result<PathBuf> {
    if destination.exists() {
        return std::fs::canonicalize(destination);
    }
    let folder = folder_of(destination);
    let name = destination.file_name().ok_or_else(|| {
        std::io::Error::new(std::io::ErrorKind::InvalidInput, "the path names no folder")
    })?;
    Ok(std::fs::canonicalize(folder)?.join(name))
}
