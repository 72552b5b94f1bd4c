//! Rigid bodies moved by an outside position solver, two-way: the soft bodies' XPBD
//! substeps push bodies and are pushed by them (the world's soft coupling).
//!
//! The outside solver runs after the rigid step of a world substep of Δt seconds, so each
//! body is at the end of that step: pose (x₁, q₁), velocities v and ω. The solver runs n
//! substeps of h = Δt/n and sees each body it may touch as a [`Proxy`]: a copy starting at
//! x₀ = x₁ − Δt v, q₀ = q₁ turned by −Δt ω, and carried by its velocities each substep
//! (x += h v, q ← q turned by h ω), so that it sweeps the motion the rigid step made.
//!
//! A correction, the positional impulse P (kg·m) at the world point p of an awake dynamic
//! body with r = p − x, is the XPBD rigid-body update (Müller et al. 2020, "Detailed rigid
//! body simulation with extended position based dynamics"):
//! - x += P/m, q ← q turned by Δθ = I⁻¹(r × P) (rad);
//! - v += P/(m h), ω += Δθ/h: the velocities the displacement implies, which carry it
//!   through the following substeps;
//!
//! and its generalised inverse mass along a unit direction n̂ is w = 1/m + (r × n̂)·I⁻¹(r × n̂)
//! (1/kg), I⁻¹ in the world frame. At the end of the world substep a corrected body takes
//! its proxy's pose and velocities.
//!
//! Static, kinematic and sleeping bodies take no correction (w = 0): the solver sees them
//! as moving walls. A velocity-level impulse J (N·s, [`Proxies::push`]) changes only the
//! velocities, v += J/m, ω += I⁻¹(r × J). The impulses P/h and J on a sleeping dynamic
//! body are gathered over the tick
//! and given to [`RigidSystem::push_sleeping_body`] at its end, which wakes it only when
//! they would move it faster than its sleep speed.

use std::collections::BTreeMap;

use super::aabb::Aabb;
use super::desc::BodyKind;
use super::filter::CollisionFilter;
use super::query::ball_contact;
use super::system::RigidSystem;
use super::transform::Transform;
use crate::math::{Mat3, Quat, Real, Vec3};
use crate::types::Handle;

/// What a slot holds in [`Proxies::of_slot`]: no proxy.
const NONE: u32 = u32::MAX;

/// One body as the outside solver sees it during the current substep.
#[derive(Clone, Debug)]
struct Proxy<R: Real> {
    slot: u32,
    /// x, m, and q.
    position: Vec3<R>,
    orientation: Quat<R>,
    /// The placement at the current substep, and at the previous one.
    placement: Transform<R>,
    previous: Transform<R>,
    /// v (m/s) and ω (rad/s).
    velocity: Vec3<R>,
    angular_velocity: Vec3<R>,
    /// 1/m (1/kg) and I⁻¹ in the world frame (1/(kg·m²)); zero unless awake and dynamic.
    inv_mass: R,
    inv_inertia: Mat3<R>,
    /// Whether the body sleeps (its pushes are gathered, not applied).
    asleep: bool,
    /// Whether a correction moved it.
    corrected: bool,
    /// Its tight box at the current substep (`None` for a plane).
    aabb: Option<Aabb<R>>,
}

/// The proxies of one world substep, and the pushes sleeping bodies gathered this tick.
/// It keeps its memory from one substep to the next.
#[derive(Debug, Default)]
pub(crate) struct Proxies<R: Real> {
    proxies: Vec<Proxy<R>>,
    /// Per slot: its proxy's index, or [`NONE`].
    of_slot: Vec<u32>,
    /// Δt and h, s.
    dt: R,
    h: R,
    /// The farthest any moving body travels in Δt, m: the largest (|v| + |ω| ρ) Δt, ρ the
    /// half diagonal of its box.
    reach: R,
    /// Per sleeping slot: the impulse (N·s) and moment about its centre (N·m·s) gathered.
    sleeping: BTreeMap<u32, (Vec3<R>, Vec3<R>)>,
    stack: Vec<u32>,
    /// The candidate slots of the last [`near`](Self::near).
    slots: Vec<usize>,
}

impl<R: Real> Proxies<R> {
    /// Starts a world substep of `dt` seconds that the outside solver splits into
    /// `substeps`: no proxy yet.
    pub fn begin(&mut self, rigid: &RigidSystem<R>, dt: R, substeps: u32) {
        for proxy in self.proxies.drain(..) {
            self.of_slot[proxy.slot as usize] = NONE;
        }
        let b = &rigid.bodies;
        self.of_slot.resize(b.len(), NONE);
        self.dt = dt;
        self.h = dt * R::from_ratio(1, i64::from(substeps));
        let mut reach = R::ZERO;
        for i in 0..b.len() {
            if !b.is_moving(i) {
                continue;
            }
            reach = reach.max(b.point_speed_bound(i) * dt);
        }
        self.reach = reach;
    }

