//! `fixstep run`: simulate a scene with its script, print stage timings and the checksum.

use std::io::Write;
use std::path::Path;
use std::time::Instant;

use super::args::RunArgs;
use super::bodies_csv::BodiesCsv;
use super::events_csv::EventsCsv;
use super::metrics_csv::MetricsCsv;
use super::output::{eprint_line, print_line, write_error};
use super::progress::Progress;
use super::scene_arg::resolve_scene;
use super::status::Status;
use super::timing_table::timing_table;
use super::warnings::{DIVERGENCE_CHECK_EVERY, health_warnings, print_warnings};
use fixstep::math::{Fx, Real};
use fixstep::replay::{AtomicFile, DEFAULT_CHECKSUM_EVERY, InputFeed, Recorder, scene_id};
use fixstep::scene::{Scene, Simulation};
use fixstep::types::read_input_file;
use fixstep::world::checksum::hex;
use fixstep::world::{
    MAX_SNAPSHOT_LEN, SceneId, TickReport, World, decode_snapshot, encode_snapshot,
};

/// What `run` steps: a recorder from the scene's first tick, or a simulation resumed from a
/// snapshot (which cannot be recorded, since a replay starts at tick 0).
enum Runner {
    Recording(Box<Recorder>),
    Resumed(Box<Simulation<Fx>>),
}

impl Runner {
    fn world(&self) -> &World<Fx> {
        match self {
            Self::Recording(recorder) => recorder.world(),
            Self::Resumed(simulation) => simulation.world(),
        }
    }

    /// Runs one tick with the scene's scripted input: the recorder is fed it from `feed`
    /// (and records it), the simulation feeds itself.
    fn step(&mut self, feed: &mut InputFeed) -> TickReport {
        match self {
            Self::Recording(recorder) => {
                let tick = recorder.world().tick();
                recorder.step(feed.at(tick))
            }
            Self::Resumed(simulation) => simulation.step(),
        }
    }
}

impl Runner {
    /// Turns on stage timing and the divergence check (neither is simulated state).
    fn enable_reports(&mut self) {
        match self {
            Self::Recording(recorder) => {
                recorder.enable_timing();
                recorder.enable_divergence_check(DIVERGENCE_CHECK_EVERY);
            }
            Self::Resumed(simulation) => {
                let world = simulation.world_mut();
                world.enable_timing();
                world.enable_divergence_check(DIVERGENCE_CHECK_EVERY);
            }
        }
    }
}

/// Opens an optional output file (written atomically), so that a bad path fails before the
/// run.
fn open_output(path: Option<&Path>) -> Result<Option<AtomicFile>, String> {
    path.map(|path| AtomicFile::create(path).map_err(|e| write_error(path, &e)))
        .transpose()
}

/// Writes `encoded` (a `what`, for the error message) to `file` and puts it in place.
fn commit_output<E: core::fmt::Display>(
    mut file: AtomicFile,
    what: &str,
    encoded: Result<Vec<u8>, E>,
) -> Result<(), String> {
    let path = file.path().to_owned();
    let bytes =
        encoded.map_err(|e| format!("{}: cannot encode the {what}: {e}", path.display()))?;
    file.write_all(&bytes)
        .and_then(|()| file.commit())
        .map_err(|e| write_error(&path, &e))
}

/// The scene's name and hash, which a snapshot file carries.
fn snapshot_scene(scene: &Scene<Fx>) -> Result<SceneId, String> {
    scene_id(scene).map_err(|e| format!("{}: cannot encode the scene: {e}", scene.name))
}

/// The scene's simulation, continued from the snapshot at `path`, which must be of this
/// scene.
fn resume(scene: &Scene<Fx>, path: &Path) -> Result<Simulation<Fx>, String> {
    let in_file = |e: &dyn core::fmt::Display| format!("{}: {e}", path.display());
    let bytes =
        read_input_file(path, MAX_SNAPSHOT_LEN, "a snapshot file").map_err(|e| in_file(&e))?;
    let snapshot = decode_snapshot::<Fx>(&bytes).map_err(|e| in_file(&e))?;
    snapshot
        .scene
        .check_same(&snapshot_scene(scene)?)
        .map_err(|e| in_file(&e))?;
    let mut world = scene.build().map_err(|e| format!("{}: {e}", scene.name))?;
    world.restore(&snapshot.state);
    if let Some(particles) = world.particles() {
        particles
            .check_user_forces()
            .map_err(|e| format!("{}: {e}", path.display()))?;
    }
    Ok(Simulation::resume(world, scene.script.clone()))
}

