//! The self-contained `index.html`: the film as embedded JSON and a small canvas player
//! in plain JavaScript (`player.js`: play/pause, a tick scrubber, view switching, and an
//! overlay of tick, energy and checksum with an energy plot). No network access needed.

use std::fmt::Write;

use super::colour::BACKGROUND;
use super::draw_list::{Figure, Primitive};
use super::film::Film;
use super::plane_cut::plane_cut;
use super::view::{Projection, View};
use fixstep::world::checksum::hex;

const TEMPLATE: &str = include_str!("player.html");
const PLAYER: &str = include_str!("player.js");

/// How the page is set up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PageSettings {
    /// Canvas size, px.
    pub width: u32,
    pub height: u32,
    /// The view shown first.
    pub view: View,
    /// Ticks between frames.
    pub every: u64,
    /// Flat colours (see [`Look::flat`](super::raster::Look::flat)).
    pub flat: bool,
}

/// The page showing `film`, titled `title`.
pub fn page(film: &Film, title: &str, settings: &PageSettings) -> String {
    let title = escape_html(title);
    TEMPLATE
        .replace("__TITLE__", &title)
        .replace("__PLAYER__", PLAYER)
        .replace("__FILM__", &film_json(film, settings))
}

/// `text` safe inside HTML text.
fn escape_html(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// A number with at most 4 decimals (0.1 mm), without trailing zeros; 0 when not finite.
fn number(out: &mut String, x: f64) {
    if !x.is_finite() {
        out.push('0');
        return;
    }
    let text = format!("{x:.4}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    out.push_str(if text == "-0" || text.is_empty() {
        "0"
    } else {
        text
    });
}

/// The film as JSON (see the item layout in `player.js`).
fn film_json(film: &Film, settings: &PageSettings) -> String {
    let mut out = String::new();
    let rgb = |c: [u8; 3]| u32::from(c[0]) << 16 | u32::from(c[1]) << 8 | u32::from(c[2]);
    let _ = write!(
        out,
        "{{\"width\":{},\"height\":{},\"tickRate\":{},\"every\":{},\"view\":\"{}\",\"flat\":{},\"background\":{},\"views\":{{",
        settings.width,
        settings.height,
        film.tick_rate,
        settings.every,
        settings.view.name(),
        settings.flat,
        rgb(BACKGROUND)
    );
    for (n, view) in View::ALL.into_iter().enumerate() {
        let p = Projection::fit(view, &film.bounds, settings.width, settings.height);
        let [r, u, t] = view.basis();
        let _ = write!(
            out,
            "{}\"{}\":{{\"s\":",
            if n > 0 { "," } else { "" },
            view.name()
        );
        number(&mut out, p.scale);
        out.push_str(",\"cx\":");
        number(&mut out, p.cx);
        out.push_str(",\"cy\":");
        number(&mut out, p.cy);
        for (key, axis) in [("r", r), ("u", u), ("t", t)] {
            let _ = write!(out, ",\"{key}\":[");
            for (k, c) in axis.iter().enumerate() {
                if k > 0 {
                    out.push(',');
                }
                number(&mut out, *c);
            }
            out.push(']');
        }
        out.push('}');
    }
    out.push_str("},\"frames\":[");
    for (n, frame) in film.frames.iter().enumerate() {
        let _ = write!(
            out,
            "{}{{\"tick\":{},\"checksum\":\"{}\",\"energy\":",
            if n > 0 { "," } else { "" },
            frame.tick,
            hex(frame.checksum)
        );
        number(&mut out, frame.energy);
        out.push_str(",\"items\":[");
        let mut first = true;
        for primitive in &frame.primitives {
            let colour = rgb(film.palette.colour(primitive.paint));
            if item(&mut out, primitive, colour, film, first) {
                first = false;
            }
        }
        out.push_str("]}");
    }
    out.push_str("]}");
    out
}

/// Appends one item `[kind, layer, rgb, numbers…]`; false when there is nothing to draw
/// (a plane that misses the film's bounds).
fn item(out: &mut String, primitive: &Primitive, colour: u32, film: &Film, first: bool) -> bool {
    let (kind, numbers): (u8, Vec<[f64; 3]>) = match &primitive.figure {
        Figure::Dot { at } => (0, vec![*at]),
        Figure::Line { a, b } => (1, vec![*a, *b]),
        Figure::Ball { centre, radius } => (2, vec![*centre, [*radius, 0.0, 0.0]]),
        Figure::Capsule { a, b, radius } => (3, vec![*a, *b, [*radius, 0.0, 0.0]]),
        Figure::Cuboid { centre, half_axes } => {
            (4, vec![*centre, half_axes[0], half_axes[1], half_axes[2]])
        }
        Figure::Polygon { corners } => (5, corners.clone()),
        Figure::Plane { normal, offset } => (6, plane_cut(*normal, *offset, &film.bounds)),
    };
    if kind == 6 && numbers.is_empty() {
        return false;
    }
    if !first {
        out.push(',');
    }
    let _ = write!(out, "[{kind},{},{colour}", primitive.layer as u8);
    if kind >= 5 {
        let _ = write!(out, ",{}", numbers.len());
    }
    // Balls and capsules end with their radius alone, not a padded triple.
    let flat: Vec<f64> = numbers.iter().flatten().copied().collect();
    let keep = match kind {
        2 => 4,
        3 => 7,
        _ => flat.len(),
    };
    for x in &flat[..keep] {
        out.push(',');
        number(out, *x);
    }
    out.push(']');
    true
}
