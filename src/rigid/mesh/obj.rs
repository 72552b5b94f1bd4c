//! Reading Wavefront OBJ files into meshes ([`read_obj_file`], [`read_obj`]).
//!
//! The subset read: `v x y z [w]` records (positions; a `w` divides them, three more
//! numbers after the position are vertex colours and are ignored) and `f` records of three
//! or more corners, each corner `v`, `v/vt`, `v//vn` or `v/vt/vn` with only `v` used.
//! Indices count from 1; a negative index counts back from the last vertex defined before
//! its record (−1 is the last), as OBJ defines. A polygon of k corners becomes k − 2
//! triangles as a fan from its first corner, keeping its winding. Every object and group
//! of the file (`o`, `g`, `usemtl`) goes into the one mesh, in file order. Normals,
//! texture coordinates, materials (`mtllib` is never opened), points (`p`), two-corner
//! lines (`l`) and unknown records are ignored; vertices no face uses are dropped.
//!
//! Refused, each with the file's name and the line of the offending record: a file that
//! cannot be read, is not a regular file, is larger than [`MAX_INPUT_FILE_LEN`] or is not
//! UTF-8 (with the byte offset); no faces; a face of fewer than three corners; a polyline (`l`) of three or more corners; an index that is 0, not a
//! number, or names a vertex not defined before its record; a record the parser cannot
//! read (the first line at which the file stops parsing); a coordinate that is NaN,
//! infinite or beyond ±100 000 m; more than [`MAX_MESH_VERTICES`] vertices or
//! [`MAX_MESH_TRIANGLES`] triangles (counted before anything is parsed, stopping at the
//! line that passes the limit); and whatever [`TriMesh::new`] refuses (a degenerate
//! triangle, an edge longer than [`MAX_EDGE_LENGTH`] m, a non-manifold edge), named by the
//! face it came from.
//!
//! The records are parsed by the `tobj` crate. It reports no lines, so a cheap scan of
//! the text first records the line of each vertex and each triangle, checks the counts
//! and the face indices, and turns the mesh's errors, which name vertices and triangles
//! by index, into lines. Coordinates are read as `f64` and converted with
//! [`Real::from_f64`] after the range check: reading a file is the one place floats are
//! allowed, never the step.

use std::path::Path;

use super::{MAX_EDGE_LENGTH, MAX_MESH_TRIANGLES, MAX_MESH_VERTICES, MeshError, TriMesh};
use crate::math::{Real, Vec3};
use crate::rigid::build::MAX_MAGNITUDE;
use crate::types::{MAX_INPUT_FILE_LEN, read_input_file};

/// The mesh of the OBJ file at `path`. Errors name the file and the line (see the module
/// documentation for what is read and what is refused).
pub fn read_obj_file<R: Real>(path: &Path) -> Result<TriMesh<R>, String> {
    let origin = path.display().to_string();
    let bytes = read_input_file(path, MAX_INPUT_FILE_LEN, "an OBJ file")
        .map_err(|e| format!("{origin}: {e}"))?;
    let text = String::from_utf8(bytes).map_err(|e| {
        format!(
            "{origin}: byte offset {}: not valid UTF-8 text",
            e.utf8_error().valid_up_to()
        )
    })?;
    read_obj(&text, &origin)
}