/// Refuses two outputs that name the same file.
fn distinct_outputs(args: &RunArgs) -> Result<(), String> {
    let outputs = [
        ("--record", &args.record),
        ("--metrics", &args.metrics),
        ("--bodies", &args.bodies),
        ("--events", &args.events),
        ("--snapshot", &args.snapshot),
    ];
    for (i, (first, a)) in outputs.iter().enumerate() {
        for (second, b) in &outputs[i + 1..] {
            if let (Some(a), Some(b)) = (a, b)
                && a == b
            {
                return Err(format!(
                    "{}: {first} and {second} name the same file",
                    a.display()
                ));
            }
        }
    }
    Ok(())
}

/// Runs the scene. The last line printed is `checksum: <16 hex digits>`.
pub fn run(args: &RunArgs) -> Result<Status, String> {
    let mut scene = resolve_scene(&args.scene)?;
    if let Some(seed) = args.seed {
        scene.seed = seed;
    }
    let ticks = args.ticks.unwrap_or(scene.ticks);
    distinct_outputs(args)?;

    // Open the outputs first, so a bad path fails before the run rather than after it.
    let replay_file = open_output(args.record.as_deref())?;
    let snapshot_file = open_output(args.snapshot.as_deref())?;
    let mut metrics = args
        .metrics
        .as_deref()
        .map(|path| MetricsCsv::create(path, args.every))
        .transpose()?;
    let mut bodies = args
        .bodies
        .as_deref()
        .map(|path| BodiesCsv::create(path, args.every))
        .transpose()?;
    let mut events = args.events.as_deref().map(EventsCsv::create).transpose()?;

    let mut runner = match &args.from_snapshot {
        Some(path) => Runner::Resumed(Box::new(resume(&scene, path)?)),
        None => Runner::Recording(Box::new(
            Recorder::new(&scene, DEFAULT_CHECKSUM_EVERY)
                .map_err(|e| format!("{}: {e}", args.scene))?,
        )),
    };
    runner.enable_reports();
    print_warnings(None, runner.world().warnings());
    if let Some(metrics) = &mut metrics {
        metrics.tick(runner.world())?;
    }
    if let Some(bodies) = &mut bodies {
        bodies.tick(runner.world())?;
    }
    let mut feed = InputFeed::new(&scene.script);
    let mut progress = Progress::new(ticks);
    let started = Instant::now(); // ok-det: wall time is reported, never simulated
    for done in 1..=ticks {
        let report = runner.step(&mut feed);
        report_broken_joints(runner.world());
        if let Some(metrics) = &mut metrics {
            metrics.tick(runner.world())?;
        }
        if let Some(bodies) = &mut bodies {
            bodies.tick(runner.world())?;
        }
        if let Some(events) = &mut events {
            events.events(&report.events)?;
        }
        progress.update(done);
    }
    let wall = started.elapsed();
    progress.finish();

    let world = runner.world();
    print_line(&format!(
        "{}: {ticks} ticks at {} Hz ({} substeps), seed {:#x}, {:.1} ms wall",
        scene.name,
        world.settings().tick_rate,
        world.settings().substeps,
        scene.seed,
        wall.as_secs_f64() * 1e3
    ))?;
    if let Some(timings) = world.timings() {
        for line in timing_table(timings) {
            print_line(&line)?;
        }
    }
    let health = world.health();
    let checksum = world.checksum().total;
    if let Some(metrics) = metrics {
        metrics.finish(world)?;
    }
    if let Some(bodies) = bodies {
        bodies.finish(world)?;
    }
    if let Some(events) = events {
        events.finish()?;
    }
    if let Some(file) = snapshot_file {
        let encoded = encode_snapshot(&world.snapshot(), &snapshot_scene(&scene)?);
        commit_output(file, "snapshot", encoded)?;
    }
    if let (Runner::Recording(recorder), Some(file)) = (runner, replay_file) {
        commit_output(file, "replay", recorder.finish().to_bytes())?;
    }
    print_warnings(None, health_warnings(&health));
    print_line(&format!("checksum: {}", hex(checksum)))?;
    Ok(Status::Ok)
}

/// One line on standard error per joint that broke during the tick just run.
fn report_broken_joints(world: &World<Fx>) {
    if let Some(rigid) = world.rigid() {
        for event in rigid.joint_events() {
            eprint_line(&format!(
                "tick {}: joint {} broke ({:.1} N, {:.1} N·m)",
                world.tick(),
                event.joint,
                event.force.to_f64(),
                event.torque.to_f64()
            ));
        }
    }
}
