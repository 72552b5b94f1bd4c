//! Soft bodies (cloth, rope, jelly) as the lines of their mesh edges, each body in its
//! own colour.

use super::colour::body_colour;
use super::draw_list::{Figure, Layer, Paint, Primitive};
use fixstep::math::Real;
use fixstep::soft::SoftSystem;

/// Appends a line per edge (XPBD distance rows, then springs, in row order), coloured by
/// the body its first vertex belongs to.
pub fn draw_soft<R: Real>(soft: &SoftSystem<R>, out: &mut Vec<Primitive>) {
    let positions = soft.positions();
    let body_of = |vertex: usize| {
        (0..soft.body_count())
            .find(|&b| soft.body_vertices(b).is_some_and(|r| r.contains(&vertex)))
            .unwrap_or(0)
    };
    let mut body = 0;
    for (a, b) in soft.edges() {
        let (a, b) = (a as usize, b as usize);
        let (Some(pa), Some(pb)) = (positions.get(a), positions.get(b)) else {
            continue;
        };
        if !soft.body_vertices(body).is_some_and(|r| r.contains(&a)) {
            body = body_of(a);
        }
        out.push(Primitive {
            figure: Figure::Line {
                a: pa.to_f64(),
                b: pb.to_f64(),
            },
            paint: Paint::Rgb(body_colour(body + 3, false)),
            layer: Layer::Moving,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use fixstep::math::Fx;
    use fixstep_scenes::builtin_scene;

    #[test]
    fn a_line_per_edge_of_the_cloth() {
        let scene = builtin_scene::<Fx>("cloth").expect("built-in");
        let world = scene.build().expect("builds");
        let soft = world.soft().expect("the cloth scene has a soft body");
        let mut out = Vec::new();
        draw_soft(soft, &mut out);
        assert_eq!(out.len(), soft.edges().count());
        // 32 × 32 vertices: 2·32·31 edges along the grid and 31² diagonals.
        assert_eq!(out.len(), 2 * 32 * 31 + 31 * 31);
        assert!(out.iter().all(|p| matches!(p.figure, Figure::Line { .. })));
    }
}
