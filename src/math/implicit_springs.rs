//! Implicit Euler for point masses joined by damped springs (Baraff & Witkin 1998): the
//! linear system of one step and its solution.
//!
//! # The step
//!
//! Backward Euler advances (x, v) by v₁ = v₀ + Δv, x₁ = x₀ + h v₁, with the forces taken at
//! the end of the step: M Δv = h f(x₁, v₁). Linearising the spring and damper forces about
//! the start of the step, f(x₁, v₁) ≈ f₀ − K (x₁ − x₀) − C Δv with x₁ − x₀ = h (v₀ + Δv),
//! gives one linear system per step:
//!
//! (M + h C + h² K) Δv = h (f₀ − h K v₀) = h M a₀ − h² K v₀,
//!
//! where a₀ = a(x₀, v₀) (m/s²) is the acceleration of every force at the start (springs,
//! gravity, drags, user forces), K the springs' stiffness matrix (N/m) and C the damping
//! matrix (N·s/m) of the spring dampers and of linear drags. Forces outside K and C
//! (gravity, quadratic drag, user forces) are thus explicit; the springs and dampers are
//! implicit, so the step is stable at any h on them. For forces that are exactly linear in
//! (x, v) this is backward Euler itself: on an undamped oscillator of angular frequency ω
//! the energy falls by the factor 1/(1 + (ωh)²) per step.
//!
//! # One spring's blocks
//!
//! A spring of stiffness k (N/m), damping c (N·s/m), rest length ℓ₀ and current length ℓ
//! along the unit axis û has the stiffness block K_s = k (ûûᵀ + t (I − ûûᵀ)) with
//! t = max(0, 1 − ℓ₀/ℓ): the exact Jacobian of the Hooke force when the spring is stretched,
//! with its transverse part dropped when it is compressed (the part that would make the
//! matrix indefinite; Choi & Ko 2002). Its damping block is C_s = c ûûᵀ. A spring between
//! particles i and j adds S = h C_s + h² K_s to the diagonal blocks of both and −S to the
//! two off-diagonal ones; a spring to a fixed point (or to a pinned particle) adds S to its
//! particle's diagonal block only. S = a ûûᵀ + b I with b = h² k t and a = h c + h² k − b.
//!
//! # The solve
//!
//! The matrix A = M + h C + h² K is symmetric positive definite (M > 0 on the movable
//! particles; pinned ones are left out, Δv = 0). When no spring joins two movable particles
//! and no particle has more than one spring, A is block diagonal with blocks
//! (m + h c_drag + b) I + a ûûᵀ, inverted in closed form (Sherman–Morrison):
//! Δv = (r − û a (û·r)/(β + a))/β, β = m + h c_drag + b. Otherwise the system is solved by
//! conjugate gradients with the diagonal (Jacobi) preconditioner, at most
//! [`MAX_ITERATIONS`] iterations, stopping early when the preconditioned residual rᵀz
//! falls to 2⁻³⁰ of its start (or to 0 in the format). Every sum runs in
//! ascending particle then row order, so the result is the same bits everywhere.
//!
//! Every equation is scaled by s = 1/max(m) (the largest movable mass), which changes
//! neither A's symmetry nor Δv but keeps the numbers near 1 in fixed point when the masses
//! are grams.

use super::spring::SpringDesc;
use super::{Real, Vec3};

/// The most conjugate-gradient iterations per step.
pub const MAX_ITERATIONS: u32 = 64;

/// Conjugate gradients stop once rᵀz ≤ this fraction of its first value: 2⁻³⁰ (the
/// residual's norm down by about 3·10⁴).
fn relative_tolerance<R: Real>() -> R {
    R::ONE.mul_pow2_recip(30)
}

/// No second end: the spring's other end is fixed.
const FIXED_END: u32 = u32::MAX;

/// One spring's contribution to the system: S = a ûûᵀ + b I on its ends, and the product
/// K v of its stiffness block.
#[derive(Clone, Copy, Debug)]
struct Row<R: Real> {
    first: u32,
    /// [`FIXED_END`] when the second end is fixed or pinned.
    second: u32,
    axis: Vec3<R>,
    /// a (scaled by s), kg.
    along: R,
    /// b (scaled by s), kg.
    across: R,
    /// k (1 − t) (N/m) and k t (N/m): K_s = k(1 − t) ûûᵀ + k t I.
    stiffness_along: R,
    stiffness_across: R,
}

