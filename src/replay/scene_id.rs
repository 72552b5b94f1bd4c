//! A scene's identity ([`SceneId`]): its name and the hash of its replay scene section,
//! which snapshots carry and networked peers compare.

use super::format::content_hash;
use super::scene_section::encode_scene;
use crate::codec::CodecError;
use crate::math::Fx;
use crate::scene::Scene;
use crate::world::SceneId;

/// The name and hash of `scene`. The hash is the `scene_hash` a replay of the scene holds:
/// the [`content_hash`] of its scene section, which has every field but the script (a
/// replay keeps the inputs apart). It fails only for a scene too large to encode.
pub fn scene_id(scene: &Scene<Fx>) -> Result<SceneId, CodecError> {
    let unscripted = Scene {
        script: Vec::new(),
        ..scene.clone()
    };
    Ok(SceneId {
        name: scene.name.clone(),
        hash: content_hash(&encode_scene(&unscripted)?),
    })
}
