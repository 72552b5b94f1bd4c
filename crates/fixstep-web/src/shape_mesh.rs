//! A rigid body's shape as a triangle mesh in the body frame, for the page to draw (floats:
//! drawing only, never simulated).

use fixstep::math::Real;
use fixstep::rigid::Shape;

/// Segments around a sphere's, capsule's, cylinder's or cone's axis.
const SIDES: usize = 20;
/// Rings from pole to pole of a sphere (and of a capsule's two caps together).
const RINGS: usize = 12;
/// Half the side (m) of the square that stands for a plane.
const PLANE_HALF_SIDE: f64 = 40.0;

/// Triangles: `positions` holds x, y, z (m, body frame) per vertex, `indices` three vertex
/// numbers per triangle, counter-clockwise seen from outside.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TriangleMesh {
    /// Vertex coordinates, three per vertex.
    pub positions: Vec<f32>,
    /// Vertex numbers, three per triangle.
    pub indices: Vec<u32>,
}

impl TriangleMesh {
    fn vertex(&mut self, p: [f64; 3]) -> u32 {
        let n = (self.positions.len() / 3) as u32;
        self.positions.extend(p.map(|c| c as f32));
        n
    }

    fn triangle(&mut self, a: u32, b: u32, c: u32) {
        self.indices.extend([a, b, c]);
    }

    /// Appends a convex polygon (corners counter-clockwise seen from outside) as a fan.
    fn polygon(&mut self, corners: &[[f64; 3]]) {
        let first: Vec<u32> = corners.iter().map(|&c| self.vertex(c)).collect();
        for k in 1..first.len().saturating_sub(1) {
            self.triangle(first[0], first[k], first[k + 1]);
        }
    }

    /// Appends `other` with every vertex moved by `place`.
    fn append(&mut self, other: &TriangleMesh, place: impl Fn([f64; 3]) -> [f64; 3]) {
        let base = (self.positions.len() / 3) as u32;
        for p in other.positions.chunks_exact(3) {
            self.vertex(place([p[0], p[1], p[2]].map(f64::from)));
        }
        self.indices.extend(other.indices.iter().map(|i| i + base));
    }
}

/// The mesh of `shape` in its body's frame.
pub fn shape_mesh<R: Real>(shape: &Shape<R>) -> TriangleMesh {
    let mut mesh = TriangleMesh::default();
    match shape {
        Shape::Sphere { radius } => lathe(&mut mesh, radius.to_f64(), 0.0),
        Shape::Capsule {
            radius,
            half_height,
        } => lathe(&mut mesh, radius.to_f64(), half_height.to_f64()),
        Shape::Box { half_extents } => {
            let [x, y, z] = half_extents.to_f64();
            let c = |sx: f64, sy: f64, sz: f64| [sx * x, sy * y, sz * z];
            for face in [
                [
                    c(1., -1., -1.),
                    c(1., 1., -1.),
                    c(1., 1., 1.),
                    c(1., -1., 1.),
                ],
                [
                    c(-1., -1., 1.),
                    c(-1., 1., 1.),
                    c(-1., 1., -1.),
                    c(-1., -1., -1.),
                ],
                [
                    c(-1., 1., -1.),
                    c(-1., 1., 1.),
                    c(1., 1., 1.),
                    c(1., 1., -1.),
                ],
                [
                    c(-1., -1., 1.),
                    c(-1., -1., -1.),
                    c(1., -1., -1.),
                    c(1., -1., 1.),
                ],
                [
                    c(-1., -1., 1.),
                    c(1., -1., 1.),
                    c(1., 1., 1.),
                    c(-1., 1., 1.),
                ],
                [
                    c(1., -1., -1.),
                    c(-1., -1., -1.),
                    c(-1., 1., -1.),
                    c(1., 1., -1.),
                ],
            ] {
                mesh.polygon(&face);
            }
        }
        Shape::Cylinder {
            radius,
            half_height,
        } => {
            let (r, h) = (radius.to_f64(), half_height.to_f64());
            let (bottom, top) = (circle(r, -h), circle(r, h));
            for k in 0..SIDES {
                let next = (k + 1) % SIDES;
                mesh.polygon(&[bottom[k], bottom[next], top[next], top[k]]);
            }
            mesh.polygon(&top);
            mesh.polygon(&bottom.iter().rev().copied().collect::<Vec<_>>());
        }
        Shape::Cone {
            radius,
            half_height,
        } => {
            let (r, h) = (radius.to_f64(), half_height.to_f64());
            let base = circle(r, -h);
            for k in 0..SIDES {
                mesh.polygon(&[base[k], base[(k + 1) % SIDES], [0.0, h, 0.0]]);
            }
            mesh.polygon(&base.iter().rev().copied().collect::<Vec<_>>());
        }
        Shape::ConvexHull { hull } => {
            let vertices: Vec<[f64; 3]> = hull.vertices().iter().map(|v| v.to_f64()).collect();
            for face in hull.faces() {
                let corners: Vec<[f64; 3]> = hull
                    .face_indices(face)
                    .iter()
                    .map(|&i| vertices[usize::from(i)])
                    .collect();
                mesh.polygon(&corners);
            }
        }
        Shape::TriMesh { .. } | Shape::HeightField { .. } => {
            if let Some(triangles) = shape.triangles() {
                for v in triangles.vertices() {
                    mesh.vertex(v.to_f64());
                }
                for t in triangles.triangles() {
                    mesh.triangle(t[0], t[1], t[2]);
                }
            }
        }
        // The half-space n · x ≤ offset: a square of the plane n · x = offset around the
        // point offset · n.
        Shape::Plane { normal, offset } => {
            let n = normalize(normal.to_f64());
            let centre = scale(n, offset.to_f64());
            let helper = if n[0].abs() < 0.9 {
                [1.0, 0.0, 0.0]
            } else {
                [0.0, 1.0, 0.0]
            };
            let u = scale(normalize(cross(helper, n)), PLANE_HALF_SIDE);
            let v = cross(n, u);
            let at = |a: f64, b: f64| add(centre, add(scale(u, a), scale(v, b)));
            mesh.polygon(&[at(-1., -1.), at(1., -1.), at(1., 1.), at(-1., 1.)]);
        }
        Shape::Compound { parts } => {
            for part in parts {
                let inner = shape_mesh(&part.shape);
                let q = part.rotation.to_f64();
                let t = part.translation.to_f64();
                mesh.append(&inner, |p| add(rotate(q, p), t));
            }
        }
    }
    mesh
}

