//! Whether two paths name one file, checked before a command runs: an output must be none
//! of the command's inputs and none of its other outputs, however they are spelt (`x` and
//! `./x`, a hard link, a symbolic link).
//!
//! An existing file is known by its device and inode (on Unix; elsewhere by its canonical
//! path); a file still to be written by the canonical path of its folder and its name.

use std::path::{Path, PathBuf};

use fixstep::replay::folder_of;

/// A file named on the command line, and the role it plays there (`--record`, `the scene
/// file`, …), for the error message.
#[derive(Clone, Copy, Debug)]
pub struct NamedFile<'a> {
    /// What the file is to the command: an option's name or a description.
    pub role: &'a str,
    /// The path as given.
    pub path: &'a Path,
}

impl<'a> NamedFile<'a> {
    /// The file `path`, in role `role`.
    pub fn new(role: &'a str, path: &'a Path) -> Self {
        Self { role, path }
    }
}

/// Refuses an output that is also an input or an earlier output: `--record my.ron is also
/// the scene file my.ron`.
pub fn refuse_shared_files(inputs: &[NamedFile], outputs: &[NamedFile]) -> Result<(), String> {
    let inputs: Vec<(NamedFile, Identity)> =
        inputs.iter().map(|f| (*f, Identity::of(f.path))).collect();
    let mut earlier: Vec<(NamedFile, Identity)> = Vec::with_capacity(outputs.len());
    for output in outputs {
        let identity = Identity::of(output.path);
        let clash = inputs
            .iter()
            .chain(&earlier)
            .find(|(_, other)| *other == identity);
        if let Some((other, _)) = clash {
            return Err(format!(
                "{} {} is also {} {}: give each output a file of its own",
                output.role,
                output.path.display(),
                other.role,
                other.path.display()
            ));
        }
        earlier.push((*output, identity));
    }
    Ok(())
}

/// What tells two files apart.
#[derive(Debug, PartialEq, Eq)]
enum Identity {
    /// An existing file: its device and inode.
    #[cfg(unix)]
    Inode { device: u64, inode: u64 },
    /// A file to be created (or, off Unix, an existing one): its canonical path.
    Path(PathBuf),
}

impl Identity {
    /// The identity of the file at `path` (following symbolic links, as reading and
    /// writing do).
    fn of(path: &Path) -> Self {
        match std::fs::metadata(path) {
            Ok(metadata) => Self::existing(path, &metadata),
            Err(_) => Self::Path(new_file_path(path)),
        }
    }

    #[cfg(unix)]
    fn existing(_path: &Path, metadata: &std::fs::Metadata) -> Self {
        use std::os::unix::fs::MetadataExt;
        Self::Inode {
            device: metadata.dev(),
            inode: metadata.ino(),
        }
    }

    #[cfg(not(unix))]
    fn existing(path: &Path, _metadata: &std::fs::Metadata) -> Self {
        Self::Path(std::fs::canonicalize(path).unwrap_or_else(|_| new_file_path(path)))
    }
}

/// The canonical path of a file that does not exist yet: its folder's canonical path and
/// its name (the folder's absolute path when the folder does not exist either).
fn new_file_path(path: &Path) -> PathBuf {
    let folder = folder_of(path);
    let folder = std::fs::canonicalize(folder)
        .or_else(|_| std::path::absolute(folder))
        .unwrap_or_else(|_| folder.to_owned());
    match path.file_name() {
        Some(name) => folder.join(name),
        None => std::path::absolute(path).unwrap_or_else(|_| path.to_owned()),
    }
}
