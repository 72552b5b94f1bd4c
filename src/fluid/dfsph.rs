//! Divergence-Free SPH (Bender & Koschier 2015, 2017): the divergence-free solve, then the
//! constant-density solve.
//!
//! Why DFSPH rather than PBF or IISPH: like IISPH it iterates a pressure solve to a
//! tolerance on the density error, which PBF does not (PBF runs a fixed number of
//! constraint projections on positions and its error depends on that count); unlike IISPH
//! its per-particle factor is computed once per substep, so an iteration is two plain
//! passes over the neighbour lists with no per-pair division and no d_ij terms to store.
//! Each iteration is Jacobi (every particle reads the values of the previous pass), so the
//! result does not depend on the order particles are visited in.
//!
//! Per substep of length Δt, with ρ̃ = ρ/ρ₀ and V₀∇W from the [kernel](super::kernel):
//!
//! - factor: Dᵢ = |Σⱼ V₀∇Wᵢⱼ + Σ_b V₀∇W_ib|² + Σⱼ |V₀∇Wᵢⱼ|² (1/m²), αᵢ = 1/(Δt² Dᵢ) (s⁻²·m²),
//!   computed as (1/Δt)/(Δt Dᵢ) so that Δt² (10⁻⁸ s²) is never formed. Dᵢ is taken at
//!   least 1/16 of its value D₀ inside the fluid at rest: only a particle with few
//!   neighbours (a splash, which is never compressed) falls below, and its factor would
//!   leave the range;
//! - predicted density: ρ̃*ᵢ = bᵢ + Δt Dρ̃ᵢ/Dt with Dρ̃ᵢ/Dt = Σⱼ (vᵢ − vⱼ)·V₀∇Wᵢⱼ +
//!   Σ_b vᵢ·V₀∇W_ib (1/s), and bᵢ = 1 in the divergence-free solve (only the compression
//!   rate counts), bᵢ = ρ̃ᵢ in the constant-density solve;
//! - stiffness: kᵢ = max(ρ̃*ᵢ − 1, 0) αᵢ (m²/s², ρ₀κᵢ/ρᵢ in the paper's terms);
//! - correction: vᵢ ← vᵢ − Δt (Σⱼ (kᵢ + kⱼ) V₀∇Wᵢⱼ + Σ_b kᵢ V₀∇W_ib),
//!
//! repeated until the mean of max(ρ̃*ᵢ − 1, 0) is at most the tolerance and no particle's is
//! above 10 % (or the iteration cap). A substep runs the factors, the divergence-free solve
//! on the velocities it starts with, then v ← v + Δt g, XSPH and the constant-density
//! solve. The constant-density corrections amount to the pressure force of
//! P̃ᵢ/ρ̃ᵢ² = Σ kᵢ over its iterations, so the pressure is p = ρ₀ ρ̃ᵢ² Σ kᵢ.
//!
//! Why both solves: the constant-density solve alone leaves the velocities it made,
//! which still compress the fluid where the next substep's prediction does not look (the
//! kernel's curvature, layers of particles that slide against each other); at substeps
//! near the time-step limit (5 ms at 1 cm spacing) that compression grows from step to step
//! and the fluid explodes within 30 steps, in I32F32 and in `f64` alike. Removing the
//! compression rate at the start of each substep keeps it bounded.
//!
//! Why the cap on a single particle: with a loose tolerance (a mean of a few per cent) the
//! mean alone lets a few particles overlap, whose stiffness then throws them out at tens
//! of m/s. 10 % is the loosest tolerance a scene may set; in the benchmark's cube at the
//! default tolerance the cap did not change the result (the mean binds first).
//!
//! Rigid bodies in the fluid add their samples to the walls' sums, with their velocities
//! in the compression rate ([`bodies`](super::bodies)).
//!
//! Magnitudes at spacing 5 mm, Δt = 10⁻⁴ s: Dᵢ ≈ 10⁵, αᵢ ≈ 10³, kᵢ ≈ 1,
//! corrections ≈ 10⁻² m/s.

