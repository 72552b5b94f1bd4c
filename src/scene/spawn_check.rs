//! The checks a scene's script gets before it runs: every spawn names a template the scene
//! has, and the spawns cannot take the bodies past [`MAX_BODIES`].

use super::description::Scene;
use crate::math::Real;
use crate::rigid::desc::MAX_BODIES;
use crate::types::{Command, SceneError};

impl<R: Real> Scene<R> {
    /// Checks the script's spawn commands; the error names the command
    /// (`script[i].players[j].commands[k]`) and what is wrong. The body limit is checked
    /// without counting removals: the scene's bodies plus every body the script spawns must
    /// stay within [`MAX_BODIES`].
    pub(crate) fn check_spawns(&self) -> Result<(), SceneError> {
        let (templates, joint_templates, mut bodies) = match &self.rigid {
            Some(r) => (
                r.templates.len(),
                r.joint_templates.len(),
                u64::from(r.body_count()),
            ),
            None => (0, 0, 0),
        };
        for (i, input) in self.script.iter().enumerate() {
            for (j, player) in input.players.iter().enumerate() {
                for (k, command) in player.commands.iter().enumerate() {
                    let field = format!("script[{i}].players[{j}].commands[{k}]");
                    let (template, count, kind) = match command {
                        Command::SpawnBody { template, .. } => (*template, templates, "body"),
                        Command::SpawnJoint { template, .. } => {
                            (*template, joint_templates, "joint")
                        }
                        _ => continue,
                    };
                    if template as usize >= count {
                        return Err(SceneError::new(
                            format!("{field}.template"),
                            format!(
                                "names {kind} template {template}, but the scene has {count} \
                                 (`rigid.{}templates`)",
                                if kind == "joint" { "joint_" } else { "" }
                            ),
                        ));
                    }
                    if matches!(command, Command::SpawnBody { .. }) {
                        bodies += 1;
                        if bodies > u64::from(MAX_BODIES) {
                            return Err(SceneError::new(
                                field,
                                format!("spawns body {bodies}, past the limit of {MAX_BODIES}"),
                            ));
                        }
                    }
                }
            }
        }
        Ok(())
    }
}