/// A sphere of radius `r` (m) whose two halves sit at y = ±`h` (m), joined by a cylinder: a
/// ball when h = 0, a capsule otherwise.
fn lathe(mesh: &mut TriangleMesh, r: f64, h: f64) {
    let mut rings = Vec::with_capacity(RINGS + 2);
    for ring in 0..=RINGS {
        let polar = core::f64::consts::PI * ring as f64 / RINGS as f64;
        let shift = if ring <= RINGS / 2 { h } else { -h };
        let y = r * polar.cos() + shift;
        let around: Vec<u32> = circle(r * polar.sin(), y)
            .into_iter()
            .map(|p| mesh.vertex(p))
            .collect();
        rings.push(around);
        if ring == RINGS / 2 && h > 0.0 {
            let around: Vec<u32> = circle(r, -h).into_iter().map(|p| mesh.vertex(p)).collect();
            rings.push(around);
        }
    }
    for pair in rings.windows(2) {
        let (upper, lower) = (&pair[0], &pair[1]);
        for k in 0..SIDES {
            let next = (k + 1) % SIDES;
            mesh.triangle(upper[k], lower[k], lower[next]);
            mesh.triangle(upper[k], lower[next], upper[next]);
        }
    }
}

/// [`SIDES`] points of the circle of radius `r` (m) in the plane y = `y`, counter-clockwise
/// seen from +y.
fn circle(r: f64, y: f64) -> Vec<[f64; 3]> {
    (0..SIDES)
        .map(|k| {
            let angle = core::f64::consts::TAU * k as f64 / SIDES as f64;
            [r * angle.cos(), y, -r * angle.sin()]
        })
        .collect()
}

fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn scale(a: [f64; 3], s: f64) -> [f64; 3] {
    a.map(|c| c * s)
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn normalize(a: [f64; 3]) -> [f64; 3] {
    let length = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
    if length > 0.0 {
        scale(a, 1.0 / length)
    } else {
        [0.0, 1.0, 0.0]
    }
}

/// p rotated by the unit quaternion q = (w, x, y, z): p + 2w(v × p) + 2v × (v × p).
fn rotate(q: [f64; 4], p: [f64; 3]) -> [f64; 3] {
    let [w, x, y, z] = q;
    let v = [x, y, z];
    let t = scale(cross(v, p), 2.0);
    add(add(p, scale(t, w)), cross(v, t))
}

#[cfg(test)]
mod tests {
    use super::*;
    use fixstep::math::{Fx, Vec3};

    #[test]
    fn a_box_is_twelve_triangles_within_its_half_extents() {
        let mesh = shape_mesh::<Fx>(&Shape::Box {
            half_extents: Vec3::from_f64(0.5, 1.0, 2.0),
        });
        assert_eq!(mesh.indices.len(), 36);
        for p in mesh.positions.chunks_exact(3) {
            assert_eq!([p[0].abs(), p[1].abs(), p[2].abs()], [0.5, 1.0, 2.0]);
        }
    }

    #[test]
    fn a_sphere_s_vertices_lie_on_it() {
        let mesh = shape_mesh::<Fx>(&Shape::Sphere {
            radius: Fx::from_f64(0.25),
        });
        assert!(!mesh.indices.is_empty());
        assert!(
            mesh.indices
                .iter()
                .all(|&i| (i as usize) < mesh.positions.len() / 3)
        );
        for p in mesh.positions.chunks_exact(3) {
            let r = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
            assert!((r - 0.25).abs() < 1e-6, "{r}");
        }
    }
}