    /// The proxies of the bodies (not sensors, accepted by `filter`) that may come within
    /// `aabb` during the world substep, in ascending slot order, written to `out`.
    pub fn near(
        &mut self,
        rigid: &RigidSystem<R>,
        aabb: &Aabb<R>,
        filter: CollisionFilter,
        out: &mut Vec<u32>,
    ) {
        let b = &rigid.bodies;
        let reach = aabb.expanded(self.reach);
        let mut slots = core::mem::take(&mut self.slots);
        slots.clear();
        let mut stack = core::mem::take(&mut self.stack);
        rigid.for_each_candidate_with(
            &mut stack,
            |fat| fat.overlaps(&reach),
            |i| {
                if b.alive[i] && !b.sensor[i] && filter.interacts(b.filter[i]) {
                    slots.push(i);
                }
            },
        );
        self.stack = stack;
        slots.sort_unstable();
        out.clear();
        out.extend(slots.iter().map(|&i| self.proxy(rigid, i)));
        self.slots = slots;
    }

    /// The proxy of the live body `body`, or `None` when it was removed.
    pub fn of_body(&mut self, rigid: &RigidSystem<R>, body: Handle) -> Option<u32> {
        let slot = rigid.bodies.slot(body)?;
        Some(self.proxy(rigid, slot))
    }

    /// The proxy of slot `i`, made at the start of the world substep's motion if new.
    fn proxy(&mut self, rigid: &RigidSystem<R>, i: usize) -> u32 {
        if self.of_slot[i] != NONE {
            return self.of_slot[i];
        }
        let b = &rigid.bodies;
        let moving = b.is_moving(i);
        let (velocity, angular_velocity) = if moving {
            (b.linear_velocity[i], b.angular_velocity[i])
        } else {
            (Vec3::ZERO, Vec3::ZERO)
        };
        let position = b.position[i].add_scaled(velocity, -self.dt);
        let orientation = if angular_velocity == Vec3::ZERO {
            b.orientation[i]
        } else {
            b.orientation[i].integrate(angular_velocity, -self.dt)
        };
        let awake_dynamic = b.is_awake_dynamic(i);
        let placement = Transform::from_pose(position, orientation);
        let proxy = Proxy {
            slot: i as u32,
            position,
            orientation,
            placement,
            previous: placement,
            velocity,
            angular_velocity,
            inv_mass: if awake_dynamic {
                b.inv_mass[i]
            } else {
                R::ZERO
            },
            inv_inertia: if awake_dynamic {
                orientation.to_mat3().rotate_inertia(b.inv_inertia[i])
            } else {
                Mat3::ZERO
            },
            asleep: b.kind[i] == BodyKind::Dynamic && b.asleep[i],
            corrected: false,
            aabb: Aabb::of_shape(&b.shape[i], &placement),
        };
        let index = self.proxies.len() as u32;
        self.proxies.push(proxy);
        self.of_slot[i] = index;
        index
    }

    /// Starts a substep: every proxy carried h seconds by its velocities.
    pub fn advance(&mut self, rigid: &RigidSystem<R>) {
        let h = self.h;
        for p in &mut self.proxies {
            p.previous = p.placement;
            if p.velocity == Vec3::ZERO && p.angular_velocity == Vec3::ZERO {
                continue;
            }
            p.position = p.position.add_scaled(p.velocity, h);
            if p.angular_velocity != Vec3::ZERO {
                p.orientation = p.orientation.integrate(p.angular_velocity, h);
            }
            p.placement = Transform::from_pose(p.position, p.orientation);
            p.aabb = Aabb::of_shape(&rigid.bodies.shape[p.slot as usize], &p.placement);
        }
    }

    /// Whether proxy `i`'s box, grown by `margin` (m), may hold `x` (always for a plane).
    pub fn may_touch(&self, i: u32, x: Vec3<R>, margin: R) -> bool {
        self.proxies[i as usize]
            .aabb
            .is_none_or(|b| b.expanded(margin).contains_point(x))
    }

