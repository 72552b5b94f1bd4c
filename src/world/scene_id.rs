//! Which scene a state belongs to: the scene's name and hash, which a snapshot file carries
//! so that it is never restored into another scene's world.

use core::fmt;

use serde::{Deserialize, Serialize};

/// A scene's name and hash. For the engine's scalar, [`crate::replay::scene_id`] computes
/// them: the hash is the one a replay of the scene holds in its header (`scene_hash`), over
/// every field of the scene but its script.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct SceneId {
    /// The scene's name, for messages.
    pub name: String,
    /// The scene's hash; two scenes are the same when their hashes are.
    pub hash: u64,
}

impl SceneId {
    /// Refuses a state of scene `self` (a snapshot's) in a world of scene `current`, with a
    /// message naming both.
    pub fn check_same(&self, current: &SceneId) -> Result<(), String> {
        if self.hash == current.hash {
            return Ok(());
        }
        let hint = if self.name == current.name {
            " (the same name, but another seed or other contents)"
        } else {
            ""
        };
        Err(format!(
            "a snapshot of scene {self}, not of scene {current}{hint}; restore it into the \
             scene it was taken in"
        ))
    }
}

impl fmt::Display for SceneId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?} (scene hash {:016x})", self.name, self.hash)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn another_scene_is_refused_naming_both() {
        let stack = SceneId {
            name: "stack".to_owned(),
            hash: 1,
        };
        let cradle = SceneId {
            name: "cradle".to_owned(),
            hash: 2,
        };
        assert_eq!(stack.check_same(&stack.clone()), Ok(()));
        let error = stack.check_same(&cradle).expect_err("another scene");
        assert!(
            error.starts_with(
                "a snapshot of scene \"stack\" (scene hash 0000000000000001), not of scene \
                 \"cradle\" (scene hash 0000000000000002)"
            ),
            "{error}"
        );
    }
}
