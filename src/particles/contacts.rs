//! Particle contacts and links (Millington's mass-aggregate engine, *Game Physics Engine
//! Development*, chapters 7 and 8): after every step the contacts are generated, then
//! resolved one at a time in order of largest closing speed.
//!
//! # Generation
//!
//! In this order, each list in ascending order: particle–plane contacts (by particle, then
//! plane), particle–particle contacts between groups (by the pair (i, j), i < j; every
//! pair is tested, O(n²)), then the links in scene order. A contact joins particle a to b
//! (or to a plane) with a unit normal n̂ along which a moves to separate from b, a
//! penetration p (m) and a restitution e:
//!
//! - plane: n̂ the plane's normal, p = r − (n̂·x − offset) > 0, r the contact radius;
//! - particles i < j of different groups: n̂ = (xᵢ − xⱼ)/d, p = 2r − d > 0 (n̂ = +y when
//!   d = 0);
//! - rod of length ℓ₀ at length ℓ ≠ ℓ₀: n̂ = (x_b − x_a)/ℓ, p = ℓ − ℓ₀ when too long,
//!   n̂ = (x_a − x_b)/ℓ, p = ℓ₀ − ℓ when too short; e = 0;
//! - cable of length ℓ_max at ℓ > ℓ_max: n̂ = (x_b − x_a)/ℓ, p = ℓ − ℓ_max, its e.
//!
//! # Resolution
//!
//! At most `iterations` resolutions per step (the scene's, default 256; Millington uses
//! twice the contact count, too few for a chain of rods under a heavy load, where each
//! resolution fixes one link and disturbs its neighbours); each picks the contact of
//! smallest separating velocity v_s = (v_a − v_b)·n̂ (m/s) among those approaching
//! (v_s < −2⁻²⁰ m/s) or penetrating (p > 2⁻²⁰ m), the lowest index on a tie, and resolves
//! it (the loop ends early when there is none):
//!
//! - velocity (when v_s < 0): the new separating velocity is e s_c, with s_c the closing
//!   speed at the moment of impact. s = −v_s was reached at the end of the step, after the
//!   particles went on closing through p under the step's relative acceleration into the
//!   contact g = −Δv_rel·n̂/h (Δv the velocity the forces gave this step), so
//!   s_c² = s² − 2 g p when g > 0 (else s_c = s). A particle dropped from h with e then
//!   rises to e²h, and a particle resting on a plane (s = g h, p = g h²) gets s_c = 0, so
//!   it does not jitter. The change Δv_s = e s_c − v_s is split by inverse mass:
//!   v_a += n̂ Δv_s w_a/(w_a + w_b), v_b −= n̂ Δv_s w_b/(w_a + w_b);
//! - interpenetration (when p > 0): x_a += n̂ p w_a/(w_a + w_b), x_b −= n̂ p w_b/(w_a + w_b),
//!   and every contact sharing a moved particle updates its p by the move along its n̂.
//!
//! Pinned particles (w = 0) take no share. Touched particles restart Störmer–Verlet from
//! (x, v).

use serde::{Deserialize, Serialize};

use super::contact_desc::{
    ContactPlaneDesc, ContactsDesc, LinkDesc, MAX_ITERATIONS, MAX_LINKS, MAX_PLANES,
};
use super::storage::{Attributes, Kinematics};
use crate::math::{Real, Vec3};
use crate::types::{Handle, SceneError};

/// A plane in compiled form.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct ContactPlane<R: Real> {
    /// Unit normal.
    pub normal: Vec3<R>,
    /// m.
    pub offset: R,
    pub restitution: R,
}

/// A link in compiled form.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub(crate) enum LinkKind {
    Rod,
    Cable,
}

/// A rod or cable between two particles.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Link<R: Real> {
    pub kind: LinkKind,
    pub a: Handle,
    pub b: Handle,
    /// ℓ₀ or ℓ_max, m.
    pub length: R,
    /// 0 for rods.
    pub restitution: R,
}

/// No second particle: the contact is with a plane.
const PLANE: u32 = u32::MAX;

/// One contact of a step.
#[derive(Clone, Copy, Debug)]
struct Contact<R: Real> {
    a: u32,
    b: u32,
    normal: Vec3<R>,
    penetration: R,
    restitution: R,
}

/// Working arrays, not state.
#[derive(Default)]
struct Scratch<R: Real> {
    start_velocities: Vec<Vec3<R>>,
    contacts: Vec<Contact<R>>,
}

