//! The quality figures, computed from each engine's positions in the same way whatever the
//! engine, so that they compare.
//!
//! - `pyramid`: the largest distance any box moved from its start, m (it should stand).
//! - `balls`: the deepest overlap at the end, m: of two spheres (radius ½ m), or of a
//!   sphere and the container's floor (y = 0) or walls (x, z = ±10 m).
//! - `falling`: the largest distance of a sphere from free fall, |y − (y₀ − ½gt²)|, m (both
//!   engines integrate with semi-implicit Euler, whose error here is ½g·dt·t).
//! - `dam_break`: the surge front Z = x_front/a at T = t·√(2g/a) against Martin & Moyce's
//!   (1952, table 2) at the same T, as a relative error, as is and with the customary
//!   shift of +0.175 in T for the gate's opening; x_front is the furthest x (plus half a
//!   spacing) of a fluid particle within one spacing of the floor, as fixstep's `front_x`.
//! - `water` and `dam_break`: the mean compression of the fluid inside, mean of
//!   max(ρᵢ/ρ₀ − 1, 0) over the fluid particles whose kernel support does not reach the
//!   tank's floor or walls, with ρᵢ the SPH sum over the fluid particles of a cubic spline of
//!   support 2 spacings, and ρ₀ the same sum at a site inside the rest lattice. Both
//!   solvers bound this quantity, each with its own kernel (fixstep a Wendland C2, salva3d
//!   this cubic spline, whose lattice sum is its rest density to 3·10⁻⁵), and each with its
//!   own boundary model, which the figure leaves out.

use crate::scenes::{DAM_WIDTH, FluidScene, RigidRun, Scene};
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
        "hills" | "hills_mesh" => run.end.iter().map(|p| p[1]).fold(f64::MAX, f64::min),
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

/// The mean compression of the fluid at `positions` inside `scene`'s tank (module docs).
pub fn mean_compression(scene: &FluidScene, positions: &[[f64; 3]]) -> f64 {
    let dx = f64::from(scene.spacing);
    let support = 2.0 * dx;
    let tank = scene.tank.map(f64::from);
    let inside = |p: &[f64; 3]| {
        p[1] >= support
            && p[0] >= support
            && p[0] <= tank[0] - support
            && p[2] >= support
            && p[2] <= tank[2] - support
    };
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
    for p in positions {
        grid.entry(cell(p)).or_default().push(*p);
    }
    let mut total = 0.0;
    let mut count = 0;
    for p in positions.iter().filter(|p| inside(p)) {
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
        count += 1;
    }
    total / f64::from(count.max(1))
}

/// Martin & Moyce (1952), table 2, n² = 2: (T, Z) (`../shared/reference/`).
const MARTIN_MOYCE: [(f64, f64); 16] = [
    (0.0, 1.0),
    (0.41, 1.11),
    (0.84, 1.22),
    (1.19, 1.44),
    (1.43, 1.67),
    (1.63, 1.89),
    (1.83, 2.11),
    (1.98, 2.33),
    (2.2, 2.56),
    (2.32, 2.78),
    (2.51, 3.0),
    (2.65, 3.22),
    (2.83, 3.44),
    (2.98, 3.67),
    (3.11, 3.89),
    (3.33, 4.11),
];

/// Martin & Moyce's Z at `t`, linearly interpolated.
fn martin_moyce(t: f64) -> f64 {
    let at = MARTIN_MOYCE
        .partition_point(|&(tk, _)| tk <= t)
        .clamp(1, MARTIN_MOYCE.len() - 1);
    let ((t0, z0), (t1, z1)) = (MARTIN_MOYCE[at - 1], MARTIN_MOYCE[at]);
    z0 + (z1 - z0) * (t - t0) / (t1 - t0)
}

/// The dam break's front after `time` seconds: (T, Z, relative error against Martin &
/// Moyce, the same with T shifted by +0.175).
pub fn dam_front(scene: &FluidScene, positions: &[[f64; 3]], time: f64) -> (f64, f64, f64, f64) {
    let dx = f64::from(scene.spacing);
    let a = f64::from(DAM_WIDTH);
    let front = positions
        .iter()
        .filter(|p| p[1] <= dx)
        .map(|p| p[0] + 0.5 * dx)
        .fold(0.0, f64::max);
    let z = front / a;
    let t = time * (2.0 * 9.81 / a).sqrt();
    let error = |reference: f64| z / reference - 1.0;
    (t, z, error(martin_moyce(t)), error(martin_moyce(t + 0.175)))
}