use super::row_sums;
use super::system::{FluidSystem, PARTICLE_CHUNK};
use crate::math::{Real, Vec3};
use crate::parallel::{for_each_mut, for_each_zip_mut, map_chunks_mut};

/// The largest predicted compression max(ρ̃*ᵢ − 1, 0) a solve leaves on any one particle:
/// 1/10, the loosest tolerance on the mean a scene may set.
fn max_particle_compression<R: Real>() -> R {
    R::from_ratio(1, 10)
}

/// Which predicted density a solve drives to the rest density.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Solve {
    /// ρ̃*ᵢ = 1 + Δt Dρ̃ᵢ/Dt: the compression rate only.
    DivergenceFree,
    /// ρ̃*ᵢ = ρ̃ᵢ + Δt Dρ̃ᵢ/Dt: the density at the end of the substep.
    ConstantDensity,
}

impl<R: Real> FluidSystem<R> {
    /// Stage 4 for DFSPH: the divergence-free solve, v ← v + Δt g, XSPH, then the
    /// constant-density solve (see the [module documentation](self)).
    pub(crate) fn dfsph_velocities(&mut self, dt: R, gravity: Vec3<R>) {
        self.compute_factors(dt);
        let bodies = &mut self.scratch.bodies;
        if bodies.active {
            bodies.compression_rates(self.positions.len());
        }
        let divergence_iterations = self.iterate(dt, Solve::DivergenceFree);
        for v in &mut self.velocities {
            *v = v.add_scaled(gravity, dt);
        }
        self.smooth_velocities();
        let density_iterations = self.iterate(dt, Solve::ConstantDensity);
        let s = &mut self.scratch;
        for (p, &rho) in s.pressure.iter_mut().zip(&s.density) {
            *p *= rho * rho;
        }
        s.last_iterations += divergence_iterations + density_iterations;
    }

    /// Jacobi iterations of `solve` until the mean of max(ρ̃*ᵢ − 1, 0) is at most the
    /// tolerance and its largest at most [`max_particle_compression`], or the cap; returns
    /// the iterations. The constant-density solve leaves Σ kᵢ in `pressure`.
    fn iterate(&mut self, dt: R, solve: Solve) -> u32 {
        let n = self.positions.len();
        let tolerance = self.settings.max_density_error * R::from_int(n as i32);
        let cap = max_particle_compression();
        let s = &mut self.scratch;
        s.pressure.clear();
        s.pressure.resize(n, R::ZERO);
        let mut iterations = 0;
        while iterations < self.settings.max_iterations {
            let (total, largest) = self.predict_stiffness(dt, solve);
            if total <= tolerance && largest <= cap {
                break;
            }
            self.correct_velocities(dt);
            if solve == Solve::ConstantDensity {
                let s = &mut self.scratch;
                for (p, &k) in s.pressure.iter_mut().zip(&s.scalar) {
                    *p += k;
                }
            }
            iterations += 1;
        }
        iterations
    }

    /// αᵢ = (1/Δt) / (Δt max(Dᵢ, D₀/16)) into `factor`, and
    /// Σ_b V₀∇W_ib into `wall_gradient`. The fluid's gradient sums pass through `delta`
    /// and `rate`, which the solves overwrite; their bit length, into `gradient_bits`,
    /// serves the iterations that follow on the same lists.
    fn compute_factors(&mut self, dt: R) {
        let inv_dt = dt.recip();
        let floor = self.settings.kernel.lattice_gradient_norm * R::from_ratio(1, 16);
        let mass = self.particle_mass();
        let s = &mut self.scratch;
        s.gradient_bits = row_sums::gradient_sums(&s.fluid, &mut s.delta, &mut s.rate);
        let n = self.positions.len();
        s.factor.clear();
        s.factor.resize(n, R::ZERO);
        s.wall_gradient.clear();
        s.wall_gradient.resize(n, Vec3::ZERO);
        let (walls, bodies, positions) = (&s.walls, &s.bodies, &self.positions);
        let (delta, rate) = (&s.delta, &s.rate);
        for_each_zip_mut(
            &mut s.wall_gradient,
            &mut s.factor,
            PARTICLE_CHUNK,
            |i, wall, factor| {
                let (sum, squares) = (delta[i], rate[i]);
                for g in walls.range(i).map(|e| walls.gradient(e)) {
                    *wall += g;
                }
                if bodies.active {
                    let lists = &bodies.lists;
                    for g in lists.range(i).map(|e| lists.gradient(e)) {
                        *wall += g;
                    }
                }
                let mut d = ((sum + *wall).length_squared() + squares).max(floor);
                if bodies.active {
                    d += bodies.mobility(i, positions[i], mass);
                }
                *factor = inv_dt / (dt * d);
            },
        );
    }

