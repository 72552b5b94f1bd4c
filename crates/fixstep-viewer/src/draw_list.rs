//! The neutral draw list: what one tick of a world looks like, as world-space figures in
//! floats, before any projection. Each subsystem adds its own figures (see
//! [`draw_particles`](super::draw_particles), [`draw_rigid`](super::draw_rigid)); the
//! rasteriser and the HTML player only ever see this list.

use super::geometry::P3;

/// A shape to draw, in world space (m).
#[derive(Clone, Debug, PartialEq)]
pub enum Figure {
    /// A dot of fixed screen size (a particle).
    Dot { at: P3 },
    /// A line of fixed screen width (a joint, a rope segment, a cloth edge).
    Line { a: P3, b: P3 },
    /// A ball of radius `radius` (m).
    Ball { centre: P3, radius: f64 },
    /// The points within `radius` (m) of the segment from `a` to `b`.
    Capsule { a: P3, b: P3, radius: f64 },
    /// A box: its centre and its three half axes (each body axis times its half extent).
    Cuboid { centre: P3, half_axes: [P3; 3] },
    /// A flat polygon (a cloth triangle), corners in order around it.
    Polygon { corners: Vec<P3> },
    /// The plane n · x = `offset` (n unit), drawn as its cut through the film's bounds.
    Plane { normal: P3, offset: f64 },
}

/// How a figure is coloured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Paint {
    /// A fixed colour, sRGB.
    Rgb([u8; 3]),
    /// A colour on the speed scale of the whole film, from the speed in m/s.
    Speed(f64),
    /// A colour on the fixed density scale of water, from ρ/ρ₀.
    Density(f64),
}

/// Drawing order: a lower layer is painted first, whatever its depth. Within a layer,
/// farther figures are painted first.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Layer {
    /// Planes (the ground): always behind everything.
    Ground,
    /// Static scenery (walls, slopes): behind what moves, so it never hides it.
    Scenery,
    /// Particle trails: behind what moves.
    Trail,
    /// Everything that moves.
    Moving,
}

/// A figure with its colour and layer.
#[derive(Clone, Debug, PartialEq)]
pub struct Primitive {
    pub figure: Figure,
    pub paint: Paint,
    pub layer: Layer,
}

/// One drawn tick: the figures and the figures reported alongside them.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// Ticks completed.
    pub tick: u64,
    /// Total mechanical energy, J (kinetic + potential, as `fixstep run --metrics`).
    pub energy: f64,
    /// The world checksum at this tick.
    pub checksum: u64,
    /// What to draw.
    pub primitives: Vec<Primitive>,
}

/// An axis-aligned box in world space, m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    pub min: P3,
    pub max: P3,
}

impl Bounds {
    /// The box around the unit cube centred on the origin: what an empty film shows.
    pub const UNIT: Bounds = Bounds {
        min: [-0.5; 3],
        max: [0.5; 3],
    };

    /// The smallest box holding every finite point of every non-plane figure of `frames`
    /// (grown by radii and half axes), or [`Bounds::UNIT`] when there is none.
    pub fn of_frames(frames: &[Frame]) -> Bounds {
        let mut bounds: Option<Bounds> = None;
        let mut grow = |p: P3, reach: f64| {
            if !(p.iter().all(|c| c.is_finite()) && reach.is_finite()) {
                return;
            }
            let lo = p.map(|c| c - reach);
            let hi = p.map(|c| c + reach);
            let b = bounds.get_or_insert(Bounds { min: lo, max: hi });
            for k in 0..3 {
                b.min[k] = b.min[k].min(lo[k]);
                b.max[k] = b.max[k].max(hi[k]);
            }
        };
        for primitive in frames.iter().flat_map(|f| &f.primitives) {
            match &primitive.figure {
                Figure::Dot { at } => grow(*at, 0.0),
                Figure::Line { a, b } => {
                    grow(*a, 0.0);
                    grow(*b, 0.0);
                }
                Figure::Ball { centre, radius } => grow(*centre, *radius),
                Figure::Capsule { a, b, radius } => {
                    grow(*a, *radius);
                    grow(*b, *radius);
                }
                Figure::Cuboid { centre, half_axes } => {
                    let reach = half_axes
                        .iter()
                        .map(|h| h.map(f64::abs))
                        .fold([0.0; 3], |sum: P3, h| {
                            [sum[0] + h[0], sum[1] + h[1], sum[2] + h[2]]
                        });
                    for k in 0..3 {
                        let mut lo = *centre;
                        let mut hi = *centre;
                        lo[k] -= reach[k];
                        hi[k] += reach[k];
                        grow(lo, 0.0);
                        grow(hi, 0.0);
                    }
                }
                Figure::Polygon { corners } => corners.iter().for_each(|c| grow(*c, 0.0)),
                Figure::Plane { .. } => {}
            }
        }
        bounds.unwrap_or(Bounds::UNIT)
    }

    /// The eight corners.
    pub fn corners(&self) -> [P3; 8] {
        core::array::from_fn(|i| {
            [
                if i & 1 == 0 { self.min[0] } else { self.max[0] },
                if i & 2 == 0 { self.min[1] } else { self.max[1] },
                if i & 4 == 0 { self.min[2] } else { self.max[2] },
            ]
        })
    }

    /// The box grown by `fraction` of its largest side on every side, and by at least a
    /// quarter of that side up to 0.5 m, so that a flat scene still has some depth and the
    /// ground shows around the bodies, without shrinking a small scene (a tank of water a
    /// few centimetres across) to a speck.
    pub fn padded(&self, fraction: f64) -> Bounds {
        let largest = (0..3)
            .map(|k| self.max[k] - self.min[k])
            .fold(0.0, f64::max);
        let pad = (largest * fraction).max(0.5_f64.min(largest / 4.0));
        Bounds {
            min: self.min.map(|c| c - pad),
            max: self.max.map(|c| c + pad),
        }
    }
}
