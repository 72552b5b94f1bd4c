//! Checking a scene's rigid-body description and compiling it into a [`RigidSystem`].

use super::bodies::NewBody;
use super::contact::NO_FRAME;
use super::desc::{BodyDesc, BodyKind, MAX_BODIES, MAX_SOLVER_SUBSTEPS, RigidDesc, SolverSettings};
use super::mass::MassProperties;
use super::shape::{Part, Shape};
use super::system::RigidSystem;
use crate::math::{Quat, Real, Vec3};
use crate::types::{SceneError, lattice_copies};

/// The largest coordinate, size or speed a scene may use (m, m/s): far inside the range of
/// every fixed-point format, so that products such as a speed times a size cannot
/// saturate.
pub(crate) const MAX_MAGNITUDE: i32 = 100_000;

impl<R: Real> RigidSystem<R> {
    /// Checks `desc` and builds the system; the error names the offending field (relative
    /// to the `rigid` section).
    pub fn from_desc(desc: &RigidDesc<R>) -> Result<Self, SceneError> {
        check_settings(&desc.solver).map_err(|e| e.within("solver"))?;
        let counts = desc.bodies.iter().map(|b| b.grid.map(|g| g.count));
        check_total(counts, MAX_BODIES, "bodies", "bodies")?;
        let mut system = Self::new(desc.solver);
        for (k, body) in desc.bodies.iter().enumerate() {
            let field = format!("bodies[{k}]");
            let template = compile_body(body).map_err(|e| e.within(&field))?;
            for offset in lattice(body)? {
                let mut copy = template.clone();
                copy.position += offset;
                system.insert(copy);
            }
        }
        system.set_templates(&desc.templates, &desc.joint_templates)?;
        Ok(system)
    }

    /// Checks the invariants of a state that comes from outside (a snapshot); the error
    /// names the offending field.
    pub fn validate(&self) -> Result<(), SceneError> {
        check_settings(&self.settings).map_err(|e| e.within("solver"))?;
        let b = &self.bodies;
        let n = b.len();
        let lengths = [
            b.position.len(),
            b.orientation.len(),
            b.linear_velocity.len(),
            b.angular_velocity.len(),
            b.inv_mass.len(),
            b.inv_inertia.len(),
            b.force.len(),
            b.torque.len(),
            b.kind.len(),
            b.shape.len(),
            b.material.len(),
            b.mass.len(),
            b.inertia.len(),
            b.isotropic.len(),
            b.linear_damping.len(),
            b.angular_damping.len(),
            b.filter.len(),
            b.sensor.len(),
            b.bullet.len(),
            b.sleep_time.len(),
            b.asleep.len(),
            b.island.len(),
            b.generation.len(),
        ];
        if lengths.iter().any(|&len| len != n) || n > MAX_BODIES as usize {
            return Err(SceneError::new(
                "bodies",
                "the body arrays have different lengths or too many slots",
            ));
        }
        for i in 0..n {
            if b.alive[i] {
                let field = format!("bodies[{i}]");
                check_shape(&b.shape[i], b.kind[i]).map_err(|e| e.within(&field))?;
                if b.island[i] as usize >= n {
                    return Err(SceneError::new(
                        format!("{field}.island"),
                        "names a slot that does not exist",
                    ));
                }
            }
        }
        let mut previous = None;
        for (k, c) in self.contacts.iter().enumerate() {
            let field = format!("contacts[{k}]");
            let (a, b_) = (c.key.body_a as usize, c.key.body_b as usize);
            if a >= b_ || b_ >= n || !b.alive[a] || !b.alive[b_] {
                return Err(SceneError::new(
                    field,
                    "does not join two live bodies A < B",
                ));
            }
            if previous.is_some_and(|p| p >= c.key) {
                return Err(SceneError::new(
                    field,
                    "contacts are not in ascending key order",
                ));
            }
            if usize::from(c.count) > super::MAX_MANIFOLD_POINTS {
                return Err(SceneError::new(field, "more than 4 points"));
            }
            if c.frame != NO_FRAME && c.frame as usize >= self.frames.len() {
                return Err(SceneError::new(
                    format!("{field}.frame"),
                    format!("names recycling frame {} of {}", c.frame, self.frames.len()),
                ));
            }
            previous = Some(c.key);
        }
        let ordered = self.sensor_overlaps.windows(2).all(|w| w[0] < w[1]);
        let live = |s: u32| (s as usize) < n && b.alive[s as usize];
        if !ordered
            || !self.sensor_overlaps.iter().all(|&(s, t)| {
                s < t && live(s) && live(t) && b.sensor[s as usize] != b.sensor[t as usize]
            })
        {
            return Err(SceneError::new(
                "sensor_overlaps",
                "must be ascending pairs A < B of a live sensor and a live body that is not one",
            ));
        }
        self.validate_joints()
    }
}

