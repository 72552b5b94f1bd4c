//! A hull's mass properties by the volume integrals of a polyhedron (Eberly, "Polyhedral
//! Mass Properties (Revisited)", 2002, after Mirtich, "Fast and Accurate Computation of
//! Polyhedral Mass Properties", 1996).
//!
//! By the divergence theorem each integral over the solid becomes a sum over its faces;
//! each face is split into a fan of triangles (v₀, vₖ, vₖ₊₁), and for a triangle with
//! corners (x₀, y₀, z₀) … and edge cross product d = (v₁ − v₀) × (v₂ − v₀) (twice its area
//! times its outward normal) the face integrals are polynomials of its corners:
//!
//! * with, for each coordinate w, f₁ = w₀ + w₁ + w₂, f₂ = w₀² + w₀w₁ + w₁² + f₁w₂,
//!   f₃ = w₀³ + w₀²w₁ + w₀w₁² + w₁³ + f₂w₂, and gᵢ = f₂ + wᵢ (f₁ + wᵢ);
//! * V = Σ dₓ f₁ₓ / 6;
//! * ∫x = Σ dₓ f₂ₓ / 24, and ∫y, ∫z likewise with d_y, d_z;
//! * ∫x² = Σ dₓ f₃ₓ / 60, and ∫y², ∫z² likewise;
//! * ∫xy = Σ dₓ (y₀g₀ₓ + y₁g₁ₓ + y₂g₂ₓ) / 120, ∫yz with d_y and g_y times z, ∫zx with d_z
//!   and g_z times x.
//!
//! The sums are exact for a polyhedron (no sampling). They are evaluated in the units the
//! construction uses: q = (v − r)/s with r the centre of the hull's bounding box and s its
//! largest half extent (m), so every corner lies in [−1, 1]³, the terms are of order one
//! whatever the hull's size (1 cm or 100 m), and the second moments about r barely cancel
//! when moved to the centre of mass. The results are scaled back at the end: volume by s³,
//! first moments by s⁴, second moments by s⁵, so the only rounding at the hull's real size
//! is that of the final values.

use super::hull::ConvexHull;
use crate::math::{Mat3, Real, Vec3};
use crate::rigid::mass::MassProperties;

impl<R: Real> ConvexHull<R> {
    /// The mass properties of the hull filled at `density` ρ (kg/m³): mass m = ρ V (kg),
    /// centre of mass c = r + s (∫q / V) (m), and the inertia tensor about c in the hull's
    /// axes, I = ρ s⁵ ((tr C) E − C) with C = ∫(q − q_c)(q − q_c)ᵀ (kg·m²); see the module
    /// documentation for the integrals.
    pub fn mass_properties(&self, density: R) -> MassProperties<R> {
        let (reference, scale) = self.reference_and_scale();
        if scale <= R::ZERO {
            return MassProperties::ZERO;
        }
        let q = |i: u16| (self.vertices[usize::from(i)] - reference) / scale;
        let mut sums = Integrals::default();
        for face in &self.faces {
            let corners = self.face_indices(face);
            let q0 = q(corners[0]);
            for pair in corners[1..].windows(2) {
                sums.add_triangle(q0, q(pair[0]), q(pair[1]));
            }
        }
        let volume = sums.volume / R::from_int(6);
        if volume <= R::ZERO {
            return MassProperties::ZERO;
        }
        let first = sums.first / R::from_int(24);
        let second = sums.second / R::from_int(60);
        let mixed = sums.mixed / R::from_int(120);
        let centre = first / volume;
        // Central second moments C = ∫q qᵀ − V q_c q_cᵀ (scaled units).
        let square = second - centre.mul_elem(centre) * volume;
        let xy = mixed.x - centre.x * centre.y * volume;
        let yz = mixed.y - centre.y * centre.z * volume;
        let zx = mixed.z - centre.z * centre.x * volume;
        // I = (tr C) E − C, back in kg·m² by ρ s⁵.
        let back = |x: R| scaled_by_power(density * x, scale, 5);
        let inertia = Mat3::from_symmetric(
            Vec3::new(
                back(square.y + square.z),
                back(square.x + square.z),
                back(square.x + square.y),
            ),
            back(-xy),
            back(-zx),
            back(-yz),
        );
        MassProperties {
            mass: scaled_by_power(density * volume, scale, 3),
            centre: reference + centre * scale,
            inertia,
        }
    }

    /// The centre r of the hull's bounding box and its largest half extent s (m).
    fn reference_and_scale(&self) -> (Vec3<R>, R) {
        let mut low = self.vertices[0];
        let mut high = self.vertices[0];
        for &v in &self.vertices {
            low = low.min_elem(v);
            high = high.max_elem(v);
        }
        (
            (low + high) * R::HALF,
            ((high - low) * R::HALF).max_component(),
        )
    }
}

/// x sⁿ by n multiplications, so that a value that grows stays exact to its own rounding
/// and one that shrinks loses at most an ulp of the result.
fn scaled_by_power<R: Real>(x: R, scale: R, power: u32) -> R {
    let mut value = x;
    for _ in 0..power {
        value *= scale;
    }
    value
}

/// The running face sums of the module documentation before their constant factors:
/// Σ dₓf₁ₓ, (Σ d f₂) per axis, (Σ d f₃) per axis, and the three mixed sums (xy, yz, zx).
#[derive(Default)]
struct Integrals<R: Real> {
    volume: R,
    first: Vec3<R>,
    second: Vec3<R>,
    mixed: Vec3<R>,
}

/// For one coordinate w of a triangle's corners: f₁, f₂, f₃ and (g₀, g₁, g₂).
fn subexpressions<R: Real>(w0: R, w1: R, w2: R) -> (R, R, R, [R; 3]) {
    let sum01 = w0 + w1;
    let f1 = sum01 + w2;
    let square0 = w0 * w0;
    let partial = square0 + w1 * sum01;
    let f2 = partial + w2 * f1;
    let f3 = w0 * square0 + w1 * partial + w2 * f2;
    let g = |w: R| f2 + w * (f1 + w);
    (f1, f2, f3, [g(w0), g(w1), g(w2)])
}

impl<R: Real> Integrals<R> {
    /// Adds the face integrals of the triangle (a, b, c), counter-clockwise from outside.
    fn add_triangle(&mut self, a: Vec3<R>, b: Vec3<R>, c: Vec3<R>) {
        let d = (b - a).cross(c - a);
        let (f1x, f2x, f3x, gx) = subexpressions(a.x, b.x, c.x);
        let (_, f2y, f3y, gy) = subexpressions(a.y, b.y, c.y);
        let (_, f2z, f3z, gz) = subexpressions(a.z, b.z, c.z);
        self.volume += d.x * f1x;
        self.first += d.mul_elem(Vec3::new(f2x, f2y, f2z));
        self.second += d.mul_elem(Vec3::new(f3x, f3y, f3z));
        let weigh = |g: [R; 3], w: [R; 3]| R::dot3(g, w);
        self.mixed += d.mul_elem(Vec3::new(
            weigh(gx, [a.y, b.y, c.y]),
            weigh(gy, [a.z, b.z, c.z]),
            weigh(gz, [a.x, b.x, c.x]),
        ));
    }
}
