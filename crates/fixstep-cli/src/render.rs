//! `fixstep render`: draw a replay or a scene to PNG frames, a GIF and a player page.

use std::time::Instant;

use super::args::RenderArgs;
use super::output::print_line;
use super::output_folder::OutputFolder;
use super::progress::Progress;
use super::scene_arg::resolve_source;
use super::status::Status;
use super::warnings::{DIVERGENCE_CHECK_EVERY, health_warnings, print_warnings};
use fixstep::world::checksum::hex;
use fixstep_viewer::{BodyColours, Film, GIF_NAME, PAGE_NAME, PageSettings, write_outputs};

/// Most frames a render keeps: every frame's figures stay in memory until the view is
/// fitted to all of them.
const MAX_FRAMES: u64 = 20_000;

/// Most figures (boxes, balls, dots, …) all the frames of a render may hold: about 1.2 GB
/// of memory and a few hundred MB of `index.html`.
const MAX_FIGURES: usize = 10_000_000;

/// Renders the input. The last line printed is `checksum: <16 hex digits>` of the last
/// frame.
pub fn render(args: &RenderArgs) -> Result<Status, String> {
    let source = resolve_source(&args.input)?;
    let ticks = args.ticks.unwrap_or(source.ticks);
    let frames = ticks / args.every + 1 + u64::from(!ticks.is_multiple_of(args.every));
    if frames > MAX_FRAMES {
        return Err(format!(
            "--ticks {ticks} with --every {} gives {frames} frames, more than {MAX_FRAMES}: \
             draw fewer ticks or a frame every more ticks",
            args.every
        ));
    }
    let folder = OutputFolder::create(&args.out)?;
    let mut world = source.build_world(&args.input)?;
    world.enable_divergence_check(DIVERGENCE_CHECK_EVERY);
    print_warnings(None, world.warnings());
    let colours = if args.flat {
        BodyColours::PerBody
    } else {
        BodyColours::Palette
    };
    let started = Instant::now(); // ok-det: wall time is reported, never simulated
    let mut progress = Progress::new(ticks);
    let film = Film::shoot_with_progress(
        world,
        &source.inputs,
        ticks,
        args.every,
        colours,
        MAX_FIGURES,
        |done| progress.update(done),
    );
    progress.finish();
    let film = film.map_err(|e| {
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
    let written = write_outputs(&film, &source.scene.name, &settings, folder.path())?;
    folder.commit()?;
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
    print_warnings(None, health_warnings(&film.health));
    let last = film.frames.last().map_or(0, |f| f.checksum);
    print_line(&format!("checksum: {}", hex(last)))?;
    Ok(Status::Ok)
}