/// Checks that the entries, each one or a lattice of `count` copies, make at most `max`
/// `what` ("bodies", "joints") in all; the error names `field`.
pub(crate) fn check_total(
    mut counts: impl Iterator<Item = Option<(u32, u32, u32)>>,
    max: u32,
    field: &str,
    what: &str,
) -> Result<(), SceneError> {
    let total = counts.try_fold(0u64, |sum, count| {
        let sum = sum.saturating_add(lattice_copies(count));
        (sum <= u64::from(max)).then_some(sum)
    });
    match total {
        Some(_) => Ok(()),
        None => Err(SceneError::new(field, format!("more than {max} {what}"))),
    }
}

/// Checks a lattice: every count at least 1 (error at `grid.count`), and the lattice
/// within ±[`MAX_MAGNITUDE`] m (error at `grid.spacing`); `max` bounds a count.
pub(crate) fn check_lattice<R: Real>(
    count: (u32, u32, u32),
    spacing: Vec3<R>,
    max: u32,
) -> Result<(), SceneError> {
    let (nx, ny, nz) = count;
    if nx == 0 || ny == 0 || nz == 0 {
        return Err(SceneError::new(
            "grid.count",
            "every count must be at least 1",
        ));
    }
    let limit = R::from_int(MAX_MAGNITUDE);
    let extent = [(nx, spacing.x), (ny, spacing.y), (nz, spacing.z)];
    if extent
        .iter()
        .any(|&(n, s)| s.abs() > limit || s.abs() * R::from_int(n.min(max) as i32) > limit)
    {
        return Err(SceneError::new(
            "grid.spacing",
            format!("the lattice must fit within ±{MAX_MAGNITUDE} m"),
        ));
    }
    Ok(())
}

fn check_settings<R: Real>(s: &SolverSettings<R>) -> Result<(), SceneError> {
    if !(1..=MAX_SOLVER_SUBSTEPS).contains(&s.substeps) {
        return Err(SceneError::new(
            "substeps",
            format!("must be 1 to {MAX_SOLVER_SUBSTEPS} (got {})", s.substeps),
        ));
    }
    let limit = R::from_int(MAX_MAGNITUDE);
    for (name, value) in [
        ("contact_hertz", s.contact_hertz),
        ("contact_damping_ratio", s.contact_damping_ratio),
        ("max_push_velocity", s.max_push_velocity),
        ("restitution_threshold", s.restitution_threshold),
        ("speculative_distance", s.speculative_distance),
        ("time_to_sleep", s.time_to_sleep),
        ("linear_sleep_speed", s.linear_sleep_speed),
        ("angular_sleep_speed", s.angular_sleep_speed),
        ("contact_recycle_distance", s.contact_recycle_distance),
    ] {
        SceneError::check_range(name, value, R::ZERO, limit, "")?;
    }
    Ok(())
}

/// Offsets of the copies of `body` (one zero offset without a grid).
fn lattice<R: Real>(body: &BodyDesc<R>) -> Result<Vec<Vec3<R>>, SceneError> {
    let Some(grid) = body.grid else {
        return Ok(vec![Vec3::ZERO]);
    };
    let (nx, ny, nz) = grid.count;
    let mut offsets = Vec::with_capacity((nx as usize) * (ny as usize) * (nz as usize));
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                offsets.push(Vec3::new(
                    grid.spacing.x * R::from_int(i as i32),
                    grid.spacing.y * R::from_int(j as i32),
                    grid.spacing.z * R::from_int(k as i32),
                ));
            }
        }
    }
    Ok(offsets)
}

