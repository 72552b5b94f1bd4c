//! The wave step: the linear shallow-water equations on a staggered grid, stepped
//! semi-implicitly.
//!
//! With u the surface height above rest (m) at the cells and q the flow per metre of edge
//! (m²/s) at the edges between them,
//!
//! ```text
//! ∂q/∂t = −c² ∂u/∂x − γ q        (c² = g · depth, γ the damping rate, 1/s)
//! ∂u/∂t = −∂q/∂x                 (and the same along z)
//! ```
//!
//! whose heights obey the wave equation ∂²u/∂t² = c²∇²u (γ = 0). One step of h seconds
//! updates every flow from the heights, then every height from the new flows (symplectic
//! Euler):
//!
//! ```text
//! q ← (q − h c²/s · (u_j − u_i)) · (1 − γ h)
//! t = h/s · q,   u_i ← u_i − t,   u_j ← u_j + t      (s the cell size)
//! ```
//!
//! Eliminating q gives the leapfrog five-point scheme u⁺ − 2u + u⁻ = (c h/s)² ∇²ₛ u, stable
//! for c h/s ≤ 1/√2; a world substep is split into [`WaterSettings::substeps`] steps so
//! that c h/s ≤ 1/2.
//!
//! # Volume
//!
//! Each edge's transfer t is rounded once and subtracted from one cell exactly as it is
//! added to the other, so with reflective borders the sum of the heights' raw integers
//! never changes: the volume is conserved to the last bit, as long as no height saturates
//! (|u| < 2³¹ m in I32F32). Only an open border and [`disturb`](super::disturb) change it.
//!
//! # Open borders
//!
//! A wave u(x − ct) carries the flow q = c u. An open border lets out, through each border
//! cell's outer edge, q = c u_i (outward), the radiation condition ∂u/∂t + c ∂u/∂n = 0:
//! a wave meeting the border head-on leaves without reflection.

use super::desc::{MAX_WATER_SUBSTEPS, WaterBorder};
use super::system::{WaterSettings, WaterSystem};
use crate::math::Real;

#[cfg(vector_kernels)]
mod kernel;
#[cfg(all(test, vector_kernels))]
mod tests;

/// The constants of one wave step, generic over the scalar.
#[derive(Clone, Copy)]
struct Factors<R> {
    /// p = h c²/s, m/s.
    push: R,
    /// κ = 1 − γh.
    keep: R,
    /// h/s, s/m.
    carry: R,
    /// c h/s, the share of a border cell's height that leaves through each outer edge of
    /// an open border; `None` with reflective borders.
    leave: Option<R>,
}

/// The fewest wave steps that split `dt` seconds so that c h / s ≤ 1/2 for wave speed `c`
/// (m/s) and cell size `s` (m); `None` when that takes more than [`MAX_WATER_SUBSTEPS`].
pub(super) fn wave_substeps<R: Real>(c: R, dt: R, s: R) -> Option<u32> {
    let travel = c * dt * R::from_int(2);
    (1..=MAX_WATER_SUBSTEPS).find(|&n| travel <= s * R::from_int(n as i32))
}

impl<R: Real> WaterSystem<R> {
    /// Advances the surface by `dt` seconds in [`WaterSettings::substeps`] wave steps.
    pub fn step(&mut self, dt: R) {
        let h = dt / R::from_int(self.settings.substeps as i32);
        for _ in 0..self.settings.substeps {
            self.wave_step(h);
        }
    }

    /// One wave step of `h` seconds (the [module](self)'s scheme). In I32F32 it runs in
    /// [`kernel`], eight edges or cells at a time, with the bits of
    /// [`scalar_wave_step`](Self::scalar_wave_step).
    fn wave_step(&mut self, h: R) {
        let factors = self.factors(h);
        #[cfg(vector_kernels)]
        if kernel::wave_step(
            &mut self.heights,
            &mut self.flow_x,
            &mut self.flow_z,
            self.settings.columns as usize,
            &factors,
            &mut self.scratch,
        ) {
            return;
        }
        self.scalar_wave_step(&factors);
    }