/// The contacts and links of a particle system (configuration: it never changes while the
/// system runs).
#[derive(Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct ParticleContacts<R: Real> {
    /// r, m.
    pub radius: R,
    /// e of particle–particle contacts.
    pub restitution: R,
    pub planes: Vec<ContactPlane<R>>,
    pub links: Vec<Link<R>>,
    /// The most resolutions per step.
    pub iterations: u32,
    #[serde(skip)]
    scratch: Scratch<R>,
}

impl<R: Real> Clone for ParticleContacts<R> {
    /// The configuration; the scratch starts empty.
    fn clone(&self) -> Self {
        Self {
            radius: self.radius,
            restitution: self.restitution,
            planes: self.planes.clone(),
            links: self.links.clone(),
            iterations: self.iterations,
            scratch: Scratch::default(),
        }
    }
}

impl<R: Real> PartialEq for ParticleContacts<R> {
    /// The configuration; the scratch is not state.
    fn eq(&self, other: &Self) -> bool {
        (self.radius, self.restitution) == (other.radius, other.restitution)
            && self.planes == other.planes
            && self.links == other.links
            && self.iterations == other.iterations
    }
}

impl<R: Real> core::fmt::Debug for ParticleContacts<R> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("ParticleContacts")
            .field("radius", &self.radius)
            .field("restitution", &self.restitution)
            .field("planes", &self.planes)
            .field("links", &self.links)
            .field("iterations", &self.iterations)
            .finish()
    }
}

/// Checks 0 ≤ e ≤ 1.
fn check_restitution<R: Real>(e: R, field: &str) -> Result<(), SceneError> {
    if (R::ZERO..=R::ONE).contains(&e) {
        Ok(())
    } else {
        Err(SceneError::new(field, format!("must be 0 to 1 (got {e})")))
    }
}

impl<R: Real> ParticleContacts<R> {
    /// Checks `desc` (field paths relative to `contacts`) for a scene of `particles`
    /// particles, and compiles it.
    pub fn from_desc(desc: &ContactsDesc<R>, particles: usize) -> Result<Self, SceneError> {
        if desc.radius < R::ZERO {
            return Err(SceneError::new(
                "radius",
                format!("must be ≥ 0 (got {})", desc.radius),
            ));
        }
        check_restitution(desc.restitution, "restitution")?;
        if desc.planes.len() > MAX_PLANES {
            return Err(SceneError::new(
                "planes",
                format!("at most {MAX_PLANES} planes (got {})", desc.planes.len()),
            ));
        }
        if desc.links.len() > MAX_LINKS {
            return Err(SceneError::new(
                "links",
                format!("at most {MAX_LINKS} links (got {})", desc.links.len()),
            ));
        }
        if !(1..=MAX_ITERATIONS).contains(&desc.iterations) {
            return Err(SceneError::new(
                "iterations",
                format!("must be 1 to {MAX_ITERATIONS} (got {})", desc.iterations),
            ));
        }
        let planes = desc
            .planes
            .iter()
            .enumerate()
            .map(|(i, plane)| compile_plane(plane).map_err(|e| e.within(&format!("planes[{i}]"))))
            .collect::<Result<_, _>>()?;
        let links = desc
            .links
            .iter()
            .enumerate()
            .map(|(i, link)| {
                compile_link(link, particles).map_err(|e| e.within(&format!("links[{i}]")))
            })
            .collect::<Result<_, _>>()?;
        Ok(Self {
            radius: desc.radius,
            restitution: desc.restitution,
            planes,
            links,
            iterations: desc.iterations,
            scratch: Scratch::default(),
        })
    }

    /// Checks the invariants of a decoded configuration (fields relative to `contacts`):
    /// what [`from_desc`](Self::from_desc) checks, with unit plane normals.
    pub fn validate(&self) -> Result<(), SceneError> {
        if self.radius < R::ZERO {
            return Err(SceneError::new("radius", "must be ≥ 0"));
        }
        check_restitution(self.restitution, "restitution")?;
        if self.planes.len() > MAX_PLANES
            || self.links.len() > MAX_LINKS
            || !(1..=MAX_ITERATIONS).contains(&self.iterations)
        {
            return Err(SceneError::new(
                "iterations",
                "too many planes or links, or iterations out of range",
            ));
        }
        for (i, plane) in self.planes.iter().enumerate() {
            check_restitution(plane.restitution, "restitution")
                .map_err(|e| e.within(&format!("planes[{i}]")))?;
            let error = (plane.normal.length_squared() - R::ONE).abs();
            if error > R::from_ratio(1, 1 << 16) {
                return Err(SceneError::new(
                    format!("planes[{i}].normal"),
                    "must be a unit vector",
                ));
            }
        }
        for (i, link) in self.links.iter().enumerate() {
            check_restitution(link.restitution, "restitution")
                .map_err(|e| e.within(&format!("links[{i}]")))?;
            if link.length <= R::ZERO || link.a == link.b {
                return Err(SceneError::new(
                    format!("links[{i}]"),
                    "a link joins two particles and has a length > 0",
                ));
            }
        }
        Ok(())
    }

