//! The water surface as a wire mesh: lines along x and along z through every few cells'
//! centres, at their surface heights.

use super::colour::WATER;
use super::draw_list::{Figure, Layer, Paint, Primitive};
use fixstep::math::Real;
use fixstep::water::WaterSystem;

/// The most lines drawn along each axis: a larger grid is drawn through every k-th cell.
const MAX_LINES: usize = 24;

/// Appends the surface's wire mesh: lines through every k-th row and column of cell
/// centres (k chosen so that at most [`MAX_LINES`] run each way, the last row and column
/// always drawn), each a polyline over the same cells.
pub fn draw_water<R: Real>(water: &WaterSystem<R>, out: &mut Vec<Primitive>) {
    let s = water.settings();
    let (n, m) = (s.columns as usize, s.rows as usize);
    let (size, origin) = (s.cell_size.to_f64(), s.origin.to_f64());
    let heights = water.heights();
    let point = |i: usize, k: usize| {
        [
            origin[0] + (i as f64 + 0.5) * size,
            origin[1] + heights[i + n * k].to_f64(),
            origin[2] + (k as f64 + 0.5) * size,
        ]
    };
    let picks = |count: usize| {
        let stride = count.div_ceil(MAX_LINES).max(1);
        let mut picked: Vec<usize> = (0..count).step_by(stride).collect();
        if picked.last() != Some(&(count - 1)) {
            picked.push(count - 1);
        }
        picked
    };
    let (columns, rows) = (picks(n), picks(m));
    let mut line = |a: [f64; 3], b: [f64; 3]| {
        out.push(Primitive {
            figure: Figure::Line { a, b },
            paint: Paint::Rgb(WATER),
            layer: Layer::Scenery,
        });
    };
    for &k in &rows {
        for w in columns.windows(2) {
            line(point(w[0], k), point(w[1], k));
        }
    }
    for &i in &columns {
        for w in rows.windows(2) {
            line(point(i, w[0]), point(i, w[1]));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use fixstep::math::Fx;
    use fixstep_scenes::builtin_scene;

    #[test]
    fn the_pond_is_a_wire_mesh_of_at_most_24_lines_each_way() {
        let scene = builtin_scene::<Fx>("pond").expect("built-in");
        let world = scene.build().expect("builds");
        let mut out = Vec::new();
        draw_water(world.water().expect("water"), &mut out);
        // 64 cells, every third: 22 rows of 21 segments, and as many columns.
        assert_eq!(out.len(), 2 * 22 * 21);
        assert!(out.iter().all(|p| matches!(p.figure, Figure::Line { .. })));
    }
}
