//! One tick of one character: knock bodies off, ride, walk or fall, slide, step, snap,
//! push.
//!
//! With dt the tick (s), g the y component of gravity (m/s², negative), h the walking
//! velocity (m/s, horizontal) and v_y the character's vertical speed:
//!
//! 0. **Knock off.** The dynamic bodies the rigid stage moved into the character are put
//!    back where they touch it and lose their approach, as against an immovable body
//!    ([`Surroundings::knock_off`]); they count as bodies hit this tick.
//! 1. **Ride.** A grounded character whose ground body moves is first carried by that
//!    body's velocity at its centre, v_b + ω × (x − c), times dt (a move-and-slide that
//!    ignores the ground body itself, which has already moved this tick).
//! 2. **Walk or fall.** Grounded, it walks h·dt along its ground plane (the horizontal
//!    speed is kept: the rise is −(n_x h_x + n_z h_z)/n_y · dt), and a jump sets
//!    v_y = `jump_speed`. Airborne, it moves h·dt + (0, v_y dt + ½ g dt², 0) and
//!    v_y ← v_y + g dt, which is exact for constant gravity at every tick.
//! 3. **Move and slide.** Up to [`MAX_SLIDES`] shape casts: each moves the shape until it
//!    is `skin` from the first body or other character in its way (ties to the lower
//!    handle, from the query; a body before a character; characters to the lower index),
//!    then the rest of the motion r is projected on the surface hit, r ← r − n (r·n) when
//!    r·n < 0. A surface steeper than `max_slope` (n_y < cos `max_slope`) is a wall for
//!    walking: the motion is first projected on its horizontal normal, so that walking
//!    never climbs it, and only then on the surface itself (falling slides down it).
//! 4. **Step.** A grounded character blocked by a steep surface tries to step: a cast up
//!    by `step_height`, forward by the rest of the horizontal motion (a probe of at least
//!    its half width), then down; the step is taken when the probe lands on a surface it
//!    can stand on whose contact is at most `step_height` above its feet, and the
//!    character then moves up, forward by the rest of its motion, and down onto the step.
//! 5. **Ground and snap.** Moving down or not at all, it casts its shape down,
//!    `snap_distance` when it was grounded and did not jump (so that it follows slopes and
//!    stairs down), 2 × `skin` otherwise; it is grounded (v_y = 0) when that meets a
//!    surface no steeper than `max_slope`, and then moves there. When the cast first meets
//!    a steep surface (the edge of a step it stands over), it stays where it is, grounded
//!    if a ray down from its centre meets ground it can stand on.
//! 6. **Push.** Each dynamic body hit takes the impulse of an inelastic collision between it
//!    and a body of `push_mass` moving at the character's velocity,
//!    J = v_n / (1/m_c + 1/m_b) along the normal, v_n the closing speed at the contact point.
//!    The character itself is not pushed back: it is kinematic.
//!
//! Every cast keeps the `skin`, so a character never ends inside the bodies it collides
//! with, whatever its speed (each cast sweeps the whole path).

use super::crowd::{Crowd, CrowdHit};
use super::desc::CharacterSettings;
use super::surroundings::Surroundings;
use super::system::{Character, CharacterEvent};
use crate::math::{Real, Vec3};
use crate::rigid::{BodyKind, EventKind, QueryFilter, RayHit, Shape};
use crate::types::Handle;

/// The most shape casts one move-and-slide makes.
pub const MAX_SLIDES: usize = 5;

/// The shortest motion a cast is made for, m: 2⁻²⁰ m.
fn tiny<R: Real>() -> R {
    R::from_ratio(1, 1 << 20)
}

/// How far the lowest point of `shape` lies below its centre, m.
pub fn foot_offset<R: Real>(shape: &Shape<R>) -> R {
    match shape {
        Shape::Sphere { radius } => *radius,
        Shape::Capsule {
            radius,
            half_height,
        } => *radius + *half_height,
        Shape::Box { half_extents } => half_extents.y,
        _ => R::ZERO,
    }
}

/// The largest horizontal half extent of `shape`, m.
fn half_width<R: Real>(shape: &Shape<R>) -> R {
    match shape {
        Shape::Sphere { radius } | Shape::Capsule { radius, .. } => *radius,
        Shape::Box { half_extents } => half_extents.x.max(half_extents.z),
        _ => R::ZERO,
    }
}

/// `r` without its part into the surface of normal `n`: r − n (r·n) when r·n < 0.
fn project<R: Real>(r: Vec3<R>, n: Vec3<R>) -> Vec3<R> {
    let into = r.dot(n);
    if into < R::ZERO { r - n * into } else { r }
}

