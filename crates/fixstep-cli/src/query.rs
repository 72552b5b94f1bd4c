//! `fixstep query`: simulate a scene or a replay to a tick, then ask the world which body a
//! ray or a moving shape hits first, or which bodies a shape overlaps.
//!
//! Output is one JSON object a line: a hit `{"body":"3v0","distance":1.25,"point":[x,y,z],
//! "normal":[x,y,z]}` (m; the normal is the hit surface's, pointing back along the ray) or
//! `{"hit":false}` (the engine's [`RayHit`]); for an overlap `{"body":"3v0"}` per body, in ascending order, nothing
//! when there is none.

use super::args::QueryArgs;
use super::output::print_line;
use super::query_spec::{QueryKind, QuerySpec};
use super::scene_arg::resolve_source;
use super::status::Status;
use fixstep::math::{Fx, Quat, Real, Vec3};
use fixstep::rigid::{QueryFilter, RayHit};
use fixstep::scene::Simulation;
use fixstep::types::Handle;

/// Runs the query and prints its answer.
pub fn query(args: &QueryArgs) -> Result<Status, String> {
    // The arguments first: a bad one fails before the simulation.
    let spec = QuerySpec::from_args(args)?;
    let source = resolve_source(&args.input)?;
    let mut simulation = Simulation::resume(source.build_world(&args.input)?, source.inputs);
    while simulation.world().tick() < args.tick {
        simulation.step();
    }
    let world = simulation.world();

    let filter = QueryFilter::new().with_mask(spec.mask);
    let lines = match &spec.kind {
        QueryKind::Ray { origin, direction } => vec![hit_json(
            world
                .cast_ray(*origin, *direction, spec.max_distance, &filter)
                .as_ref(),
        )],
        QueryKind::Cast {
            shape,
            from,
            direction,
        } => vec![hit_json(
            world
                .cast_shape(
                    shape,
                    *from,
                    Quat::IDENTITY,
                    *direction,
                    spec.max_distance,
                    &filter,
                )
                .as_ref(),
        )],
        QueryKind::Overlap { shape, at } => {
            // The engine gives them ascending.
            let bodies = world.overlap(shape, *at, Quat::IDENTITY, &filter);
            bodies.iter().map(|&body| body_json(body)).collect()
        }
    };
    for line in lines {
        print_line(&line)?;
    }
    Ok(Status::Ok)
}

/// `{"body":"3v0","distance":..,"point":[..],"normal":[..]}`, or `{"hit":false}`.
fn hit_json(hit: Option<&RayHit<Fx>>) -> String {
    match hit {
        Some(hit) => format!(
            "{{\"body\":\"{}\",\"distance\":{},\"point\":{},\"normal\":{}}}",
            hit.body,
            hit.distance.to_f64(),
            array(hit.point),
            array(hit.normal)
        ),
        None => "{\"hit\":false}".to_owned(),
    }
}

/// `{"body":"3v0"}`.
fn body_json(body: Handle) -> String {
    format!("{{\"body\":\"{body}\"}}")
}

/// `[x,y,z]`.
fn array(v: Vec3<Fx>) -> String {
    let [x, y, z] = v.to_f64();
    format!("[{x},{y},{z}]")
}