/// Checks one body description and computes what the storage needs. A compound is
/// recentred so that its centre of mass is the body's origin, and the body's position
/// moves to that centre.
pub(crate) fn compile_body<R: Real>(body: &BodyDesc<R>) -> Result<NewBody<R>, SceneError> {
    check_shape(&body.shape, body.kind).map_err(|e| e.within("shape"))?;
    let limit = R::from_int(MAX_MAGNITUDE);
    for (name, v) in [
        ("position", body.position),
        ("velocity", body.velocity),
        ("angular_velocity", body.angular_velocity),
    ] {
        if v.abs().max_component() > limit {
            return Err(SceneError::new(
                name,
                format!("components must be within ±{MAX_MAGNITUDE}"),
            ));
        }
    }
    if let Some(grid) = body.grid {
        check_lattice(grid.count, grid.spacing, MAX_BODIES)?;
    }
    let orientation = SceneError::unit_quaternion("orientation", body.orientation)?;
    for (name, value) in [
        ("density", body.density),
        ("material.friction", body.material.friction),
        ("linear_damping", body.linear_damping),
        ("angular_damping", body.angular_damping),
    ] {
        SceneError::check_range(name, value, R::ZERO, limit, "")?;
    }
    if body.material.restitution < R::ZERO || body.material.restitution > R::ONE {
        return Err(SceneError::new(
            "material.restitution",
            format!("must be 0 to 1 (got {})", body.material.restitution),
        ));
    }
    let mut shape = body.shape.clone();
    if let Shape::Compound { parts } = &mut shape {
        // `check_shape` found every rotation normalisable.
        for part in parts.iter_mut() {
            part.rotation = part.rotation.normalize();
        }
    }
    let mut position = body.position;
    let mut mass = MassProperties::ZERO;
    if body.kind == BodyKind::Dynamic {
        mass = shape.mass_properties(body.density);
        if mass.mass <= R::ZERO {
            return Err(SceneError::new(
                "density",
                "a dynamic body needs a positive mass (a positive density and a solid shape)",
            ));
        }
        if mass.centre != Vec3::ZERO {
            shape = centred_on_mass(shape, mass.centre);
            position += orientation.rotate(mass.centre);
        }
    }
    Ok(NewBody {
        kind: body.kind,
        shape,
        material: body.material,
        mass: mass.mass,
        inertia: mass.inertia,
        position,
        orientation,
        linear_velocity: if body.kind == BodyKind::Static {
            Vec3::ZERO
        } else {
            body.velocity
        },
        angular_velocity: if body.kind == BodyKind::Static {
            Vec3::ZERO
        } else {
            body.angular_velocity
        },
        linear_damping: body.linear_damping,
        angular_damping: body.angular_damping,
        filter: body.filter,
        sensor: body.sensor,
        bullet: body.bullet,
    })
}

/// `shape` moved by −`centre` (m) so that its centre of mass is the origin: every part of a
/// compound moved, a hull's vertices moved, any other shape (a cone) made the one part of a
/// compound placed at −`centre`.
fn centred_on_mass<R: Real>(shape: Shape<R>, centre: Vec3<R>) -> Shape<R> {
    match shape {
        Shape::Compound { mut parts } => {
            for part in &mut parts {
                part.translation -= centre;
            }
            Shape::Compound { parts }
        }
        Shape::ConvexHull { hull } => Shape::ConvexHull {
            hull: hull.translated(-centre),
        },
        other => Shape::Compound {
            parts: vec![Part {
                rotation: Quat::IDENTITY,
                translation: -centre,
                shape: other,
            }],
        },
    }
}

