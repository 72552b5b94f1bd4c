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
//!
//! A fluid is written as format 3 wrote it ([`FluidFields`]: every field of [`FluidDesc`]
//! but the CFL number); a fluid whose substeps adapt adds [`Addition::FluidCfl`] with its
//! CFL number, which is never 0 and never without a fluid. Likewise rigid bodies are
//! written as state version 4 wrote them ([`RigidFields`]: every solver setting but the
//! contact recycle distance), and a scene that recycles contacts adds
//! [`Addition::RigidRecycle`] with its distance, which is never 0 and never without rigid
//! bodies: a file written before recycling existed reads as a scene without it.
//!
//! Bodies are written as state version 5 wrote them ([`BodyFields`]: all but the collision
//! filter and the sensor flag); the bodies whose filter or sensor flag is not the default
//! are listed, by index in ascending order, in [`Addition::RigidBodyFlags`], which is never
//! empty and never names a body that does not exist. A scene with spawn templates adds
//! [`Addition::RigidTemplates`]: its body and joint templates, never both empty, the body
//! templates as state version 5 wrote them ([`TemplateFields`]: all but the bullet flag).
//! A scene with bullets adds [`Addition::RigidBullets`]: the indices, each list ascending,
//! of the bullet bodies and of the bullet templates, never both empty and never naming one
//! that does not exist.
//!
//! Particles are written as format 1 wrote them ([`ParticlesFields`]: all but the
//! collisions), and a scene whose particle groups collide adds
//! [`Addition::ParticleCollisions`], never empty and never without particles.
//!
//! Soft bodies are written as snapshot format 9 wrote them ([`SoftFields`],
//! [`SoftBodyFields`]: all but the ties to and contacts with rigid bodies), and a scene
//! whose soft bodies have either adds [`Addition::SoftCoupling`]: per such body, by index
//! in ascending order, its ties and contacts, never both absent, never naming a body that
//! does not exist. A fluid that meets rigid bodies adds [`Addition::FluidBodies`] with
//! their filter, never without a fluid. Kinematic characters add
//! [`Addition::Characters`], never empty. A water surface adds [`Addition::Water`] with
//! its whole description. Particles with contacts,
//! planes, rods or cables add [`Addition::ParticleContacts`], never without particles.

use serde::{Deserialize, Serialize};

use crate::character::CharacterDesc;
use crate::codec::{self, CodecError};
use crate::fluid::{FluidBlock, FluidBodiesDesc, FluidBox, FluidDesc, FluidEmitter, FluidSolver};
use crate::math::{Fx, Real, Vec3};
use crate::particles::{
    CollisionDesc, ContactsDesc, EmitterDesc, ForceDesc, Integrator, ParticleDesc,
    ParticleTemplate, ParticlesDesc,
};
use crate::rigid::{
    BodyDesc, BodyKind, BodyTemplate, CollisionFilter, Grid, JointTemplate, JointsDesc, Material,
    RigidDesc, Shape, SolverSettings,
};
use crate::scene::Scene;
use crate::soft::{
    AttachmentDesc, BodyAttachmentDesc, BodyContactsDesc, ColliderDesc, SoftBodyDesc, SoftDesc,
    SoftModel, SoftShape, XpbdSettings,
};
use crate::water::WaterDesc;
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
    particles: Option<ParticlesFields<R>>,
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
    particles: Option<ParticlesFields<R>>,
    script: Vec<TickInput<R>>,
}

/// [`ParticlesDesc`]'s fields as format 1 wrote them, in that order: all but the
/// collisions.
#[derive(Serialize, Deserialize)]
#[serde(bound = "")]
struct ParticlesFields<R: Real> {
    integrator: Integrator,
    capacity: u32,
    particles: Vec<ParticleDesc<R>>,
    templates: Vec<ParticleTemplate<R>>,
    emitters: Vec<EmitterDesc<R>>,
    forces: Vec<ForceDesc<R>>,
}

impl<R: Real> ParticlesFields<R> {
    /// The fields of `desc` but its collisions.
    fn of(desc: &ParticlesDesc<R>) -> Self {
        Self {
            integrator: desc.integrator,
            capacity: desc.capacity,
            particles: desc.particles.clone(),
            templates: desc.templates.clone(),
            emitters: desc.emitters.clone(),
            forces: desc.forces.clone(),
        }
    }

