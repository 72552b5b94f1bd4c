//! The seven integration schemes, one step of length h each.
//!
//! Notation: x position (m), v velocity (m/s), a(x, v) acceleration (m/s², see
//! `ForceField::accelerations` in `forces.rs`), h the step (s), n the step index. Every loop
//! visits slots in ascending order and skips pinned and dead slots (inverse mass 0).
//! Velocity-dependent forces (drag, spring damping) are evaluated with the velocity each
//! scheme has at hand, written out below; the schemes keep their order for position-only
//! forces and lose at most one order in the velocity-dependent terms.

use core::fmt;

use super::forces::ForceField;
use super::fused_euler;
use super::implicit_euler;
use super::storage::{Attributes, Kinematics};
use crate::math::implicit_springs::ImplicitSprings;
pub use crate::math::integration::Integrator;
use crate::math::integration::kick_then_drift;
use crate::math::{Fraction, Real, Vec3};

/// Working arrays of the integrators, reused from step to step so that a step allocates
/// nothing once the slot count stops growing. Not simulation state: nothing in them
/// survives a step, so they are not hashed, serialised, cloned or compared.
#[derive(Default)]
pub(crate) struct Scratch<R: Real> {
    acceleration: Vec<Vec3<R>>,
    stage_positions: Vec<Vec3<R>>,
    stage_velocities: Vec<Vec3<R>>,
    position_sum: Vec<Vec3<R>>,
    velocity_sum: Vec<Vec3<R>>,
    implicit: ImplicitSprings<R>,
}

impl<R: Real> Scratch<R> {
    /// Sizes the arrays `integrator` uses to `slots`.
    fn prepare(&mut self, integrator: Integrator, slots: usize) {
        self.acceleration.resize(slots, Vec3::ZERO);
        if integrator == Integrator::Rk4 {
            for buffer in [
                &mut self.stage_positions,
                &mut self.stage_velocities,
                &mut self.position_sum,
                &mut self.velocity_sum,
            ] {
                buffer.resize(slots, Vec3::ZERO);
            }
        }
    }
}

impl<R: Real> Clone for Scratch<R> {
    /// Empty: scratch contents never outlive a step.
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl<R: Real> PartialEq for Scratch<R> {
    /// Always true: scratch is not state.
    fn eq(&self, _other: &Self) -> bool {
        true
    }
}

impl<R: Real> fmt::Debug for Scratch<R> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("Scratch")
    }
}

/// h and the constants derived from it, computed once per step (s, s², 1/s).
struct StepLengths<R: Real> {
    h: R,
    half_h: R,
    h_squared: R,
    half_h_squared: R,
    sixth_h: R,
    inv_h: R,
}

impl<R: Real> StepLengths<R> {
    fn new(h: R) -> Self {
        let h_squared = h * h;
        Self {
            h,
            half_h: h * R::HALF,
            h_squared,
            half_h_squared: h_squared * R::HALF,
            sixth_h: h * R::from_ratio(1, 6),
            inv_h: h.recip(),
        }
    }
}

/// What one integration step works on.
pub(crate) struct StepContext<'a, 'f, R: Real> {
    pub kinematics: &'a mut Kinematics<R>,
    pub attributes: &'a Attributes<R>,
    pub field: &'a ForceField<'f, R>,
    pub scratch: &'a mut Scratch<R>,
    /// Whether `kinematics.accelerations` holds a(x, v) of the current state (velocity
    /// Verlet); updated by the step.
    pub accelerations_current: &'a mut bool,
}