/// The working arrays of an implicit step, reused from step to step. Not state: nothing in
/// it survives a step.
#[derive(Default)]
pub struct ImplicitSprings<R: Real> {
    rows: Vec<Row<R>>,
    /// Rows touching each particle, to detect the closed-form case.
    touching: Vec<u32>,
    diagonal: Vec<Vec3<R>>,
    /// m + h c_drag per particle, scaled by s; 0 for pinned ones.
    mass_terms: Vec<R>,
    residual: Vec<Vec3<R>>,
    preconditioned: Vec<Vec3<R>>,
    direction: Vec<Vec3<R>>,
    product: Vec<Vec3<R>>,
    delta_v: Vec<Vec3<R>>,
    coupled: bool,
}

impl<R: Real> Clone for ImplicitSprings<R> {
    /// Empty: nothing in it outlives a step.
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl<R: Real> core::fmt::Debug for ImplicitSprings<R> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("ImplicitSprings")
    }
}

/// The iterations the last solve took (0 for the closed form), for tests and benchmarks.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SolveReport {
    /// Conjugate-gradient iterations.
    pub iterations: u32,
}

impl<R: Real> ImplicitSprings<R> {
    /// Starts a step over `particles` point masses with no springs.
    pub fn begin(&mut self, particles: usize) {
        self.rows.clear();
        self.touching.clear();
        self.touching.resize(particles, 0);
        self.coupled = false;
    }

    /// Adds a damped spring from particle `first` to particle `second` (or to a fixed point
    /// when `second` is `None`), with `offset` d = x_first − x_second (m) and step `h` (s).
    /// `movable` says which particles move (inverse mass ≠ 0). A spring whose ends coincide
    /// (no axis) or that joins two pinned particles adds nothing.
    pub fn add_spring(
        &mut self,
        first: usize,
        second: Option<usize>,
        spring: &SpringDesc<R>,
        offset: Vec3<R>,
        h: R,
        movable: impl Fn(usize) -> bool,
    ) {
        let Some((axis, length)) = offset.try_normalize() else {
            return;
        };
        let (first, second) = match second {
            Some(j) if movable(first) && movable(j) => (first, j as u32),
            Some(j) if movable(j) => (j, FIXED_END),
            _ if movable(first) => (first, FIXED_END),
            _ => return,
        };
        let k = spring.stiffness;
        let stretch = (R::ONE - spring.rest_length / length).max(R::ZERO);
        let stiffness_across = k * stretch;
        let h_squared = h * h;
        let across = h_squared * stiffness_across;
        let along = h * spring.damping + h_squared * k - across;
        self.touching[first] += 1;
        if second != FIXED_END {
            self.touching[second as usize] += 1;
            self.coupled = true;
        }
        self.rows.push(Row {
            first: first as u32,
            second,
            axis,
            along,
            across,
            stiffness_along: k - stiffness_across,
            stiffness_across,
        });
    }

    /// Solves the step's system for Δv (m/s) and returns it, one entry per particle (0 for
    /// pinned ones), given the `masses` (kg, 0 when pinned), each particle's isotropic
    /// linear drag coefficient `drag(i)` (kg/s), the accelerations `a0` = a(x₀, v₀) (m/s²)
    /// of every force and the velocities `v0` (m/s) at the start, and the step `h` (s).
    pub fn solve(
        &mut self,
        h: R,
        masses: &[R],
        drag: impl Fn(usize) -> R,
        a0: &[Vec3<R>],
        v0: &[Vec3<R>],
    ) -> (&[Vec3<R>], SolveReport) {
        let n = masses.len();
        for buffer in [
            &mut self.diagonal,
            &mut self.residual,
            &mut self.preconditioned,
            &mut self.direction,
            &mut self.product,
            &mut self.delta_v,
        ] {
            buffer.clear();
            buffer.resize(n, Vec3::ZERO);
        }
        let heaviest = masses.iter().fold(R::ZERO, |m, &x| m.max(x));
        if heaviest == R::ZERO {
            // Nothing moves (no particle, or all pinned).
            return (&self.delta_v, SolveReport::default());
        }
        let scale = heaviest.recip();
        for row in &mut self.rows {
            row.along *= scale;
            row.across *= scale;
        }
        // r = s (h M a₀ − h² K v₀); the mass terms (m + h c_drag) s.
        self.mass_terms.clear();
        self.mass_terms.extend((0..n).map(|i| {
            if masses[i] == R::ZERO {
                R::ZERO
            } else {
                (masses[i] + h * drag(i)) * scale
            }
        }));
        for i in 0..n {
            if masses[i] != R::ZERO {
                self.residual[i] = a0[i] * (h * masses[i] * scale);
            }
        }
        let h_squared_scaled = h * h * scale;
        for row in &self.rows {
            let i = row.first as usize;
            let relative = if row.second == FIXED_END {
                v0[i]
            } else {
                v0[i] - v0[row.second as usize]
            };
            let k_v = row.axis * (row.stiffness_along * row.axis.dot(relative))
                + relative * row.stiffness_across;
            let term = k_v * h_squared_scaled;
            self.residual[i] -= term;
            if row.second != FIXED_END {
                self.residual[row.second as usize] += term;
            }
        }
        if !self.coupled && self.touching.iter().all(|&count| count <= 1) {
            self.solve_blocks();
            return (&self.delta_v, SolveReport::default());
        }
        let iterations = self.conjugate_gradients();
        (&self.delta_v, SolveReport { iterations })
    }

