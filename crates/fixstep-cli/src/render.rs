//! `fixstep render`: draw a replay or a scene to PNG frames, a GIF and a player page.

use std::path::Path;
use std::time::Instant;

use super::args::RenderArgs;
use super::output::print_line;
use super::scene_arg::resolve_scene;
use super::status::Status;
use fixstep::math::Fx;
use fixstep::replay::Replay;
use fixstep::scene::Scene;
use fixstep::world::TickInput;
use fixstep::world::checksum::hex;
use fixstep_viewer::{BodyColours, Film, GIF_NAME, PAGE_NAME, PageSettings, write_outputs};

/// Most frames a render keeps: every frame's figures stay in memory until the view is
/// fitted to all of them.
const MAX_FRAMES: u64 = 20_000;

/// Most figures (boxes, balls, dots, …) all the frames of a render may hold: about 1.2 GB
/// of memory and a few hundred MB of `index.html`.
const MAX_FIGURES: usize = 10_000_000;

/// What to simulate: a scene, its inputs and how many ticks by default.
struct Source {
    scene: Scene<Fx>,
    inputs: Vec<TickInput<Fx>>,
    ticks: u64,
}

/// The replay file or scene `input` names. A name ending in `.replay` is a replay.
fn source(input: &str) -> Result<Source, String> {
    if input.ends_with(".replay") {
        let replay = Replay::read(Path::new(input)).map_err(|e| e.to_string())?;
        return Ok(Source {
            scene: replay.scene().clone(),
            inputs: replay.inputs().to_vec(),
            ticks: replay.ticks(),
        });
    }
    let scene = resolve_scene(input)?;
    Ok(Source {
        inputs: scene.script.clone(),
        ticks: scene.ticks,
        scene,
    })
}

/// Renders the input. The last line printed is `checksum: <16 hex digits>` of the last
/// frame.
pub fn render(args: &RenderArgs) -> Result<Status, String> {
    let source = source(&args.input)?;
    let ticks = args.ticks.unwrap_or(source.ticks);
    let frames = ticks / args.every + 1 + u64::from(!ticks.is_multiple_of(args.every));
    if frames > MAX_FRAMES {
        return Err(format!(
            "--ticks {ticks} with --every {} gives {frames} frames, more than {MAX_FRAMES}: \
             draw fewer ticks or a frame every more ticks",
            args.every
        ));
    }
    std::fs::create_dir_all(&args.out)
        .map_err(|e| format!("{}: cannot create the directory: {e}", args.out.display()))?;
    let world = source
        .scene
        .build()
        .and_then(|world| {
            if let Some(particles) = world.particles() {
                particles.check_user_forces()?;
            }
            Ok(world)
        })
        .map_err(|e| format!("{}: {e}", args.input))?;
    let colours = if args.flat {
        BodyColours::PerBody
    } else {
        BodyColours::Palette
    };
    let started = Instant::now(); // ok-det: wall time is reported, never simulated
    let film = Film::shoot(
        world,
        &source.inputs,
        ticks,
        args.every,
        colours,
        MAX_FIGURES,
    )
    .map_err(|e| {
        format!(
            "{}: the frames up to tick {} hold {} figures, more than {}: draw fewer ticks \
             (--ticks) or a frame every more ticks (--every)",
            args.input, e.tick, e.figures, e.limit
        )
    })?;
    let (width, height) = args.size;
    let settings = PageSettings {
        width,
        height,
        view: args.view,
        every: args.every,
        flat: args.flat,
    };
    let written = write_outputs(&film, &source.scene.name, &settings, &args.out)?;
    let wall = started.elapsed();
    let out = args.out.display();
    print_line(&format!(
        "{}: {ticks} ticks, {} frames ({} view, {width}x{height}), {:.1} ms wall",
        source.scene.name,
        written.frames.len(),
        args.view.name(),
        wall.as_secs_f64() * 1e3
    ))?;
    print_line(&format!(
        "wrote {out}/tick-*.png, {out}/{GIF_NAME}, {out}/{PAGE_NAME}"
    ))?;
    let last = film.frames.last().map_or(0, |f| f.checksum);
    print_line(&format!("checksum: {}", hex(last)))?;
    Ok(Status::Ok)
}