    /// Keeps the velocities at the start of a step, v₀ (m/s), from which
    /// [`resolve`](Self::resolve) takes what the step's forces added.
    pub fn remember(&mut self, velocities: &[Vec3<R>]) {
        self.scratch.start_velocities.clear();
        self.scratch.start_velocities.extend_from_slice(velocities);
    }

    /// Generates and resolves the step's contacts after a step of `dt` seconds (see the
    /// [module documentation](self)); returns whether any particle moved.
    pub fn resolve(
        &mut self,
        dt: R,
        kinematics: &mut Kinematics<R>,
        attributes: &Attributes<R>,
    ) -> bool {
        self.generate(&kinematics.positions, attributes);
        let contacts = &mut self.scratch.contacts;
        if contacts.is_empty() {
            return false;
        }
        // The velocity each particle's forces gave it this step, Δv = v₁ − v₀, taken before
        // any contact changes v₁.
        let kicks = &mut self.scratch.start_velocities;
        for (kick, &v1) in kicks.iter_mut().zip(&kinematics.velocities) {
            *kick = v1 - *kick;
        }
        let kicks = &*kicks;
        let w = &attributes.inv_masses;
        let x = &mut kinematics.positions;
        let v = &mut kinematics.velocities;
        let inv_dt = dt.recip();
        let velocity_of = |v: &[Vec3<R>], i: u32| {
            if i == PLANE {
                Vec3::ZERO
            } else {
                v[i as usize]
            }
        };
        let kick = |i: u32| {
            if i == PLANE {
                Vec3::ZERO
            } else {
                kicks.get(i as usize).copied().unwrap_or(Vec3::ZERO)
            }
        };
        let weight = |i: u32| if i == PLANE { R::ZERO } else { w[i as usize] };
        let slop = R::ONE.mul_pow2_recip(20);
        for _ in 0..self.iterations {
            let mut chosen = None;
            let mut lowest = R::MAX;
            for (index, c) in contacts.iter().enumerate() {
                let separating = (velocity_of(v, c.a) - velocity_of(v, c.b)).dot(c.normal);
                if separating < lowest && (separating < -slop || c.penetration > slop) {
                    lowest = separating;
                    chosen = Some(index);
                }
            }
            let Some(index) = chosen else {
                break;
            };
            let c = contacts[index];
            let (wa, wb) = (weight(c.a), weight(c.b));
            let total = wa + wb;
            if total == R::ZERO {
                contacts[index].penetration = R::ZERO;
                continue;
            }
            let (share_a, share_b) = (wa / total, wb / total);
            if lowest < R::ZERO {
                let closing = -lowest;
                let into = -(kick(c.a) - kick(c.b)).dot(c.normal) * inv_dt;
                let impact = if into > R::ZERO && c.penetration > R::ZERO {
                    (closing * closing - R::TWO * into * c.penetration)
                        .max(R::ZERO)
                        .sqrt()
                } else {
                    closing
                };
                let change = c.restitution * impact - lowest;
                if c.a != PLANE {
                    v[c.a as usize] = v[c.a as usize].add_scaled(c.normal, change * share_a);
                }
                if c.b != PLANE {
                    v[c.b as usize] = v[c.b as usize].add_scaled(c.normal, -(change * share_b));
                }
            }
            if c.penetration > R::ZERO {
                let move_a = c.normal * (c.penetration * share_a);
                let move_b = c.normal * -(c.penetration * share_b);
                for (i, moved) in [(c.a, move_a), (c.b, move_b)] {
                    if i == PLANE || moved == Vec3::ZERO {
                        continue;
                    }
                    x[i as usize] += moved;
                    for other in contacts.iter_mut() {
                        if other.a == i {
                            other.penetration -= moved.dot(other.normal);
                        } else if other.b == i {
                            other.penetration += moved.dot(other.normal);
                        }
                    }
                }
                contacts[index].penetration = R::ZERO;
            }
        }
        for c in contacts.iter() {
            for i in [c.a, c.b] {
                if i != PLANE {
                    kinematics.has_previous_position[i as usize] = false;
                }
            }
        }
        true
    }