/// Advances every movable particle by one step of `dt` seconds with `integrator`.
pub(crate) fn advance<R: Real>(integrator: Integrator, dt: R, context: StepContext<'_, '_, R>) {
    let lengths = StepLengths::new(dt);
    let slots = context.kinematics.positions.len();
    context.scratch.prepare(integrator, slots);
    match integrator {
        Integrator::ExplicitEuler => explicit_euler(&lengths, context),
        Integrator::SemiImplicitEuler => semi_implicit_euler(&lengths, context),
        Integrator::StormerVerlet => stormer_verlet(&lengths, context),
        Integrator::VelocityVerlet => velocity_verlet(&lengths, context),
        Integrator::Leapfrog => leapfrog(&lengths, context),
        Integrator::Rk4 => rk4(&lengths, context),
        Integrator::ImplicitEuler => implicit_euler::step(
            dt,
            context.kinematics,
            context.attributes,
            context.field,
            &mut context.scratch.acceleration,
            &mut context.scratch.implicit,
        ),
    }
}

/// x_{n+1} = x_n + h v_n, v_{n+1} = v_n + h a(x_n, v_n).
fn explicit_euler<R: Real>(l: &StepLengths<R>, c: StepContext<'_, '_, R>) {
    let k = c.kinematics;
    let acceleration = &mut c.scratch.acceleration;
    c.field
        .accelerations(&k.positions, &k.velocities, acceleration);
    for (i, &a) in acceleration.iter().enumerate() {
        if c.attributes.is_movable(i) {
            let v = k.velocities[i];
            k.positions[i] = k.positions[i].add_scaled(v, l.h);
            k.velocities[i] = v.add_scaled(a, l.h);
        }
    }
}

/// v_{n+1} = v_n + h a(x_n, v_n), x_{n+1} = x_n + h v_{n+1}. Linear fields (uniform
/// gravity and linear drags, `LinearField`) with h < 0.5 s take the one-pass step of
/// `fused_euler`, which gives the same bits.
fn semi_implicit_euler<R: Real>(l: &StepLengths<R>, c: StepContext<'_, '_, R>) {
    let k = c.kinematics;
    if let (Some(field), Some(h)) = (c.field.linear(), Fraction::new(l.h)) {
        fused_euler::step(&field, h, k, c.attributes);
        return;
    }
    let acceleration = &mut c.scratch.acceleration;
    c.field
        .accelerations(&k.positions, &k.velocities, acceleration);
    kick_then_drift(
        acceleration,
        &c.attributes.inv_masses,
        &mut k.velocities,
        &mut k.positions,
        l.h,
        l.h,
    );
}

/// x_{n+1} = x_n + (x_n − x_{n−1}) + h² a_n, or x₀ + h v₀ + ½ h² a₀ without a previous
/// position; v_{n+1} = (x_{n+1} − x_n)/h + ½ h a_n, with a_n = a(x_n, v_n).
fn stormer_verlet<R: Real>(l: &StepLengths<R>, c: StepContext<'_, '_, R>) {
    let k = c.kinematics;
    let acceleration = &mut c.scratch.acceleration;
    c.field
        .accelerations(&k.positions, &k.velocities, acceleration);
    for (i, &a) in acceleration.iter().enumerate() {
        if !c.attributes.is_movable(i) {
            continue;
        }
        let x = k.positions[i];
        let next = if k.has_previous_position[i] {
            x + (x - k.previous_positions[i]) + a * l.h_squared
        } else {
            x + k.velocities[i] * l.h + a * l.half_h_squared
        };
        k.velocities[i] = (next - x) * l.inv_h + a * l.half_h;
        k.previous_positions[i] = x;
        k.positions[i] = next;
        k.has_previous_position[i] = true;
    }
}

/// Kick–drift–kick with the stored a_n (recomputed first when stale):
/// v_{n+½} = v_n + ½ h a_n, x_{n+1} = x_n + h v_{n+½}, a_{n+1} = a(x_{n+1}, v_{n+½}),
/// v_{n+1} = v_{n+½} + ½ h a_{n+1}.
fn velocity_verlet<R: Real>(l: &StepLengths<R>, c: StepContext<'_, '_, R>) {
    let k = c.kinematics;
    if !*c.accelerations_current {
        c.field
            .accelerations(&k.positions, &k.velocities, &mut k.accelerations);
    }
    for i in 0..k.positions.len() {
        if c.attributes.is_movable(i) {
            let half_step_velocity = k.velocities[i].add_scaled(k.accelerations[i], l.half_h);
            k.velocities[i] = half_step_velocity;
            k.positions[i] = k.positions[i].add_scaled(half_step_velocity, l.h);
        }
    }
    c.field
        .accelerations(&k.positions, &k.velocities, &mut k.accelerations);
    for i in 0..k.positions.len() {
        if c.attributes.is_movable(i) {
            k.velocities[i] = k.velocities[i].add_scaled(k.accelerations[i], l.half_h);
        }
    }
    *c.accelerations_current = true;
}

