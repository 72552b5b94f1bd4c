//! The characters' state ([`Character`], [`CharacterSystem`]), how a scene builds it and how
//! commands drive it.

use serde::{Deserialize, Serialize};

use super::crowd::Crowd;
use super::desc::{CharacterDesc, CharacterSettings};
use super::movement::move_character;
use super::surroundings::Surroundings;
use crate::math::{Fx, Real, Vec3};
use crate::rigid::{EventKind, Shape};
use crate::types::{Command, Handle, SceneError};

/// The largest coordinate or size a character may have, m.
const MAX_MAGNITUDE: i32 = 100_000;

/// One character's state. Everything here is simulated state: snapshots carry it and the
/// checksum hashes it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Character<R: Real = Fx> {
    /// Its shape (sphere, capsule along y, or box), never rotated.
    pub shape: Shape<R>,
    /// How it moves.
    pub settings: CharacterSettings<R>,
    /// Its centre, m.
    pub position: Vec3<R>,
    /// Its own velocity, m/s: horizontally the walking velocity it was given, vertically
    /// what gravity and jumps made (0 while grounded). A platform's motion is not in it.
    pub velocity: Vec3<R>,
    /// The walking velocity the last [`Command::MoveCharacter`] asked for, m/s (its y is
    /// ignored); it keeps walking so until told otherwise.
    pub desired_velocity: Vec3<R>,
    /// Whether a jump was asked for this tick (it happens only if the character is
    /// grounded).
    pub jump: bool,
    /// Whether it stands on a surface no steeper than its `max_slope`.
    pub grounded: bool,
    /// The unit normal of the ground it stands on; zero when airborne.
    pub ground_normal: Vec3<R>,
    /// The body it stands on, when grounded.
    pub ground_body: Option<Handle>,
    /// The bodies it hit while moving during the last tick, ascending (a body hit again
    /// the next tick raises no new event).
    pub touching: Vec<Handle>,
}

/// What a character did during a tick, for [`crate::rigid::Event`]s.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CharacterEvent {
    /// [`EventKind::CharacterLand`] or [`EventKind::CharacterHit`].
    pub kind: EventKind,
    /// The character.
    pub character: Handle,
    /// The body landed on or hit.
    pub body: Handle,
}

/// Every character of a world, in index order (handle = (index, 0): characters are never
/// removed).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct CharacterSystem<R: Real = Fx> {
    pub(super) characters: Vec<Character<R>>,
}

impl<R: Real> CharacterSystem<R> {
    /// The characters a scene describes, each checked (the error names its index and
    /// field).
    pub fn from_desc(descs: &[CharacterDesc<R>]) -> Result<Self, SceneError> {
        let characters = descs
            .iter()
            .map(|d| Character {
                shape: d.shape.clone(),
                settings: d.settings,
                position: d.position,
                velocity: Vec3::ZERO,
                desired_velocity: Vec3::ZERO,
                jump: false,
                grounded: false,
                ground_normal: Vec3::ZERO,
                ground_body: None,
                touching: Vec::new(),
            })
            .collect();
        let system = Self { characters };
        system.validate()?;
        Ok(system)
    }

    /// The characters, in index order.
    pub fn characters(&self) -> &[Character<R>] {
        &self.characters
    }

    /// The character of `handle`, if it exists.
    pub fn get(&self, handle: Handle) -> Option<&Character<R>> {
        self.slot(handle).map(|i| &self.characters[i])
    }

    /// The handle of the character at `index`.
    pub fn handle(index: usize) -> Handle {
        Handle::new(index as u32, 0)
    }

    fn slot(&self, handle: Handle) -> Option<usize> {
        let i = handle.index as usize;
        (handle.generation == 0 && i < self.characters.len()).then_some(i)
    }