    /// The description without collisions.
    fn into_desc(self) -> ParticlesDesc<R> {
        ParticlesDesc {
            integrator: self.integrator,
            capacity: self.capacity,
            particles: self.particles,
            templates: self.templates,
            emitters: self.emitters,
            forces: self.forces,
            collisions: Vec::new(),
            contacts: None,
        }
    }
}

/// A subsystem description added to the scene after format 1. Variants are only ever
/// appended.
#[derive(Serialize, Deserialize)]
#[serde(bound = "")]
enum Addition<R: Real> {
    Rigid(RigidFields<R>),
    Fluid(FluidFields<R>),
    Soft(SoftFields<R>),
    Joints(JointsDesc<R>),
    /// The fluid's CFL number ([`FluidDesc::cfl`]), when not 0.
    FluidCfl(R),
    /// The rigid bodies' contact recycle distance
    /// ([`SolverSettings::contact_recycle_distance`]), when not 0.
    RigidRecycle(R),
    /// The bodies with a filter or a sensor flag other than the default.
    RigidBodyFlags(Vec<BodyFlags>),
    /// The rigid bodies' spawn templates, when there are any.
    RigidTemplates(Vec<TemplateFields<R>>, Vec<JointTemplate<R>>),
    /// The bullet bodies and the bullet templates, by index, when there are any.
    RigidBullets(Vec<u32>, Vec<u32>),
    /// The particle groups that collide with the rigid bodies, when there are any.
    ParticleCollisions(Vec<CollisionDesc<R>>),
    /// The soft bodies tied to or touching rigid bodies, when there are any.
    SoftCoupling(Vec<SoftCoupling<R>>),
    /// The layers of the rigid bodies the fluid meets, when it meets any.
    FluidBodies(CollisionFilter),
    /// The kinematic characters, when there are any.
    Characters(Vec<CharacterDesc<R>>),
    /// The water surface, when the scene has one.
    Water(WaterDesc<R>),
    /// The particles' contacts, planes, rods and cables, when the scene has them.
    ParticleContacts(ContactsDesc<R>),
}

/// [`SoftDesc`]'s fields as snapshot format 9 wrote them, with its bodies as
/// [`SoftBodyFields`].
#[derive(Serialize, Deserialize)]
#[serde(bound = "")]
struct SoftFields<R: Real> {
    bodies: Vec<SoftBodyFields<R>>,
    colliders: Vec<ColliderDesc<R>>,
    solver: XpbdSettings,
}

/// [`SoftBodyDesc`]'s fields as snapshot format 9 wrote them, in that order: all but the
/// ties to and contacts with rigid bodies.
#[derive(Serialize, Deserialize)]
#[serde(bound = "")]
struct SoftBodyFields<R: Real> {
    shape: SoftShape<R>,
    model: SoftModel<R>,
    mass: R,
    pins: Vec<u32>,
    attachments: Vec<AttachmentDesc<R>>,
    velocity: Vec3<R>,
    damping: R,
    radius: R,
    wind: Vec3<R>,
    drag: R,
}

/// One soft body's ties to and contacts with rigid bodies.
#[derive(Serialize, Deserialize)]
#[serde(bound = "")]
struct SoftCoupling<R: Real> {
    /// The soft body, by index.
    body: u32,
    attachments: Vec<BodyAttachmentDesc<R>>,
    contacts: Option<BodyContactsDesc<R>>,
}

impl<R: Real> SoftFields<R> {
    /// The fields of `desc` but its bodies' coupling.
    fn of(desc: &SoftDesc<R>) -> Self {
        Self {
            bodies: desc
                .bodies
                .iter()
                .map(|b| SoftBodyFields {
                    shape: b.shape.clone(),
                    model: b.model.clone(),
                    mass: b.mass,
                    pins: b.pins.clone(),
                    attachments: b.attachments.clone(),
                    velocity: b.velocity,
                    damping: b.damping,
                    radius: b.radius,
                    wind: b.wind,
                    drag: b.drag,
                })
                .collect(),
            colliders: desc.colliders.clone(),
            solver: desc.solver,
        }
    }

