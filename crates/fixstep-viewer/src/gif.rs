//! The animated GIF: frames quantised to one fixed palette, written as they come.
//!
//! The palette is the 6 × 6 × 6 colour cube plus the viewer's own flat colours
//! (background, ground, scenery, the body palette awake and asleep), so flat areas keep
//! their exact colour. Each pixel takes the palette entry nearest (in squared RGB
//! distance, ties to the lower index) to its colour at 5 bits per channel, through a
//! lookup table built once: fast, and the same pixels always give the same bytes.

use std::borrow::Cow;
use std::io::Write;

use gif::{DisposalMethod, Encoder, Repeat};
use tiny_skia::Pixmap;

use super::colour::{BACKGROUND, GROUND, STATIC, body_colour};

/// Bits per channel of the lookup table.
const LOOKUP_BITS: u32 = 5;

/// A GIF being written.
pub struct GifWriter<W: Write> {
    encoder: Encoder<W>,
    lookup: Vec<u8>,
    width: u16,
    height: u16,
    /// Hundredths of a second each frame shows.
    delay: u16,
    /// Palette indices of the picture shown so far.
    shown: Vec<u8>,
    /// Palette indices of the frame being pushed.
    indices: Vec<u8>,
    /// The changed rectangle of the frame being pushed, row by row.
    patch: Vec<u8>,
}

/// The palette: the colour cube, then the viewer's flat colours.
fn palette() -> Vec<[u8; 3]> {
    let mut colours: Vec<[u8; 3]> = Vec::with_capacity(256);
    for r in 0..6u8 {
        for g in 0..6u8 {
            for b in 0..6u8 {
                colours.push([r * 51, g * 51, b * 51]);
            }
        }
    }
    colours.extend([BACKGROUND, GROUND, STATIC]);
    for sleeping in [false, true] {
        colours.extend((0..8).map(|slot| body_colour(slot, sleeping)));
    }
    colours
}

/// For every colour at [`LOOKUP_BITS`] bits per channel, the index of the nearest entry
/// of `palette`.
fn nearest_lookup(palette: &[[u8; 3]]) -> Vec<u8> {
    let levels = 1u32 << LOOKUP_BITS;
    let step = 256 / levels;
    let mut lookup = Vec::with_capacity((levels * levels * levels) as usize);
    for r in 0..levels {
        for g in 0..levels {
            for b in 0..levels {
                let centre = [r, g, b].map(|c| (c * step + step / 2) as i32);
                let distance = |p: &[u8; 3]| -> i32 {
                    (0..3).map(|k| (i32::from(p[k]) - centre[k]).pow(2)).sum()
                };
                let best = (0..palette.len())
                    .min_by_key(|&i| (distance(&palette[i]), i))
                    .unwrap_or(0);
                lookup.push(best as u8);
            }
        }
    }
    lookup
}

impl<W: Write> GifWriter<W> {
    /// Starts a looping GIF of `width` × `height` pixels (at most 65535 each) showing each
    /// frame for `seconds_per_frame`.
    pub fn new(out: W, width: u32, height: u32, seconds_per_frame: f64) -> Result<Self, String> {
        let too_big =
            || format!("a GIF is at most 65535 pixels wide and high, not {width}x{height}");
        let width = u16::try_from(width).map_err(|_| too_big())?;
        let height = u16::try_from(height).map_err(|_| too_big())?;
        let colours = palette();
        let flat: Vec<u8> = colours.iter().flatten().copied().collect();
        let mut encoder = Encoder::new(out, width, height, &flat)
            .map_err(|e| format!("cannot start the GIF: {e}"))?;
        encoder
            .set_repeat(Repeat::Infinite)
            .map_err(|e| format!("cannot write the GIF: {e}"))?;
        // GIF delays are in hundredths of a second; browsers treat less than 2 as 10.
        let delay = (seconds_per_frame * 100.0).round().clamp(2.0, 65535.0) as u16;
        Ok(Self {
            encoder,
            lookup: nearest_lookup(&colours),
            width,
            height,
            delay,
            shown: Vec::new(),
            indices: Vec::new(),
            patch: Vec::new(),
        })
    }