    /// Applies a [`Command::MoveCharacter`]: sets the walking velocity (m/s) and asks for
    /// a jump. False for another command or a character that does not exist.
    pub fn apply_command(&mut self, command: &Command<R>) -> bool {
        let Command::MoveCharacter {
            target,
            desired_velocity,
            jump,
        } = *command
        else {
            return false;
        };
        let Some(i) = self.slot(target) else {
            return false;
        };
        let c = &mut self.characters[i];
        c.desired_velocity = desired_velocity;
        c.jump |= jump;
        true
    }

    /// Moves every character, in index order, by one tick of `dt` seconds under `gravity`
    /// (m/s²; its y component) among `surroundings` and the other characters
    /// ([`move_character`]: those before it in index order where they moved to this tick,
    /// the others where they were); the tick's events, in character order.
    pub fn step_tick(
        &mut self,
        dt: R,
        gravity: Vec3<R>,
        surroundings: &mut dyn Surroundings<R>,
    ) -> Vec<CharacterEvent> {
        let mut events = Vec::new();
        let mut crowd = Crowd::new(&self.characters);
        for (i, c) in self.characters.iter_mut().enumerate() {
            let handle = Self::handle(i);
            move_character(c, handle, dt, gravity.y, surroundings, &crowd, &mut events);
            crowd.moved(i, c.position);
        }
        events
    }

    /// Checks every character: shape (sphere, capsule or box, sizes positive), finite
    /// position, settings in range; the error names the character and the field.
    pub fn validate(&self) -> Result<(), SceneError> {
        for (i, c) in self.characters.iter().enumerate() {
            check_character(c).map_err(|e| e.within(&format!("characters[{i}]")))?;
        }
        Ok(())
    }
}

fn check_character<R: Real>(c: &Character<R>) -> Result<(), SceneError> {
    let limit = R::from_int(MAX_MAGNITUDE);
    let size = |name: &str, v: R| {
        if v <= R::ZERO || v > limit {
            Err(SceneError::new(
                name,
                format!("must be above 0 and at most {MAX_MAGNITUDE} m (got {v})"),
            ))
        } else {
            Ok(())
        }
    };
    let at_most = |name: &str, v: R| {
        if v < R::ZERO || v > limit {
            Err(SceneError::new(
                name,
                format!("must be 0 to {MAX_MAGNITUDE} (got {v})"),
            ))
        } else {
            Ok(())
        }
    };
    match &c.shape {
        Shape::Sphere { radius } => size("shape.Sphere.radius", *radius)?,
        Shape::Capsule {
            radius,
            half_height,
        } => {
            size("shape.Capsule.radius", *radius)?;
            at_most("shape.Capsule.half_height", *half_height)?;
        }
        Shape::Box { half_extents } => {
            size("shape.Box.half_extents.x", half_extents.x)?;
            size("shape.Box.half_extents.y", half_extents.y)?;
            size("shape.Box.half_extents.z", half_extents.z)?;
        }
        _ => {
            return Err(SceneError::new(
                "shape",
                "a character is a Sphere, a Capsule or a Box",
            ));
        }
    }
    for (name, v) in [("position", c.position), ("velocity", c.velocity)] {
        if v.abs().max_component() > limit {
            return Err(SceneError::new(
                name,
                format!("must be within ±{MAX_MAGNITUDE} (got {v:?})"),
            ));
        }
    }
    let s = &c.settings;
    if s.max_slope <= R::ZERO || s.max_slope >= R::FRAC_PI_2 {
        return Err(SceneError::new(
            "settings.max_slope",
            format!("must be above 0 and below π/2 rad (got {})", s.max_slope),
        ));
    }
    at_most("settings.step_height", s.step_height)?;
    at_most("settings.snap_distance", s.snap_distance)?;
    size("settings.skin", s.skin)?;
    at_most("settings.jump_speed", s.jump_speed)?;
    at_most("settings.push_mass", s.push_mass)?;
    if c.touching.windows(2).any(|w| w[0] >= w[1]) {
        return Err(SceneError::new("touching", "must be ascending, no repeats"));
    }
    Ok(())
}
