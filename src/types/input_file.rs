//! Reading a user's input file (a scene, a mesh, a replay, a snapshot): only a regular file
//! under a size limit, refused before it is opened otherwise.
//!
//! The file's type and length come from its metadata first, because opening is not
//! harmless: opening a named pipe (FIFO) for reading waits for a writer, and a character
//! device such as `/dev/zero` never ends. The read itself stops one byte past the limit, so
//! a file that grows after the check is refused too rather than read without bound.

use core::fmt;
use std::fs::{File, FileType};
use std::io::Read;
use std::path::Path;

/// The largest scene, mesh or snapshot file read: 256 MiB. Replays have their own limit
/// (`replay::MAX_FILE_LEN`), three sections of at most this many bytes each.
pub const MAX_INPUT_FILE_LEN: u64 = 256 << 20;

/// Why an input file was not read. Its text does not name the file: the caller prefixes
/// the path (`PATH: is a named pipe (FIFO), not a scene file`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum InputFileError {
    /// The file's metadata could not be read, or the file could not be opened or read.
    Unreadable(String),
    /// The path names something other than a regular file: `kind` says what ("a
    /// directory", "a named pipe (FIFO)"), `expected` what the caller reads ("a scene
    /// file").
    NotAFile {
        /// What the path is.
        kind: &'static str,
        /// What was expected there.
        expected: &'static str,
    },
    /// The file is larger than `limit` bytes.
    TooLarge {
        /// Its length (at least `limit + 1` when it grew while being read).
        len: u64,
        /// The largest length accepted.
        limit: u64,
        /// What was expected there.
        expected: &'static str,
    },
}

impl fmt::Display for InputFileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Unreadable(why) => write!(f, "cannot read: {why}"),
            Self::NotAFile { kind, expected } => write!(f, "is {kind}, not {expected}"),
            Self::TooLarge {
                len,
                limit,
                expected,
            } => write!(
                f,
                "is {len} bytes, over the {limit}-byte limit of {expected}"
            ),
        }
    }
}

impl std::error::Error for InputFileError {}

/// The bytes of the regular file at `path`, refused if it holds more than `limit` bytes.
/// `expected` names what the file should be in messages ("a scene file").
pub fn read_input_file(
    path: &Path,
    limit: u64,
    expected: &'static str,
) -> Result<Vec<u8>, InputFileError> {
    let unreadable = |e: std::io::Error| InputFileError::Unreadable(e.to_string());
    let metadata = std::fs::metadata(path).map_err(unreadable)?;
    if !metadata.is_file() {
        return Err(InputFileError::NotAFile {
            kind: kind_of(&metadata.file_type()),
            expected,
        });
    }
    let too_large = |len: u64| InputFileError::TooLarge {
        len,
        limit,
        expected,
    };
    if metadata.len() > limit {
        return Err(too_large(metadata.len()));
    }
    let mut bytes = Vec::new();
    File::open(path)
        .and_then(|file| file.take(limit.saturating_add(1)).read_to_end(&mut bytes))
        .map_err(unreadable)?;
    if bytes.len() as u64 > limit {
        return Err(too_large(bytes.len() as u64));
    }
    Ok(bytes)
}

/// What a path that is not a regular file is, for messages.
fn kind_of(file_type: &FileType) -> &'static str {
    if file_type.is_dir() {
        return "a directory";
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if file_type.is_fifo() {
            return "a named pipe (FIFO)";
        }
        if file_type.is_char_device() {
            return "a character device";
        }
        if file_type.is_block_device() {
            return "a block device";
        }
        if file_type.is_socket() {
            return "a socket";
        }
    }
    "not a regular file"
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("fixstep-input-file-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("scratch directory");
        dir.join(name)
    }

    #[test]
    fn a_regular_file_within_the_limit_is_read_whole() {
        let path = scratch("small");
        std::fs::write(&path, b"twelve bytes").expect("write");
        assert_eq!(
            read_input_file(&path, 12, "a scene file").expect("read"),
            b"twelve bytes"
        );
        let error = read_input_file(&path, 11, "a scene file").expect_err("too large");
        assert_eq!(
            error.to_string(),
            "is 12 bytes, over the 11-byte limit of a scene file"
        );
    }

    #[test]
    fn a_directory_and_a_missing_file_are_named() {
        let dir = std::env::temp_dir();
        let error = read_input_file(&dir, MAX_INPUT_FILE_LEN, "a scene file").expect_err("dir");
        assert_eq!(error.to_string(), "is a directory, not a scene file");
        let error = read_input_file(&scratch("absent"), 1, "a scene file").expect_err("absent");
        assert!(error.to_string().starts_with("cannot read: "), "{error}");
    }

    #[cfg(unix)]
    #[test]
    fn a_character_device_is_refused_before_it_is_read() {
        let error = read_input_file(Path::new("/dev/zero"), MAX_INPUT_FILE_LEN, "a replay file")
            .expect_err("a device");
        assert_eq!(
            error.to_string(),
            "is a character device, not a replay file"
        );
    }
}
