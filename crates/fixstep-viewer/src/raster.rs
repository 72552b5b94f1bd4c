//! Drawing a frame into pixels with tiny-skia (pure Rust), and encoding PNG.
//!
//! Painter's algorithm: figures are painted by layer, then from far to near (depth of
//! their centre along the view's `toward` axis), ties in list order. Boxes show their
//! faces that look toward the viewer, lit by a fixed light; balls get a radial highlight;
//! everything has a thin darker outline. In flat mode ([`Look::flat`]) there is no
//! shading, outline or anti-aliasing, so each body is exactly one colour.

use tiny_skia::{
    Color, FillRule, GradientStop, LineCap, Paint, Path, PathBuilder, Pixmap, Point,
    RadialGradient, SpreadMode, Stroke, Transform,
};

use super::colour::{BACKGROUND, Palette, shade};
use super::draw_list::{Bounds, Figure, Frame, Primitive};
use super::geometry::{P3, add, cross, dot, normalize, scale, sub};
use super::plane_cut::plane_cut;
use super::view::Projection;

/// Direction toward the light, in world space (from above, front right).
const LIGHT: P3 = [0.3, 0.85, 0.45];

/// How a film is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Look {
    /// The film's colours.
    pub palette: Palette,
    /// The box planes are cut to.
    pub bounds: Bounds,
    /// Flat colours: no shading, outline or anti-aliasing.
    pub flat: bool,
}

/// Draws `frame` as seen through `projection`.
pub fn rasterise(frame: &Frame, projection: &Projection, look: &Look) -> Result<Pixmap, String> {
    let mut pixmap = Pixmap::new(projection.width, projection.height).ok_or_else(|| {
        format!(
            "cannot make a {}x{} picture",
            projection.width, projection.height
        )
    })?;
    let [r, g, b] = BACKGROUND;
    pixmap.fill(Color::from_rgba8(r, g, b, 255));
    let mut painter = Painter {
        pixmap: &mut pixmap,
        projection,
        look,
        unit: f64::from(projection.width.min(projection.height)),
    };
    for primitive in painting_order(frame, projection) {
        painter.primitive(primitive);
    }
    Ok(pixmap)
}

/// The primitives of `frame` in the order to paint them.
fn painting_order<'a>(frame: &'a Frame, projection: &Projection) -> Vec<&'a Primitive> {
    let mut order: Vec<(usize, f64)> = frame
        .primitives
        .iter()
        .enumerate()
        .map(|(i, p)| (i, centre_depth(&p.figure, projection)))
        .collect();
    order.sort_by(|(i, a), (j, b)| {
        let (pi, pj) = (&frame.primitives[*i], &frame.primitives[*j]);
        pi.layer.cmp(&pj.layer).then(a.total_cmp(b)).then(i.cmp(j))
    });
    order
        .into_iter()
        .map(|(i, _)| &frame.primitives[i])
        .collect()
}

/// How near the figure's centre is to the viewer, m.
fn centre_depth(figure: &Figure, projection: &Projection) -> f64 {
    match figure {
        Figure::Dot { at } => projection.depth(*at),
        Figure::Line { a, b } | Figure::Capsule { a, b, .. } => {
            projection.depth(scale(add(*a, *b), 0.5))
        }
        Figure::Ball { centre, .. } | Figure::Cuboid { centre, .. } => projection.depth(*centre),
        Figure::Polygon { corners } => {
            corners.iter().map(|c| projection.depth(*c)).sum::<f64>() / corners.len().max(1) as f64
        }
        Figure::Plane { .. } => f64::NEG_INFINITY,
    }
}

/// The visible faces of a box, far to near: (corners in order, outward unit normal).
pub fn visible_faces(centre: P3, half_axes: &[P3; 3], toward: P3) -> Vec<([P3; 4], P3)> {
    let mut faces = Vec::with_capacity(3);
    for k in 0..3 {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        for sign in [1.0, -1.0] {
            let normal = normalize(scale(half_axes[k], sign));
            if dot(normal, toward) <= 1e-9 {
                continue;
            }
            let middle = add(centre, scale(half_axes[k], sign));
            let (u, v) = (half_axes[i], half_axes[j]);
            faces.push((
                [
                    add(add(middle, u), v),
                    add(sub(middle, u), v),
                    sub(sub(middle, u), v),
                    sub(add(middle, u), v),
                ],
                normal,
            ));
        }
    }
    faces
}

/// Light falling on a surface of unit normal `normal`: ambient 0.55 plus diffuse 0.45.
fn lighting(normal: P3) -> f64 {
    0.55 + 0.45 * dot(normal, normalize(LIGHT)).max(0.0)
}