/// The mesh of the OBJ text `text`; `origin` names the file in error messages, which
/// start with it and name the line.
pub fn read_obj<R: Real>(text: &str, origin: &str) -> Result<TriMesh<R>, String> {
    let at = |line: usize, what: &str| format!("{origin}: line {line}: {what}");
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let scan = scan(text).map_err(|(line, what)| at(line, &what))?;
    if scan.triangles.is_empty() {
        return Err(format!(
            "{origin}: no triangles (the file has no faces, `f` records)"
        ));
    }
    let positions = parse(text, &scan).map_err(|(line, what)| at(line, &what))?;

    // The vertices the faces use, in file order, and the line of each.
    let mut index = vec![u32::MAX; positions.len()];
    let mut vertices = Vec::new();
    let mut vertex_lines = Vec::new();
    for (i, position) in positions.iter().enumerate() {
        let Some(p) = position else { continue };
        let line = scan.vertex_lines[i];
        if let Some(c) = p.iter().find(|c| !c.is_finite()) {
            return Err(at(line, &format!("coordinate {c} is not a finite number")));
        }
        let limit = f64::from(MAX_MAGNITUDE); // ok-det: reading a file, before from_f64
        if let Some(c) = p.iter().find(|c| c.abs() > limit) {
            return Err(at(
                line,
                &format!("coordinate {c} is beyond ±{MAX_MAGNITUDE} m"),
            ));
        }
        index[i] = vertices.len() as u32;
        vertices.push(Vec3::from_f64(p[0], p[1], p[2]));
        vertex_lines.push(line);
    }
    let triangles = scan
        .triangles
        .iter()
        .map(|t| t.map(|v| index[v as usize]))
        .collect();
    TriMesh::new(vertices, triangles).map_err(|e| {
        let face = |t: usize| scan.triangle_lines[t];
        match e {
            MeshError::Degenerate { triangle } => at(
                face(triangle),
                "degenerate face (no area: two corners equal, or all on a line)",
            ),
            MeshError::EdgeTooLong { triangle } => at(
                face(triangle),
                &format!("a face edge is longer than {MAX_EDGE_LENGTH} m along an axis; split it"),
            ),
            MeshError::NonManifold { triangle } => at(
                face(triangle),
                "non-manifold: this face puts a third triangle on an edge two triangles \
                 already share",
            ),
            MeshError::IndexOutOfRange { triangle, .. } => at(face(triangle), &e.to_string()),
            MeshError::VertexOutOfRange { vertex } => at(vertex_lines[vertex], &e.to_string()),
            _ => format!("{origin}: {e}"),
        }
    })
}

/// What the scan of an OBJ text found: the line of each record the mesh is made of.
struct Scan {
    /// The line (from 1) of each `v` record, in file order.
    vertex_lines: Vec<usize>,
    /// The triangles of the faces after fan triangulation, as 0-based `v` record indices.
    triangles: Vec<[u32; 3]>,
    /// The line of the `f` record of each triangle.
    triangle_lines: Vec<usize>,
}

/// Scans `text` line by line without parsing numbers: records the lines of the vertices
/// and the triangles, resolves the face indices, and stops at the first line that passes
/// a count limit or holds a bad face. Errors are (line, what is wrong).
fn scan(text: &str) -> Result<Scan, (usize, String)> {
    let mut scan = Scan {
        vertex_lines: Vec::new(),
        triangles: Vec::new(),
        triangle_lines: Vec::new(),
    };
    let mut corners = Vec::new();
    for (n, line) in text.split('\n').enumerate() {
        let line_number = n + 1;
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                if scan.vertex_lines.len() == MAX_MESH_VERTICES {
                    return Err((
                        line_number,
                        format!(
                            "more than {MAX_MESH_VERTICES} vertices: a mesh takes at most that many"
                        ),
                    ));
                }
                scan.vertex_lines.push(line_number);
            }
            Some("f") => {
                let defined = scan.vertex_lines.len();
                corners.clear();
                for word in words {
                    corners.push(corner(word, defined).map_err(|e| (line_number, e))?);
                }
                if corners.len() < 3 {
                    return Err((
                        line_number,
                        format!(
                            "a face needs at least 3 corners; this one has {}",
                            corners.len()
                        ),
                    ));
                }
                for pair in corners[1..].windows(2) {
                    if scan.triangles.len() == MAX_MESH_TRIANGLES {
                        return Err((
                            line_number,
                            format!(
                                "more than {MAX_MESH_TRIANGLES} triangles (a face of k corners \
                                 makes k − 2): a mesh takes at most that many"
                            ),
                        ));
                    }
                    scan.triangles.push([corners[0], pair[0], pair[1]]);
                    scan.triangle_lines.push(line_number);
                }
            }
            Some("l") if words.count() > 2 => {
                return Err((
                    line_number,
                    "a polyline (`l`) of 3 or more corners is not supported; write faces".into(),
                ));
            }
            _ => {}
        }
    }
    Ok(scan)
}

