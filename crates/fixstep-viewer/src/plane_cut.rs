//! The visible part of an infinite plane: its cut through the film's bounding box.

use super::draw_list::Bounds;
use super::geometry::{P3, add, cross, dot, normalize, scale, sub};

/// The convex polygon where the plane n · x = `offset` (n unit) crosses `bounds`, corners
/// in order around it; empty when the plane misses the box.
///
/// Each of the box's 12 edges p + t (q − p), t ∈ [0, 1], crosses the plane at
/// t = (offset − n · p) / (n · (q − p)); the crossings are then ordered by their angle
/// about their centroid, measured in a basis (u, n × u) of the plane.
pub fn plane_cut(normal: P3, offset: f64, bounds: &Bounds) -> Vec<P3> {
    let corners = bounds.corners();
    let mut points: Vec<P3> = Vec::new();
    for i in 0..8 {
        for bit in [1, 2, 4] {
            let j = i | bit;
            if j == i {
                continue;
            }
            let (p, q) = (corners[i], corners[j]);
            let along = dot(normal, sub(q, p));
            if along.abs() < 1e-12 {
                continue;
            }
            let t = (offset - dot(normal, p)) / along;
            if (0.0..=1.0).contains(&t) {
                let x = add(p, scale(sub(q, p), t));
                if !points.iter().any(|y| dot(sub(*y, x), sub(*y, x)) < 1e-18) {
                    points.push(x);
                }
            }
        }
    }
    if points.len() < 3 {
        return Vec::new();
    }
    let centroid = scale(
        points.iter().fold([0.0; 3], |sum, p| add(sum, *p)),
        1.0 / points.len() as f64,
    );
    let helper = if normal[0].abs() < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let u = normalize(cross(normal, helper));
    let v = cross(normal, u);
    let angle = |p: &P3| {
        let d = sub(*p, centroid);
        dot(d, v).atan2(dot(d, u))
    };
    points.sort_by(|a, b| angle(a).total_cmp(&angle(b)));
    points
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ground_cuts_a_box_in_a_rectangle() {
        let bounds = Bounds {
            min: [-2.0, -1.0, -3.0],
            max: [2.0, 5.0, 3.0],
        };
        let cut = plane_cut([0.0, 1.0, 0.0], 0.0, &bounds);
        assert_eq!(cut.len(), 4);
        assert!(cut.iter().all(|p| p[1].abs() < 1e-12));
    }

    #[test]
    fn a_plane_outside_the_box_shows_nothing() {
        let bounds = Bounds::UNIT;
        assert!(plane_cut([0.0, 1.0, 0.0], 10.0, &bounds).is_empty());
    }
}