    /// The constants of a wave step of `h` seconds: p = h c²/s, κ = 1 − γh, h/s and, on an
    /// open border, c h/s.
    fn factors(&self, h: R) -> Factors<R> {
        let s = &self.settings;
        let carry = h / s.cell_size;
        Factors {
            push: h * s.wave_speed * s.wave_speed / s.cell_size,
            keep: R::ONE - s.damping * h,
            carry,
            leave: (s.border == WaterBorder::Open).then(|| s.wave_speed * carry),
        }
    }

    /// The wave step with the scalar operators: every flow, the outflow of an open border,
    /// then every height.
    fn scalar_wave_step(&mut self, factors: &Factors<R>) {
        self.update_flows(factors.push, factors.keep);
        if let Some(leave) = factors.leave {
            self.let_out(leave);
        }
        self.update_heights(factors.carry);
    }

    /// q ← (q − p (u_j − u_i))·κ on every edge, p = h c²/s (`push`, m/s), κ = 1 − γh
    /// (`keep`).
    fn update_flows(&mut self, push: R, keep: R) {
        let s = &self.settings;
        let (n, m) = (s.columns as usize, s.rows as usize);
        let u = &self.heights;
        for k in 0..m {
            for i in 0..n - 1 {
                let e = i + (n - 1) * k;
                let q = &mut self.flow_x[e];
                *q = (*q - push * (u[i + 1 + n * k] - u[i + n * k])) * keep;
            }
        }
        for k in 0..m - 1 {
            for i in 0..n {
                let e = i + n * k;
                let q = &mut self.flow_z[e];
                *q = (*q - push * (u[i + n * (k + 1)] - u[i + n * k])) * keep;
            }
        }
    }

    /// The open border: `leave` = c h/s of u leaves each border cell through each outer
    /// edge.
    fn let_out(&mut self, leave: R) {
        let s = &self.settings;
        let (n, m) = (s.columns as usize, s.rows as usize);
        let u = &mut self.heights;
        for k in 0..m {
            for_each_border_cell_of_row(n, m, k, |cell, outer_edges| {
                let t = leave * u[cell];
                for _ in 0..outer_edges {
                    u[cell] -= t;
                }
            });
        }
    }

    /// t = (h/s)·q across every edge (`carry` = h/s), taken from one cell and given to
    /// the other: x edges in slot order, then z edges.
    fn update_heights(&mut self, carry: R) {
        let s = &self.settings;
        let (n, m) = (s.columns as usize, s.rows as usize);
        let u = &mut self.heights;
        for k in 0..m {
            for i in 0..n - 1 {
                let t = carry * self.flow_x[i + (n - 1) * k];
                u[i + n * k] -= t;
                u[i + 1 + n * k] += t;
            }
        }
        for k in 0..m - 1 {
            for i in 0..n {
                let t = carry * self.flow_z[i + n * k];
                u[i + n * k] -= t;
                u[i + n * (k + 1)] += t;
            }
        }
    }
}

/// Calls `f(cell, outer_edges)` once for every cell of row `k` on the border of an n × m
/// grid, with how many of its edges are on the border (2 at a corner, up to 4 on a grid
/// one cell wide). An open border lets c h/s · u out of the cell through each, u taken
/// before the step.
fn for_each_border_cell_of_row(n: usize, m: usize, k: usize, mut f: impl FnMut(usize, u32)) {
    let edges = |i: usize| {
        u32::from(i == 0) + u32::from(i == n - 1) + u32::from(k == 0) + u32::from(k == m - 1)
    };
    if k == 0 || k == m - 1 {
        for i in 0..n {
            f(i + n * k, edges(i));
        }
    } else {
        f(n * k, edges(0));
        if n > 1 {
            f(n - 1 + n * k, edges(n - 1));
        }
    }
}

impl<R: Real> WaterSettings<R> {
    /// The Courant number c h / s of one wave step within a world substep of `dt` s.
    pub fn courant(&self, dt: R) -> R {
        self.wave_speed * dt / (R::from_int(self.substeps as i32) * self.cell_size)
    }
}