    /// The contact (outward unit normal, depth in m) of a ball of radius `r` at `x` with
    /// proxy `i`'s shape, the ball having been at `previous` at the start of the substep
    /// (see [`ball_contact`]).
    pub fn contact(
        &self,
        rigid: &RigidSystem<R>,
        i: u32,
        x: Vec3<R>,
        previous: Vec3<R>,
        r: R,
    ) -> Option<(Vec3<R>, R)> {
        let p = &self.proxies[i as usize];
        let from = p.placement.point(p.previous.inverse_point(previous));
        ball_contact(
            &rigid.bodies.shape[p.slot as usize],
            &p.placement,
            x,
            from,
            r,
        )
    }

    /// The world position of the body-frame point `local` of proxy `i`, m.
    pub fn point(&self, i: u32, local: Vec3<R>) -> Vec3<R> {
        self.proxies[i as usize].placement.point(local)
    }

    /// The velocity of proxy `i`'s material point at `p` (m): v + ω × (p − x), m/s.
    pub fn velocity_at(&self, i: u32, p: Vec3<R>) -> Vec3<R> {
        let proxy = &self.proxies[i as usize];
        proxy.velocity + proxy.angular_velocity.cross(p - proxy.position)
    }

    /// Proxy `i`'s generalised inverse mass at `p` along the unit `n`:
    /// 1/m + (r × n̂)·I⁻¹(r × n̂), 1/kg; 0 unless it is awake and dynamic.
    pub fn inverse_mass(&self, i: u32, p: Vec3<R>, n: Vec3<R>) -> R {
        let proxy = &self.proxies[i as usize];
        if proxy.inv_mass == R::ZERO {
            return R::ZERO;
        }
        let arm = (p - proxy.position).cross(n);
        proxy.inv_mass + arm.dot(proxy.inv_inertia * arm)
    }

    /// Applies the positional impulse `impulse` P (kg·m) at `p` (m) to proxy `i` (see the
    /// [module](self)); on a sleeping body it is gathered instead.
    pub fn correct(&mut self, i: u32, p: Vec3<R>, impulse: Vec3<R>) {
        let h = self.h;
        let proxy = &mut self.proxies[i as usize];
        if proxy.inv_mass == R::ZERO {
            self.push(i, p, impulse * h.recip());
            return;
        }
        let shift = impulse * proxy.inv_mass;
        let turn = proxy.inv_inertia * (p - proxy.position).cross(impulse);
        let inv_h = h.recip();
        proxy.position += shift;
        proxy.orientation = proxy.orientation.integrate(turn, R::ONE);
        proxy.velocity = proxy.velocity.add_scaled(shift, inv_h);
        proxy.angular_velocity = proxy.angular_velocity.add_scaled(turn, inv_h);
        proxy.placement = Transform::from_pose(proxy.position, proxy.orientation);
        proxy.corrected = true;
    }

    /// Applies the impulse `impulse` J (N·s) at `p` (m) to proxy `i`'s velocities:
    /// v += J/m, ω += I⁻¹(r × J); on a sleeping body it is gathered instead.
    pub fn push(&mut self, i: u32, p: Vec3<R>, impulse: Vec3<R>) {
        let proxy = &mut self.proxies[i as usize];
        let moment = (p - proxy.position).cross(impulse);
        if proxy.inv_mass == R::ZERO {
            if proxy.asleep {
                let total = self
                    .sleeping
                    .entry(proxy.slot)
                    .or_insert((Vec3::ZERO, Vec3::ZERO));
                total.0 += impulse;
                total.1 += moment;
            }
            return;
        }
        proxy.velocity = proxy.velocity.add_scaled(impulse, proxy.inv_mass);
        proxy.angular_velocity += proxy.inv_inertia * moment;
        proxy.corrected = true;
    }

    /// Ends the world substep: each corrected body takes its proxy's pose and velocities,
    /// and the query index follows them.
    pub fn finish_substep(&mut self, rigid: &mut RigidSystem<R>) {
        let mut moved = false;
        let b = &mut rigid.bodies;
        for p in &self.proxies {
            if !p.corrected {
                continue;
            }
            let i = p.slot as usize;
            b.position[i] = p.position;
            b.orientation[i] = p.orientation;
            b.linear_velocity[i] = p.velocity;
            b.angular_velocity[i] = p.angular_velocity;
            moved = true;
        }
        if moved {
            rigid.update_query_index();
        }
    }

    /// Ends the tick: the pushes gathered by sleeping bodies, in ascending slot order.
    pub fn finish_tick(&mut self, rigid: &mut RigidSystem<R>) {
        for (slot, (impulse, moment)) in core::mem::take(&mut self.sleeping) {
            rigid.push_sleeping_body(slot as usize, impulse, moment);
        }
    }
}