struct Painter<'a> {
    pixmap: &'a mut Pixmap,
    projection: &'a Projection,
    look: &'a Look,
    /// The picture's smaller side, px: dot and line sizes scale with it.
    unit: f64,
}

impl Painter<'_> {
    fn primitive(&mut self, primitive: &Primitive) {
        let colour = self.look.palette.colour(primitive.paint);
        let flat = self.look.flat;
        match &primitive.figure {
            Figure::Dot { at } => {
                let radius = (self.unit / 220.0).max(1.5);
                self.disc(*at, radius, colour);
            }
            Figure::Line { a, b } => {
                let width = (self.unit / 400.0).max(1.0);
                self.segment(*a, *b, width, colour);
            }
            Figure::Ball { centre, radius } => self.ball(*centre, *radius, colour),
            Figure::Capsule { a, b, radius } => {
                let width = 2.0 * radius * self.projection.scale;
                if !flat {
                    self.segment(*a, *b, width + 2.0, shade(colour, 0.55));
                }
                self.segment(*a, *b, width.max(1.0), colour);
            }
            Figure::Cuboid { centre, half_axes } => {
                let toward = self.projection.view.basis()[2];
                for (corners, normal) in visible_faces(*centre, half_axes, toward) {
                    let light = if flat { 1.0 } else { lighting(normal) };
                    self.polygon(&corners, shade(colour, light));
                }
            }
            Figure::Polygon { corners } => {
                let normal = match corners.as_slice() {
                    [a, b, c, ..] => normalize(cross(sub(*b, *a), sub(*c, *a))),
                    _ => [0.0, 1.0, 0.0],
                };
                let light = if flat {
                    1.0
                } else {
                    0.55 + 0.45 * dot(normal, normalize(LIGHT)).abs()
                };
                self.polygon(corners, shade(colour, light));
            }
            Figure::Plane { normal, offset } => {
                let corners = plane_cut(*normal, *offset, &self.look.bounds);
                self.polygon(&corners, colour);
            }
        }
    }

    fn paint(&self, colour: [u8; 3]) -> Paint<'static> {
        let mut paint = Paint::default();
        paint.set_color_rgba8(colour[0], colour[1], colour[2], 255);
        paint.anti_alias = !self.look.flat;
        paint
    }

    fn point(&self, p: P3) -> (f32, f32) {
        let (x, y) = self.projection.screen(p);
        (x as f32, y as f32)
    }

    /// A filled polygon with a thin darker outline.
    fn polygon(&mut self, corners: &[P3], colour: [u8; 3]) {
        let mut builder = PathBuilder::new();
        for (n, corner) in corners.iter().enumerate() {
            let (x, y) = self.point(*corner);
            if n == 0 {
                builder.move_to(x, y);
            } else {
                builder.line_to(x, y);
            }
        }
        builder.close();
        let Some(path) = builder.finish() else {
            return;
        };
        let paint = self.paint(colour);
        self.fill(&path, &paint);
        if !self.look.flat {
            self.outline(&path, shade(colour, 0.6));
        }
    }

    /// Fills `path` with `paint` (non-zero winding).
    fn fill(&mut self, path: &Path, paint: &Paint<'_>) {
        self.pixmap
            .fill_path(path, paint, FillRule::Winding, Transform::identity(), None);
    }

    fn outline(&mut self, path: &Path, colour: [u8; 3]) {
        let stroke = Stroke {
            width: 1.0,
            ..Stroke::default()
        };
        let paint = self.paint(colour);
        self.pixmap
            .stroke_path(path, &paint, &stroke, Transform::identity(), None);
    }

    /// A round-capped segment `width` px wide; a dot (at least 1 px in radius) when it
    /// projects to a point.
    fn segment(&mut self, a: P3, b: P3, width: f64, colour: [u8; 3]) {
        let ((ax, ay), (bx, by)) = (self.point(a), self.point(b));
        if (ax - bx).hypot(ay - by) < 0.25 {
            self.circle(ax, ay, (width as f32 / 2.0).max(1.0), colour);
            return;
        }
        let mut builder = PathBuilder::new();
        builder.move_to(ax, ay);
        builder.line_to(bx, by);
        let Some(path) = builder.finish() else {
            return;
        };
        let stroke = Stroke {
            width: width as f32,
            line_cap: LineCap::Round,
            ..Stroke::default()
        };
        let paint = self.paint(colour);
        self.pixmap
            .stroke_path(&path, &paint, &stroke, Transform::identity(), None);
    }

    /// A flat disc of `radius` px at world point `at`.
    fn disc(&mut self, at: P3, radius: f64, colour: [u8; 3]) {
        let (x, y) = self.point(at);
        self.circle(x, y, radius as f32, colour);
    }

    fn circle(&mut self, x: f32, y: f32, radius: f32, colour: [u8; 3]) {
        if let Some(path) = PathBuilder::from_circle(x, y, radius.max(0.5)) {
            let paint = self.paint(colour);
            self.fill(&path, &paint);
        }
    }

    /// A ball: a disc lit from the upper left by a radial gradient, with an outline.
    fn ball(&mut self, centre: P3, radius: f64, colour: [u8; 3]) {
        let (x, y) = self.point(centre);
        let r = ((radius * self.projection.scale) as f32).max(0.75);
        let Some(path) = PathBuilder::from_circle(x, y, r) else {
            return;
        };
        let mut paint = self.paint(colour);
        if !self.look.flat {
            let highlight = colour.map(|c| ((u16::from(c) + 2 * 255) / 3) as u8);
            let rim = shade(colour, 0.62);
            let to_color = |[r, g, b]: [u8; 3]| Color::from_rgba8(r, g, b, 255);
            if let Some(shader) = RadialGradient::new(
                Point::from_xy(x - 0.35 * r, y - 0.35 * r),
                0.0,
                Point::from_xy(x, y),
                r,
                vec![
                    GradientStop::new(0.0, to_color(highlight)),
                    GradientStop::new(0.45, to_color(colour)),
                    GradientStop::new(1.0, to_color(rim)),
                ],
                SpreadMode::Pad,
                Transform::identity(),
            ) {
                paint.shader = shader;
            }
        }
        self.fill(&path, &paint);
        if !self.look.flat {
            self.outline(&path, shade(colour, 0.5));
        }
    }
}

