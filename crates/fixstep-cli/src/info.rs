//! `fixstep info`: what a replay holds, without simulating it.

use std::path::Path;

use super::output::print_line;
use super::status::Status;
use fixstep::fluid::FluidDesc;
use fixstep::math::{Fx, Real};
use fixstep::particles::{ForceDesc, ParticlesDesc};
use fixstep::replay::format::FORMAT_VERSION;
use fixstep::replay::{Replay, StateVersionCheck};
use fixstep::rigid::{JointsDesc, RigidDesc, Shape};
use fixstep::soft::{SoftDesc, SoftModel, SoftShape};
use fixstep::types::lattice_copies as copies;
use fixstep::world::STATE_VERSION;
use fixstep::world::checksum::hex;

/// Prints the header fields, a scene summary and the checkpoints of a replay.
pub fn info(path: &Path) -> Result<Status, String> {
    let replay =
        Replay::read_with(path, StateVersionCheck::CurrentOrOlder).map_err(|e| e.to_string())?;
    let header = replay
        .header()
        .map_err(|e| format!("{}: cannot encode the replay: {e}", path.display()))?;
    let scene = replay.scene();
    let gravity = scene.gravity;
    let mut lines = vec![
        format!("file: {}", path.display()),
        format!("format version: {FORMAT_VERSION}"),
        format!(
            "state version: {} (this build: {STATE_VERSION})",
            header.state_version
        ),
        format!("scalar: {}", header.scalar),
        format!("scene: {}", scene.name),
        format!("description: {}", scene.description),
        format!("tick rate: {} Hz", scene.tick_rate),
        format!("substeps: {}", scene.substeps),
        format!("seed: {:#x}", scene.seed),
        format!(
            "gravity: ({}, {}, {}) m/s²",
            gravity.x, gravity.y, gravity.z
        ),
        format!("particles: {}", particles_summary(scene.particles.as_ref())),
        format!(
            "rigid bodies: {}",
            scene
                .rigid
                .as_ref()
                .map_or_else(|| "none".to_owned(), rigid_summary)
        ),
        format!(
            "joints: {}",
            scene
                .joints
                .as_ref()
                .map_or_else(|| "none".to_owned(), joints_summary)
        ),
        format!(
            "soft bodies: {}",
            scene
                .soft
                .as_ref()
                .map_or_else(|| "none".to_owned(), soft_summary)
        ),
        format!(
            "fluid: {}",
            scene
                .fluid
                .as_ref()
                .map_or_else(|| "none".to_owned(), fluid_summary)
        ),
        format!("ticks: {}", replay.ticks()),
        format!("input ticks: {}", replay.inputs().len()),
        format!(
            "checkpoints: {} (every {} ticks)",
            replay.checkpoints().len(),
            replay.checksum_every()
        ),
        format!(
            "sections: scene {} bytes (hash {}), inputs {} bytes (hash {})",
            header.scene_len,
            hex(header.scene_hash),
            header.inputs_len,
            hex(header.inputs_hash)
        ),
        format!("final checksum: {}", hex(replay.final_checksum())),
    ];
    if header.state_version != STATE_VERSION {
        lines.push(format!(
            "note: recorded with state version {}; `fixstep rerecord` records it again",
            header.state_version
        ));
    }
    for line in lines {
        print_line(&line)?;
    }
    Ok(Status::Ok)
}

