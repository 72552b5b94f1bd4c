//! Colours: the body palette, the one-colour-per-body palette of `--flat`, the speed
//! scale of particles and the density scale of fluids.

use super::draw_list::{Frame, Paint};

/// The background of every picture, sRGB.
pub const BACKGROUND: [u8; 3] = [246, 247, 249];

/// Planes (the ground), sRGB.
pub const GROUND: [u8; 3] = [214, 218, 224];

/// Static bodies, sRGB.
pub const STATIC: [u8; 3] = [150, 156, 166];

/// Rods, ropes and springs between their anchors: dark slate.
pub const JOINT: [u8; 3] = [60, 66, 78];

/// A water surface's wire mesh: lake blue.
pub const WATER: [u8; 3] = [72, 139, 194];

/// Moving bodies take these in turn by slot, so neighbours differ.
const BODY_PALETTE: [[u8; 3]; 8] = [
    [231, 111, 81],
    [42, 157, 143],
    [233, 196, 106],
    [69, 123, 157],
    [244, 162, 97],
    [131, 96, 195],
    [106, 176, 76],
    [214, 93, 143],
];

/// The colour of the moving body in slot `slot`; a sleeping body is greyed (mixed half
/// with grey), as in the Box2D testbed.
pub fn body_colour(slot: usize, sleeping: bool) -> [u8; 3] {
    let colour = BODY_PALETTE[slot % BODY_PALETTE.len()];
    if sleeping {
        colour.map(|c| ((u16::from(c) + 160) / 2) as u8)
    } else {
        colour
    }
}

/// A colour unique to `index` among the first 4096 indices, and never the background:
/// each channel holds four bits of `index + 1` on levels 8, 24, …, 248.
pub fn id_colour(index: usize) -> [u8; 3] {
    let n = index % 4095 + 1;
    [n & 15, (n >> 4) & 15, (n >> 8) & 15].map(|nibble| (nibble * 16 + 8) as u8)
}

/// Stops of the speed scale: slow is blue, fast is red (a short "turbo"-like ramp).
const SPEED_RAMP: [[f64; 3]; 5] = [
    [48.0, 18.0, 160.0],
    [40.0, 140.0, 230.0],
    [60.0, 200.0, 110.0],
    [245.0, 190.0, 40.0],
    [215.0, 40.0, 30.0],
];

/// Turns paints into colours for one film: speeds are scaled by the fastest speed of the
/// whole film, so a colour means the same speed in every frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Palette {
    /// The speed drawn in the last colour of the ramp, m/s.
    pub top_speed: f64,
}

impl Palette {
    /// The palette of `frames`.
    pub fn of_frames(frames: &[Frame]) -> Palette {
        let top_speed = frames
            .iter()
            .flat_map(|f| &f.primitives)
            .filter_map(|p| match p.paint {
                Paint::Speed(v) if v.is_finite() => Some(v.abs()),
                _ => None,
            })
            .fold(0.0, f64::max);
        Palette { top_speed }
    }

    /// The colour of `paint`.
    pub fn colour(&self, paint: Paint) -> [u8; 3] {
        match paint {
            Paint::Rgb(rgb) => rgb,
            Paint::Speed(v) => {
                let t = if self.top_speed > 0.0 && v.is_finite() {
                    (v.abs() / self.top_speed).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                ramp(t)
            }
            Paint::Density(ratio) => water(ratio),
        }
    }
}

/// Water at density ratio ρ/ρ₀: pale blue at 1 − [`DENSITY_SPAN`] or below (stretched,
/// near the surface), deep blue at 1 + [`DENSITY_SPAN`] or above (compressed). A fixed
/// scale, so that the same colour means the same compression in every film.
fn water(ratio: f64) -> [u8; 3] {
    const PALE: [f64; 3] = [150.0, 205.0, 240.0];
    const DEEP: [f64; 3] = [10.0, 60.0, 160.0];
    let t = if ratio.is_finite() {
        ((ratio - 1.0) / (2.0 * DENSITY_SPAN) + 0.5).clamp(0.0, 1.0)
    } else {
        0.5
    };
    core::array::from_fn(|k| (PALE[k] + (DEEP[k] - PALE[k]) * t).round() as u8)
}

/// Half the density range the water scale spans: ±2 % around ρ₀.
const DENSITY_SPAN: f64 = 0.02;

/// The colour at `t` ∈ [0, 1] along [`SPEED_RAMP`], linearly between stops.
fn ramp(t: f64) -> [u8; 3] {
    let position = t * (SPEED_RAMP.len() - 1) as f64;
    let below = (position.floor() as usize).min(SPEED_RAMP.len() - 2);
    let f = position - below as f64;
    let (a, b) = (SPEED_RAMP[below], SPEED_RAMP[below + 1]);
    core::array::from_fn(|k| (a[k] + (b[k] - a[k]) * f).round() as u8)
}

/// `colour` scaled by `light` ∈ [0, 1].
pub fn shade(colour: [u8; 3], light: f64) -> [u8; 3] {
    colour.map(|c| (f64::from(c) * light.clamp(0.0, 1.0)).round() as u8)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn id_colours_are_distinct_and_never_the_background() {
        let mut seen = std::collections::BTreeSet::new();
        for i in 0..4095 {
            let c = id_colour(i);
            assert_ne!(c, BACKGROUND);
            assert!(seen.insert(c), "index {i} repeats a colour");
        }
    }

    #[test]
    fn ramp_ends_at_its_stops() {
        assert_eq!(ramp(0.0), [48, 18, 160]);
        assert_eq!(ramp(1.0), [215, 40, 30]);
    }
}