/// A plane only on a static body, a mesh or a heightfield only on a static or kinematic
/// one, neither inside a compound; sizes positive and bounded; a
/// plane's normal of unit length (it is not normalised for the user).
fn check_shape<R: Real>(shape: &Shape<R>, kind: BodyKind) -> Result<(), SceneError> {
    let limit = R::from_int(MAX_MAGNITUDE);
    let size = |name: &str, v: R| {
        if v <= R::ZERO || v > limit {
            Err(SceneError::new(
                name,
                format!("must be above 0 and at most {MAX_MAGNITUDE} m (got {v})"),
            ))
        } else {
            Ok(())
        }
    };
    match shape {
        Shape::Sphere { radius } => size("Sphere.radius", *radius),
        Shape::Box { half_extents } => {
            size("Box.half_extents.x", half_extents.x)?;
            size("Box.half_extents.y", half_extents.y)?;
            size("Box.half_extents.z", half_extents.z)
        }
        Shape::Capsule {
            radius,
            half_height,
        } => {
            size("Capsule.radius", *radius)?;
            if *half_height < R::ZERO || *half_height > limit {
                return Err(SceneError::new(
                    "Capsule.half_height",
                    format!("must be 0 to {MAX_MAGNITUDE} m"),
                ));
            }
            Ok(())
        }
        Shape::Cylinder {
            radius,
            half_height,
        } => {
            size("Cylinder.radius", *radius)?;
            size("Cylinder.half_height", *half_height)
        }
        Shape::Cone {
            radius,
            half_height,
        } => {
            size("Cone.radius", *radius)?;
            size("Cone.half_height", *half_height)
        }
        Shape::ConvexHull { hull } => {
            match hull
                .vertices()
                .iter()
                .position(|v| v.abs().max_component() > limit)
            {
                Some(k) => Err(SceneError::new(
                    format!("ConvexHull.points[{k}]"),
                    format!("components must be within ±{MAX_MAGNITUDE} m"),
                )),
                None => Ok(()),
            }
        }
        Shape::TriMesh { .. } | Shape::HeightField { .. } => {
            // The mesh checked its own data when it was made.
            if kind == BodyKind::Dynamic {
                let name = if matches!(shape, Shape::TriMesh { .. }) {
                    "TriMesh"
                } else {
                    "HeightField"
                };
                return Err(SceneError::new(
                    name,
                    "a mesh or a heightfield can only be a static or kinematic body",
                ));
            }
            Ok(())
        }
        Shape::Plane { normal, offset } => {
            if kind != BodyKind::Static {
                return Err(SceneError::new(
                    "Plane",
                    "a plane can only be a static body",
                ));
            }
            let len2 = normal.length_squared();
            let tolerance = R::from_ratio(1, 1000);
            if (len2 - R::ONE).abs() > tolerance {
                return Err(SceneError::new("Plane.normal", "must have length 1"));
            }
            if offset.abs() > limit {
                return Err(SceneError::new(
                    "Plane.offset",
                    format!("must be within ±{MAX_MAGNITUDE} m"),
                ));
            }
            Ok(())
        }
        Shape::Compound { parts } => {
            if parts.is_empty() || parts.len() > usize::from(u16::MAX) {
                return Err(SceneError::new(
                    "Compound.parts",
                    "must hold 1 to 65535 parts",
                ));
            }
            for (k, part) in parts.iter().enumerate() {
                let field = format!("Compound.parts[{k}]");
                if matches!(
                    part.shape,
                    Shape::Compound { .. }
                        | Shape::Plane { .. }
                        | Shape::TriMesh { .. }
                        | Shape::HeightField { .. }
                ) {
                    return Err(SceneError::new(
                        format!("{field}.shape"),
                        "a part must be a sphere, box, capsule, cylinder, cone or convex hull",
                    ));
                }
                check_shape(&part.shape, kind).map_err(|e| e.within(&field))?;
                if part.translation.abs().max_component() > limit {
                    return Err(SceneError::new(
                        format!("{field}.translation"),
                        format!("components must be within ±{MAX_MAGNITUDE}"),
                    ));
                }
                SceneError::unit_quaternion(format!("{field}.rotation"), part.rotation)?;
            }
            Ok(())
        }
    }
}
