//! Writing a film to a directory: PNG frames, an animated GIF and `index.html`.

use std::path::{Path, PathBuf};
use std::sync::mpsc;

use tiny_skia::Pixmap;

use super::draw_list::Frame;
use super::film::Film;
use super::gif::GifWriter;
use super::html::{PageSettings, page};
use super::raster::{Look, encode_png, rasterise};
use super::view::Projection;
use fixstep::replay::{AtomicFile, write_atomic};

/// Name of the animated GIF in the output directory.
pub const GIF_NAME: &str = "animation.gif";

/// Name of the player page in the output directory.
pub const PAGE_NAME: &str = "index.html";

/// Most threads drawing frames at once.
const MAX_WORKERS: usize = 8;

/// The PNG file name of the frame at `tick`: `tick-000060.png`.
pub fn frame_name(tick: u64) -> String {
    format!("tick-{tick:06}.png")
}

/// What [`write_outputs`] wrote.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Written {
    /// The PNG frames, in tick order.
    pub frames: Vec<PathBuf>,
    pub gif: PathBuf,
    pub page: PathBuf,
}

/// Draws every frame of `film` with `settings` and writes them into `dir` (which must
/// exist) as PNG files, one GIF and the player page, each atomically. `title` names the
/// film on the page.
pub fn write_outputs(
    film: &Film,
    title: &str,
    settings: &PageSettings,
    dir: &Path,
) -> Result<Written, String> {
    let projection = Projection::fit(settings.view, &film.bounds, settings.width, settings.height);
    let look = Look {
        palette: film.palette,
        bounds: film.bounds,
        flat: settings.flat,
    };
    let gif_path = dir.join(GIF_NAME);
    let gif_file = AtomicFile::create(&gif_path).map_err(|e| write_error(&gif_path, &e))?;
    let seconds_per_frame = settings.every as f64 / f64::from(film.tick_rate.max(1));
    let mut gif = GifWriter::new(gif_file, settings.width, settings.height, seconds_per_frame)?;
    let mut frames = Vec::with_capacity(film.frames.len());
    draw_in_parallel(film, &projection, &look, |tick, pixmap, png| {
        let path = dir.join(frame_name(tick));
        write_replacing(&path, &png).map_err(|e| write_error(&path, &e))?;
        gif.push(&pixmap)?;
        frames.push(path);
        Ok(())
    })?;
    gif.finish()?
        .commit()
        .map_err(|e| write_error(&gif_path, &e))?;
    let page_path = dir.join(PAGE_NAME);
    write_atomic(&page_path, page(film, title, settings).as_bytes())
        .map_err(|e| write_error(&page_path, &e))?;
    Ok(Written {
        frames,
        gif: gif_path,
        page: page_path,
    })
}

/// A drawn frame: its tick, its pixels and their PNG encoding.
type Drawn = (u64, Pixmap, Vec<u8>);

/// Draws and PNG-encodes the frames of `film` on one worker thread per core (each frame
/// is independent, so the bytes do not depend on the thread count) and hands them to
/// `take` in tick order, on this thread. Stops at the first error.
fn draw_in_parallel(
    film: &Film,
    projection: &Projection,
    look: &Look,
    mut take: impl FnMut(u64, Pixmap, Vec<u8>) -> Result<(), String>,
) -> Result<(), String> {
    let count = film.frames.len();
    let workers = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .clamp(1, MAX_WORKERS);
    std::thread::scope(|scope| {
        // Worker w draws frames w, w + workers, …; frames are taken round-robin from the
        // workers' short queues, so they come in order and no worker runs far ahead.
        let receivers: Vec<mpsc::Receiver<Result<Drawn, String>>> = (0..workers)
            .map(|worker| {
                let (sender, receiver) = mpsc::sync_channel(2);
                scope.spawn(move || {
                    // The worker's previous frame: a scene at rest draws the same figures
                    // again, and then the same pixels and bytes are reused.
                    let mut previous: Option<(&Frame, Pixmap, Vec<u8>)> = None;
                    for frame in film.frames.iter().skip(worker).step_by(workers) {
                        let drawn = match &previous {
                            Some((before, pixmap, png))
                                if before.primitives == frame.primitives =>
                            {
                                Ok((pixmap.clone(), png.clone()))
                            }
                            _ => rasterise(frame, projection, look).and_then(|pixmap| {
                                let png = encode_png(&pixmap)?;
                                Ok((pixmap, png))
                            }),
                        };
                        let drawn = drawn.map(|(pixmap, png)| {
                            previous = Some((frame, pixmap.clone(), png.clone()));
                            (frame.tick, pixmap, png)
                        });
                        if sender.send(drawn).is_err() {
                            return;
                        }
                    }
                });
                receiver
            })
            .collect();
        for index in 0..count {
            let drawn = receivers[index % workers]
                .recv()
                .map_err(|_| "a drawing thread stopped".to_owned())?;
            let (tick, pixmap, png) = drawn?;
            take(tick, pixmap, png)?;
        }
        Ok(())
    })
}

/// Writes `bytes` to a temporary file beside `path` and renames it over `path`, so readers
/// see the old file or the new one, never a part. Unlike
/// [`write_atomic`] it does not sync each file to disk: a
/// render writes hundreds of frames, and syncing each would take most of the time.
fn write_replacing(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let mut name = path.as_os_str().to_owned();
    name.push(format!(".tmp-{}", std::process::id()));
    let temporary = PathBuf::from(name);
    let result = std::fs::write(&temporary, bytes).and_then(|()| std::fs::rename(&temporary, path));
    if result.is_err() {
        let _ = std::fs::remove_file(&temporary);
    }
    result
}

fn write_error(path: &Path, error: &std::io::Error) -> String {
    format!("{}: cannot write: {error}", path.display())
}