/// Body count (lattice copies counted) and the count of each shape, in declaration order,
/// with the vertices and faces of the convex hulls and the triangles, vertices and active
/// edges of the meshes and heightfields among them.
fn rigid_summary(desc: &RigidDesc<Fx>) -> String {
    const KINDS: [&str; 10] = [
        "sphere",
        "box",
        "capsule",
        "plane",
        "compound",
        "cylinder",
        "cone",
        "convex hull",
        "triangle mesh",
        "heightfield",
    ];
    let mut counts = [0u64; 10];
    let (mut vertices, mut faces) = (0u64, 0u64);
    // Triangles, vertices and active edges of the meshes, then of the heightfields.
    let mut meshes = [[0u64; 3]; 2];
    for body in &desc.bodies {
        let copies = copies(body.grid.map(|g| g.count));
        let kind = match &body.shape {
            Shape::Sphere { .. } => 0,
            Shape::Box { .. } => 1,
            Shape::Capsule { .. } => 2,
            Shape::Plane { .. } => 3,
            Shape::Compound { .. } => 4,
            Shape::Cylinder { .. } => 5,
            Shape::Cone { .. } => 6,
            Shape::ConvexHull { hull } => {
                vertices = vertices.saturating_add(hull.vertices().len() as u64 * copies);
                faces = faces.saturating_add(hull.faces().len() as u64 * copies);
                7
            }
            Shape::TriMesh { .. } | Shape::HeightField { .. } => {
                let kind = if matches!(body.shape, Shape::TriMesh { .. }) {
                    8
                } else {
                    9
                };
                if let Some(mesh) = body.shape.triangles() {
                    let stats = [
                        mesh.triangles().len(),
                        mesh.vertices().len(),
                        mesh.active_edge_count(),
                    ];
                    for (total, n) in meshes[kind - 8].iter_mut().zip(stats) {
                        *total = total.saturating_add(n as u64 * copies);
                    }
                }
                kind
            }
        };
        counts[kind] = counts[kind].saturating_add(copies);
    }
    let kinds: Vec<String> = KINDS
        .iter()
        .zip(counts)
        .filter(|&(_, n)| n > 0)
        .map(|(kind, n)| match *kind {
            "convex hull" => format!("{n} {kind} ({vertices} vertices, {faces} faces)"),
            "triangle mesh" | "heightfield" => {
                let [t, v, e] = meshes[usize::from(*kind == "heightfield")];
                format!("{n} {kind} ({t} triangles, {v} vertices, {e} active edges)")
            }
            _ => format!("{n} {kind}"),
        })
        .collect();
    format!("{} ({})", desc.body_count(), kinds.join(", "))
}

/// Joint count (lattice copies counted) and the count of each kind, in declaration order.
fn joints_summary(desc: &JointsDesc<Fx>) -> String {
    const KINDS: [&str; 8] = [
        "ball",
        "cone-twist",
        "hinge",
        "slider",
        "fixed",
        "rod",
        "rope",
        "spring",
    ];
    let mut counts = [0u64; 8];
    for joint in &desc.list {
        let count = &mut counts[usize::from(joint.kind.code())];
        *count = count.saturating_add(copies(joint.grid.map(|g| g.count)));
    }
    let total = counts.iter().fold(0u64, |sum, &n| sum.saturating_add(n));
    let kinds: Vec<String> = KINDS
        .iter()
        .zip(counts)
        .filter(|&(_, n)| n > 0)
        .map(|(kind, n)| format!("{n} {kind}"))
        .collect();
    format!("{total} ({})", kinds.join(", "))
}

