//! The encoding of a replay's scene section, which stays readable as subsystems are added.
//!
//! The section is the codec encoding of the scene's *base* fields, in this order: `name`,
//! `description`, `gravity`, `tick_rate`, `substeps`, `seed`, `ticks`, `particles`,
//! `script` (exactly what format 1 wrote, so every recorded replay still reads), followed,
//! only when the scene has one, by its *additions*: a `u64` count and that many
//! [`Addition`]s, each a `u32` variant index and the subsystem's description, in variant
//! order with no repeats. A scene with no additions ends after `script`. Adding a variant
//! later (fluids, soft bodies, joints were added so) changes nothing for existing files,
//! and each scene has exactly one encoding: readers reject an empty or unordered list of
//! additions.

use serde::{Deserialize, Serialize};

use crate::codec::{self, CodecError};
use crate::fluid::FluidDesc;
use crate::math::{Fx, Real, Vec3};
use crate::particles::ParticlesDesc;
use crate::rigid::{JointsDesc, RigidDesc};
use crate::scene::Scene;
use crate::soft::SoftDesc;
use crate::world::TickInput;

/// The scene fields format 1 wrote, borrowed for writing.
#[derive(Serialize)]
#[serde(bound = "")]
struct BaseRef<'a, R: Real> {
    name: &'a String,
    description: &'a String,
    gravity: &'a Vec3<R>,
    tick_rate: u32,
    substeps: u32,
    seed: u64,
    ticks: u64,
    particles: &'a Option<ParticlesDesc<R>>,
    script: &'a Vec<TickInput<R>>,
}

/// The same fields, owned, for reading.
#[derive(Deserialize)]
#[serde(bound = "")]
struct Base<R: Real> {
    name: String,
    description: String,
    gravity: Vec3<R>,
    tick_rate: u32,
    substeps: u32,
    seed: u64,
    ticks: u64,
    particles: Option<ParticlesDesc<R>>,
    script: Vec<TickInput<R>>,
}

/// A subsystem description added to the scene after format 1. Variants are only ever
/// appended.
#[derive(Serialize, Deserialize)]
#[serde(bound = "")]
enum Addition<R: Real> {
    Rigid(RigidDesc<R>),
    Fluid(FluidDesc<R>),
    Soft(SoftDesc<R>),
    Joints(JointsDesc<R>),
}

impl<R: Real> Addition<R> {
    fn index(&self) -> u32 {
        match self {
            Self::Rigid(_) => 0,
            Self::Fluid(_) => 1,
            Self::Soft(_) => 2,
            Self::Joints(_) => 3,
        }
    }
}

/// The scene section's bytes.
pub fn encode_scene(scene: &Scene<Fx>) -> Result<Vec<u8>, CodecError> {
    let mut bytes = codec::encode(&BaseRef {
        name: &scene.name,
        description: &scene.description,
        gravity: &scene.gravity,
        tick_rate: scene.tick_rate,
        substeps: scene.substeps,
        seed: scene.seed,
        ticks: scene.ticks,
        particles: &scene.particles,
        script: &scene.script,
    })?;
    let mut additions = Vec::new();
    if let Some(rigid) = &scene.rigid {
        additions.push(Addition::Rigid(rigid.clone()));
    }
    if let Some(fluid) = &scene.fluid {
        additions.push(Addition::Fluid(fluid.clone()));
    }
    if let Some(soft) = &scene.soft {
        additions.push(Addition::Soft(soft.clone()));
    }
    if let Some(joints) = &scene.joints {
        additions.push(Addition::Joints(joints.clone()));
    }
    if !additions.is_empty() {
        bytes.extend(codec::encode(&additions)?);
    }
    Ok(bytes)
}

/// Decodes a scene section. On failure, returns the offset within the section where the
/// problem lies and what it is.
pub fn decode_scene(bytes: &[u8]) -> Result<Scene<Fx>, (usize, SceneSectionError)> {
    let (base, used) =
        codec::decode_prefix::<Base<Fx>>(bytes).map_err(|e| (0, SceneSectionError::Codec(e)))?;
    let mut scene = Scene {
        name: base.name,
        description: base.description,
        gravity: base.gravity,
        tick_rate: base.tick_rate,
        substeps: base.substeps,
        seed: base.seed,
        ticks: base.ticks,
        particles: base.particles,
        rigid: None,
        fluid: None,
        soft: None,
        joints: None,
        script: base.script,
    };
    if used == bytes.len() {
        return Ok(scene);
    }
    let rest = &bytes[used..];
    let (additions, extra) = codec::decode_prefix::<Vec<Addition<Fx>>>(rest)
        .map_err(|e| (used, SceneSectionError::Codec(e)))?;
    if extra != rest.len() {
        return Err((
            used + extra,
            SceneSectionError::Trailing(rest.len() - extra),
        ));
    }
    if additions.is_empty() {
        return Err((
            used,
            SceneSectionError::NotCanonical("an empty list of additions"),
        ));
    }
    if !additions.windows(2).all(|w| w[0].index() < w[1].index()) {
        return Err((
            used,
            SceneSectionError::NotCanonical("additions out of order or repeated"),
        ));
    }
    for addition in additions {
        match addition {
            Addition::Rigid(rigid) => scene.rigid = Some(rigid),
            Addition::Fluid(fluid) => scene.fluid = Some(fluid),
            Addition::Soft(soft) => scene.soft = Some(soft),
            Addition::Joints(joints) => scene.joints = Some(joints),
        }
    }
    Ok(scene)
}

/// What is wrong with a scene section.
#[derive(Debug)]
pub enum SceneSectionError {
    /// The codec could not decode a value.
    Codec(CodecError),
    /// Bytes follow the last value.
    Trailing(usize),
    /// A value decodes but is not the one encoding this format allows.
    NotCanonical(&'static str),
}
