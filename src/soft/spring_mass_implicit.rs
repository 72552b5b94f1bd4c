//! Implicit Euler for spring-mass bodies: the body's springs and its air drag become the
//! system of [`implicit_springs`](crate::math::implicit_springs) (Baraff & Witkin 1998),
//! gravity and the wind's push act explicitly through a(x₀, v₀).

use super::system::{Model, SoftSystem};
use crate::math::spring::SpringDesc;
use crate::math::{Real, Vec3};

impl<R: Real> SoftSystem<R> {
    /// One implicit Euler step of `dt` seconds for spring-mass body `b`, with a(x₀, v₀)
    /// already in the scratch accelerations: (M + h C + h² K) Δv = h M a₀ − h² K v₀ over the
    /// body's vertices (pinned ones excluded), then v ← v₀ + Δv, x ← x₀ + h v.
    pub(crate) fn implicit_spring_mass_step(&mut self, b: usize, dt: R) {
        let body = &self.bodies[b];
        let Model::SpringMass {
            stiffness,
            damping,
            springs,
            ..
        } = body.model
        else {
            return;
        };
        let range = body.range();
        let base = range.start;
        let vertices = &mut self.vertices;
        let scratch = &mut self.scratch;
        scratch.implicit_masses.clear();
        scratch.implicit_masses.extend(range.clone().map(|i| {
            if vertices.inv_mass[i] == R::ZERO {
                R::ZERO
            } else {
                vertices.mass[i]
            }
        }));
        let masses = &scratch.implicit_masses;
        let movable = |i: usize| masses[i] != R::ZERO;
        let solver = &mut scratch.implicit;
        solver.begin(range.len());
        let x = &vertices.position;
        let s = &self.springs;
        for k in springs.0 as usize..springs.1 as usize {
            let (i, j) = (s.a[k] as usize, s.b[k] as usize);
            let spring = SpringDesc {
                stiffness,
                damping,
                rest_length: s.rest[k],
            };
            solver.add_spring(i - base, Some(j - base), &spring, x[i] - x[j], dt, movable);
        }
        let drag = body.drag;
        let (delta_v, _) = solver.solve(
            dt,
            masses,
            |_| drag,
            &scratch.acceleration[range.clone()],
            &vertices.velocity[range.clone()],
        );
        for (offset, &dv) in delta_v.iter().enumerate() {
            let i = base + offset;
            if vertices.inv_mass[i] != R::ZERO {
                let v: Vec3<R> = vertices.velocity[i] + dv;
                vertices.velocity[i] = v;
                vertices.position[i] = vertices.position[i].add_scaled(v, dt);
            }
        }
    }
}
