//! Reading scene files (RON) and naming what is wrong with them.

use std::path::Path;

use ron::extensions::Extensions;

use super::description::Scene;
use crate::math::Real;
use crate::rigid::shape_serde::with_scene_directory;
use crate::types::{MAX_INPUT_FILE_LEN, SceneError, read_input_file};

/// Parses a scene from RON text. `origin` names the file in error messages, which give the
/// line and column where reading stopped.
///
/// `Some(…)` may be left out around optional sections (RON's `implicit_some`). Mesh files
/// (`TriMesh(file: ...)`) are named relative to the current directory, or to the one set
/// by [`crate::rigid::shape_serde::with_scene_directory`].
pub fn parse_scene<R: Real>(text: &str, origin: &str) -> Result<Scene<R>, SceneError> {
    let options = ron::Options::default().with_default_extension(Extensions::IMPLICIT_SOME);
    options.from_str::<Scene<R>>(text).map_err(|e| {
        SceneError::in_file(origin, e.code.to_string()).at_line(e.span.start.line, e.span.start.col)
    })
}

/// Reads and parses a scene file (a regular file of at most [`MAX_INPUT_FILE_LEN`] bytes),
/// and checks that it builds a world. Mesh files (`TriMesh(file: ...)`) are named relative
/// to the scene file's directory. Every error names the file.
pub fn load_scene_file<R: Real>(path: &Path) -> Result<Scene<R>, SceneError> {
    let origin = path.display().to_string();
    let bytes = read_input_file(path, MAX_INPUT_FILE_LEN, "a scene file")
        .map_err(|e| SceneError::in_file(&origin, e.to_string()))?;
    let text = String::from_utf8(bytes).map_err(|e| {
        SceneError::in_file(
            &origin,
            format!(
                "byte offset {}: not valid UTF-8 text",
                e.utf8_error().valid_up_to()
            ),
        )
    })?;
    let directory = path.parent().unwrap_or(Path::new(""));
    let scene = with_scene_directory(directory, || parse_scene(&text, &origin))?;
    scene.build().map_err(|e| e.with_file(origin))?;
    Ok(scene)
}
