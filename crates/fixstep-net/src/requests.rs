//! Fulfilling GGRS requests on a world: save, load, advance.

use ggrs::{GgrsRequest, InputStatus};

use super::checksum::checksum128;
use super::config::FixstepConfig;
use super::input::{NetInput, tick_input};
use fixstep::math::Fx;
use fixstep::scene::Scene;
use fixstep::world::World;

/// Carries out `requests` in order on `world`, the world of `scene`:
/// - save: a snapshot of the world and its [`checksum128`], for GGRS to compare;
/// - load: restores a snapshot exactly;
/// - advance: one tick with the players' inputs (and the scene's scripted input), after
///   `before_advance(world, inputs)` has seen the world at the start of the tick, and with
///   `after_advance(world)` called at its end.
///
/// A request for a frame other than the world's tick means GGRS and the world disagree on
/// time: it is an error, never a silent skip.
pub fn fulfil(
    scene: &Scene<Fx>,
    world: &mut World<Fx>,
    requests: Vec<GgrsRequest<FixstepConfig>>,
    mut before_advance: impl FnMut(&World<Fx>, &[NetInput]) -> Result<(), String>,
    mut after_advance: impl FnMut(&mut World<Fx>),
) -> Result<(), String> {
    for request in requests {
        match request {
            GgrsRequest::SaveGameState { cell, frame } => {
                check_frame(world, frame, "save")?;
                cell.save(frame, Some(world.snapshot()), Some(checksum128(world)));
            }
            GgrsRequest::LoadGameState { cell, frame } => {
                let state = cell
                    .load()
                    .ok_or_else(|| format!("GGRS asked to load frame {frame}, never saved"))?;
                world.restore(&state);
                check_frame(world, frame, "load")?;
            }
            GgrsRequest::AdvanceFrame { inputs } => {
                let inputs: Vec<NetInput> = inputs
                    .into_iter()
                    .map(|(input, status)| match status {
                        InputStatus::Disconnected => NetInput::default(),
                        InputStatus::Confirmed | InputStatus::Predicted => input,
                    })
                    .collect();
                before_advance(world, &inputs)?;
                world.step(&tick_input(scene, world.tick(), &inputs));
                after_advance(world);
            }
        }
    }
    Ok(())
}

fn check_frame(world: &World<Fx>, frame: ggrs::Frame, what: &str) -> Result<(), String> {
    if u64::try_from(frame).ok() == Some(world.tick()) {
        Ok(())
    } else {
        Err(format!(
            "GGRS asked to {what} frame {frame} while the world is at tick {}",
            world.tick()
        ))
    }
}
