//! `fixstep run`: simulate a scene with its script, print stage timings and the checksum.

use std::io::Write;
use std::time::Instant;

use super::args::RunArgs;
use super::metrics_csv::MetricsCsv;
use super::output::{eprint_line, print_line, write_error};
use super::progress::Progress;
use super::scene_arg::resolve_scene;
use super::status::Status;
use super::timing_table::timing_table;
use crate::replay::{AtomicFile, DEFAULT_CHECKSUM_EVERY, InputFeed, Recorder};
use crate::world::checksum::hex;

/// Runs the scene. The last line printed is `checksum: <16 hex digits>`.
pub fn run(args: &RunArgs) -> Result<Status, String> {
    let mut scene = resolve_scene(&args.scene)?;
    if let Some(seed) = args.seed {
        scene.seed = seed;
    }
    let ticks = args.ticks.unwrap_or(scene.ticks);

    if let (Some(record), Some(metrics)) = (&args.record, &args.metrics)
        && record == metrics
    {
        return Err(format!(
            "{}: --record and --metrics name the same file",
            record.display()
        ));
    }
    // Open the outputs first, so a bad path fails before the run rather than after it.
    let replay_file = args
        .record
        .as_deref()
        .map(|path| AtomicFile::create(path).map_err(|e| write_error(path, &e)))
        .transpose()?;
    let mut metrics = args
        .metrics
        .as_deref()
        .map(|path| MetricsCsv::create(path, args.every))
        .transpose()?;

    let mut recorder = Recorder::new(&scene, DEFAULT_CHECKSUM_EVERY)
        .map_err(|e| format!("{}: {e}", args.scene))?;
    recorder.enable_timing();
    if let Some(metrics) = &mut metrics {
        metrics.tick(recorder.world())?;
    }
    let mut feed = InputFeed::new(&scene.script);
    let mut progress = Progress::new(ticks);
    let started = Instant::now(); // ok-det: wall time is reported, never simulated
    for done in 1..=ticks {
        let tick = recorder.world().tick();
        recorder.step(feed.at(tick));
        if let Some(metrics) = &mut metrics {
            metrics.tick(recorder.world())?;
        }
        progress.update(done);
    }
    let wall = started.elapsed();
    progress.finish();

    let world = recorder.world();
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
    let saturations = world.saturations_total();
    if let Some(metrics) = metrics {
        metrics.finish(world)?;
    }
    let replay = recorder.finish();
    if let Some(mut file) = replay_file {
        let path = file.path().to_owned();
        let bytes = replay
            .to_bytes()
            .map_err(|e| format!("{}: cannot encode the replay: {e}", path.display()))?;
        file.write_all(&bytes)
            .and_then(|()| file.commit())
            .map_err(|e| write_error(&path, &e))?;
    }
    if saturations > 0 {
        eprint_line(&format!(
            "warning: {saturations} fixed-point saturations (values hit the numeric range)"
        ));
    }
    print_line(&format!("checksum: {}", hex(replay.final_checksum())))?;
    Ok(Status::Ok)
}
