//! Orthographic views and fitting them to a film's bounds.
//!
//! World y is up. A view is an orthonormal basis: `right` and `up` span the picture,
//! `toward` points from the scene to the viewer (right × up = toward). Screen pixels are
//! x = cx + s (p · right), y = cy − s (p · up), with one scale s (px/m) for the whole
//! film, so that sizes and motion compare between frames.

use super::draw_list::Bounds;
use super::geometry::{P3, dot, normalize};

/// The three views of `fixstep render --view`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    /// From above the (+x, +y, +z) octant, looking at the origin (isometric).
    Iso,
    /// From +z, looking along −z: x to the right, y up.
    Front,
    /// From +y, looking down: x to the right, −z up.
    Top,
}

impl View {
    /// Every view, in the order of the player's menu.
    pub const ALL: [View; 3] = [View::Iso, View::Front, View::Top];

    /// The view called `name` (`iso`, `front` or `top`).
    pub fn from_name(name: &str) -> Option<View> {
        View::ALL.into_iter().find(|v| v.name() == name)
    }

    /// The name used on the command line and in the player.
    pub fn name(self) -> &'static str {
        match self {
            View::Iso => "iso",
            View::Front => "front",
            View::Top => "top",
        }
    }

    /// (right, up, toward) of the view: an orthonormal, right-handed basis.
    pub fn basis(self) -> [P3; 3] {
        match self {
            View::Iso => [
                normalize([1.0, 0.0, -1.0]),
                normalize([-1.0, 2.0, -1.0]),
                normalize([1.0, 1.0, 1.0]),
            ],
            View::Front => [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            View::Top => [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]],
        }
    }
}

/// Fraction of the picture's smaller side left free around the scene, on each side.
const MARGIN: f64 = 0.04;

/// A view fitted to a picture: world points to pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Projection {
    pub view: View,
    /// Picture width and height, px.
    pub width: u32,
    pub height: u32,
    /// Pixels per metre.
    pub scale: f64,
    /// Pixel position of the world origin.
    pub cx: f64,
    pub cy: f64,
}

impl Projection {
    /// The projection of `view` that shows all of `bounds` as large as fits in a
    /// `width` × `height` picture, centred.
    pub fn fit(view: View, bounds: &Bounds, width: u32, height: u32) -> Projection {
        let [right, up, _] = view.basis();
        let corners = bounds.corners();
        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for c in corners {
            let (x, y) = (dot(c, right), dot(c, up));
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
        let (w, h) = (f64::from(width), f64::from(height));
        let margin = 2.0 * MARGIN * w.min(h);
        let scale = ((w - margin) / (x1 - x0).max(1e-9)).min((h - margin) / (y1 - y0).max(1e-9));
        Projection {
            view,
            width,
            height,
            scale,
            cx: w / 2.0 - scale * (x0 + x1) / 2.0,
            cy: h / 2.0 + scale * (y0 + y1) / 2.0,
        }
    }

    /// The pixel position of world point `p`.
    pub fn screen(&self, p: P3) -> (f64, f64) {
        let [right, up, _] = self.view.basis();
        (
            self.cx + self.scale * dot(p, right),
            self.cy - self.scale * dot(p, up),
        )
    }

    /// How near `p` is to the viewer, m (larger is nearer).
    pub fn depth(&self, p: P3) -> f64 {
        dot(p, self.view.basis()[2])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::cross;

    #[test]
    fn bases_are_right_handed_and_orthonormal() {
        for view in View::ALL {
            let [r, u, t] = view.basis();
            let c = cross(r, u);
            for k in 0..3 {
                assert!((c[k] - t[k]).abs() < 1e-12, "{view:?}");
            }
            assert!(dot(r, u).abs() < 1e-12 && (dot(r, r) - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn fitted_bounds_lie_inside_the_picture() {
        let bounds = Bounds {
            min: [-3.0, 0.0, -1.0],
            max: [5.0, 7.0, 2.0],
        };
        for view in View::ALL {
            let p = Projection::fit(view, &bounds, 320, 200);
            for c in bounds.corners() {
                let (x, y) = p.screen(c);
                assert!(
                    (0.0..=320.0).contains(&x) && (0.0..=200.0).contains(&y),
                    "{view:?}"
                );
            }
        }
    }
}