/// Drift–kick–drift: x_{n+½} = x_n + ½ h v_n, v_{n+1} = v_n + h a(x_{n+½}, v_n),
/// x_{n+1} = x_{n+½} + ½ h v_{n+1}.
fn leapfrog<R: Real>(l: &StepLengths<R>, c: StepContext<'_, '_, R>) {
    let k = c.kinematics;
    let acceleration = &mut c.scratch.acceleration;
    for i in 0..acceleration.len() {
        if c.attributes.is_movable(i) {
            k.positions[i] = k.positions[i].add_scaled(k.velocities[i], l.half_h);
        }
    }
    c.field
        .accelerations(&k.positions, &k.velocities, acceleration);
    kick_then_drift(
        acceleration,
        &c.attributes.inv_masses,
        &mut k.velocities,
        &mut k.positions,
        l.h,
        l.half_h,
    );
}

/// Classical RK4 on y = (x, v), y' = (v, a(x, v)):
/// k₁ = f(y_n), k₂ = f(y_n + ½h k₁), k₃ = f(y_n + ½h k₂), k₄ = f(y_n + h k₃),
/// y_{n+1} = y_n + (h/6)(k₁ + 2k₂ + 2k₃ + k₄).
fn rk4<R: Real>(l: &StepLengths<R>, c: StepContext<'_, '_, R>) {
    let k = c.kinematics;
    let movable = |i: usize| c.attributes.is_movable(i);
    let Scratch {
        acceleration,
        stage_positions,
        stage_velocities,
        position_sum,
        velocity_sum,
        ..
    } = c.scratch;
    // Pinned particles keep their place in every stage (springs read them).
    stage_positions.copy_from_slice(&k.positions);
    stage_velocities.copy_from_slice(&k.velocities);

    // k₁ = (v_n, a(x_n, v_n)).
    c.field
        .accelerations(&k.positions, &k.velocities, acceleration);
    for i in 0..acceleration.len() {
        if movable(i) {
            let (v, a) = (k.velocities[i], acceleration[i]);
            position_sum[i] = v;
            velocity_sum[i] = a;
            stage_positions[i] = k.positions[i].add_scaled(v, l.half_h);
            stage_velocities[i] = v.add_scaled(a, l.half_h);
        }
    }
    // k₂ and k₃ (weight 2 each); k₃'s stage is a full step ahead.
    for stage_step in [l.half_h, l.h] {
        c.field
            .accelerations(stage_positions, stage_velocities, acceleration);
        for i in 0..acceleration.len() {
            if movable(i) {
                let (v, a) = (stage_velocities[i], acceleration[i]);
                position_sum[i] += v + v;
                velocity_sum[i] += a + a;
                stage_positions[i] = k.positions[i].add_scaled(v, stage_step);
                stage_velocities[i] = k.velocities[i].add_scaled(a, stage_step);
            }
        }
    }
    // k₄, then the weighted sum.
    c.field
        .accelerations(stage_positions, stage_velocities, acceleration);
    for i in 0..acceleration.len() {
        if movable(i) {
            k.positions[i] =
                k.positions[i].add_scaled(position_sum[i] + stage_velocities[i], l.sixth_h);
            k.velocities[i] =
                k.velocities[i].add_scaled(velocity_sum[i] + acceleration[i], l.sixth_h);
        }
    }
}
