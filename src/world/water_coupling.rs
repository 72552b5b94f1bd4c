//! The float force generator between the water surface and what is in it: at the start of
//! each tick, right after the inputs, every floating particle and body gets its buoyancy
//! and drag ([`crate::water::float`]) from the surface as it is then, added to its force
//! for the tick as an [`ApplyForce`](crate::types::Command::ApplyForce) command's would
//! be: the integrators hold it over the tick's substeps, with gravity.
//!
//! - A particle of a floating group is a vertical column of the group's volume and height
//!   centred on it; the surface is sampled under it.
//! - A dynamic rigid body whose filter interacts with the water's: a sphere by its
//!   submerged cap, the surface sampled under its centre, the force at the centre; a box
//!   as eight octants, each a horizontal slab with the surface sampled under its centre
//!   and its force applied there (so a tilted box rights itself and waves tilt it); any
//!   other shape as the box that bounds it in its own frame. A body in the water is kept
//!   awake, as a command's force keeps it. Its angular drag is τ = −k f I ω.
//!
//! # Energy
//!
//! A force held over a tick from the positions at its start is not what the integrators
//! expect of a spring-like force: an integrator that splits the tick of h seconds into n
//! semi-implicit Euler substeps moves a body by x' = x + h v + c h² a with
//! c = (n + 1)/(2n), and the map (x, v) → (x', v') of an oscillator a = −ω²x then scales
//! phase-space areas by 1 + (1 − c)(ωh)² per tick: the body bobs higher and higher.
//! Sampling the water at the position predicted a lead β h ahead, x + β h v (and the
//! orientation turned by β h ω), scales them by 1 + (1 − c − β)(ωh)², so
//! β = 1 − c = (n − 1)/(2n) keeps the oscillator's energy ([`lead`]): 0 for particles
//! stepped once a tick, 2/5 h for rigid bodies in the solver's 5 substeps.
//!
//! Bodies and particles outside the grid's footprint feel nothing. The water does not feel
//! them (one-way coupling). Slots are visited in ascending order.

use super::pipeline::Settings;
use crate::math::{Mat3, Real, Vec3};
use crate::particles::ParticleSystem;
use crate::rigid::{Aabb, BodyKind, RigidSystem, Shape, Transform};
use crate::types::Target;
use crate::water::float::{
    column_fraction, float_force, slab_submerged_volume, sphere_submerged_volume,
};
use crate::water::{WaterBodiesDesc, WaterSystem};

/// Adds this tick's float forces (N) under the world's `settings` (gravity, tick rate,
/// substeps) to the particles and bodies in `water`.
pub(super) fn apply_float_forces<R: Real>(
    water: &WaterSystem<R>,
    particles: Option<&mut ParticleSystem<R>>,
    rigid: Option<&mut RigidSystem<R>>,
    settings: &Settings<R>,
) {
    let gravity = settings.gravity;
    if let Some(particles) = particles
        && !water.settings().particles.is_empty()
    {
        let lead = lead(settings, settings.substeps);
        float_particles(water, particles, gravity, lead);
    }
    if let (Some(rigid), Some(bodies)) = (rigid, &water.settings().bodies) {
        let substeps = settings.substeps.saturating_mul(rigid.settings().substeps);
        float_bodies(water, bodies, rigid, gravity, lead(settings, substeps));
    }
}

/// The lead β h = (n − 1)/(2n) · h (s) at which the water is sampled ahead of a body
/// integrated in `n` semi-implicit substeps per tick of h = 1/tick_rate seconds (see the
/// [module](self)'s Energy).
fn lead<R: Real>(settings: &Settings<R>, n: u32) -> R {
    let n = i64::from(n.max(1));
    R::from_ratio(n - 1, 2 * n * i64::from(settings.tick_rate))
}

/// Buoyancy ρ g V f and drag −k m f v on every live, movable particle of a floating group.
fn float_particles<R: Real>(
    water: &WaterSystem<R>,
    particles: &mut ParticleSystem<R>,
    gravity: Vec3<R>,
    lead: R,
) {
    let density = water.settings().density;
    let forces: Vec<_> = particles
        .handles()
        .filter_map(|handle| {
            let group = particles.group(handle)?;
            let float = water
                .settings()
                .particles
                .iter()
                .find(|f| f.group == group)?;
            let mass = particles.mass(handle).filter(|&m| m > R::ZERO)?;
            let velocity = particles.velocity(handle)?;
            let p = particles.position(handle)?.add_scaled(velocity, lead);
            let surface = water.surface_at(p.x, p.z)?;
            let fraction = column_fraction(p.y, float.height, surface);
            if fraction == R::ZERO {
                return None;
            }
            let submerged = float.volume * fraction;
            let force = float_force(
                gravity,
                density,
                submerged,
                float.volume,
                mass,
                float.drag,
                velocity,
            );
            Some((handle, force))
        })
        .collect();
    for (handle, force) in forces {
        particles.apply_force(Target::Particle(handle), force);
    }
}

