//! Render interpolation: `Transform` between the last two poses, by the fraction of a tick
//! that has passed since the last step. Floats only, after the simulation; nothing here is
//! read back.

use bevy::prelude::*;

use super::components::RenderPose;
use super::plugin::Stepping;

/// Sets the `Transform` of every entity with a [`RenderPose`] to
/// previous + α (current − previous) (rotation by normalised lerp, glam's `Quat::lerp`), α the overstep fraction
/// of Bevy's fixed clock when the plugin steps in `FixedUpdate`, and 1 under bevy_ggrs
/// (whose frames are not on Bevy's fixed clock).
pub(crate) fn interpolate(
    stepping: Res<Stepping>,
    fixed: Res<Time<Fixed>>,
    mut poses: Query<(&RenderPose, &mut Transform)>,
) {
    let alpha = match *stepping {
        Stepping::FixedUpdate => fixed.overstep_fraction(),
        Stepping::Ggrs => 1.0,
    };
    for (pose, mut transform) in &mut poses {
        let translation = pose
            .previous
            .translation
            .lerp(pose.current.translation, alpha);
        let rotation = pose.previous.rotation.lerp(pose.current.rotation, alpha);
        transform.translation = translation.into();
        transform.rotation = rotation;
    }
}
