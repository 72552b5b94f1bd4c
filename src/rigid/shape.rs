//! Collision shapes and their mass properties at a given density.
//!
//! Each shape is described in its body's frame, centred on the origin; compounds place
//! parts with a rotation and a translation. The axis of capsules, cylinders and cones is y.
//! A dynamic body's origin is its centre of mass: when a shape's centre of mass is not its
//! origin (a cone, most hulls, compounds), building the body moves the shape so that it is
//! and moves the body's position by the same amount (see `build.rs`).

use serde::{Deserialize, Serialize};

use super::convex::ConvexHull;
use super::mass::MassProperties;
use super::mesh::{HeightField, TriMesh};
use crate::math::{Fx, Quat, Real, Vec3};

/// A part of a compound shape: a shape placed in the body frame.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Part<R: Real = Fx> {
    /// Rotation of the part relative to the body (normalised when the body is built).
    pub rotation: Quat<R>,
    /// Position of the part's origin in the body frame, m.
    pub translation: Vec3<R>,
    /// The part's shape (not itself a compound or a plane).
    pub shape: Shape<R>,
}

/// A collision shape.
///
/// Written and read as its source data (`shape_serde.rs`): a scene writes
/// `Sphere(radius: 0.5)`, `ConvexHull(points: [...])`, `TriMesh(vertices: [...],
/// triangles: [...])` or `TriMesh(file: "level.obj")`, `HeightField(rows: .., columns: ..,
/// scale: .., heights: [...])`.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(bound = "", try_from = "super::shape_serde::ShapeSource<R>")]
pub enum Shape<R: Real = Fx> {
    /// A ball of radius `radius` (m).
    Sphere { radius: R },
    /// A box of half extents `half_extents` (m) along the body axes.
    Box { half_extents: Vec3<R> },
    /// The points within `radius` (m) of the segment from (0, −h, 0) to (0, h, 0), h =
    /// `half_height` (m).
    Capsule { radius: R, half_height: R },
    /// The half-space n · x ≤ `offset` (m) below the plane with unit normal `normal`, for
    /// static ground and walls; it has no finite mass.
    Plane { normal: Vec3<R>, offset: R },
    /// Rigidly joined parts.
    Compound { parts: Vec<Part<R>> },
    // Variants are appended, never inserted: replays encode the variant's index.
    /// The solid cylinder of radius `radius` (m) whose axis runs from (0, −h, 0) to
    /// (0, h, 0), h = `half_height` (m).
    Cylinder { radius: R, half_height: R },
    /// The solid cone with its base, a disc of radius `radius` (m), centred at (0, −h, 0)
    /// and its apex at (0, h, 0), h = `half_height` (m). Its centre of mass is h/2 above
    /// the base's centre, at (0, −h/2, 0).
    Cone { radius: R, half_height: R },
    /// The convex hull of a set of points (m), computed deterministically when the shape is
    /// made (see [`ConvexHull::new`]); a scene writes `ConvexHull(points: [...])`.
    ConvexHull { hull: ConvexHull<R> },
    /// A triangle mesh (see [`TriMesh`]), for static or kinematic level geometry; it has no
    /// finite mass and cannot be a compound's part.
    TriMesh { mesh: TriMesh<R> },
    /// A grid of heights (see [`HeightField`]), for static or kinematic terrain; it has no
    /// finite mass and cannot be a compound's part.
    HeightField { field: HeightField<R> },
}

impl<R: Real> Shape<R> {
    /// The mesh of a triangle mesh or a heightfield, `None` for other shapes.
    #[inline]
    pub fn triangles(&self) -> Option<&TriMesh<R>> {
        match self {
            Self::TriMesh { mesh } => Some(mesh),
            Self::HeightField { field } => Some(field.mesh()),
            _ => None,
        }
    }

    /// The mass properties of the shape filled at `density` (kg/m³). A plane, a mesh or a
    /// heightfield, which have no finite volume, and a compound made only of planes give
    /// [`MassProperties::ZERO`]: a body with such a shape can only be static or kinematic.
    pub fn mass_properties(&self, density: R) -> MassProperties<R> {
        match self {
            Self::Sphere { radius } => MassProperties::sphere_from_density(density, *radius),
            Self::Box { half_extents } => MassProperties::box_from_density(density, *half_extents),
            Self::Capsule {
                radius,
                half_height,
            } => MassProperties::solid_capsule(density, *radius, *half_height),
            Self::Cylinder {
                radius,
                half_height,
            } => MassProperties::cylinder_from_density(density, *radius, *half_height),
            Self::Cone {
                radius,
                half_height,
            } => MassProperties::cone_from_density(density, *radius, *half_height),
            Self::ConvexHull { hull } => hull.mass_properties(density),
            Self::Plane { .. } | Self::TriMesh { .. } | Self::HeightField { .. } => {
                MassProperties::ZERO
            }
            Self::Compound { parts } => {
                let placed: Vec<MassProperties<R>> = parts
                    .iter()
                    .map(|part| {
                        part.shape
                            .mass_properties(density)
                            .transformed(part.rotation, part.translation)
                    })
                    .collect();
                MassProperties::combine(&placed)
            }
        }
    }
}
