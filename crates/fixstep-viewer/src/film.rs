//! A film: the frames of a run, every K ticks, with what they share (bounds and colours).

use super::colour::Palette;
use super::draw_fluid::draw_fluid;
use super::draw_joints::draw_joints;
use super::draw_list::{Bounds, Frame, Primitive};
use super::draw_particles::draw_particles;
use super::draw_rigid::{BodyColours, draw_rigid};
use super::draw_soft::draw_soft;
use super::draw_trails::Trails;
use super::draw_water::draw_water;
use fixstep::math::{Fx, Real};
use fixstep::replay::InputFeed;
use fixstep::world::{Health, TickInput, World};

/// Fraction of the scene's largest side added around it, so the ground shows.
const PADDING: f64 = 0.06;

/// The drawn frames of a run.
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    /// Frames at ticks 0, K, 2K, … and the last tick.
    pub frames: Vec<Frame>,
    /// The padded box around every figure of every frame: what each view is fitted to.
    pub bounds: Bounds,
    /// The colours of the whole film.
    pub palette: Palette,
    /// Ticks per simulated second.
    pub tick_rate: u32,
    /// What the run had to warn about up to the last frame ([`World::health`]): nothing
    /// for a film made from frames.
    pub health: Health,
}

/// A film stopped because its frames would hold too many figures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TooManyFigures {
    /// The tick of the frame that went over the limit.
    pub tick: u64,
    /// Figures in the frames up to and including that one.
    pub figures: usize,
    /// The limit.
    pub limit: usize,
}

/// The frame of the world's current tick.
pub fn capture<R: Real>(world: &World<R>, colours: BodyColours) -> Frame {
    let mut primitives: Vec<Primitive> = Vec::new();
    if let Some(rigid) = world.rigid() {
        draw_rigid(rigid, colours, &mut primitives);
        draw_joints(rigid, &mut primitives);
    }
    if let Some(particles) = world.particles() {
        draw_particles(particles, &mut primitives);
    }
    if let Some(soft) = world.soft() {
        draw_soft(soft, &mut primitives);
    }
    if let Some(fluid) = world.fluid() {
        draw_fluid(fluid, &mut primitives);
    }
    if let Some(water) = world.water() {
        draw_water(water, &mut primitives);
    }
    Frame {
        tick: world.tick(),
        energy: world.metrics().total_energy(),
        checksum: world.checksum().total,
        primitives,
    }
}

impl Film {
    /// Steps `world` `ticks` times with `inputs` (sorted by tick, as a replay's or a
    /// scene's script), capturing a frame every `every` ticks (at least 1) and after the
    /// last tick; particles leave trails (see [`Trails`]). Every frame is held until the film is complete, so the film stops with
    /// an error once its frames hold more than `max_figures` figures in all.
    pub fn shoot(
        world: World<Fx>,
        inputs: &[TickInput<Fx>],
        ticks: u64,
        every: u64,
        colours: BodyColours,
        max_figures: usize,
    ) -> Result<Film, TooManyFigures> {
        Self::shoot_with_progress(world, inputs, ticks, every, colours, max_figures, |_| {})
    }

    /// [`Film::shoot`], calling `on_tick` with the number of ticks simulated after each
    /// tick (to show progress).
    pub fn shoot_with_progress(
        mut world: World<Fx>,
        inputs: &[TickInput<Fx>],
        ticks: u64,
        every: u64,
        colours: BodyColours,
        max_figures: usize,
        mut on_tick: impl FnMut(u64),
    ) -> Result<Film, TooManyFigures> {
        let every = every.max(1);
        let mut feed = InputFeed::new(inputs);
        let mut frames = Vec::new();
        let mut figures = 0;
        let mut keep = |frame: Frame| {
            figures += frame.primitives.len();
            if figures > max_figures {
                return Err(TooManyFigures {
                    tick: frame.tick,
                    figures,
                    limit: max_figures,
                });
            }
            frames.push(frame);
            Ok(())
        };
        let mut trails = Trails::default();
        let shot = |world: &World<Fx>, trails: &Trails| {
            let mut frame = capture(world, colours);
            trails.draw(&mut frame.primitives);
            frame
        };
        if let Some(particles) = world.particles() {
            trails.record(particles);
        }
        keep(shot(&world, &trails))?;
        for done in 1..=ticks {
            let tick = world.tick();
            world.step(feed.at(tick));
            if let Some(particles) = world.particles() {
                trails.record(particles);
            }
            if done % every == 0 || done == ticks {
                keep(shot(&world, &trails))?;
            }
            on_tick(done);
        }
        Ok(Film {
            health: world.health(),
            ..Film::from_frames(frames, world.settings().tick_rate)
        })
    }

    /// The film of `frames`, with their shared bounds and colours.
    pub fn from_frames(frames: Vec<Frame>, tick_rate: u32) -> Film {
        Film {
            bounds: Bounds::of_frames(&frames).padded(PADDING),
            palette: Palette::of_frames(&frames),
            frames,
            tick_rate,
            health: Health::default(),
        }
    }
}