    /// The closed form of the block-diagonal case: Δv = (r − û a (û·r)/(β + a))/β,
    /// β = m + h c_drag + b, for each particle with one spring; Δv = r/(m + h c_drag) for
    /// the others.
    fn solve_blocks(&mut self) {
        for (i, &mass_term) in self.mass_terms.iter().enumerate() {
            if mass_term != R::ZERO {
                self.delta_v[i] = self.residual[i] / mass_term;
            }
        }
        for row in &self.rows {
            let i = row.first as usize;
            let beta = self.mass_terms[i] + row.across;
            let r = self.residual[i];
            let along = row.axis * (row.along * row.axis.dot(r) / (beta + row.along));
            self.delta_v[i] = (r - along) / beta;
        }
    }

    /// `product` ← A `direction`, in scaled units.
    fn multiply(&mut self) {
        let vector = &self.direction;
        for (i, out) in self.product.iter_mut().enumerate() {
            *out = vector[i] * self.mass_terms[i];
        }
        for row in &self.rows {
            let i = row.first as usize;
            let relative = if row.second == FIXED_END {
                vector[i]
            } else {
                vector[i] - vector[row.second as usize]
            };
            let s_v = row.axis * (row.along * row.axis.dot(relative)) + relative * row.across;
            self.product[i] += s_v;
            if row.second != FIXED_END {
                self.product[row.second as usize] -= s_v;
            }
        }
    }

    /// Preconditioned conjugate gradients from Δv = 0 on A Δv = r; returns the iterations.
    fn conjugate_gradients(&mut self) -> u32 {
        // Jacobi preconditioner: the diagonal of A, component by component.
        for (i, d) in self.diagonal.iter_mut().enumerate() {
            let m = self.mass_terms[i];
            *d = Vec3::new(m, m, m);
        }
        for row in &self.rows {
            let u = row.axis;
            let block = Vec3::new(
                row.along * u.x * u.x,
                row.along * u.y * u.y,
                row.along * u.z * u.z,
            ) + Vec3::new(row.across, row.across, row.across);
            self.diagonal[row.first as usize] += block;
            if row.second != FIXED_END {
                self.diagonal[row.second as usize] += block;
            }
        }
        let precondition = |r: Vec3<R>, d: Vec3<R>| {
            let part = |r: R, d: R| if d == R::ZERO { R::ZERO } else { r / d };
            Vec3::new(part(r.x, d.x), part(r.y, d.y), part(r.z, d.z))
        };
        let mut rz = R::ZERO;
        for i in 0..self.residual.len() {
            let z = precondition(self.residual[i], self.diagonal[i]);
            self.preconditioned[i] = z;
            self.direction[i] = z;
            rz += self.residual[i].dot(z);
        }
        let stop = rz * relative_tolerance();
        let mut iterations = 0;
        while iterations < MAX_ITERATIONS && rz > stop && rz > R::ZERO {
            iterations += 1;
            self.multiply();
            let curvature = dot_all(&self.direction, &self.product);
            if curvature <= R::ZERO {
                break;
            }
            let alpha = rz / curvature;
            let mut next_rz = R::ZERO;
            for i in 0..self.residual.len() {
                self.delta_v[i] = self.delta_v[i].add_scaled(self.direction[i], alpha);
                self.residual[i] = self.residual[i].add_scaled(self.product[i], -alpha);
                let z = precondition(self.residual[i], self.diagonal[i]);
                self.preconditioned[i] = z;
                next_rz += self.residual[i].dot(z);
            }
            let beta = next_rz / rz;
            rz = next_rz;
            for (p, &z) in self.direction.iter_mut().zip(&self.preconditioned) {
                *p = z.add_scaled(*p, beta);
            }
        }
        iterations
    }
}

/// Σᵢ aᵢ·bᵢ in ascending order.
fn dot_all<R: Real>(a: &[Vec3<R>], b: &[Vec3<R>]) -> R {
    a.iter().zip(b).fold(R::ZERO, |sum, (x, y)| sum + x.dot(*y))
}