/// Body count, each body's shape and model, vertex and collider counts, and the XPBD
/// solver's substeps and iterations (when a body uses it) of the scene's soft bodies.
fn soft_summary(desc: &SoftDesc<Fx>) -> String {
    let mut vertices = 0u64;
    let bodies: Vec<String> = desc
        .bodies
        .iter()
        .map(|body| {
            let (shape, count) = match &body.shape {
                SoftShape::Cloth { columns, rows, .. } => (
                    format!("{columns}x{rows} cloth"),
                    u64::from(*columns) * u64::from(*rows),
                ),
                SoftShape::Rope { links, .. } => {
                    (format!("{links}-link rope"), u64::from(*links) + 1)
                }
                SoftShape::Lattice {
                    count: (x, y, z), ..
                } => (format!("{x}x{y}x{z} lattice"), copies(Some((*x, *y, *z)))),
            };
            vertices = vertices.saturating_add(count);
            let model = match body.model {
                SoftModel::Xpbd { .. } => "XPBD",
                SoftModel::SpringMass { .. } => "spring-mass",
            };
            let mut coupling = Vec::new();
            let ties: usize = body.body_attachments.iter().map(|t| t.vertices.len()).sum();
            if ties > 0 {
                let mut tied: Vec<u32> = body.body_attachments.iter().map(|t| t.body).collect();
                tied.dedup();
                let names: Vec<String> = tied.iter().map(|b| format!("body {b}")).collect();
                let noun = if ties == 1 { "vertex" } else { "vertices" };
                coupling.push(format!("{ties} {noun} tied to {}", names.join(", ")));
            }
            if let Some(contacts) = &body.body_contacts {
                coupling.push(format!("touching rigid bodies (μ {})", contacts.friction));
            }
            if coupling.is_empty() {
                format!("{shape}, {model}")
            } else {
                format!("{shape}, {model}, {}", coupling.join(", "))
            }
        })
        .collect();
    let xpbd = desc
        .bodies
        .iter()
        .any(|body| matches!(body.model, SoftModel::Xpbd { .. }));
    let solver = if xpbd {
        format!(
            ", XPBD {} substeps of {} iterations",
            desc.solver.substeps, desc.solver.iterations
        )
    } else {
        String::new()
    };
    format!(
        "{} ({}), {vertices} vertices, {} colliders{solver}",
        desc.bodies.len(),
        bodies.join("; "),
        desc.colliders.len(),
    )
}

/// Solver, spacing, blocks, emitters and substeps of the scene's fluid, and the rigid
/// bodies it meets.
fn fluid_summary(desc: &FluidDesc<Fx>) -> String {
    let substeps = if desc.cfl == Fx::ZERO {
        format!("{} substeps", desc.substeps)
    } else {
        format!(
            "adaptive substeps (CFL {}), at most {}",
            desc.cfl, desc.substeps
        )
    };
    let bodies = desc.bodies.map_or_else(String::new, |b| {
        format!(
            "; meets rigid bodies on layers {:#x} (mask {:#x}), two-way",
            b.filter.layers, b.filter.mask
        )
    });
    format!(
        "{:?}, spacing {} m, {} blocks, {} emitters, {substeps}{bodies}",
        desc.solver,
        desc.spacing,
        desc.blocks.len(),
        desc.emitters.len()
    )
}

/// Particle count, templates, emitters, forces and colliding groups of the scene's particle
/// section.
fn particles_summary(particles: Option<&ParticlesDesc<Fx>>) -> String {
    let Some(desc) = particles else {
        return "none".to_owned();
    };
    let forces: Vec<&str> = desc.forces.iter().map(force_name).collect();
    let mut summary = format!(
        "{} initial, {} templates, {} emitters, {} forces ({}), {:?} integrator, capacity {}",
        desc.particles.len(),
        desc.templates.len(),
        desc.emitters.len(),
        desc.forces.len(),
        forces.join(", "),
        desc.integrator,
        desc.capacity
    );
    if !desc.collisions.is_empty() {
        let groups: Vec<String> = desc
            .collisions
            .iter()
            .map(|c| {
                let push = if c.push { ", pushing" } else { "" };
                format!(
                    "group {} (e {}, μ {}{push})",
                    c.group, c.restitution, c.friction
                )
            })
            .collect();
        summary.push_str(&format!(
            "; colliding with rigid bodies: {}",
            groups.join(", ")
        ));
    }
    summary
}

/// A force generator's kind, for the summary.
fn force_name(force: &ForceDesc<Fx>) -> &'static str {
    match force {
        ForceDesc::Gravity { .. } => "gravity",
        ForceDesc::LinearDrag { .. } => "linear drag",
        ForceDesc::QuadraticDrag { .. } => "quadratic drag",
        ForceDesc::Damping { .. } => "damping",
        ForceDesc::AnchoredSpring { .. } => "anchored spring",
        ForceDesc::Spring { .. } => "spring",
        ForceDesc::PointGravity { .. } => "point gravity",
        ForceDesc::User { .. } => "user",
    }
}
