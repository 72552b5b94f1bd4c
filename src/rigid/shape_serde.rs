//! How shapes are written and read.
//!
//! A shape is written as its source data: a hull as its points, a mesh as its vertices
//! and triangles, a heightfield as its grid; reading builds the shape again, tables and
//! all, and refuses data that makes none (with the reason as the error message). Meshes
//! have two written forms in scene files:
//!
//! - `TriMesh(vertices: [(x: .., y: .., z: ..), ...], triangles: [(i, j, k), ...])`;
//! - `TriMesh(file: "level.obj")`, read from a Wavefront OBJ file (`obj.rs`) named
//!   relative to the directory set by [`with_scene_directory`] (the scene file's, when the
//!   scene is read with [`load_scene_file`](crate::scene::load_scene_file)), or to the
//!   current directory.
//!
//! Binary encodings (replays, snapshots) always hold the vertices and triangles, and an
//! empty `file` field, so a replay never depends on a file beside it.

use std::cell::RefCell;
use std::path::{Path, PathBuf};

use serde::ser::{Serialize, Serializer};
use serde::{Deserialize, Serialize as DeriveSerialize};

use super::convex::ConvexHull;
use super::mesh::{HeightField, TriMesh};
use super::shape::{Part, Shape};
use crate::math::{Real, Vec3};

/// The shape as read, before its hull, mesh or grid is built.
#[derive(Deserialize)]
#[serde(bound = "", rename = "Shape")]
pub(super) enum ShapeSource<R: Real> {
    Sphere {
        radius: R,
    },
    Box {
        half_extents: Vec3<R>,
    },
    Capsule {
        radius: R,
        half_height: R,
    },
    Plane {
        normal: Vec3<R>,
        offset: R,
    },
    Compound {
        parts: Vec<Part<R>>,
    },
    Cylinder {
        radius: R,
        half_height: R,
    },
    Cone {
        radius: R,
        half_height: R,
    },
    ConvexHull {
        points: ConvexHull<R>,
    },
    TriMesh {
        #[serde(default)]
        vertices: Vec<Vec3<R>>,
        #[serde(default)]
        triangles: Vec<[u32; 3]>,
        #[serde(default)]
        file: Option<String>,
    },
    HeightField {
        rows: u32,
        columns: u32,
        scale: Vec3<R>,
        heights: Vec<R>,
    },
}

/// The shape as written, borrowed. `binary` only decides whether a mesh's empty `file`
/// field is written (always in binary encodings, whose fields are positional; never in
/// text).
#[derive(DeriveSerialize)]
#[serde(bound = "", rename = "Shape")]
enum ShapeRef<'a, R: Real> {
    Sphere {
        radius: &'a R,
    },
    Box {
        half_extents: &'a Vec3<R>,
    },
    Capsule {
        radius: &'a R,
        half_height: &'a R,
    },
    Plane {
        normal: &'a Vec3<R>,
        offset: &'a R,
    },
    Compound {
        parts: &'a [Part<R>],
    },
    Cylinder {
        radius: &'a R,
        half_height: &'a R,
    },
    Cone {
        radius: &'a R,
        half_height: &'a R,
    },
    ConvexHull {
        points: &'a [Vec3<R>],
    },
    TriMesh {
        vertices: &'a [Vec3<R>],
        triangles: &'a [[u32; 3]],
        #[serde(skip_serializing_if = "NoFile::is_text")]
        file: NoFile,
    },
    HeightField {
        rows: u32,
        columns: u32,
        scale: Vec3<R>,
        heights: &'a [R],
    },
}

/// A mesh's `file` field as written: always none, and only in binary encodings.
struct NoFile {
    binary: bool,
}

impl NoFile {
    fn is_text(&self) -> bool {
        !self.binary
    }
}

impl Serialize for NoFile {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_none()
    }
}