/// The horizontal part of `v`.
fn horizontal<R: Real>(v: Vec3<R>) -> Vec3<R> {
    Vec3::new(v.x, R::ZERO, v.z)
}

/// What a cast met: a body, or another character.
#[derive(Clone, Copy, Debug)]
struct Hit<R: Real> {
    /// The body met; `None` for another character.
    body: Option<Handle>,
    /// Travel along the unit direction at impact, m.
    distance: R,
    /// The contact point, m.
    point: Vec3<R>,
    /// Unit normal from what was met towards the character.
    normal: Vec3<R>,
}

impl<R: Real> From<RayHit<R>> for Hit<R> {
    fn from(h: RayHit<R>) -> Self {
        Self {
            body: Some(h.body),
            distance: h.distance,
            point: h.point,
            normal: h.normal,
        }
    }
}

impl<R: Real> From<CrowdHit<R>> for Hit<R> {
    fn from(h: CrowdHit<R>) -> Self {
        Self {
            body: None,
            distance: h.distance,
            point: h.point,
            normal: h.normal,
        }
    }
}

/// One character's shape and settings, moving among its surroundings.
struct Mover<'a, R: Real> {
    shape: Shape<R>,
    settings: CharacterSettings<R>,
    /// cos `max_slope`: the least normal y of a surface it stands on.
    min_ground_y: R,
    surroundings: &'a mut dyn Surroundings<R>,
    /// The other characters.
    crowd: &'a Crowd<R>,
    /// This character's index.
    me: usize,
}

