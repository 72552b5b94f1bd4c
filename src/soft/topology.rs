//! Builders of the three soft-body shapes: the starting positions, the edges, the bending
//! stencils of a cloth and the tetrahedra of a lattice, in a fixed order (the order the
//! solver visits them).

use super::desc::SoftShape;
use crate::math::{Real, Vec3};

/// A body's geometry, with vertex indices local to the body.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Topology<R: Real> {
    /// Starting positions, m.
    pub positions: Vec<Vec3<R>>,
    /// Edges (a, b), a < b.
    pub edges: Vec<[u32; 2]>,
    /// Interior cloth edges with their two wings: (edge end, edge end, wing, wing).
    pub hinges: Vec<[u32; 4]>,
    /// Tetrahedra of a lattice.
    pub tetrahedra: Vec<[u32; 4]>,
}

/// The geometry of `shape`; its counts were checked (each at least 2 vertices per side, at
/// least one link) and fit in `u32`.
pub(crate) fn build<R: Real>(shape: &SoftShape<R>) -> Topology<R> {
    match *shape {
        SoftShape::Cloth {
            origin,
            u,
            v,
            columns,
            rows,
        } => cloth(origin, u, v, columns, rows),
        SoftShape::Rope { start, end, links } => rope(start, end, links),
        SoftShape::Lattice {
            origin,
            spacing,
            count,
        } => lattice(origin, spacing, count),
    }
}

/// A `columns` × `rows` sheet, quads cut along the diagonal a–d when i + j is even and b–c
/// otherwise (a, b the quad's lower corners, c, d the upper ones), so that the sheet has no
/// preferred shear direction.
fn cloth<R: Real>(origin: Vec3<R>, u: Vec3<R>, v: Vec3<R>, columns: u32, rows: u32) -> Topology<R> {
    let mut t = Topology::default();
    let (cu, cv) = (i64::from(columns - 1), i64::from(rows - 1));
    for j in 0..rows {
        for i in 0..columns {
            let fu = R::from_ratio(i64::from(i), cu);
            let fv = R::from_ratio(i64::from(j), cv);
            t.positions.push(origin + u * fu + v * fv);
        }
    }
    let mut triangles = Vec::new();
    for j in 0..rows {
        for i in 0..columns {
            let a = j * columns + i;
            if i + 1 < columns {
                t.edges.push([a, a + 1]);
            }
            if j + 1 < rows {
                t.edges.push([a, a + columns]);
            }
            if i + 1 < columns && j + 1 < rows {
                let (b, c) = (a + 1, a + columns);
                let d = c + 1;
                if (i + j) % 2 == 0 {
                    t.edges.push([a, d]);
                    triangles.push([a, b, d]);
                    triangles.push([a, d, c]);
                } else {
                    t.edges.push([b, c]);
                    triangles.push([a, b, c]);
                    triangles.push([b, d, c]);
                }
            }
        }
    }
    t.hinges = hinges(&triangles);
    t
}

/// Every edge shared by two triangles, with the vertex of each triangle opposite it, in
/// ascending (edge, wing) order.
fn hinges(triangles: &[[u32; 3]]) -> Vec<[u32; 4]> {
    let mut sides: Vec<(u32, u32, u32)> = triangles
        .iter()
        .flat_map(|&[a, b, c]| [(a, b, c), (b, c, a), (c, a, b)])
        .map(|(p, q, opposite)| (p.min(q), p.max(q), opposite))
        .collect();
    sides.sort_unstable();
    sides
        .windows(2)
        .filter(|w| (w[0].0, w[0].1) == (w[1].0, w[1].1))
        .map(|w| [w[0].0, w[0].1, w[0].2, w[1].2])
        .collect()
}

/// `links + 1` vertices from `start` to `end`.
fn rope<R: Real>(start: Vec3<R>, end: Vec3<R>, links: u32) -> Topology<R> {
    let mut t = Topology::default();
    for k in 0..=links {
        t.positions
            .push(start.lerp(end, R::from_ratio(i64::from(k), i64::from(links))));
    }
    t.edges = (0..links).map(|k| [k, k + 1]).collect();
    t
}

/// Half of the 26 neighbour offsets (the other half are their opposites), in the order
/// edges are created: axes, face diagonals, body diagonals.
const HALF_NEIGHBOURS: [(i32, i32, i32); 13] = [
    (1, 0, 0),
    (0, 1, 0),
    (0, 0, 1),
    (1, 1, 0),
    (1, -1, 0),
    (1, 0, 1),
    (1, 0, -1),
    (0, 1, 1),
    (0, 1, -1),
    (1, 1, 1),
    (1, 1, -1),
    (1, -1, 1),
    (1, -1, -1),
];

/// The three axes in the six orders that cut a cube into the six Kuhn tetrahedra
/// (corner 0, +e_a, +e_a+e_b, corner 7), which share the cube's main diagonal.
const KUHN_ORDERS: [[u32; 3]; 6] = [
    [0, 1, 2],
    [0, 2, 1],
    [1, 0, 2],
    [1, 2, 0],
    [2, 0, 1],
    [2, 1, 0],
];

/// A block of `count` vertices `spacing` apart.
fn lattice<R: Real>(origin: Vec3<R>, spacing: R, count: (u32, u32, u32)) -> Topology<R> {
    let mut t = Topology::default();
    let (nx, ny, nz) = count;
    let index = |i: u32, j: u32, k: u32| (k * ny + j) * nx + i;
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                t.positions.push(
                    origin
                        + Vec3::new(
                            R::from_int(i as i32),
                            R::from_int(j as i32),
                            R::from_int(k as i32),
                        ) * spacing,
                );
            }
        }
    }
    let inside = |c: i64, n: u32| (0..i64::from(n)).contains(&c);
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                for (dx, dy, dz) in HALF_NEIGHBOURS {
                    let (x, y, z) = (
                        i64::from(i) + i64::from(dx),
                        i64::from(j) + i64::from(dy),
                        i64::from(k) + i64::from(dz),
                    );
                    if inside(x, nx) && inside(y, ny) && inside(z, nz) {
                        let (a, b) = (index(i, j, k), index(x as u32, y as u32, z as u32));
                        t.edges.push([a.min(b), a.max(b)]);
                    }
                }
                if i + 1 < nx && j + 1 < ny && k + 1 < nz {
                    let corner = |bits: u32| {
                        index(i + (bits & 1), j + ((bits >> 1) & 1), k + ((bits >> 2) & 1))
                    };
                    for [a, b, _] in KUHN_ORDERS {
                        let first = 1 << a;
                        let second = first | (1 << b);
                        t.tetrahedra
                            .push([corner(0), corner(first), corner(second), corner(7)]);
                    }
                }
            }
        }
    }
    t
}