    /// The description without coupling.
    fn into_desc(self) -> SoftDesc<R> {
        SoftDesc {
            bodies: self
                .bodies
                .into_iter()
                .map(|b| SoftBodyDesc {
                    shape: b.shape,
                    model: b.model,
                    mass: b.mass,
                    pins: b.pins,
                    attachments: b.attachments,
                    body_attachments: Vec::new(),
                    body_contacts: None,
                    velocity: b.velocity,
                    damping: b.damping,
                    radius: b.radius,
                    wind: b.wind,
                    drag: b.drag,
                })
                .collect(),
            colliders: self.colliders,
            solver: self.solver,
        }
    }
}

/// The coupling of each soft body of `desc` that has some, by index.
fn soft_coupling<R: Real>(desc: &SoftDesc<R>) -> Vec<SoftCoupling<R>> {
    desc.bodies
        .iter()
        .enumerate()
        .filter(|(_, b)| !b.body_attachments.is_empty() || b.body_contacts.is_some())
        .map(|(k, b)| SoftCoupling {
            body: k as u32,
            attachments: b.body_attachments.clone(),
            contacts: b.body_contacts.clone(),
        })
        .collect()
}

/// [`BodyTemplate`]'s fields as state version 5 wrote them, in that order: all but the
/// bullet flag.
#[derive(Serialize, Deserialize)]
#[serde(bound = "")]
struct TemplateFields<R: Real> {
    kind: BodyKind,
    shape: Shape<R>,
    density: R,
    material: Material<R>,
    linear_damping: R,
    angular_damping: R,
    filter: CollisionFilter,
    sensor: bool,
}

impl<R: Real> TemplateFields<R> {
    fn of(t: &BodyTemplate<R>) -> Self {
        Self {
            kind: t.kind,
            shape: t.shape.clone(),
            density: t.density,
            material: t.material,
            linear_damping: t.linear_damping,
            angular_damping: t.angular_damping,
            filter: t.filter,
            sensor: t.sensor,
        }
    }

    /// The template, not a bullet.
    fn into_template(self) -> BodyTemplate<R> {
        let mut t = BodyTemplate::new(self.shape);
        t.kind = self.kind;
        t.density = self.density;
        t.material = self.material;
        t.linear_damping = self.linear_damping;
        t.angular_damping = self.angular_damping;
        t.filter = self.filter;
        t.sensor = self.sensor;
        t
    }
}

/// The indices of the items that are bullets, ascending.
fn bullet_indices<T>(items: &[T], bullet: impl Fn(&T) -> bool) -> Vec<u32> {
    items
        .iter()
        .enumerate()
        .filter(|(_, item)| bullet(item))
        .map(|(k, _)| k as u32)
        .collect()
}

/// The collision filter and sensor flag of body description `body`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
struct BodyFlags {
    body: u32,
    filter: CollisionFilter,
    sensor: bool,
}

impl BodyFlags {
    /// The flags of the descriptions that do not have the default ones, in order.
    fn of<R: Real>(bodies: &[BodyDesc<R>]) -> Vec<Self> {
        bodies
            .iter()
            .enumerate()
            .filter(|(_, b)| b.filter != CollisionFilter::ALL || b.sensor)
            .map(|(k, b)| Self {
                body: k as u32,
                filter: b.filter,
                sensor: b.sensor,
            })
            .collect()
    }
}

/// [`BodyDesc`]'s fields as state version 5 wrote them, in that order: all but the
/// collision filter and the sensor flag.
#[derive(Serialize, Deserialize)]
#[serde(bound = "")]
struct BodyFields<R: Real> {
    kind: BodyKind,
    shape: Shape<R>,
    position: Vec3<R>,
    orientation: crate::math::Quat<R>,
    velocity: Vec3<R>,
    angular_velocity: Vec3<R>,
    density: R,
    material: Material<R>,
    linear_damping: R,
    angular_damping: R,
    grid: Option<Grid<R>>,
}

impl<R: Real> BodyFields<R> {
    fn of(b: &BodyDesc<R>) -> Self {
        Self {
            kind: b.kind,
            shape: b.shape.clone(),
            position: b.position,
            orientation: b.orientation,
            velocity: b.velocity,
            angular_velocity: b.angular_velocity,
            density: b.density,
            material: b.material,
            linear_damping: b.linear_damping,
            angular_damping: b.angular_damping,
            grid: b.grid,
        }
    }