impl<R: Real> Mover<'_, R> {
    /// Whether a surface of normal `n` can be stood on.
    fn walkable(&self, n: Vec3<R>) -> bool {
        n.y >= self.min_ground_y
    }

    /// How far (m, 0 to |motion|) the shape at `p` moves along `motion` before it is
    /// `skin` from a body or another character, and the hit (a body before a character at
    /// the same distance). A body or character touched at the start that the motion leaves
    /// (n · motion ≥ 0) does not stop it.
    fn cast(&self, p: Vec3<R>, motion: Vec3<R>, filter: &QueryFilter) -> (R, Option<Hit<R>>) {
        let len = motion.length();
        if len <= tiny() {
            return (R::ZERO, None);
        }
        let skin = self.settings.skin;
        let reach = len + skin;
        let leaves =
            |distance: R, normal: Vec3<R>| distance <= tiny() && normal.dot(motion) >= R::ZERO;
        let s = &*self.surroundings;
        let mut body = s.cast(&self.shape, p, motion, reach, filter);
        if let Some(h) = body
            && leaves(h.distance, h.normal)
        {
            let mut past = filter.clone();
            past.exclude.push(h.body);
            body = s.cast(&self.shape, p, motion, reach, &past);
        }
        let crowd = |exclude: &[usize]| {
            let f = self.settings.filter;
            self.crowd
                .cast(self.me, &self.shape, p, motion, reach, f, exclude)
        };
        let mut other = crowd(&[]);
        if let Some(h) = other
            && leaves(h.distance, h.normal)
        {
            other = crowd(&[h.index]);
        }
        let hit = match (body, other) {
            (Some(b), Some(o)) if o.distance < b.distance => Some(Hit::from(o)),
            (Some(b), _) => Some(Hit::from(b)),
            (None, o) => o.map(Hit::from),
        };
        match hit {
            None => (len, None),
            Some(h) => ((h.distance - skin).clamp(R::ZERO, len), Some(h)),
        }
    }

    /// `p` moved by `travel` (m) along `motion` of length `len` (exactly `motion` when the
    /// whole of it).
    fn advanced(p: Vec3<R>, motion: Vec3<R>, travel: R, len: R) -> Vec3<R> {
        if travel >= len {
            p + motion
        } else {
            p + motion * (travel / len)
        }
    }

    /// `motion` projected on the surface of normal `n` (see the [module](self), step 3).
    fn slide(&self, motion: Vec3<R>, n: Vec3<R>) -> Vec3<R> {
        if self.walkable(n) || n.y < R::ZERO {
            return project(motion, n);
        }
        let wall = horizontal(n)
            .try_normalize()
            .map_or(motion, |(h, _)| project(motion, h));
        project(wall, n)
    }

    /// Moves the shape from `p` by `motion`, sliding along what it hits (steps up when
    /// `can_step`), recording each body hit in `touches`; the end position.
    fn move_and_slide(
        &self,
        mut p: Vec3<R>,
        motion: Vec3<R>,
        can_step: bool,
        filter: &QueryFilter,
        touches: &mut Vec<Hit<R>>,
    ) -> Vec3<R> {
        let mut remaining = motion;
        for _ in 0..MAX_SLIDES {
            let len = remaining.length();
            if len <= tiny() {
                break;
            }
            let (travel, hit) = self.cast(p, remaining, filter);
            p = Self::advanced(p, remaining, travel, len);
            let Some(hit) = hit else {
                break;
            };
            touches.push(hit);
            remaining = if travel >= len {
                Vec3::ZERO
            } else {
                remaining * ((len - travel) / len)
            };
            let flat = horizontal(remaining);
            if can_step
                && !self.walkable(hit.normal)
                && hit.normal.y >= R::ZERO
                && let Some((stepped, fraction)) = self.step_up(p, flat, filter)
            {
                p = stepped;
                remaining = Vec3::new(R::ZERO, remaining.y, R::ZERO) + flat * (R::ONE - fraction);
                continue;
            }
            remaining = self.slide(remaining, hit.normal);
        }
        p
    }

    /// A step up from `p` along the horizontal motion `flat` (see the [module](self), step
    /// 4): the position on the step and the fraction of `flat` travelled, or `None`.
    fn step_up(&self, p: Vec3<R>, flat: Vec3<R>, filter: &QueryFilter) -> Option<(Vec3<R>, R)> {
        let height = self.settings.step_height;
        let flat_len = flat.length();
        if height <= tiny() || flat_len <= tiny() {
            return None;
        }
        let (lift, _) = self.cast(p, Vec3::new(R::ZERO, height, R::ZERO), filter);
        if lift <= tiny() {
            return None;
        }
        let raised = p + Vec3::new(R::ZERO, lift, R::ZERO);
        // Probe at least the shape's half width ahead, so that the landing is looked for
        // on the step's top rather than at its edge.
        let probe_len = flat_len.max(half_width(&self.shape) + self.settings.skin * R::TWO);
        let probe = flat * (probe_len / flat_len);
        let (advance, _) = self.cast(raised, probe, filter);
        if advance <= tiny() {
            return None;
        }
        let ahead = Self::advanced(raised, probe, advance, probe_len);
        let (drop, hit) = self.cast(ahead, Vec3::new(R::ZERO, -lift, R::ZERO), filter);
        let hit = hit?;
        let feet = p.y - foot_offset(&self.shape);
        if !self.walkable(hit.normal) || hit.point.y - feet > height {
            return None;
        }
        let forward = advance.min(flat_len);
        let moved = Self::advanced(raised, flat, forward, flat_len);
        let (settle, _) = self.cast(moved, Vec3::new(R::ZERO, -drop, R::ZERO), filter);
        let landed = moved - Vec3::new(R::ZERO, settle, R::ZERO);
        Some((landed, forward / flat_len))
    }

    /// Ground within `reach` (m) below `p`: the position on it and the surface, or `None`
    /// (see the [module](self), step 5). When the shape would first meet a steep surface
    /// (the edge of a step), it stays where it is, grounded on what a ray straight down
    /// from its centre meets within its feet's depth plus `reach` and `step_height`, if
    /// that can be stood on.
    fn find_ground(&self, p: Vec3<R>, reach: R, filter: &QueryFilter) -> Option<(Vec3<R>, Hit<R>)> {
        let down = Vec3::new(R::ZERO, -reach, R::ZERO);
        let (travel, hit) = self.cast(p, down, filter);
        let hit = hit?;
        if self.walkable(hit.normal) {
            return Some((p - Vec3::new(R::ZERO, travel, R::ZERO), hit));
        }
        let depth = foot_offset(&self.shape)
            + reach.max(self.settings.step_height)
            + self.settings.skin * R::TWO;
        let below = self.surroundings.cast_ray(p, -Vec3::Y, depth, filter)?;
        self.walkable(below.normal).then_some((p, below.into()))
    }
}

