//! Particles bouncing off surfaces: the groups that collide, the bounce, and the pass over
//! the particles after each step.
//!
//! A colliding particle is a point. After a step moved it from x₀ to x₁, the path is cast
//! against the surfaces ([`Surfaces`]), each seen moving with its own velocity u at x₀, so
//! the cast follows the path relative to the surface, x₀ → x₁ − u Δt. At the first hit
//! (fraction f of the path, unit normal n̂ out of the surface) the particle bounces: its
//! relative velocity is reflected by [`bounce`], and for the rest of the step, τ = (1 − f)
//! Δt, it moves on from the hit point (2⁻¹⁶ m off the surface) with the reflected relative
//! velocity and the step's own acceleration, plus the surface's motion u τ. Up to
//! [`MAX_BOUNCES`] hits are followed per step (a corner); a particle still hitting after them
//! stops at its last hit.
//!
//! With `push`, the surface's body receives the opposite of the particle's momentum
//! change, J = −m (v′ − v) (N·s), at the hit point, so momentum is conserved. Particles are
//! visited in ascending slot order, so the pushes add up in one order on every peer.

use super::ParticleSystem;
use super::desc::CollisionDesc;
use crate::math::{Real, Vec3};
use crate::rigid::CollisionFilter;
use crate::types::SceneError;

/// The most hits followed per particle and step.
pub const MAX_BOUNCES: u32 = 3;

/// How far off a surface a bounced particle is left, m: 2⁻¹⁶ m, so that its next path
/// starts outside the surface.
fn skin<R: Real>() -> R {
    R::from_ratio(1, 1 << 16)
}

/// Checks one group's [`CollisionDesc`] (field paths relative to it): 0 ≤ e ≤ 1, μ ≥ 0.
pub(crate) fn check_collision<R: Real>(desc: &CollisionDesc<R>) -> Result<(), SceneError> {
    if !(R::ZERO..=R::ONE).contains(&desc.restitution) {
        return Err(SceneError::new(
            "restitution",
            format!("must be 0 to 1 (got {})", desc.restitution),
        ));
    }
    if desc.friction < R::ZERO {
        return Err(SceneError::new(
            "friction",
            format!("must be ≥ 0 (got {})", desc.friction),
        ));
    }
    Ok(())
}

/// A particle's state before a step ([`ParticleSystem::path_starts`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PathStart<R: Real> {
    /// x₀, m.
    pub position: Vec3<R>,
    /// v₀, m/s.
    pub velocity: Vec3<R>,
    /// The slot's generation, to tell a particle that died and was replaced.
    pub generation: u32,
}

/// The first surface a particle's path meets.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SurfaceHit<R: Real> {
    /// Which body, as the surfaces number them.
    pub body: u32,
    /// Where along the relative path, in [0, 1].
    pub fraction: R,
    /// Unit normal out of the surface.
    pub normal: Vec3<R>,
    /// The surface's velocity at the path's start, m/s.
    pub velocity: Vec3<R>,
}

/// What particles collide with: the rigid bodies, seen by the world's coupling.
pub(crate) trait Surfaces<R: Real> {
    /// The first surface the point moving from `from` to `to` (m) during `dt` seconds
    /// enters, among those `filter` interacts with; each surface seen moving with its
    /// velocity at `from`. A path that starts inside a surface passes out of it freely.
    fn cast(
        &mut self,
        from: Vec3<R>,
        to: Vec3<R>,
        dt: R,
        filter: CollisionFilter,
    ) -> Option<SurfaceHit<R>>;

    /// Applies impulse J (N·s) at `point` (m) to body `body`.
    fn push(&mut self, body: u32, impulse: Vec3<R>, point: Vec3<R>);
}

/// A bounce off a surface of unit normal n̂, with restitution e and friction μ: the relative
/// velocity w (m/s) is split into its normal part wₙ = (w·n̂) n̂ and tangential part
/// wₜ = w − wₙ, and becomes w′ = −e wₙ + k wₜ when it approaches (w·n̂ < 0; a leaving normal
/// part is kept). Newton's restitution gives the normal part; Coulomb friction caps the
/// tangential impulse at μ times the normal one, μ(1 + e)|w·n̂| against the tangential speed
/// |wₜ|, so k = max(0, 1 − μ(1 + e)|w·n̂| / |wₜ|): a particle whose friction can stop it
/// sticks at once.
fn bounce<R: Real>(w: Vec3<R>, normal: Vec3<R>, restitution: R, friction: R) -> Vec3<R> {
    let along = w.dot(normal);
    let tangential = w - normal * along;
    let speed = tangential.length();
    let removed = friction * (R::ONE + restitution) * (-along).max(R::ZERO);
    let tangential_kept = if removed >= speed {
        R::ZERO
    } else {
        R::ONE - removed / speed
    };
    let normal_after = if along < R::ZERO {
        -restitution * along
    } else {
        along
    };
    tangential * tangential_kept + normal * normal_after
}