    /// The description with the default filter, not a sensor.
    fn into_desc(self) -> BodyDesc<R> {
        let mut desc = BodyDesc::new(self.shape, self.position);
        desc.kind = self.kind;
        desc.orientation = self.orientation;
        desc.velocity = self.velocity;
        desc.angular_velocity = self.angular_velocity;
        desc.density = self.density;
        desc.material = self.material;
        desc.linear_damping = self.linear_damping;
        desc.angular_damping = self.angular_damping;
        desc.grid = self.grid;
        desc
    }
}

impl<R: Real> Addition<R> {
    fn index(&self) -> u32 {
        match self {
            Self::Rigid(_) => 0,
            Self::Fluid(_) => 1,
            Self::Soft(_) => 2,
            Self::Joints(_) => 3,
            Self::FluidCfl(_) => 4,
            Self::RigidRecycle(_) => 5,
            Self::RigidBodyFlags(_) => 6,
            Self::RigidTemplates(..) => 7,
            Self::RigidBullets(..) => 8,
            Self::ParticleCollisions(_) => 9,
            Self::SoftCoupling(_) => 10,
            Self::FluidBodies(_) => 11,
            Self::Characters(_) => 12,
            Self::Water(_) => 13,
            Self::ParticleContacts(_) => 14,
        }
    }
}

/// [`FluidDesc`]'s fields as format 3 wrote them, in that order: all but the CFL number.
#[derive(Serialize, Deserialize)]
#[serde(bound = "")]
struct FluidFields<R: Real> {
    solver: FluidSolver,
    spacing: R,
    support: R,
    rest_density: R,
    speed_of_sound: R,
    viscosity: R,
    xsph: R,
    substeps: u32,
    max_density_error: R,
    max_iterations: u32,
    tank: FluidBox<R>,
    blocks: Vec<FluidBlock<R>>,
    emitters: Vec<FluidEmitter<R>>,
}

impl<R: Real> FluidFields<R> {
    /// The fields of `desc` but its CFL number.
    fn of(desc: &FluidDesc<R>) -> Self {
        Self {
            solver: desc.solver,
            spacing: desc.spacing,
            support: desc.support,
            rest_density: desc.rest_density,
            speed_of_sound: desc.speed_of_sound,
            viscosity: desc.viscosity,
            xsph: desc.xsph,
            substeps: desc.substeps,
            max_density_error: desc.max_density_error,
            max_iterations: desc.max_iterations,
            tank: desc.tank,
            blocks: desc.blocks.clone(),
            emitters: desc.emitters.clone(),
        }
    }

    /// The description with a fixed count of substeps (CFL number 0).
    fn into_desc(self) -> FluidDesc<R> {
        let mut desc = FluidDesc::new(self.solver, self.spacing, self.tank);
        desc.support = self.support;
        desc.rest_density = self.rest_density;
        desc.speed_of_sound = self.speed_of_sound;
        desc.viscosity = self.viscosity;
        desc.xsph = self.xsph;
        desc.substeps = self.substeps;
        desc.max_density_error = self.max_density_error;
        desc.max_iterations = self.max_iterations;
        desc.blocks = self.blocks;
        desc.emitters = self.emitters;
        desc
    }
}

/// [`RigidDesc`]'s fields as state version 4 wrote them: the bodies, and every solver
/// setting but the contact recycle distance, in [`SolverSettings`]' order.
#[derive(Serialize, Deserialize)]
#[serde(bound = "")]
struct RigidFields<R: Real> {
    bodies: Vec<BodyFields<R>>,
    substeps: u32,
    contact_hertz: R,
    contact_damping_ratio: R,
    max_push_velocity: R,
    restitution_threshold: R,
    speculative_distance: R,
    sleeping: bool,
    time_to_sleep: R,
    linear_sleep_speed: R,
    angular_sleep_speed: R,
}