    /// Appends `pixmap` (of the GIF's size, opaque) as the next frame.
    pub fn push(&mut self, pixmap: &Pixmap) -> Result<(), String> {
        if pixmap.width() != u32::from(self.width) || pixmap.height() != u32::from(self.height) {
            return Err("a GIF frame differs in size from the GIF".to_owned());
        }
        let shift = 8 - LOOKUP_BITS;
        self.indices.clear();
        self.indices.extend(pixmap.pixels().iter().map(|p| {
            let key = (usize::from(p.red() >> shift) << (2 * LOOKUP_BITS))
                | (usize::from(p.green() >> shift) << LOOKUP_BITS)
                | usize::from(p.blue() >> shift);
            self.lookup[key]
        }));
        // Only the rectangle that changed is stored, over the frame before it (disposal
        // Keep): a scene at rest costs one pixel per frame.
        let (left, top, width, height) = self.changed_rectangle();
        let row = usize::from(self.width);
        self.patch.clear();
        for y in top..top + height {
            let start = y * row + left;
            self.patch
                .extend_from_slice(&self.indices[start..start + width]);
        }
        core::mem::swap(&mut self.shown, &mut self.indices);
        let frame = gif::Frame {
            left: left as u16,
            top: top as u16,
            width: width as u16,
            height: height as u16,
            delay: self.delay,
            dispose: DisposalMethod::Keep,
            buffer: Cow::Borrowed(&self.patch),
            ..gif::Frame::default()
        };
        self.encoder
            .write_frame(&frame)
            .map_err(|e| format!("cannot write the GIF: {e}"))
    }

    /// (left, top, width, height) of the smallest rectangle holding every pixel of
    /// `indices` that differs from `shown`: the whole picture for the first frame, one
    /// pixel when nothing changed.
    fn changed_rectangle(&self) -> (usize, usize, usize, usize) {
        let (w, h) = (usize::from(self.width), usize::from(self.height));
        if self.shown.len() != self.indices.len() {
            return (0, 0, w, h);
        }
        let (mut x0, mut y0, mut x1, mut y1) = (w, h, 0, 0);
        for (y, (new, old)) in self
            .indices
            .chunks_exact(w)
            .zip(self.shown.chunks_exact(w))
            .enumerate()
        {
            if new == old {
                continue;
            }
            let first = new.iter().zip(old).position(|(a, b)| a != b).unwrap_or(0);
            let last = new.iter().zip(old).rposition(|(a, b)| a != b).unwrap_or(0);
            x0 = x0.min(first);
            x1 = x1.max(last + 1);
            y0 = y0.min(y);
            y1 = y + 1;
        }
        if x0 >= x1 {
            (0, 0, 1, 1)
        } else {
            (x0, y0, x1 - x0, y1 - y0)
        }
    }

    /// Writes the trailer and hands back the output.
    pub fn finish(self) -> Result<W, String> {
        self.encoder
            .into_inner()
            .map_err(|e| format!("cannot finish the GIF: {e}"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flat_colours_map_to_themselves() {
        let colours = palette();
        assert!(colours.len() <= 256);
        let lookup = nearest_lookup(&colours);
        let index = |c: [u8; 3]| {
            let s = 8 - LOOKUP_BITS;
            lookup[(usize::from(c[0] >> s) << 10)
                | (usize::from(c[1] >> s) << 5)
                | usize::from(c[2] >> s)]
        };
        assert_eq!(colours[usize::from(index(BACKGROUND))], BACKGROUND);
        assert_eq!(colours[usize::from(index([0, 0, 0]))], [0, 0, 0]);
    }
}
