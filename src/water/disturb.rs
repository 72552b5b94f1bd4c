//! Disturbances dropped on the surface by inputs
//! ([`Command::DisturbWater`](crate::types::Command::DisturbWater)).

use super::system::{WaterSystem, cell_below};
use crate::math::Real;

impl<R: Real> WaterSystem<R> {
    /// Raises the surface by a smooth bump centred at (x, z) (m): every cell whose centre
    /// lies within `radius` (m) of it, at distance r, rises by
    /// `height · (1 − r²/radius²)²` (m; a negative height digs a dip). The bump adds about
    /// `height · π radius² / 3` m³ of water. A radius shorter than the distance to every
    /// cell centre, or a centre farther than that from the grid, changes nothing.
    pub fn disturb(&mut self, x: R, z: R, height: R, radius: R) {
        let s = &self.settings;
        if radius <= R::ZERO {
            return;
        }
        let size = s.cell_size;
        let half = R::from_ratio(1, 2);
        let (fx, fz) = (
            (x - s.origin.x) / size - half,
            (z - s.origin.z) / size - half,
        );
        let reach = radius / size + R::ONE;
        let misses = |f: R, n: u32| f + reach < R::ZERO || f - reach > R::from_int(n as i32);
        if misses(fx, s.columns) || misses(fz, s.rows) {
            return;
        }
        let (i_lo, _) = cell_below(fx - reach, s.columns);
        let (i_hi, _) = cell_below(fx + reach, s.columns);
        let (k_lo, _) = cell_below(fz - reach, s.rows);
        let (k_hi, _) = cell_below(fz + reach, s.rows);
        let n = s.columns as usize;
        let inv_r2 = R::ONE / (radius * radius);
        for k in k_lo..=k_hi {
            for i in i_lo..=i_hi {
                let cx = s.origin.x + (R::from_int(i as i32) + half) * size;
                let cz = s.origin.z + (R::from_int(k as i32) + half) * size;
                let (dx, dz) = (cx - x, cz - z);
                let w = R::ONE - (dx * dx + dz * dz) * inv_r2;
                if w > R::ZERO {
                    self.heights[i + n * k] += height * w * w;
                }
            }
        }
    }
}