impl<R: Real> ParticleSystem<R> {
    /// Whether any group collides.
    pub(crate) fn collides(&self) -> bool {
        !self.collisions.is_empty()
    }

    /// Where each slot's path starts (its position, velocity and generation) when it holds
    /// a particle, `None` when it is dead, overwriting `starts`. Taken before a step, it
    /// tells [`collide`](Self::collide) which particles the step moved (a slot the step
    /// filled anew, or emptied and filled again, has no path yet).
    pub(crate) fn path_starts(&self, starts: &mut Vec<Option<PathStart<R>>>) {
        let attributes = &self.storage.attributes;
        let kinematics = &self.storage.kinematics;
        starts.clear();
        starts.extend((0..kinematics.positions.len()).map(|i| {
            attributes.alive[i].then(|| PathStart {
                position: kinematics.positions[i],
                velocity: kinematics.velocities[i],
                generation: attributes.generations[i],
            })
        }));
    }

    /// After a step of `dt` seconds from the [`path_starts`](Self::path_starts) `starts`:
    /// bounces the movable particles of the colliding groups off `surfaces`, in ascending
    /// slot order.
    ///
    /// The step's velocity change Δv = v₁ − v₀ is taken as uniform in time, so a hit at
    /// fraction f of the path meets the surface at v_f = v₀ + f Δv; the bounce turns it into
    /// v_f′, and the rest of the step adds (1 − f) Δv again: v₁′ = v_f′ + (1 − f) Δv. (Taking
    /// v₁ itself as the impact velocity would overstate it by (1 − f) g Δt, a rebound height
    /// error of up to 2 g Δt / v.)
    pub(crate) fn collide(
        &mut self,
        dt: R,
        starts: &[Option<PathStart<R>>],
        surfaces: &mut impl Surfaces<R>,
    ) {
        let mut bounced = false;
        let attributes = &self.storage.attributes;
        let kinematics = &mut self.storage.kinematics;
        for (i, start) in starts.iter().enumerate() {
            let Some(start) = *start else {
                continue;
            };
            if !attributes.is_movable(i) || attributes.generations[i] != start.generation {
                continue;
            }
            let group = attributes.groups[i];
            let Some(rule) = self.collisions.iter().find(|c| c.group == group) else {
                continue;
            };
            let mut from = start.position;
            let mut to = kinematics.positions[i];
            let mut velocity = start.velocity;
            let mut change = kinematics.velocities[i] - start.velocity;
            let mut time = dt;
            let mut hit_any = false;
            for hits in 1..=MAX_BOUNCES {
                let Some(hit) = surfaces.cast(from, to, time, rule.filter) else {
                    break;
                };
                hit_any = true;
                let u = hit.velocity;
                let f = hit.fraction;
                let relative_end = to - u * time;
                // The hit in the frame that moves with the surface, and in the world (where
                // the surface has moved on by u f Δt since the path began).
                let point = from + (relative_end - from) * f;
                let world_point = point + u * (time * f);
                let impact = velocity + change * f;
                let after = u + bounce(impact - u, hit.normal, rule.restitution, rule.friction);
                if rule.push {
                    let impulse = (impact - after) * attributes.masses[i];
                    surfaces.push(hit.body, impulse, world_point);
                }
                let last = hits == MAX_BOUNCES;
                time *= R::ONE - f;
                change *= R::ONE - f;
                let rest = if last {
                    Vec3::ZERO
                } else {
                    ((after - u) + change * R::HALF) * time
                };
                from = world_point.add_scaled(hit.normal, skin());
                to = from + rest + u * time;
                velocity = after;
                if last {
                    break;
                }
            }
            if hit_any {
                kinematics.positions[i] = to;
                kinematics.velocities[i] = velocity + change;
                kinematics.has_previous_position[i] = false;
                bounced = true;
            }
        }
        if bounced {
            self.accelerations_current = false;
        }
    }
}
