//! The tank: boundary particles lining its floor and walls, and the walls' hard limit.
//!
//! The boundary is a lattice of fixed particles one spacing apart, as many layers thick as
//! the kernel reaches (⌈H/spacing⌉), outside the floor and the four walls up to the tank's
//! top. A boundary particle has the volume of a fluid particle, so a fluid particle next
//! to a wall sees the same kernel sum as one inside the fluid, and its density is right
//! (Akinci et al. 2012 with uniform sampling, where ψ = ρ₀V₀). In the pressure force a
//! boundary particle pushes with the fluid particle's own P/ρ² once (Akinci's one-sided
//! term; see [`wcsph`](super::wcsph) and [`dfsph`](super::dfsph)).
//!
//! As a last guard the walls are also a hard limit: after advection a particle closer than
//! a quarter spacing to the floor or a wall is put back at that distance, its velocity
//! into the wall removed. So no particle ever leaves the tank except upward, however fast.

use super::settings::FluidSettings;
use super::system::PARTICLE_CHUNK;
use crate::math::{Real, Vec3};
use crate::parallel::for_each_zip_mut;

/// The lattice sites `lo + (i + ½)·spacing` below `hi`, as coordinates.
fn sites<R: Real>(lo: R, hi: R, spacing: R) -> Vec<R> {
    let mut out = Vec::new();
    let mut at = lo + spacing * R::HALF;
    while at < hi {
        out.push(at);
        at += spacing;
    }
    out
}

/// The boundary particles of the tank of `settings`: the floor layers (under the walls too),
/// then the walls at low x and high x, then those at low z and high z; within each part
/// x fastest, then y, then z.
pub(crate) fn sample_walls<R: Real>(settings: &FluidSettings<R>) -> Vec<Vec3<R>> {
    let dx = settings.spacing;
    let t = &settings.tank;
    let thickness = dx * R::from_int(super::kernel::lattice_reach(settings.support));
    let outer_x = sites(t.min.x - thickness, t.max.x + thickness, dx);
    let outer_z = sites(t.min.z - thickness, t.max.z + thickness, dx);
    let inner_x = sites(t.min.x, t.max.x, dx);
    let inner_y = sites(t.min.y, t.max.y, dx);
    let layers = sites(R::ZERO, thickness, dx);
    let mut points = Vec::new();
    for &z in &outer_z {
        for &depth in &layers {
            for &x in &outer_x {
                points.push(Vec3::new(x, t.min.y - depth, z));
            }
        }
    }
    for &z in &outer_z {
        for &y in &inner_y {
            for &depth in &layers {
                points.push(Vec3::new(t.min.x - depth, y, z));
                points.push(Vec3::new(t.max.x + depth, y, z));
            }
        }
    }
    for &depth in &layers {
        for &y in &inner_y {
            for &x in &inner_x {
                points.push(Vec3::new(x, y, t.min.z - depth));
                points.push(Vec3::new(x, y, t.max.z + depth));
            }
        }
    }
    points
}

/// How many boundary particles [`sample_walls`] makes, counted axis by axis (for bounding
/// before sampling): the counts along x, y, z and of the layers, each at most `cap`.
pub(crate) fn boundary_count<R: Real>(settings: &FluidSettings<R>, cap: u64) -> u64 {
    let dx = settings.spacing;
    let t = &settings.tank;
    let thickness = dx * R::from_int(super::kernel::lattice_reach(settings.support));
    let count = |lo: R, hi: R| {
        let mut n = 0u64;
        let mut at = lo + dx * R::HALF;
        while at < hi && n <= cap {
            n += 1;
            at += dx;
        }
        n
    };
    let outer_x = count(t.min.x - thickness, t.max.x + thickness);
    let outer_z = count(t.min.z - thickness, t.max.z + thickness);
    let inner_x = count(t.min.x, t.max.x);
    let inner_y = count(t.min.y, t.max.y);
    let layers = count(R::ZERO, thickness);
    layers * (outer_x * outer_z + 2 * inner_y * outer_z + 2 * inner_y * inner_x)
}

/// Stage 5: x ← x + Δt v (m) for each fluid particle (`positions`, `velocities` in step),
/// then the hard limit of the floor and walls: a coordinate closer than ¼ spacing to a wall
/// is set to that distance and the velocity component into the wall is removed.
pub(crate) fn advect<R: Real>(
    s: &FluidSettings<R>,
    positions: &mut [Vec3<R>],
    velocities: &mut [Vec3<R>],
    dt: R,
) {
    let gap = s.spacing * R::from_ratio(1, 4);
    let lo = Vec3::new(s.tank.min.x + gap, s.tank.min.y + gap, s.tank.min.z + gap);
    let hi = Vec3::new(s.tank.max.x - gap, R::MAX, s.tank.max.z - gap);
    for_each_zip_mut(positions, velocities, PARTICLE_CHUNK, |_, x, v| {
        let mut p = x.add_scaled(*v, dt);
        limit(&mut p.x, &mut v.x, lo.x, hi.x);
        limit(&mut p.y, &mut v.y, lo.y, hi.y);
        limit(&mut p.z, &mut v.z, lo.z, hi.z);
        *x = p;
    });
}

/// Keeps one coordinate in `[lo, hi]`, removing the velocity that points out.
#[inline(always)]
fn limit<R: Real>(x: &mut R, v: &mut R, lo: R, hi: R) {
    if *x < lo {
        *x = lo;
        *v = v.max(R::ZERO);
    } else if *x > hi {
        *x = hi;
        *v = v.min(R::ZERO);
    }
}
