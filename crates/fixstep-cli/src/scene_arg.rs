//! Turning the SCENE argument into a scene: a built-in name or a RON file; and the
//! REPLAY|SCENE argument into a scene with its inputs.

use std::path::Path;

use fixstep::math::Fx;
use fixstep::replay::Replay;
use fixstep::scene::{Scene, load_scene_file};
use fixstep::world::{TickInput, World};
use fixstep_scenes::{BUILTIN_SCENES, builtin_scene};

/// The file the SCENE argument `arg` names, or `None` when it is a built-in scene's name
/// or names nothing. A built-in name wins unless `arg` looks like a path (ends in `.ron` or
/// contains a path separator); anything else that exists is a file.
pub fn scene_file(arg: &str) -> Option<&Path> {
    let path = Path::new(arg);
    let looks_like_path = arg.ends_with(".ron") || arg.contains('/') || arg.contains('\\');
    let builtin = BUILTIN_SCENES.iter().any(|(name, _)| *name == arg);
    (looks_like_path || (!builtin && path.exists())).then_some(path)
}

/// The scene `arg` names: a built-in scene or a RON file (see [`scene_file`]).
pub fn resolve_scene(arg: &str) -> Result<Scene<Fx>, String> {
    if let Some(path) = scene_file(arg) {
        return load_scene_file(path).map_err(|e| e.to_string());
    }
    if let Some(scene) = builtin_scene(arg) {
        return Ok(scene);
    }
    let names: Vec<&str> = BUILTIN_SCENES.iter().map(|(name, _)| *name).collect();
    Err(format!(
        "unknown scene `{arg}`: not a built-in scene ({}) and no such file",
        names.join(", ")
    ))
}

/// What to simulate: a scene, its inputs and how many ticks by default.
pub struct Source {
    /// The scene.
    pub scene: Scene<Fx>,
    /// The inputs, in ascending tick order: a replay's recorded ones or the scene's script.
    pub inputs: Vec<TickInput<Fx>>,
    /// The replay's ticks, or the scene's `ticks`.
    pub ticks: u64,
}

impl Source {
    /// The scene's world at its first tick; errors start with `input`, the argument.
    pub fn build_world(&self, input: &str) -> Result<World<Fx>, String> {
        self.scene
            .build()
            .and_then(|world| {
                if let Some(particles) = world.particles() {
                    particles.check_user_forces()?;
                }
                Ok(world)
            })
            .map_err(|e| format!("{input}: {e}"))
    }
}

/// The replay file or scene `input` names. A name ending in `.replay` is a replay; anything
/// else is resolved by [`resolve_scene`].
pub fn resolve_source(input: &str) -> Result<Source, String> {
    if input.ends_with(".replay") {
        let replay = Replay::read(Path::new(input)).map_err(|e| e.to_string())?;
        return Ok(Source {
            scene: replay.scene().clone(),
            inputs: replay.inputs().to_vec(),
            ticks: replay.ticks(),
        });
    }
    let scene = resolve_scene(input)?;
    Ok(Source {
        inputs: scene.script.clone(),
        ticks: scene.ticks,
        scene,
    })
}
