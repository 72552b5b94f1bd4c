//! Mass properties: mass, centre of mass and inertia tensor, from the standard table of
//! solids, moved by the parallel-axis theorem, and summed for compounds.
//!
//! Units: kg, m, kg·m². Every tensor here is about the body's own centre of mass, in the
//! frame the constructor states (the y axis is the axis of symmetry of cylinders, cones,
//! rods and capsules, as for the capsule shape). Formulas are from the standard table of
//! moments of inertia (e.g. Goldstein, *Classical Mechanics*, or any engineering handbook);
//! the capsule is a cylinder plus two hemispheres, each moved to the capsule's centre by the
//! parallel-axis theorem.

use serde::{Deserialize, Serialize};

use crate::math::{Fx, Mat3, Quat, Real, Vec3};

/// The mass, centre of mass and inertia tensor of a body or a part of one.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct MassProperties<R: Real = Fx> {
    /// m, kg.
    pub mass: R,
    /// Centre of mass in the body frame, m.
    pub centre: Vec3<R>,
    /// Inertia tensor about `centre`, body axes, kg·m².
    pub inertia: Mat3<R>,
}

impl<R: Real> MassProperties<R> {
    /// A point-like nothing: zero mass, zero inertia.
    pub const ZERO: Self = Self {
        mass: R::ZERO,
        centre: Vec3::ZERO,
        inertia: Mat3::ZERO,
    };

    /// A body of mass `mass` at the origin with principal moments `moments` about x, y, z.
    fn principal(mass: R, moments: Vec3<R>) -> Self {
        Self {
            mass,
            centre: Vec3::ZERO,
            inertia: Mat3::from_diagonal(moments),
        }
    }

    /// Solid sphere of radius r: I = ⅖ m r² about every axis.
    pub fn solid_sphere(mass: R, radius: R) -> Self {
        let moment = mass * radius * radius * R::from_ratio(2, 5);
        Self::principal(mass, Vec3::new(moment, moment, moment))
    }

    /// Thin hollow sphere (a shell) of radius r: I = ⅔ m r² about every axis.
    pub fn hollow_sphere(mass: R, radius: R) -> Self {
        let moment = mass * radius * radius * R::from_ratio(2, 3);
        Self::principal(mass, Vec3::new(moment, moment, moment))
    }

    /// Solid box of half extents (a, b, c): Iₓ = ⅓ m (b² + c²), I_y = ⅓ m (a² + c²),
    /// I_z = ⅓ m (a² + b²) (that is, m/12 times the sum of the squared full side lengths).
    pub fn solid_box(mass: R, half_extents: Vec3<R>) -> Self {
        let sq = half_extents.mul_elem(half_extents);
        let third = mass * R::from_ratio(1, 3);
        Self::principal(
            mass,
            Vec3::new(
                third * (sq.y + sq.z),
                third * (sq.x + sq.z),
                third * (sq.x + sq.y),
            ),
        )
    }

    /// Solid cylinder of radius r and half height h along y: I_y = ½ m r²,
    /// Iₓ = I_z = m (3r² + (2h)²)/12 = m (r²/4 + h²/3).
    pub fn solid_cylinder(mass: R, radius: R, half_height: R) -> Self {
        let r2 = radius * radius;
        let axial = mass * r2 * R::HALF;
        let transverse =
            mass * (r2 * R::from_ratio(1, 4) + half_height * half_height / R::from_int(3));
        Self::principal(mass, Vec3::new(transverse, axial, transverse))
    }

    /// Solid cone of base radius r and height H along y, about its centre of mass, which lies
    /// on the axis at H/4 above the base: I_y = (3/10) m r², Iₓ = I_z = (3/20) m r² +
    /// (3/80) m H². `centre` is (0, H/4, 0) when the base is centred at the origin.
    pub fn solid_cone(mass: R, radius: R, height: R) -> Self {
        let r2 = radius * radius;
        let axial = mass * r2 * R::from_ratio(3, 10);
        let transverse =
            mass * (r2 * R::from_ratio(3, 20) + height * height * R::from_ratio(3, 80));
        Self {
            centre: Vec3::new(R::ZERO, height * R::from_ratio(1, 4), R::ZERO),
            ..Self::principal(mass, Vec3::new(transverse, axial, transverse))
        }
    }

    /// Thin rod of length L along y, about its middle: Iₓ = I_z = m L²/12, I_y = 0 (an
    /// inverse inertia treats the zero moment as infinite: see
    /// [`Mat3::safe_inverse_symmetric`]).
    pub fn thin_rod(mass: R, length: R) -> Self {
        let transverse = mass * length * length / R::from_int(12);
        Self::principal(mass, Vec3::new(transverse, R::ZERO, transverse))
    }

