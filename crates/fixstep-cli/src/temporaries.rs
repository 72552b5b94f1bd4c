//! The temporary files and folders this process is writing, and their removal when SIGINT or
//! SIGTERM stops it (exit 130 or 143, as a shell reports a process a signal ended).
//!
//! Every output is written to a temporary path beside its destination and renamed into place
//! at the end. Each temporary path is listed here between its creation and its rename; the
//! list is locked around both, so a signal either finds a temporary path and removes it, or
//! finds the output already in place.

use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard, PoisonError};

/// The temporary paths in use.
static TEMPORARIES: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// The list of temporary paths, locked: while it is held, a signal waits.
pub struct Temporaries(MutexGuard<'static, Vec<PathBuf>>);

impl Temporaries {
    /// Locks the list.
    pub fn lock() -> Self {
        Self(TEMPORARIES.lock().unwrap_or_else(PoisonError::into_inner))
    }

    /// Lists `path`, a temporary file or folder just created.
    pub fn add(&mut self, path: &Path) {
        self.0.push(path.to_owned());
    }

    /// Takes `path` off the list (renamed into place, or removed).
    pub fn forget(&mut self, path: &Path) {
        self.0.retain(|p| p != path);
    }

    /// Removes every listed file and folder (best effort: the process is ending).
    fn remove_all(&mut self) {
        for path in self.0.drain(..) {
            if path.is_dir() {
                let _ = std::fs::remove_dir_all(&path);
            } else {
                let _ = std::fs::remove_file(&path);
            }
        }
    }
}

/// From now on, SIGINT and SIGTERM remove the temporary paths and end the process with
/// 128 + the signal's number. (Elsewhere than on Unix, a stopped process may leave
/// temporary files; a failed command still removes its own.)
pub fn remove_on_signal() -> Result<(), String> {
    #[cfg(unix)]
    {
        use signal_hook::consts::{SIGINT, SIGTERM};
        let mut signals = signal_hook::iterator::Signals::new([SIGINT, SIGTERM])
            .map_err(|e| format!("cannot handle SIGINT and SIGTERM: {e}"))?;
        std::thread::spawn(move || {
            if let Some(signal) = signals.forever().next() {
                let mut temporaries = Temporaries::lock();
                temporaries.remove_all();
                std::process::exit(128 + signal);
            }
        });
    }
    Ok(())
}
