//! The quality figures, computed from each engine's positions in the same way whatever the
//! engine, so that they compare.
//!
//! - `pyramid`: the largest distance any box moved from its start, m (it should stand).
//! - `balls`: the deepest overlap at the end, m: of two spheres (radius ½ m), or of a
//!   sphere and the container's floor (y = 0) or walls (x, z = ±10 m).
//! - `falling`: the largest distance of a sphere from free fall, |y − (y₀ − ½gt²)|, m (both
//!   engines integrate with semi-implicit Euler, whose error here is ½g·dt·t).
//! - `water`: the mean compression of the fluid, mean of max(ρᵢ/ρ₀ − 1, 0) over the fluid
//!   particles, with ρᵢ the SPH sum over the fluid and the tank's boundary particles of a
//!   cubic spline of support 2 spacings, and ρ₀ the same sum at a site inside the rest
//!   lattice. Both solvers bound this quantity, each with its own kernel (fixstep a
//!   Wendland C2, salva3d this cubic spline), so neither kernel is the reference.

use crate::scenes::{FluidScene, RigidRun, Scene};
use std::collections::BTreeMap;

/// The scene's quality figure for one run, m; `None` when the run has no bodies.
pub fn rigid(scene: Scene, run: &RigidRun) -> Option<f64> {
    if run.end.is_empty() || run.start.len() != run.end.len() {
        return None;
    }
    Some(match scene.name {
        "pyramid" => run
            .start
            .iter()
            .zip(&run.end)
            .map(|(a, b)| distance(*a, *b))
            .fold(0.0, f64::max),
        "balls" => deepest_overlap(&run.end),
        "falling" => {
            let t = f64::from(scene.steps) / 60.0;
            run.start
                .iter()
                .zip(&run.end)
                .map(|(a, b)| (b[1] - (a[1] - 0.5 * 9.81 * t * t)).abs())
                .fold(0.0, f64::max)
        }
        _ => return None,
    })
}

/// The deepest overlap of spheres of radius ½ m at `centres` in the `balls` container.
fn deepest_overlap(centres: &[[f64; 3]]) -> f64 {
    let mut deepest: f64 = 0.0;
    for c in centres {
        deepest = deepest
            .max(0.5 - c[1])
            .max(c[0] + 0.5 - 10.0)
            .max(-10.0 - (c[0] - 0.5))
            .max(c[2] + 0.5 - 10.0)
            .max(-10.0 - (c[2] - 0.5));
    }
    let mut by_x: Vec<&[f64; 3]> = centres.iter().collect();
    by_x.sort_by(|a, b| a[0].total_cmp(&b[0]));
    for (i, a) in by_x.iter().enumerate() {
        for b in &by_x[i + 1..] {
            if b[0] - a[0] >= 1.0 {
                break;
            }
            deepest = deepest.max(1.0 - distance(**a, **b));
        }
    }
    deepest
}

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

/// The cubic spline of support 1 over q = r/H, up to its normalisation (which cancels
/// against ρ₀'s).
fn cubic_spline(q: f64) -> f64 {
    if q >= 1.0 {
        0.0
    } else if q > 0.5 {
        2.0 * (1.0 - q).powi(3)
    } else {
        6.0 * q * q * (q - 1.0) + 1.0
    }
}

/// The mean compression of the fluid at `positions` in `scene`'s tank (module docs).
pub fn mean_compression(scene: &FluidScene, positions: &[[f64; 3]]) -> f64 {
    let dx = f64::from(scene.spacing);
    let support = 2.0 * dx;
    let walls: Vec<[f64; 3]> = scene.walls().iter().map(|p| p.map(f64::from)).collect();
    // ρ₀: the sum at a lattice site, over the sites within the support.
    let reach = 2;
    let mut rest = 0.0;
    for i in -reach..=reach {
        for j in -reach..=reach {
            for k in -reach..=reach {
                let r = dx * f64::from(i * i + j * j + k * k).sqrt();
                rest += cubic_spline(r / support);
            }
        }
    }
    let cell = |p: &[f64; 3]| p.map(|c| (c / support).floor() as i64);
    let mut grid: BTreeMap<[i64; 3], Vec<[f64; 3]>> = BTreeMap::new();
    for p in positions.iter().chain(&walls) {
        grid.entry(cell(p)).or_default().push(*p);
    }
    let mut total = 0.0;
    for p in positions {
        let c = cell(p);
        let mut sum = 0.0;
        for i in -1..=1 {
            for j in -1..=1 {
                for k in -1..=1 {
                    if let Some(points) = grid.get(&[c[0] + i, c[1] + j, c[2] + k]) {
                        sum += points
                            .iter()
                            .map(|q| cubic_spline(distance(*p, *q) / support))
                            .sum::<f64>();
                    }
                }
            }
        }
        total += (sum / rest - 1.0).max(0.0);
    }
    total / positions.len().max(1) as f64
}
