//! `fixstep run`: simulate a scene with its script, print stage timings and the checksum.

use std::io::Write;
use std::path::Path;
use std::time::Instant;

use super::args::RunArgs;
use super::bodies_csv::BodiesCsv;
use super::events_csv::EventsCsv;
use super::file_identity::{NamedFile, refuse_shared_files};
use super::metrics_csv::MetricsCsv;
use super::output::{eprint_line, print_line, write_error};
use super::output_file::OutputFile;
use super::progress::Progress;
use super::scene_arg::{resolve_scene, scene_file};
use super::status::Status;
use super::timing_table::timing_table;
use super::warnings::{DIVERGENCE_CHECK_EVERY, health_warnings, print_warnings};
use fixstep::math::{Fx, Real};
use fixstep::replay::{DEFAULT_CHECKSUM_EVERY, InputFeed, StreamingRecorder, scene_id};
use fixstep::scene::{Scene, Simulation};
use fixstep::types::read_input_file;
use fixstep::world::checksum::hex;
use fixstep::world::{
    MAX_SNAPSHOT_LEN, SceneId, TickInput, TickReport, World, decode_snapshot, encode_snapshot,
};

/// What `run` steps: a recorder writing the replay as it goes (`--record`), or a simulation
/// that keeps nothing per tick (from the scene's first tick, or resumed from a snapshot), so
/// that memory does not grow with the ticks.
enum Runner {
    Recording(Box<StreamingRecorder>),
    Plain(Box<Simulation<Fx>>),
}

impl Runner {
    fn world(&self) -> &World<Fx> {
        match self {
            Self::Recording(recorder) => recorder.world(),
            Self::Plain(simulation) => simulation.world(),
        }
    }

    /// Runs one tick with the scene's scripted input: the recorder is fed it from `feed`
    /// (and records it), the simulation feeds itself. Fails when the recording cannot be
    /// written.
    fn step(&mut self, feed: &mut InputFeed) -> std::io::Result<TickReport> {
        match self {
            Self::Recording(recorder) => {
                let tick = recorder.world().tick();
                recorder.step(feed.at(tick))
            }
            Self::Plain(simulation) => Ok(simulation.step()),
        }
    }

    /// Turns on stage timing and the divergence check (neither is simulated state).
    fn enable_reports(&mut self) {
        match self {
            Self::Recording(recorder) => {
                recorder.enable_timing();
                recorder.enable_divergence_check(DIVERGENCE_CHECK_EVERY);
            }
            Self::Plain(simulation) => {
                let world = simulation.world_mut();
                world.enable_timing();
                world.enable_divergence_check(DIVERGENCE_CHECK_EVERY);
            }
        }
    }
}

/// The scene's script as a recorder feeds it: each input with its players in canonical
/// order, without players or ticks that give no command. A run that is not recorded steps
/// these, so that its checksum is the recorded run's.
fn canonical_script(scene: &Scene<Fx>) -> Vec<TickInput<Fx>> {
    let mut script = scene.script.clone();
    for input in &mut script {
        input.canonicalize();
        input.players.retain(|p| !p.commands.is_empty());
    }
    script.retain(|input| !input.is_empty());
    script
}

/// The recorder of `--record path`: its checkpoints wait in an anonymous spool file in the
/// replay's folder (never in memory, never a name left behind).
fn streaming_recorder(
    scene: &Scene<Fx>,
    origin: &str,
    replay: &OutputFile,
) -> Result<StreamingRecorder, String> {
    let spool =
        tempfile::tempfile_in(replay.folder()).map_err(|e| write_error(replay.path(), &e))?;
    StreamingRecorder::new(scene, DEFAULT_CHECKSUM_EVERY, spool)
        .map_err(|e| format!("{origin}: {e}"))
}

/// The scene's name and hash, which a snapshot file carries.
fn snapshot_scene(scene: &Scene<Fx>) -> Result<SceneId, String> {
    scene_id(scene).map_err(|e| format!("{}: cannot encode the scene: {e}", scene.name))
}

/// The scene's simulation from its first tick, fed its script as a recorder feeds it, and
/// refused as a recorder refuses it (a scene whose user forces no code registers); errors
/// start with `origin`, the SCENE argument.
fn simulation(scene: &Scene<Fx>, origin: &str) -> Result<Simulation<Fx>, String> {
    let world = scene.build().map_err(|e| format!("{origin}: {e}"))?;
    if let Some(particles) = world.particles() {
        particles
            .check_user_forces()
            .map_err(|e| format!("{origin}: {}", e.within("particles")))?;
    }
    Ok(Simulation::resume(world, canonical_script(scene)))
}

/// The scene's simulation, continued from the snapshot at `path`, which must be of this
/// scene (fed the script as written).
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

/// Refuses an output that is also an input (the scene file, the snapshot resumed from) or
/// another output, however the paths are spelt.
pub fn refuse_clashes(args: &RunArgs) -> Result<(), String> {
    let mut inputs = Vec::new();
    if let Some(path) = scene_file(&args.scene) {
        inputs.push(NamedFile::new("the scene file", path));
    }
    if let Some(path) = &args.from_snapshot {
        inputs.push(NamedFile::new("--from-snapshot", path));
    }
    let outputs: Vec<NamedFile> = [
        ("--record", &args.record),
        ("--metrics", &args.metrics),
        ("--bodies", &args.bodies),
        ("--events", &args.events),
        ("--snapshot", &args.snapshot),
    ]
    .into_iter()
    .filter_map(|(role, path)| path.as_deref().map(|path| NamedFile::new(role, path)))
    .collect();
    refuse_shared_files(&inputs, &outputs)
}

/// Runs the scene. The last line printed is `checksum: <16 hex digits>`.
/// The caller has made the checks of [`read_command_line`](crate::read_command_line).
pub fn run(args: &RunArgs) -> Result<Status, String> {
    let mut scene = resolve_scene(&args.scene)?;
    if let Some(seed) = args.seed {
        scene.seed = seed;
    }
    let ticks = args.ticks.unwrap_or(scene.ticks);

    // Open the outputs first, so a bad path fails before the run rather than after it.
    let mut replay_file = args.record.as_deref().map(OutputFile::create).transpose()?;
    let snapshot_file = args
        .snapshot
        .as_deref()
        .map(OutputFile::create)
        .transpose()?;
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

    let mut runner = match (&args.from_snapshot, &replay_file) {
        (Some(path), _) => Runner::Plain(Box::new(resume(&scene, path)?)),
        (None, Some(file)) => {
            Runner::Recording(Box::new(streaming_recorder(&scene, &args.scene, file)?))
        }
        (None, None) => Runner::Plain(Box::new(simulation(&scene, &args.scene)?)),
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
        let report = runner.step(&mut feed).map_err(|e| {
            let path = args.record.as_deref().unwrap_or(Path::new("--record"));
            write_error(path, &e)
        })?;
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
    if let Some(mut file) = snapshot_file {
        let bytes = encode_snapshot(&world.snapshot(), &snapshot_scene(&scene)?)
            .map_err(|e| format!("{}: cannot encode the snapshot: {e}", file.path().display()))?;
        file.write_all(&bytes)
            .map_err(|e| write_error(file.path(), &e))?;
        file.commit()?;
    }
    if let (Runner::Recording(recorder), Some(mut file)) = (runner, replay_file.take()) {
        recorder
            .finish(&mut file)
            .map_err(|e| write_error(file.path(), &e))?;
        file.commit()?;
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