impl<R: Real> Serialize for Shape<R> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let binary = !s.is_human_readable();
        let shape = match self {
            Shape::Sphere { radius } => ShapeRef::Sphere { radius },
            Shape::Box { half_extents } => ShapeRef::Box { half_extents },
            Shape::Capsule {
                radius,
                half_height,
            } => ShapeRef::Capsule {
                radius,
                half_height,
            },
            Shape::Plane { normal, offset } => ShapeRef::Plane { normal, offset },
            Shape::Compound { parts } => ShapeRef::Compound { parts },
            Shape::Cylinder {
                radius,
                half_height,
            } => ShapeRef::Cylinder {
                radius,
                half_height,
            },
            Shape::Cone {
                radius,
                half_height,
            } => ShapeRef::Cone {
                radius,
                half_height,
            },
            Shape::ConvexHull { hull } => ShapeRef::ConvexHull {
                points: hull.vertices(),
            },
            Shape::TriMesh { mesh } => ShapeRef::TriMesh {
                vertices: mesh.vertices(),
                triangles: mesh.triangles(),
                file: NoFile { binary },
            },
            Shape::HeightField { field } => ShapeRef::HeightField {
                rows: field.rows(),
                columns: field.columns(),
                scale: field.scale(),
                heights: field.heights(),
            },
        };
        shape.serialize(s)
    }
}

impl<R: Real> TryFrom<ShapeSource<R>> for Shape<R> {
    type Error = String;

    fn try_from(source: ShapeSource<R>) -> Result<Self, String> {
        Ok(match source {
            ShapeSource::Sphere { radius } => Shape::Sphere { radius },
            ShapeSource::Box { half_extents } => Shape::Box { half_extents },
            ShapeSource::Capsule {
                radius,
                half_height,
            } => Shape::Capsule {
                radius,
                half_height,
            },
            ShapeSource::Plane { normal, offset } => Shape::Plane { normal, offset },
            ShapeSource::Compound { parts } => Shape::Compound { parts },
            ShapeSource::Cylinder {
                radius,
                half_height,
            } => Shape::Cylinder {
                radius,
                half_height,
            },
            ShapeSource::Cone {
                radius,
                half_height,
            } => Shape::Cone {
                radius,
                half_height,
            },
            ShapeSource::ConvexHull { points } => Shape::ConvexHull { hull: points },
            ShapeSource::TriMesh {
                vertices,
                triangles,
                file: None,
            } => Shape::TriMesh {
                mesh: TriMesh::new(vertices, triangles).map_err(|e| format!("TriMesh: {e}"))?,
            },
            ShapeSource::TriMesh {
                vertices,
                triangles,
                file: Some(file),
            } => {
                if !vertices.is_empty() || !triangles.is_empty() {
                    return Err(
                        "TriMesh: give either `file` or `vertices` and `triangles`, not both"
                            .into(),
                    );
                }
                let path = resolve(&file);
                Shape::TriMesh {
                    mesh: super::mesh::read_obj_file(&path)?,
                }
            }
            ShapeSource::HeightField {
                rows,
                columns,
                scale,
                heights,
            } => Shape::HeightField {
                field: HeightField::new(rows, columns, scale, heights)
                    .map_err(|e| format!("HeightField: {e}"))?,
            },
        })
    }
}

thread_local! {
    /// The directory mesh files are named relative to while a scene is read.
    static SCENE_DIRECTORY: RefCell<Option<PathBuf>> = const { RefCell::new(None) };
}

/// Runs `read` with mesh files (`TriMesh(file: ...)`) named relative to `directory`, on
/// this thread, and restores the previous directory afterwards.
pub fn with_scene_directory<T>(directory: &Path, read: impl FnOnce() -> T) -> T {
    let previous = SCENE_DIRECTORY.with(|d| d.replace(Some(directory.to_path_buf())));
    let result = read();
    SCENE_DIRECTORY.with(|d| *d.borrow_mut() = previous);
    result
}

/// `file` relative to the scene directory, if one is set and `file` is relative.
fn resolve(file: &str) -> PathBuf {
    let path = Path::new(file);
    match SCENE_DIRECTORY.with(|d| d.borrow().clone()) {
        Some(directory) if path.is_relative() => directory.join(path),
        _ => path.to_path_buf(),
    }
}