/// One tick of `character` (handle `handle`) of `dt` seconds under the vertical gravity
/// `gravity_y` (m/s²) among `surroundings` and the other characters of `crowd` (see the
/// [module](self)); its landing and new hits go to `events`.
pub fn move_character<R: Real>(
    character: &mut Character<R>,
    handle: Handle,
    dt: R,
    gravity_y: R,
    surroundings: &mut dyn Surroundings<R>,
    crowd: &Crowd<R>,
    events: &mut Vec<CharacterEvent>,
) {
    let c = character;
    let settings = c.settings;
    let filter = QueryFilter {
        filter: settings.filter,
        exclude: Vec::new(),
        sensors: false,
    };
    // 0. Knock off the dynamic bodies the rigid stage moved into it.
    let knocked = surroundings.knock_off(&c.shape, c.position, c.velocity, dt, &filter);
    let mut mover = Mover {
        shape: c.shape.clone(),
        settings,
        min_ground_y: settings.max_slope.cos(),
        surroundings,
        crowd,
        me: handle.index as usize,
    };
    let was_grounded = c.grounded;

    // 1. Ride the ground body.
    if was_grounded
        && let Some(body) = c.ground_body
        && let Some(motion) = mover.surroundings.motion(body)
        && motion.kind != BodyKind::Static
    {
        let carry = motion.velocity_at(c.position) * dt;
        let mut riding = filter.clone();
        riding.exclude.push(body);
        c.position = mover.move_and_slide(c.position, carry, false, &riding, &mut Vec::new());
    }

    // 2. Walk or fall.
    let jumped = was_grounded && c.jump && settings.jump_speed > R::ZERO;
    let on_ground = was_grounded && !jumped;
    let walk = horizontal(c.desired_velocity) * dt;
    let mut vy = if jumped {
        settings.jump_speed
    } else if on_ground {
        R::ZERO
    } else {
        c.velocity.y
    };
    let motion = if on_ground {
        let n = c.ground_normal;
        let rise = if n.y > R::ZERO {
            -(n.x * walk.x + n.z * walk.z) / n.y
        } else {
            R::ZERO
        };
        Vec3::new(walk.x, rise, walk.z)
    } else {
        let fall = vy * dt + gravity_y * dt * dt * R::HALF;
        vy += gravity_y * dt;
        Vec3::new(walk.x, fall, walk.z)
    };

    // 3, 4. Move and slide, stepping up when grounded.
    let start = c.position;
    let mut touches = Vec::new();
    c.position = mover.move_and_slide(start, motion, on_ground, &filter, &mut touches);
    if !on_ground {
        // Stopped by a floor or a ceiling, its vertical speed is what it achieved; sliding
        // down a steep surface keeps the fall's (the projection then gives g sin²θ).
        let moved = c.position.y - start.y;
        let floor = touches.iter().any(|t| mover.walkable(t.normal));
        let ceiling = touches.iter().any(|t| t.normal.y < R::ZERO);
        if floor && motion.y < R::ZERO && moved > motion.y {
            vy = vy.max(moved / dt);
        } else if ceiling && motion.y > R::ZERO && moved < motion.y {
            vy = vy.min(moved / dt);
        }
    }

    // 5. Ground and snap.
    let reach = if on_ground {
        settings.snap_distance.max(settings.skin * R::TWO)
    } else {
        settings.skin * R::TWO
    };
    let ground = if vy <= R::ZERO {
        mover.find_ground(c.position, reach, &filter)
    } else {
        None
    };
    match ground {
        Some((p, hit)) => {
            c.position = p;
            c.grounded = true;
            c.ground_normal = hit.normal;
            c.ground_body = hit.body;
            vy = R::ZERO;
        }
        None => {
            c.grounded = false;
            c.ground_normal = Vec3::ZERO;
            c.ground_body = None;
        }
    }
    if c.grounded
        && !was_grounded
        && let Some(body) = c.ground_body
    {
        events.push(CharacterEvent {
            kind: EventKind::CharacterLand,
            character: handle,
            body,
        });
    }

    // 6. Push the dynamic bodies hit (each once, at its first contact), raise the new hits.
    let velocity = Vec3::new(c.desired_velocity.x, vy, c.desired_velocity.z);
    let own = motion / dt;
    let mut hit_bodies = knocked;
    for touch in &touches {
        let Some(body) = touch.body else {
            continue;
        };
        if hit_bodies.contains(&body) {
            continue;
        }
        hit_bodies.push(body);
        push_body(&mut mover, settings.push_mass, own, body, touch);
    }
    hit_bodies.sort_unstable();
    for &body in &hit_bodies {
        if c.touching.binary_search(&body).is_err() {
            events.push(CharacterEvent {
                kind: EventKind::CharacterHit,
                character: handle,
                body,
            });
        }
    }
    c.touching = hit_bodies;
    c.velocity = velocity;
    c.jump = false;
}

/// The push of a character moving at `own` (m/s) with mass `push_mass` (kg) on the body
/// it touched (see the [module](self), step 6).
fn push_body<R: Real>(
    mover: &mut Mover<'_, R>,
    push_mass: R,
    own: Vec3<R>,
    handle: Handle,
    touch: &Hit<R>,
) {
    if push_mass <= R::ZERO {
        return;
    }
    let Some(body) = mover.surroundings.motion(handle) else {
        return;
    };
    if body.kind != BodyKind::Dynamic {
        return;
    }
    let closing = (own - body.velocity_at(touch.point)).dot(-touch.normal);
    if closing <= R::ZERO {
        return;
    }
    let impulse = closing / (R::ONE / push_mass + body.inverse_mass);
    mover
        .surroundings
        .push(handle, -touch.normal * impulse, touch.point);
}
