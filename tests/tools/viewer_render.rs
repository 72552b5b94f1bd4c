//! The viewer: every built-in scene draws something, simple scenes show every body, and
//! the same replay gives the same bytes twice.

use std::collections::BTreeSet;

use crate::replay_support::TempPath;
use fixstep::math::Fx;
use fixstep::replay::Replay;
use fixstep::scene::Scene;
use fixstep_scenes::{BUILTIN_SCENES, builtin_scene};
use fixstep_viewer::colour::BACKGROUND;
use fixstep_viewer::{
    BodyColours, Film, Look, PageSettings, Projection, View, encode_png, rasterise, write_outputs,
};
use tiny_skia::Pixmap;

fn scene(name: &str) -> Scene<Fx> {
    builtin_scene(name).unwrap_or_else(|| panic!("no built-in scene {name}"))
}

fn shoot(scene: &Scene<Fx>, ticks: u64, colours: BodyColours) -> Film {
    let world = scene.build().expect("the scene builds");
    Film::shoot(world, &scene.script, ticks, 1, colours, usize::MAX).expect("a film")
}

/// The last frame of `film` drawn in `view` at `width` × `height`.
fn draw_last(film: &Film, view: View, width: u32, height: u32, flat: bool) -> Pixmap {
    let projection = Projection::fit(view, &film.bounds, width, height);
    let look = Look {
        palette: film.palette,
        bounds: film.bounds,
        flat,
    };
    rasterise(film.frames.last().expect("a frame"), &projection, &look).expect("draws")
}

/// The colours of the pixels, apart from the background.
fn colours(pixmap: &Pixmap) -> BTreeSet<[u8; 3]> {
    pixmap
        .pixels()
        .iter()
        .map(|p| [p.red(), p.green(), p.blue()])
        .filter(|c| *c != BACKGROUND)
        .collect()
}

fn drawn_pixels(pixmap: &Pixmap) -> usize {
    pixmap
        .pixels()
        .iter()
        .filter(|p| [p.red(), p.green(), p.blue()] != BACKGROUND)
        .count()
}

#[test]
fn every_builtin_scene_draws_something_in_every_view() {
    for (name, _) in BUILTIN_SCENES {
        let film = shoot(&scene(name), 3, BodyColours::Palette);
        assert_eq!(film.frames.len(), 4, "{name}: frames at ticks 0 to 3");
        for view in View::ALL {
            let pixmap = draw_last(&film, view, 160, 120, false);
            let drawn = drawn_pixels(&pixmap);
            // At least 0.2 % of the picture (38 pixels): a handful of particle dots.
            assert!(drawn > 38, "{name} {view:?}: only {drawn} pixels drawn");
        }
    }
}

#[test]
fn simple_scenes_show_every_body() {
    // In flat mode each body has one colour of its own: the distinct colours of the
    // picture are the visible bodies.
    for (name, view, bodies) in [
        ("stack", View::Iso, 11),   // 10 boxes and the ground
        ("stack", View::Front, 10), // the ground is seen edge on
        ("cradle", View::Front, 6),
        ("spinner", View::Top, 1),
        ("incline", View::Front, 2), // the near slope and block hide the far ones
        ("incline", View::Top, 4),   // 2 slopes side by side, a block on each
    ] {
        let film = shoot(&scene(name), 2, BodyColours::PerBody);
        let pixmap = draw_last(&film, view, 320, 240, true);
        assert_eq!(
            colours(&pixmap).len(),
            bodies,
            "{name} {view:?}: distinct body colours"
        );
    }
}