    /// kᵢ = max(ρ̃*ᵢ − 1, 0) αᵢ into `scalar`, ρ̃*ᵢ = bᵢ + Δt Dρ̃ᵢ/Dt with bᵢ as `solve`
    /// says; returns Σ max(ρ̃*ᵢ − 1, 0) and the largest max(ρ̃*ᵢ − 1, 0).
    fn predict_stiffness(&mut self, dt: R, solve: Solve) -> (R, R) {
        let s = &mut self.scratch;
        row_sums::density_rates(&s.fluid, s.gradient_bits, &self.velocities, &mut s.rate);
        s.scalar.clear();
        s.scalar.resize(self.velocities.len(), R::ZERO);
        let velocities = &self.velocities;
        let (wall_gradient, bodies, rate) = (&s.wall_gradient, &s.bodies, &s.rate);
        let (density, factor) = (&s.density, &s.factor);
        // Σ and max over fixed chunks of particles, folded in chunk order: in fixed point
        // the sum is exact in any grouping unless it saturates, and the chunks depend on
        // the particle count alone, never on the thread count.
        let parts = map_chunks_mut(&mut s.scalar, PARTICLE_CHUNK, |start, scalar| {
            let mut total = R::ZERO;
            let mut largest = R::ZERO;
            for (k, stiffness) in scalar.iter_mut().enumerate() {
                let i = start + k;
                let vi = velocities[i];
                // Away from the walls (most of the fluid) the wall term is zero.
                let wall = wall_gradient[i];
                let mut walls = if wall == Vec3::ZERO {
                    R::ZERO
                } else {
                    vi.dot(wall)
                };
                if bodies.active {
                    walls -= bodies.rate[i];
                }
                let change = (rate[i] + walls) * dt;
                let error = match solve {
                    Solve::DivergenceFree => change,
                    Solve::ConstantDensity => density[i] + change - R::ONE,
                }
                .max(R::ZERO);
                total += error;
                largest = largest.max(error);
                *stiffness = error * factor[i];
            }
            (total, largest)
        });
        parts
            .into_iter()
            .fold((R::ZERO, R::ZERO), |(total, largest), (t, l)| {
                (total + t, largest.max(l))
            })
    }

    /// vᵢ ← vᵢ − Δt (Σⱼ (kᵢ + kⱼ) V₀∇Wᵢⱼ + Σ_b kᵢ V₀∇W_ib), Jacobi.
    fn correct_velocities(&mut self, dt: R) {
        let mass = self.particle_mass();
        let s = &mut self.scratch;
        row_sums::pressure_pushes(&s.fluid, s.gradient_bits, &s.scalar, &mut s.delta);
        let (wall_gradient, delta, scalar) = (&s.wall_gradient, &s.delta, &s.scalar);
        for_each_mut(&mut self.velocities, PARTICLE_CHUNK, |i, v| {
            let wall = wall_gradient[i];
            let push = if wall == Vec3::ZERO {
                delta[i]
            } else {
                delta[i] + wall * scalar[i]
            };
            *v -= push * dt;
        });
        if s.bodies.active {
            s.bodies.push_iteration(&s.scalar, mass * dt);
        }
    }
}