    /// Fills the scratch contact list from the positions `x` (m).
    fn generate(&mut self, x: &[Vec3<R>], attributes: &Attributes<R>) {
        let contacts = &mut self.scratch.contacts;
        contacts.clear();
        let movable = |i: usize| attributes.is_movable(i);
        for (i, &position) in x.iter().enumerate() {
            if !movable(i) {
                continue;
            }
            for plane in &self.planes {
                let penetration = self.radius - (plane.normal.dot(position) - plane.offset);
                if penetration > R::ZERO {
                    contacts.push(Contact {
                        a: i as u32,
                        b: PLANE,
                        normal: plane.normal,
                        penetration,
                        restitution: plane.restitution,
                    });
                }
            }
        }
        if self.radius > R::ZERO {
            let reach = self.radius + self.radius;
            let reach_squared = reach * reach;
            let live = |i: usize| attributes.alive[i];
            for i in 0..x.len() {
                if !live(i) {
                    continue;
                }
                for j in i + 1..x.len() {
                    if !live(j)
                        || attributes.groups[i] == attributes.groups[j]
                        || !(movable(i) || movable(j))
                    {
                        continue;
                    }
                    let offset = x[i] - x[j];
                    let distance_squared = offset.length_squared();
                    if distance_squared >= reach_squared {
                        continue;
                    }
                    let (normal, distance) = offset
                        .try_normalize()
                        .unwrap_or((Vec3::new(R::ZERO, R::ONE, R::ZERO), R::ZERO));
                    contacts.push(Contact {
                        a: i as u32,
                        b: j as u32,
                        normal,
                        penetration: reach - distance,
                        restitution: self.restitution,
                    });
                }
            }
        }
        for link in &self.links {
            let (Some(a), Some(b)) = (attributes.resolve(link.a), attributes.resolve(link.b))
            else {
                continue;
            };
            if !(movable(a) || movable(b)) {
                continue;
            }
            let Some((axis, length)) = (x[b] - x[a]).try_normalize() else {
                continue;
            };
            let (normal, penetration) = match link.kind {
                LinkKind::Rod if length > link.length => (axis, length - link.length),
                LinkKind::Rod if length < link.length => (-axis, link.length - length),
                LinkKind::Cable if length > link.length => (axis, length - link.length),
                _ => continue,
            };
            contacts.push(Contact {
                a: a as u32,
                b: b as u32,
                normal,
                penetration,
                restitution: link.restitution,
            });
        }
    }

    /// The two ends of every link whose particles are alive, m, in scene order, with
    /// whether it is a rod. For drawing.
    pub fn link_ends<'a>(
        &'a self,
        positions: &'a [Vec3<R>],
        attributes: &'a Attributes<R>,
    ) -> impl Iterator<Item = (Vec3<R>, Vec3<R>, bool)> + 'a {
        self.links.iter().filter_map(move |link| {
            let a = attributes.resolve(link.a)?;
            let b = attributes.resolve(link.b)?;
            Some((positions[a], positions[b], link.kind == LinkKind::Rod))
        })
    }
}

/// Checks and compiles one plane (fields relative to it).
fn compile_plane<R: Real>(plane: &ContactPlaneDesc<R>) -> Result<ContactPlane<R>, SceneError> {
    check_restitution(plane.restitution, "restitution")?;
    let Some((normal, _)) = plane.normal.try_normalize() else {
        return Err(SceneError::new("normal", "must not be the zero vector"));
    };
    Ok(ContactPlane {
        normal,
        offset: plane.offset,
        restitution: plane.restitution,
    })
}

/// Checks and compiles one link (fields relative to it) of a scene of `particles`
/// particles.
fn compile_link<R: Real>(link: &LinkDesc<R>, particles: usize) -> Result<Link<R>, SceneError> {
    let (kind, a, b, length, restitution, length_field) = match *link {
        LinkDesc::Rod { a, b, length } => (LinkKind::Rod, a, b, length, R::ZERO, "Rod.length"),
        LinkDesc::Cable {
            a,
            b,
            max_length,
            restitution,
        } => {
            check_restitution(restitution, "Cable.restitution")?;
            (
                LinkKind::Cable,
                a,
                b,
                max_length,
                restitution,
                "Cable.max_length",
            )
        }
    };
    let name = if kind == LinkKind::Rod {
        "Rod"
    } else {
        "Cable"
    };
    for (end, field) in [(a, "a"), (b, "b")] {
        if end as usize >= particles {
            return Err(SceneError::new(
                format!("{name}.{field}"),
                format!("particle {end} does not exist (the scene has {particles})"),
            ));
        }
    }
    if a == b {
        return Err(SceneError::new(
            format!("{name}.b"),
            format!("links particle {a} to itself"),
        ));
    }
    if length <= R::ZERO {
        return Err(SceneError::new(
            length_field,
            format!("must be > 0 (got {length})"),
        ));
    }
    Ok(Link {
        kind,
        a: Handle::new(a, 0),
        b: Handle::new(b, 0),
        length,
        restitution,
    })
}