    /// Solid capsule: a cylinder of radius r and half height h along y capped by two
    /// hemispheres of radius r, of uniform density ρ (kg/m³). With the cylinder's mass
    /// m_c = ρ π r² 2h and each hemisphere's m_s = ρ ⅔ π r³:
    ///
    /// * I_y = ½ m_c r² + 2 · ⅖ m_s r²;
    /// * Iₓ = I_z = m_c (r²/4 + h²/3) + 2 m_s (⅖ r² + h² + ¾ h r), the hemispheres' own
    ///   transverse moment (83/320) m_s r² about their centre of mass (3r/8 from the flat
    ///   face) moved by the parallel-axis theorem to the capsule's centre, h + 3r/8 away.
    pub fn solid_capsule(density: R, radius: R, half_height: R) -> Self {
        let r2 = radius * radius;
        let cylinder_mass = density * R::PI * r2 * (half_height * R::TWO);
        let cap_mass = density * R::PI * r2 * radius * R::from_ratio(2, 3);
        let axial = cylinder_mass * r2 * R::HALF + cap_mass * r2 * R::from_ratio(4, 5);
        let cylinder =
            cylinder_mass * (r2 * R::from_ratio(1, 4) + half_height * half_height / R::from_int(3));
        let caps = cap_mass
            * R::TWO
            * (r2 * R::from_ratio(2, 5)
                + half_height * half_height
                + half_height * radius * R::from_ratio(3, 4));
        let transverse = cylinder + caps;
        Self::principal(
            cylinder_mass + cap_mass * R::TWO,
            Vec3::new(transverse, axial, transverse),
        )
    }

    /// Solid sphere of radius r and density ρ: m = ρ ⁴⁄₃ π r³.
    pub fn sphere_from_density(density: R, radius: R) -> Self {
        let mass = density * R::PI * radius * radius * radius * R::from_ratio(4, 3);
        Self::solid_sphere(mass, radius)
    }

    /// Solid box of half extents (a, b, c) and density ρ: m = 8 ρ a b c.
    pub fn box_from_density(density: R, half_extents: Vec3<R>) -> Self {
        let volume = half_extents.x * half_extents.y * half_extents.z * R::from_int(8);
        Self::solid_box(density * volume, half_extents)
    }

    /// Solid cylinder of radius r and half height h along y at density ρ (kg/m³):
    /// m = ρ π r² (2h), moments as [`Self::solid_cylinder`].
    pub fn cylinder_from_density(density: R, radius: R, half_height: R) -> Self {
        let mass = density * R::PI * radius * radius * (half_height + half_height);
        Self::solid_cylinder(mass, radius, half_height)
    }

    /// Solid cone of base radius r, base centred at (0, −h, 0) and apex at (0, h, 0), at
    /// density ρ (kg/m³): m = ρ π r² H / 3 with H = 2h, moments as [`Self::solid_cone`],
    /// centre of mass at (0, −h/2, 0) (a quarter of the height above the base).
    pub fn cone_from_density(density: R, radius: R, half_height: R) -> Self {
        let height = half_height + half_height;
        let mass = density * R::PI * radius * radius * height / R::from_int(3);
        let about_centre = Self::solid_cone(mass, radius, height);
        Self {
            centre: Vec3::new(R::ZERO, -half_height * R::HALF, R::ZERO),
            ..about_centre
        }
    }

    /// The same body placed in a parent frame by `rotation` then `translation`: the centre
    /// becomes t + R c and the inertia R I Rᵀ (still about the centre of mass).
    pub fn transformed(self, rotation: Quat<R>, translation: Vec3<R>) -> Self {
        Self {
            mass: self.mass,
            centre: translation + rotation.rotate(self.centre),
            inertia: rotation.to_mat3().rotate_inertia(self.inertia),
        }
    }

    /// The inertia about a point `offset` away from the centre of mass (parallel-axis
    /// theorem): I_o = I_c + m (|d|² E − d dᵀ), with d = `offset` (m).
    pub fn inertia_about(self, offset: Vec3<R>) -> Mat3<R> {
        let d = offset;
        let shift = Mat3::from_symmetric(
            Vec3::new(
                d.y * d.y + d.z * d.z,
                d.x * d.x + d.z * d.z,
                d.x * d.x + d.y * d.y,
            ),
            -(d.x * d.y),
            -(d.x * d.z),
            -(d.y * d.z),
        );
        self.inertia + shift * self.mass
    }

    /// The mass properties of rigidly joined parts, each already in the body frame: M = Σ mᵢ,
    /// c = Σ mᵢ cᵢ / M, I = Σ (Iᵢ moved by the parallel-axis theorem from cᵢ to c). Parts
    /// are summed in the order given. An empty list, or parts of zero total mass, give
    /// [`MassProperties::ZERO`].
    pub fn combine(parts: &[Self]) -> Self {
        let mass = parts.iter().fold(R::ZERO, |sum, part| sum + part.mass);
        if mass <= R::ZERO {
            return Self::ZERO;
        }
        let weighted = parts
            .iter()
            .fold(Vec3::ZERO, |sum, part| sum + part.centre * part.mass);
        let centre = weighted / mass;
        let inertia = parts.iter().fold(Mat3::ZERO, |sum, part| {
            sum + part.inertia_about(part.centre - centre)
        });
        Self {
            mass,
            centre,
            inertia,
        }
    }
}