/// The picture as PNG bytes: 8-bit RGB (the pictures are opaque), fast compression, and
/// no timestamps or other metadata, so the same pixels always give the same bytes.
pub fn encode_png(pixmap: &Pixmap) -> Result<Vec<u8>, String> {
    let rgb: Vec<u8> = pixmap
        .pixels()
        .iter()
        .flat_map(|p| [p.red(), p.green(), p.blue()])
        .collect();
    let mut bytes = Vec::new();
    let mut encoder = png::Encoder::new(&mut bytes, pixmap.width(), pixmap.height());
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_compression(png::Compression::Fast);
    let fail = |e: png::EncodingError| format!("cannot encode a PNG: {e}");
    let mut writer = encoder.write_header().map_err(fail)?;
    writer.write_image_data(&rgb).map_err(fail)?;
    writer.finish().map_err(fail)?;
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::colour::Palette;
    use crate::draw_list::{Layer, Paint};
    use crate::view::View;

    fn frame(figure: Figure) -> Frame {
        Frame {
            tick: 0,
            energy: 0.0,
            checksum: 0,
            primitives: vec![Primitive {
                figure,
                paint: Paint::Rgb([200, 40, 40]),
                layer: Layer::Moving,
            }],
        }
    }

    /// Pixels of `frame` that are not background, drawn flat in the front view of the
    /// box from (−1, −1, −1) to (1, 1, 1) at 40 × 40.
    fn coverage(frame: &Frame) -> usize {
        let bounds = Bounds {
            min: [-1.0; 3],
            max: [1.0; 3],
        };
        let look = Look {
            palette: Palette { top_speed: 1.0 },
            bounds,
            flat: true,
        };
        let projection = Projection::fit(View::Front, &bounds, 40, 40);
        let pixmap = rasterise(frame, &projection, &look).expect("draws");
        pixmap
            .pixels()
            .iter()
            .filter(|p| [p.red(), p.green(), p.blue()] == [200, 40, 40])
            .count()
    }

    #[test]
    fn a_polygon_fills_its_projected_area() {
        // A square of half the view's side covers about a quarter of the fitted area.
        let square = Figure::Polygon {
            corners: vec![
                [-0.5, -0.5, 0.0],
                [0.5, -0.5, 0.0],
                [0.5, 0.5, 0.0],
                [-0.5, 0.5, 0.0],
            ],
        };
        let covered = coverage(&frame(square)) as f64;
        let full = coverage(&frame(Figure::Cuboid {
            centre: [0.0; 3],
            half_axes: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        })) as f64;
        assert!((covered / full - 0.25).abs() < 0.05, "{covered} of {full}");
    }

    #[test]
    fn a_line_and_a_capsule_seen_end_on_still_show() {
        let along_z = |figure| coverage(&frame(figure));
        assert!(
            along_z(Figure::Line {
                a: [0.0, 0.0, -1.0],
                b: [0.0, 0.0, 1.0],
            }) > 0
        );
        assert!(
            along_z(Figure::Capsule {
                a: [0.0, 0.0, -1.0],
                b: [0.0, 0.0, 1.0],
                radius: 0.2,
            }) > 0
        );
    }
}
