//! Turning the SCENE argument into a scene: a built-in name or a RON file.

use std::path::Path;

use fixstep::math::Fx;
use fixstep::scene::{Scene, load_scene_file};
use fixstep_scenes::{BUILTIN_SCENES, builtin_scene};

/// The scene `arg` names. A built-in name wins unless `arg` looks like a path (ends in
/// `.ron` or contains a path separator); anything else that exists is read as a RON file.
pub fn resolve_scene(arg: &str) -> Result<Scene<Fx>, String> {
    let path = Path::new(arg);
    let looks_like_path = arg.ends_with(".ron") || arg.contains('/') || arg.contains('\\');
    if !looks_like_path && let Some(scene) = builtin_scene(arg) {
        return Ok(scene);
    }
    if looks_like_path || path.exists() {
        return load_scene_file(path);
    }
    let names: Vec<&str> = BUILTIN_SCENES.iter().map(|(name, _)| *name).collect();
    Err(format!(
        "unknown scene `{arg}`: not a built-in scene ({}) and no such file",
        names.join(", ")
    ))
}