#[test]
fn the_same_replay_gives_the_same_bytes_twice() {
    let replay = Replay::read(std::path::Path::new(concat!(
        concat!(env!("CARGO_MANIFEST_DIR"), "/../.."),
        "/replays/cradle.replay"
    )))
    .expect("the committed replay reads");
    let settings = PageSettings {
        width: 200,
        height: 150,
        view: View::Iso,
        every: 20,
        flat: false,
    };
    let render = || {
        let world = replay.scene().build().expect("builds");
        let film = Film::shoot(world, replay.inputs(), 60, 20, BodyColours::Palette, 1000)
            .expect("4 frames of 11 figures");
        let dir = TempPath::new("viewer-render");
        std::fs::create_dir_all(dir.path()).expect("a temporary directory");
        let written = write_outputs(&film, "cradle", &settings, dir.path()).expect("writes");
        let mut files: Vec<_> = written.frames.clone();
        files.push(written.gif.clone());
        files.push(written.page.clone());
        let bytes: Vec<Vec<u8>> = files
            .iter()
            .map(|f| std::fs::read(f).expect("written"))
            .collect();
        (written.frames.len(), bytes)
    };
    let (frames, first) = render();
    let (_, second) = render();
    assert_eq!(frames, 4, "ticks 0, 20, 40, 60");
    assert!(first.iter().all(|b| !b.is_empty()));
    assert!(first == second, "a second render differs");
}

#[test]
fn a_film_stops_at_its_figure_limit() {
    // `stack` draws 11 figures a frame: ticks 0 to 4 would need 55.
    let world = scene("stack").build().expect("builds");
    let error = Film::shoot(world, &[], 4, 1, BodyColours::Palette, 50).expect_err("too many");
    assert_eq!((error.tick, error.figures, error.limit), (4, 55, 50));
}

#[test]
fn png_bytes_decode_to_the_drawn_pixels() {
    let film = shoot(&scene("spinner"), 1, BodyColours::Palette);
    let pixmap = draw_last(&film, View::Iso, 64, 48, false);
    let png = encode_png(&pixmap).expect("encodes");
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    let decoder = png::Decoder::new(std::io::Cursor::new(png));
    let mut reader = decoder.read_info().expect("a PNG");
    let mut rgb = vec![0; reader.output_buffer_size().expect("a size")];
    reader.next_frame(&mut rgb).expect("pixels");
    let expected: Vec<u8> = pixmap
        .pixels()
        .iter()
        .flat_map(|p| [p.red(), p.green(), p.blue()])
        .collect();
    assert_eq!(rgb, expected);
}

/// A rope is drawn as a line from anchor to anchor; a ball joint, whose bodies touch, is
/// not drawn.
#[test]
fn ropes_are_drawn_as_lines_between_their_anchors() {
    use fixstep::math::{Real, Vec3};
    use fixstep::rigid::{BodyDesc, JointDesc, JointKind, JointsDesc, RigidDesc, Shape};
    use fixstep_viewer::draw_list::Figure;
    let anchor = BodyDesc::new(
        Shape::Sphere {
            radius: Fx::from_ratio(1, 10),
        },
        Vec3::Y * Fx::from_int(3),
    )
    .fixed();
    let ball = BodyDesc::new(
        Shape::Sphere {
            radius: Fx::from_ratio(1, 5),
        },
        Vec3::Y,
    );
    let mut s = Scene::empty("rope");
    s.rigid = Some(RigidDesc {
        bodies: vec![anchor, ball],
        solver: Default::default(),
        ..RigidDesc::default()
    });
    let rope = JointDesc::new(
        JointKind::Rope { max_length: None },
        0,
        1,
        Vec3::Y * Fx::from_int(3),
    )
    .with_anchor_b(Vec3::Y);
    let ball_joint = JointDesc::new(JointKind::Ball, 0, 1, Vec3::Y * Fx::from_int(3));
    for (joint, lines) in [(rope, 1), (ball_joint, 0)] {
        s.joints = Some(JointsDesc::new(vec![joint]));
        let film = shoot(&s, 1, BodyColours::Palette);
        let frame = film.frames.last().expect("a frame");
        let drawn: Vec<&Figure> = frame
            .primitives
            .iter()
            .map(|p| &p.figure)
            .filter(|f| matches!(f, Figure::Line { .. }))
            .collect();
        assert_eq!(drawn.len(), lines, "{drawn:?}");
        if let Some(Figure::Line { a, b }) = drawn.first() {
            assert!(
                (a[1] - 3.0).abs() < 1e-6 && (b[1] - 1.0).abs() < 0.01,
                "{a:?} {b:?}"
            );
        }
    }
}