/// Buoyancy at the centre of each submerged piece, linear drag at the centre of mass and
/// angular drag, on every floating dynamic body.
fn float_bodies<R: Real>(
    water: &WaterSystem<R>,
    desc: &WaterBodiesDesc<R>,
    rigid: &mut RigidSystem<R>,
    gravity: Vec3<R>,
    lead: R,
) {
    let density = water.settings().density;
    for i in 0..rigid.bodies.len() {
        let b = &rigid.bodies;
        if !b.alive[i] || b.kind[i] != BodyKind::Dynamic || !b.filter[i].interacts(desc.filter) {
            continue;
        }
        let (v, w, mass) = (b.linear_velocity[i], b.angular_velocity[i], b.mass[i]);
        let ahead = b.position[i].add_scaled(v, lead);
        let turned = b.orientation[i].integrate(w, lead).to_mat3();
        let pieces = submerged_pieces(water, &b.shape[i], ahead, turned);
        let (volume, submerged) = pieces.iter().fold((R::ZERO, R::ZERO), |(v, s), p| {
            (v + p.volume, s + p.submerged)
        });
        if submerged == R::ZERO || volume == R::ZERO {
            continue;
        }
        let fraction = (submerged / volume).clamp(R::ZERO, R::ONE);
        let inertia = b.orientation[i].to_mat3().rotate_inertia(b.inertia[i]);
        let back = v * -lead;
        for piece in pieces.iter().filter(|p| p.submerged > R::ZERO) {
            let lift = gravity * -(density * piece.submerged);
            rigid.apply_force(i, lift, Some(piece.centre + back));
        }
        let drag = v * -(desc.drag * mass * fraction);
        rigid.apply_force(i, drag, None);
        let torque = (inertia * w) * -(desc.angular_drag * fraction);
        rigid.bodies.torque[i] += torque;
    }
}

/// A piece of a body for buoyancy: its volume, how much of it is under water (m³) and
/// where the lift acts (m, world frame).
struct Piece<R: Real> {
    volume: R,
    submerged: R,
    centre: Vec3<R>,
}

/// The pieces of a body of `shape` at `position` turned by `rotation` under `water`:
/// one for a sphere, eight octant slabs for a box, and the eight octants of the local
/// bounding box for any other shape with a finite one (none for planes and meshes).
fn submerged_pieces<R: Real>(
    water: &WaterSystem<R>,
    shape: &Shape<R>,
    position: Vec3<R>,
    rotation: Mat3<R>,
) -> Vec<Piece<R>> {
    if let Shape::Sphere { radius } = *shape {
        let volume = R::PI * radius * radius * radius * R::from_ratio(4, 3);
        let Some(surface) = water.surface_at(position.x, position.z) else {
            return Vec::new();
        };
        let submerged = sphere_submerged_volume(position.y, radius, surface);
        return vec![Piece {
            volume,
            submerged,
            centre: position,
        }];
    }
    let (centre, half) = match *shape {
        Shape::Box { half_extents } => (Vec3::ZERO, half_extents),
        _ => match Aabb::of_shape(shape, &Transform::IDENTITY) {
            Some(bounds) => (
                (bounds.min + bounds.max) * R::HALF,
                (bounds.max - bounds.min) * R::HALF,
            ),
            None => return Vec::new(),
        },
    };
    let quarter = half * R::HALF;
    let volume = quarter.x * quarter.y * quarter.z * R::from_int(8);
    let vertical = rotation.row(1).abs().dot(quarter);
    let mut pieces = Vec::with_capacity(8);
    for corner in 0..8 {
        let sign = |bit: u32| if corner & bit == 0 { -R::ONE } else { R::ONE };
        let local = centre + Vec3::new(sign(1), sign(2), sign(4)).mul_elem(quarter);
        let at = position + rotation * local;
        let Some(surface) = water.surface_at(at.x, at.z) else {
            continue;
        };
        pieces.push(Piece {
            volume,
            submerged: slab_submerged_volume(at.y, vertical, volume, surface),
            centre: at,
        });
    }
    pieces
}