impl<R: Real> RigidFields<R> {
    /// The fields of `desc` but its contact recycle distance.
    fn of(desc: &RigidDesc<R>) -> Self {
        let s = &desc.solver;
        Self {
            bodies: desc.bodies.iter().map(BodyFields::of).collect(),
            substeps: s.substeps,
            contact_hertz: s.contact_hertz,
            contact_damping_ratio: s.contact_damping_ratio,
            max_push_velocity: s.max_push_velocity,
            restitution_threshold: s.restitution_threshold,
            speculative_distance: s.speculative_distance,
            sleeping: s.sleeping,
            time_to_sleep: s.time_to_sleep,
            linear_sleep_speed: s.linear_sleep_speed,
            angular_sleep_speed: s.angular_sleep_speed,
        }
    }

    /// The description without contact recycling (distance 0).
    fn into_desc(self) -> RigidDesc<R> {
        RigidDesc {
            bodies: self.bodies.into_iter().map(BodyFields::into_desc).collect(),
            solver: SolverSettings {
                substeps: self.substeps,
                contact_hertz: self.contact_hertz,
                contact_damping_ratio: self.contact_damping_ratio,
                max_push_velocity: self.max_push_velocity,
                restitution_threshold: self.restitution_threshold,
                speculative_distance: self.speculative_distance,
                sleeping: self.sleeping,
                time_to_sleep: self.time_to_sleep,
                linear_sleep_speed: self.linear_sleep_speed,
                angular_sleep_speed: self.angular_sleep_speed,
                contact_recycle_distance: R::ZERO,
            },
            ..RigidDesc::default()
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
        particles: scene.particles.as_ref().map(ParticlesFields::of),
        script: &scene.script,
    })?;
    let mut additions = Vec::new();
    if let Some(rigid) = &scene.rigid {
        additions.push(Addition::Rigid(RigidFields::of(rigid)));
    }
    if let Some(fluid) = &scene.fluid {
        additions.push(Addition::Fluid(FluidFields::of(fluid)));
    }
    if let Some(soft) = &scene.soft {
        additions.push(Addition::Soft(SoftFields::of(soft)));
    }
    if let Some(joints) = &scene.joints {
        additions.push(Addition::Joints(joints.clone()));
    }
    if let Some(fluid) = scene.fluid.as_ref().filter(|f| f.cfl != Fx::ZERO) {
        additions.push(Addition::FluidCfl(fluid.cfl));
    }
    if let Some(rigid) = scene
        .rigid
        .as_ref()
        .filter(|r| r.solver.contact_recycle_distance != Fx::ZERO)
    {
        additions.push(Addition::RigidRecycle(
            rigid.solver.contact_recycle_distance,
        ));
    }
    if let Some(rigid) = &scene.rigid {
        let flags = BodyFlags::of(&rigid.bodies);
        if !flags.is_empty() {
            additions.push(Addition::RigidBodyFlags(flags));
        }
        if !rigid.templates.is_empty() || !rigid.joint_templates.is_empty() {
            additions.push(Addition::RigidTemplates(
                rigid.templates.iter().map(TemplateFields::of).collect(),
                rigid.joint_templates.clone(),
            ));
        }
        let bodies = bullet_indices(&rigid.bodies, |b| b.bullet);
        let templates = bullet_indices(&rigid.templates, |t| t.bullet);
        if !bodies.is_empty() || !templates.is_empty() {
            additions.push(Addition::RigidBullets(bodies, templates));
        }
    }
    if let Some(particles) = scene
        .particles
        .as_ref()
        .filter(|p| !p.collisions.is_empty())
    {
        additions.push(Addition::ParticleCollisions(particles.collisions.clone()));
    }
    if let Some(coupling) = scene.soft.as_ref().map(soft_coupling)
        && !coupling.is_empty()
    {
        additions.push(Addition::SoftCoupling(coupling));
    }
    if let Some(bodies) = scene.fluid.as_ref().and_then(|f| f.bodies) {
        additions.push(Addition::FluidBodies(bodies.filter));
    }
    if !scene.characters.is_empty() {
        additions.push(Addition::Characters(scene.characters.clone()));
    }
    if let Some(water) = &scene.water_surface {
        additions.push(Addition::Water(water.clone()));
    }
    if let Some(contacts) = scene.particles.as_ref().and_then(|p| p.contacts.as_ref()) {
        additions.push(Addition::ParticleContacts(contacts.clone()));
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
        particles: base.particles.map(ParticlesFields::into_desc),
        rigid: None,
        fluid: None,
        soft: None,
        joints: None,
        characters: Vec::new(),
        water_surface: None,
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
            Addition::Rigid(rigid) => scene.rigid = Some(rigid.into_desc()),
            Addition::Fluid(fluid) => scene.fluid = Some(fluid.into_desc()),
            Addition::Soft(soft) => scene.soft = Some(soft.into_desc()),
            Addition::Joints(joints) => scene.joints = Some(joints),
            Addition::FluidCfl(cfl) => {
                let not_canonical = |what| Err((used, SceneSectionError::NotCanonical(what)));
                let Some(fluid) = &mut scene.fluid else {
                    return not_canonical("a fluid CFL number without a fluid");
                };
                if cfl == Fx::ZERO {
                    return not_canonical("a fluid CFL number of 0 (written by leaving it out)");
                }
                fluid.cfl = cfl;
            }
            Addition::RigidRecycle(distance) => {
                let not_canonical = |what| Err((used, SceneSectionError::NotCanonical(what)));
                let Some(rigid) = &mut scene.rigid else {
                    return not_canonical("a contact recycle distance without rigid bodies");
                };
                if distance == Fx::ZERO {
                    return not_canonical(
                        "a contact recycle distance of 0 (written by leaving it out)",
                    );
                }
                rigid.solver.contact_recycle_distance = distance;
            }
            Addition::RigidBodyFlags(flags) => {
                let not_canonical = |what| Err((used, SceneSectionError::NotCanonical(what)));
                let Some(rigid) = &mut scene.rigid else {
                    return not_canonical("body flags without rigid bodies");
                };
                if flags.is_empty() {
                    return not_canonical("an empty list of body flags");
                }
                if !flags.windows(2).all(|w| w[0].body < w[1].body) {
                    return not_canonical("body flags out of order or repeated");
                }
                for f in flags {
                    let Some(body) = rigid.bodies.get_mut(f.body as usize) else {
                        return not_canonical("body flags for a body that does not exist");
                    };
                    if f.filter == CollisionFilter::ALL && !f.sensor {
                        return not_canonical("default body flags (written by leaving them out)");
                    }
                    body.filter = f.filter;
                    body.sensor = f.sensor;
                }
            }
            Addition::RigidTemplates(bodies, joints) => {
                let not_canonical = |what| Err((used, SceneSectionError::NotCanonical(what)));
                let Some(rigid) = &mut scene.rigid else {
                    return not_canonical("spawn templates without rigid bodies");
                };
                if bodies.is_empty() && joints.is_empty() {
                    return not_canonical("empty lists of spawn templates");
                }
                rigid.templates = bodies
                    .into_iter()
                    .map(TemplateFields::into_template)
                    .collect();
                rigid.joint_templates = joints;
            }
            Addition::RigidBullets(bodies, templates) => {
                let not_canonical = |what| Err((used, SceneSectionError::NotCanonical(what)));
                let Some(rigid) = &mut scene.rigid else {
                    return not_canonical("bullets without rigid bodies");
                };
                if bodies.is_empty() && templates.is_empty() {
                    return not_canonical("empty lists of bullets");
                }
                let ascending = |list: &[u32]| list.windows(2).all(|w| w[0] < w[1]);
                if !ascending(&bodies) || !ascending(&templates) {
                    return not_canonical("bullets out of order or repeated");
                }
                for k in bodies {
                    let Some(body) = rigid.bodies.get_mut(k as usize) else {
                        return not_canonical("a bullet body that does not exist");
                    };
                    body.bullet = true;
                }
                for k in templates {
                    let Some(template) = rigid.templates.get_mut(k as usize) else {
                        return not_canonical("a bullet template that does not exist");
                    };
                    template.bullet = true;
                }
            }
            Addition::ParticleCollisions(collisions) => {
                let not_canonical = |what| Err((used, SceneSectionError::NotCanonical(what)));
                let Some(particles) = &mut scene.particles else {
                    return not_canonical("particle collisions without particles");
                };
                if collisions.is_empty() {
                    return not_canonical("an empty list of particle collisions");
                }
                particles.collisions = collisions;
            }
            Addition::SoftCoupling(coupling) => {
                let not_canonical = |what| Err((used, SceneSectionError::NotCanonical(what)));
                let Some(soft) = &mut scene.soft else {
                    return not_canonical("soft-body coupling without soft bodies");
                };
                if coupling.is_empty() {
                    return not_canonical("an empty list of soft-body coupling");
                }
                if !coupling.windows(2).all(|w| w[0].body < w[1].body) {
                    return not_canonical("soft-body coupling out of order or repeated");
                }
                for c in coupling {
                    let Some(body) = soft.bodies.get_mut(c.body as usize) else {
                        return not_canonical("soft-body coupling for a body that does not exist");
                    };
                    if c.attachments.is_empty() && c.contacts.is_none() {
                        return not_canonical(
                            "empty soft-body coupling (written by leaving it out)",
                        );
                    }
                    body.body_attachments = c.attachments;
                    body.body_contacts = c.contacts;
                }
            }
            Addition::FluidBodies(filter) => {
                let Some(fluid) = &mut scene.fluid else {
                    return Err((
                        used,
                        SceneSectionError::NotCanonical("fluid bodies without a fluid"),
                    ));
                };
                fluid.bodies = Some(FluidBodiesDesc { filter });
            }
            Addition::Characters(characters) => {
                if characters.is_empty() {
                    return Err((used, SceneSectionError::NotCanonical("no characters")));
                }
                scene.characters = characters;
            }
            Addition::Water(water) => scene.water_surface = Some(water),
            Addition::ParticleContacts(contacts) => {
                let Some(particles) = &mut scene.particles else {
                    return Err((
                        used,
                        SceneSectionError::NotCanonical("particle contacts without particles"),
                    ));
                };
                particles.contacts = Some(contacts);
            }
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixstep_scenes::builtin_scene;

    /// The built-in dam break, its fluid's substeps adapting at CFL number 0.2.
    fn adaptive_dam_break() -> Scene<Fx> {
        let mut scene = builtin_scene::<Fx>("dam_break").expect("a built-in scene");
        scene.fluid.as_mut().expect("a fluid").cfl = Fx::from_ratio(1, 5);
        scene
    }

    /// The section of `scene` with `additions` in place of its own.
    fn with_additions(scene: &Scene<Fx>, additions: &[Addition<Fx>]) -> Vec<u8> {
        let mut bare = scene.clone();
        (bare.rigid, bare.fluid, bare.soft, bare.joints) = (None, None, None, None);
        let mut bytes = encode_scene(&bare).expect("encodes");
        bytes.extend(codec::encode(&additions).expect("encodes"));
        bytes
    }

    fn rejection(bytes: &[u8]) -> String {
        match decode_scene(bytes) {
            Ok(_) => panic!("decoded"),
            Err((_, SceneSectionError::NotCanonical(what))) => what.to_owned(),
            Err((_, e)) => panic!("another error: {e:?}"),
        }
    }

    #[test]
    fn a_cfl_number_survives_the_round_trip() {
        let scene = adaptive_dam_break();
        let bytes = encode_scene(&scene).expect("encodes");
        assert_eq!(decode_scene(&bytes).expect("decodes"), scene);
    }

    #[test]
    fn a_fixed_count_writes_no_cfl_addition() {
        let mut scene = adaptive_dam_break();
        let adaptive = encode_scene(&scene).expect("encodes");
        scene.fluid.as_mut().expect("a fluid").cfl = Fx::ZERO;
        let fixed = encode_scene(&scene).expect("encodes");
        let fluid = FluidFields::of(scene.fluid.as_ref().expect("a fluid"));
        assert_eq!(fixed, with_additions(&scene, &[Addition::Fluid(fluid)]));
        // The adaptive scene adds one addition: its count, then the variant and the number.
        assert_eq!(adaptive.len(), fixed.len() + 4 + 8);
        assert_eq!(decode_scene(&fixed).expect("decodes"), scene);
    }

    #[test]
    fn a_recycle_distance_survives_the_round_trip_and_none_is_zero() {
        let mut scene = builtin_scene::<Fx>("stack").expect("a built-in scene");
        let distance = scene
            .rigid
            .as_ref()
            .expect("rigid bodies")
            .solver
            .contact_recycle_distance;
        assert_ne!(distance, Fx::ZERO);
        let recycling = encode_scene(&scene).expect("encodes");
        assert_eq!(decode_scene(&recycling).expect("decodes"), scene);
        // A section without the addition (as state version 4 wrote) reads as distance 0.
        let rigid = RigidFields::of(scene.rigid.as_ref().expect("rigid bodies"));
        let older = with_additions(&scene, &[Addition::Rigid(rigid)]);
        assert_eq!(recycling.len(), older.len() + 4 + 8);
        scene
            .rigid
            .as_mut()
            .expect("rigid bodies")
            .solver
            .contact_recycle_distance = Fx::ZERO;
        assert_eq!(decode_scene(&older).expect("decodes"), scene);
        assert_eq!(encode_scene(&scene).expect("encodes"), older);
    }

    #[test]
    fn a_recycle_distance_of_zero_or_without_rigid_bodies_is_refused() {
        let scene = builtin_scene::<Fx>("stack").expect("a built-in scene");
        let rigid = RigidFields::of(scene.rigid.as_ref().expect("rigid bodies"));
        let zero = with_additions(
            &scene,
            &[Addition::Rigid(rigid), Addition::RigidRecycle(Fx::ZERO)],
        );
        assert!(rejection(&zero).contains("of 0"));
        let alone = with_additions(&scene, &[Addition::RigidRecycle(Fx::ONE)]);
        assert!(rejection(&alone).contains("without rigid bodies"));
    }

    #[test]
    fn bullets_survive_the_round_trip_and_cost_nothing_when_absent() {
        let mut scene = builtin_scene::<Fx>("shooter").expect("a built-in scene");
        let plain = encode_scene(&scene).expect("encodes");
        let rigid = scene.rigid.as_mut().expect("rigid bodies");
        rigid.bodies[2].bullet = true;
        rigid.templates[0].bullet = true;
        let bullets = encode_scene(&scene).expect("encodes");
        assert_eq!(decode_scene(&bullets).expect("decodes"), scene);
        // One more addition: its variant index, then two lists of one index each.
        assert_eq!(bullets.len(), plain.len() + 4 + (8 + 4) * 2);
        let alone = with_additions(&scene, &[Addition::RigidBullets(vec![2], vec![])]);
        assert!(rejection(&alone).contains("without rigid bodies"));
        let rigid = RigidFields::of(scene.rigid.as_ref().expect("rigid bodies"));
        let missing = with_additions(
            &scene,
            &[
                Addition::Rigid(rigid),
                Addition::RigidBullets(vec![99], vec![]),
            ],
        );
        assert!(rejection(&missing).contains("does not exist"));
    }

    #[test]
    fn particle_collisions_survive_the_round_trip_and_are_never_empty_or_alone() {
        let scene = builtin_scene::<Fx>("debris").expect("a built-in scene");
        let bytes = encode_scene(&scene).expect("encodes");
        assert_eq!(decode_scene(&bytes).expect("decodes"), scene);
        let mut bare = scene.clone();
        bare.particles
            .as_mut()
            .expect("particles")
            .collisions
            .clear();
        let plain = encode_scene(&bare).expect("encodes");
        assert!(plain.len() < bytes.len());
        assert_eq!(decode_scene(&plain).expect("decodes"), bare);
        let empty = with_additions(&bare, &[Addition::ParticleCollisions(Vec::new())]);
        assert!(rejection(&empty).contains("an empty list of particle collisions"));
        let mut none = bare.clone();
        none.particles = None;
        let alone = with_additions(
            &none,
            &[Addition::ParticleCollisions(vec![CollisionDesc::new(0)])],
        );
        assert!(rejection(&alone).contains("without particles"));
    }

    #[test]
    fn a_cfl_number_without_a_fluid_is_refused() {
        let scene = adaptive_dam_break();
        let bytes = with_additions(&scene, &[Addition::FluidCfl(Fx::from_ratio(1, 5))]);
        assert!(rejection(&bytes).contains("without a fluid"));
    }

    #[test]
    fn a_written_cfl_number_of_zero_is_refused() {
        let scene = adaptive_dam_break();
        let fluid = FluidFields::of(scene.fluid.as_ref().expect("a fluid"));
        let bytes = with_additions(
            &scene,
            &[Addition::Fluid(fluid), Addition::FluidCfl(Fx::ZERO)],
        );
        assert!(rejection(&bytes).contains("of 0"));
    }
}
