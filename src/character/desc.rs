//! What a scene says about its characters: shape, start position and settings.

use serde::{Deserialize, Serialize};

use crate::math::{Fx, Real, Vec3};
use crate::rigid::{CollisionFilter, Shape};

/// One character of a scene.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct CharacterDesc<R: Real = Fx> {
    /// Its shape: a `Capsule` (upright, along y), a `Sphere` or a `Box` (axis-aligned; a
    /// character never turns).
    pub shape: Shape<R>,
    /// Where its centre starts, m.
    pub position: Vec3<R>,
    /// How it moves; every field has a default.
    #[serde(default)]
    pub settings: CharacterSettings<R>,
}

/// How a character moves. Up is +y: slopes are measured from it and a jump goes along it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct CharacterSettings<R: Real = Fx> {
    /// The steepest slope it stands on and walks up, rad, in (0, π/2). Default π/4 (45°).
    /// On a steeper surface it is not grounded: it slides down under gravity.
    #[serde(default = "default_max_slope")]
    pub max_slope: R,
    /// The highest step it walks onto without jumping, m, at least 0. Default 0.3 m.
    #[serde(default = "default_step_height")]
    pub step_height: R,
    /// How far below its feet it looks for ground to stay on while walking down slopes
    /// and steps, m, at least 0. Default 0.3 m.
    #[serde(default = "default_snap_distance")]
    pub snap_distance: R,
    /// The gap it keeps from every surface, m, above 0. Default 0.01 m.
    #[serde(default = "default_skin")]
    pub skin: R,
    /// The upward speed a jump starts with, m/s, at least 0. Default 5 m/s (a 1.27 m jump
    /// under 9.81 m/s²).
    #[serde(default = "default_jump_speed")]
    pub jump_speed: R,
    /// The mass with which it pushes dynamic bodies, kg, at least 0 (0: it pushes
    /// nothing). Default 80 kg.
    #[serde(default = "default_push_mass")]
    pub push_mass: R,
    /// The layers it is on and the layers of the bodies it collides with (see
    /// [`CollisionFilter`]). Default all. Sensors never block it.
    #[serde(default)]
    pub filter: CollisionFilter,
}

fn default_max_slope<R: Real>() -> R {
    R::PI.mul_pow2_recip(2)
}

fn default_step_height<R: Real>() -> R {
    R::from_ratio(3, 10)
}

fn default_snap_distance<R: Real>() -> R {
    R::from_ratio(3, 10)
}

fn default_skin<R: Real>() -> R {
    R::from_ratio(1, 100)
}

fn default_jump_speed<R: Real>() -> R {
    R::from_int(5)
}

fn default_push_mass<R: Real>() -> R {
    R::from_int(80)
}

impl<R: Real> Default for CharacterSettings<R> {
    fn default() -> Self {
        Self {
            max_slope: default_max_slope(),
            step_height: default_step_height(),
            snap_distance: default_snap_distance(),
            skin: default_skin(),
            jump_speed: default_jump_speed(),
            push_mass: default_push_mass(),
            filter: CollisionFilter::ALL,
        }
    }
}

impl<R: Real> CharacterDesc<R> {
    /// A character of `shape` at `position` with the default settings.
    pub fn new(shape: Shape<R>, position: Vec3<R>) -> Self {
        Self {
            shape,
            position,
            settings: CharacterSettings::default(),
        }
    }
}
