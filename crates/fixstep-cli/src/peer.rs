//! `fixstep peer`: one peer of a networked session (see [`fixstep_net`]).

use std::io::Write;
use std::time::{Duration, Instant};

use super::args::PeerArgs;
use super::file_identity::{NamedFile, refuse_shared_files};
use super::output::{print_line, write_error};
use super::output_file::OutputFile;
use super::scene_arg::{resolve_scene, scene_file};
use super::status::Status;
use fixstep::world::checksum::hex;
use fixstep_net::{
    Bot, DesyncReport, InputSource, Mode, PeerOptions, PeerOutcome, build_world, part_byte,
    read_script, run_peer, total,
};

/// Runs the peer. On success the last line printed is `checksum: <16 hex digits>`, the
/// checksum of the confirmed world after the last tick; on a desync, one line names the
/// frame, both checksums and the part that differs, and the status is [`Status::Desync`].
/// The caller has made the checks of [`read_command_line`](crate::read_command_line).
pub fn peer(args: &PeerArgs) -> Result<Status, String> {
    let scene = resolve_scene(&args.scene)?;
    let ticks = args.ticks.unwrap_or(scene.ticks);
    let mode = if args.rollback {
        Mode::Rollback
    } else {
        Mode::Lockstep
    };
    let inputs = match &args.inputs {
        Some(path) => InputSource::Script(read_script(path)?),
        None => {
            let seed = args.bot.unwrap_or(args.player_index as u64);
            InputSource::Bot(Bot::new(seed, &build_world(&scene)?))
        }
    };
    // Open the replay first, so that a bad path fails before the session.
    let replay_file = args.record.as_deref().map(OutputFile::create).transpose()?;
    let name = scene.name.clone();
    let started = Instant::now(); // ok-det: wall time is reported, never simulated
    let outcome = run_peer(PeerOptions {
        scene,
        local_port: args.local_port,
        remotes: args.remotes.clone(),
        player: args.player_index,
        ticks,
        mode,
        inputs,
        desync_every: args.desync_every,
        nudge_at: args.nudge_at,
        timeout: Duration::from_secs(args.timeout),
    })?;
    match outcome {
        PeerOutcome::Desync(report) => {
            print_line(&desync_line(&report))?;
            Ok(Status::Desync)
        }
        PeerOutcome::Finished(replay) => {
            let mode = match mode {
                Mode::Lockstep => "lockstep",
                Mode::Rollback => "rollback",
            };
            print_line(&format!(
                "{name}: {ticks} ticks, {mode}, player {} of {}, {:.1} ms wall",
                args.player_index,
                args.remotes.len() + 1,
                started.elapsed().as_secs_f64() * 1e3
            ))?;
            let checksum = replay.final_checksum();
            if let Some(mut file) = replay_file {
                let path = file.path().to_owned();
                let bytes = replay
                    .to_bytes()
                    .map_err(|e| format!("{}: cannot encode the replay: {e}", path.display()))?;
                file.write_all(&bytes).map_err(|e| write_error(&path, &e))?;
                file.commit()?;
            }
            print_line(&format!("checksum: {}", hex(checksum)))?;
            Ok(Status::Ok)
        }
    }
}

/// Refuses a `--record` file that is also the scene file or the `--inputs` file.
pub fn refuse_clashes(args: &PeerArgs) -> Result<(), String> {
    let mut inputs = Vec::new();
    if let Some(path) = scene_file(&args.scene) {
        inputs.push(NamedFile::new("the scene file", path));
    }
    if let Some(path) = &args.inputs {
        inputs.push(NamedFile::new("--inputs", path));
    }
    let outputs: Vec<NamedFile> = args
        .record
        .iter()
        .map(|path| NamedFile::new("--record", path))
        .collect();
    refuse_shared_files(&inputs, &outputs)
}

/// `desync at frame F with peer ADDR: local checksum L, remote checksum R; sub-checksum
/// PART differs (local ab, remote cd)`.
fn desync_line(report: &DesyncReport) -> String {
    let part = match report.part {
        Some(part) => format!(
            "sub-checksum {part} differs (digest byte local {:02x}, remote {:02x})",
            part_byte(report.local, part),
            part_byte(report.remote, part)
        ),
        None => "no sub-checksum digest differs".to_owned(),
    };
    format!(
        "desync at frame {} with peer {}: local checksum {}, remote checksum {}; {part}",
        report.frame,
        report.remote_addr,
        hex(total(report.local)),
        hex(total(report.remote))
    )
}