/// The 0-based vertex index of a face corner `word` (`v`, `v/vt`, `v//vn` or `v/vt/vn`)
/// in a record after `defined` vertices.
fn corner(word: &str, defined: usize) -> Result<u32, String> {
    let field = word.split('/').next().unwrap_or(word);
    let index: i64 = field
        .parse()
        .map_err(|_| format!("face corner `{word}` does not start with a vertex index"))?;
    let resolved = match index {
        0 => {
            return Err(
                "face vertex index 0: OBJ indices start at 1 (negative ones count \
                        back from the last vertex)"
                    .into(),
            );
        }
        1.. => index - 1,
        _ => (defined as i64).saturating_add(index),
    };
    if resolved < 0 || resolved >= defined as i64 {
        return Err(format!(
            "face vertex index {index} is out of range (the file has {defined} vertices \
             before this line)"
        ));
    }
    Ok(resolved as u32)
}

/// The vertex positions as tobj reads them, m.
type Positions = Vec<Option<[f64; 3]>>; // ok-det: reading a file, before any step

/// Parses `text` with `tobj` and returns the position of each `v` record that a face
/// uses (`None` for the others), matching tobj's triangles to the scan's in file order.
/// Errors are (line, what is wrong): tobj's errors are placed at the first line at which
/// the text stops parsing.
fn parse(text: &str, scan: &Scan) -> Result<Positions, (usize, String)> {
    let models = match load(text) {
        Ok(models) => models,
        Err(e) => {
            return Err((
                first_failing_line(text),
                format!("cannot read this record ({e})"),
            ));
        }
    };
    let mut positions = vec![None; scan.vertex_lines.len()];
    let mut count = 0;
    for model in &models {
        let mesh = &model.mesh;
        for local in mesh.indices.chunks_exact(3) {
            if let Some(triangle) = scan.triangles.get(count) {
                for (&l, &v) in local.iter().zip(triangle) {
                    let p = &mesh.positions[3 * l as usize..3 * l as usize + 3];
                    positions[v as usize] = Some([p[0], p[1], p[2]]);
                }
            }
            count += 1;
        }
    }
    if count != scan.triangles.len() {
        let line = scan.triangle_lines[count.min(scan.triangle_lines.len() - 1)];
        let what = "the parser and the scan disagree on the faces here (a bug: please report \
                    the file)";
        return Err((line, what.into()));
    }
    Ok(positions)
}

/// The models of `text` as tobj reads them: triangulated, positions only, no materials.
fn load(text: &str) -> Result<Vec<tobj::Model>, tobj::LoadError> {
    let options = tobj::LoadOptions {
        single_index: true,
        triangulate: true,
        ignore_points: true,
        ignore_lines: true,
    };
    tobj::load_obj_buf(&mut text.as_bytes(), &options, |_| Ok(Default::default()))
        .map(|(models, _materials)| models)
}

/// The first line of `text` at which tobj fails: the smallest number of lines from the
/// start that it refuses, found by bisection (called only once the whole text failed).
fn first_failing_line(text: &str) -> usize {
    let ends: Vec<usize> = text
        .match_indices('\n')
        .map(|(i, _)| i + 1)
        .chain(std::iter::once(text.len()))
        .collect();
    // Lines 1..=hi fail; lines 1..=lo parse.
    let (mut lo, mut hi) = (0, ends.len());
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if load(&text[..ends[mid - 1]]).is_err() {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}
