//! Commands on soft bodies: moving a kinematic attachment target.

use super::system::SoftSystem;
use crate::math::Real;
use crate::types::{Command, Target};

impl<R: Real> SoftSystem<R> {
    /// Applies `command` if it is for this system; false when it names no target here.
    ///
    /// `MoveKinematic { target: SoftAttachment(g), position }` sets the goal of target g
    /// (numbered over the scene's attachments, body after body): its first vertex's target
    /// point reaches `position` (m) at the end of the tick, the others keep their offsets
    /// from it, and every point moves along a straight line over the tick's substeps.
    pub fn apply_command(&mut self, command: &Command<R>) -> bool {
        let Command::MoveKinematic {
            target: Target::SoftAttachment(g),
            position,
        } = *command
        else {
            return false;
        };
        let g = g as usize;
        if g >= self.attachments.origin.len() {
            return false;
        }
        self.attachments.goal[g] = position - self.attachments.origin[g];
        true
    }
}
