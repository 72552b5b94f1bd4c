//! Semi-implicit Euler for a [`LinearField`] in one pass over blocks of slots.
//!
//! For every movable particle, with F_ext the tick's external force (N), kⱼ the linear drag
//! coefficients that apply to it (kg/s, 0 ≤ kⱼ < 1/2), 1/m its inverse mass (1/kg), g the
//! uniform gravity (m/s²) and h the step (s, 0 ≤ h < 1/2):
//!
//! ```text
//! F  = F_ext − k₁ v − k₂ v − …      (N, drags in scene order)
//! a  = g + F · (1/m)                (m/s²)
//! v' = v + a · h                    (m/s)
//! x' = x + v' · h                   (m)
//! ```
//!
//! which is what the general path computes in four passes over all slots (external forces,
//! each generator, F → a, kick and drift); pinned and dead slots (1/m = 0) keep x and v.
//! Here one loop over a block of [`BLOCK`] slots does it all per particle, reading each
//! slot's attributes once and writing x and v once. The kind of each generator is settled
//! before the step ([`LinearField`] holds only drag coefficients), so the particle loop
//! only runs over a short array of (kⱼ, group) pairs.
//!
//! # Exactness
//!
//! The same operations run on the same values in the same order as in the general path,
//! with the [guarded](crate::math::guarded) operators in place of the checked ones:
//! `mul_fraction` for v·kⱼ, a·h and v'·h (kⱼ and h are fractions, so these never leave
//! the range and equal the checked `*`), `guarded_sub`, `guarded_mul` and `guarded_add`
//! for the rest. Each guarded operator returns the checked operator's bits whenever that
//! does not saturate, and trips the block's guard whenever it might. The general path
//! forms g + F·(1/m) with the fused `add_scaled`, which equals the checked product followed
//! by the checked sum whenever neither saturates. So, per block:
//!
//! * guard clear → no operation of the block saturates in the general path either, and the
//!   block buffers hold its bits; they are copied to the state;
//! * guard tripped → the buffers are dropped and the block runs again through the general
//!   path's own functions restricted to the block ([`add_linear_drag`],
//!   [`forces_to_accelerations`], [`kick_then_drift`]), which saturate and count exactly as
//!   they do over all slots.
//!
//! Every particle's update reads only its own slot, so running the general path block by
//! block gives the same bits and the same saturation count as running it over all slots at
//! once. The guarded operators never count, so the counter sees exactly the general path's
//! saturations.
//!
//! # I32F32 in vector code
//!
//! On x86-64 processors with AVX2 or AVX-512 (the backend of
//! [`math::wide`](crate::math::wide)), I32F32 blocks go to [`kernel`] first: one pass takes
//! the magnitudes of the block's values, and when these bound every result of the block
//! inside the range (so that the general path saturates nowhere in it), the block is
//! computed in place, eight particles at a time, by exact integer identities for the
//! rounded products. Other blocks run as above. The result is the
//! general path's in every case; other processors, targets and formats never take this
//! path.

use super::forces::{LinearField, add_linear_drag, forces_to_accelerations};
use super::groups::applies_to;
use super::storage::{Attributes, Kinematics};
use crate::math::integration::kick_then_drift;
use crate::math::{Fraction, Guard, Real, Vec3};

/// Slots per block: the two block buffers (3 KiB for I32F32) stay in L1.
const BLOCK: usize = 64;

/// One semi-implicit Euler step of length `h` (s) of every movable particle in `field`.
///
/// I32F32 takes the vector kernel ([`kernel`]) on x86-64 processors that have AVX2 or
/// AVX-512; everything else takes the portable guarded computation. Both
/// give the general path's bits.
pub(super) fn step<R: Real>(
    field: &LinearField<R>,
    h: Fraction<R>,
    kinematics: &mut Kinematics<R>,
    attributes: &Attributes<R>,
) {
    #[cfg(vector_kernels)]
    if kernel::step(field, h, kinematics, attributes) {
        return;
    }
    step_portable(field, h, kinematics, attributes);
}

/// [`step`] with the portable guarded computation for every block.
pub(super) fn step_portable<R: Real>(
    field: &LinearField<R>,
    h: Fraction<R>,
    kinematics: &mut Kinematics<R>,
    attributes: &Attributes<R>,
) {
    for_each_block(kinematics, attributes, |block, buffers| {
        block.step_portable(buffers, field, h);
    });
}

/// Slots a chunk of a step split across a pool's workers holds: whole blocks, so the
/// blocks are those of one thread.
const CHUNK: usize = 16 * BLOCK;

/// Calls `f` on each block of [`BLOCK`] slots, with block buffers to reuse: in turn on one
/// thread, or in chunks of [`CHUNK`] slots across the workers when the loop splits
/// ([`crate::parallel::splits`]). Each block's step reads and writes its own slots only,
/// so the order changes no bit.
fn for_each_block<R: Real>(
    kinematics: &mut Kinematics<R>,
    attributes: &Attributes<R>,
    f: impl Fn(Block<'_, R>, &mut Buffers<R>) + Sync,
) {
    let slots = kinematics.positions.len();
    let chunk = if crate::parallel::splits() {
        CHUNK
    } else {
        slots.max(1)
    };
    let jobs: Vec<_> = kinematics
        .positions
        .chunks_mut(chunk)
        .zip(kinematics.velocities.chunks_mut(chunk))
        .enumerate()
        .map(|(c, (positions, velocities))| (c * chunk, positions, velocities))
        .collect();
    crate::parallel::for_each_job(jobs, |(first, positions, velocities)| {
        let mut buffers = Buffers::new();
        let mut start = 0;
        while start < positions.len() {
            let range = start..positions.len().min(start + BLOCK);
            let slots = first + range.start..first + range.end;
            f(
                Block {
                    positions: &mut positions[range.clone()],
                    velocities: &mut velocities[range.clone()],
                    external_forces: &attributes.external_forces[slots.clone()],
                    inv_masses: &attributes.inv_masses[slots.clone()],
                    groups: &attributes.groups[slots],
                },
                &mut buffers,
            );
            start = range.end;
        }
    });
}

/// The slots of one block.
struct Block<'a, R: Real> {
    positions: &'a mut [Vec3<R>],
    velocities: &'a mut [Vec3<R>],
    external_forces: &'a [Vec3<R>],
    inv_masses: &'a [R],
    groups: &'a [u16],
}

impl<R: Real> Block<'_, R> {
    /// The block's step with the portable guarded computation into `buffers`, copied to the
    /// state when its guard stays clear; through the general path's passes otherwise.
    fn step_portable(self, buffers: &mut Buffers<R>, field: &LinearField<R>, h: Fraction<R>) {
        if buffers.step_guarded(&self, field, h) {
            let len = self.positions.len();
            self.velocities.copy_from_slice(&buffers.velocities[..len]);
            self.positions.copy_from_slice(&buffers.positions[..len]);
        } else {
            self.step_checked(field, h.get());
        }
    }

    /// The general path's passes, restricted to the block.
    fn step_checked(self, field: &LinearField<R>, h: R) {
        let mut forces = [Vec3::ZERO; BLOCK];
        let forces = &mut forces[..self.positions.len()];
        forces.copy_from_slice(self.external_forces);
        for &(k, group) in field.drags() {
            add_linear_drag(
                k.get(),
                group,
                self.velocities,
                self.inv_masses,
                self.groups,
                forces,
            );
        }
        forces_to_accelerations(field.uniform_gravity, self.inv_masses, forces);
        kick_then_drift(
            forces,
            self.inv_masses,
            self.velocities,
            self.positions,
            h,
            h,
        );
    }
}

/// The block's new velocities and positions from the guarded computation, reused from
/// block to block.
struct Buffers<R: Real> {
    velocities: [Vec3<R>; BLOCK],
    positions: [Vec3<R>; BLOCK],
}

impl<R: Real> Buffers<R> {
    fn new() -> Self {
        Self {
            velocities: [Vec3::ZERO; BLOCK],
            positions: [Vec3::ZERO; BLOCK],
        }
    }

    /// Computes the block's new velocities (m/s) and positions (m) into the buffers by the
    /// equations of the module documentation, with guarded arithmetic; false when the guard
    /// tripped (the buffers are then meaningless).
    fn step_guarded(
        &mut self,
        block: &Block<'_, R>,
        field: &LinearField<R>,
        h: Fraction<R>,
    ) -> bool {
        let mut guard = Guard::new();
        let (g, drags) = (field.uniform_gravity, field.drags());
        let old = block.positions.iter().zip(block.velocities.iter());
        let new = self.positions.iter_mut().zip(self.velocities.iter_mut());
        let attributes = block
            .external_forces
            .iter()
            .zip(block.inv_masses.iter().zip(block.groups));
        for (((&x, &v), (new_x, new_v)), (&external, (&inv_mass, &group))) in
            old.zip(new).zip(attributes)
        {
            (*new_x, *new_v) = if inv_mass == R::ZERO {
                (x, v)
            } else {
                let mut force = external;
                for &(k, restriction) in drags {
                    if applies_to(restriction, group) {
                        force = zip_with(force, v, |f, v| {
                            f.guarded_sub(v.mul_fraction(k), &mut guard)
                        });
                    }
                }
                let a = zip_with(g, force, |g, f| {
                    g.guarded_add(f.guarded_mul(inv_mass, &mut guard), &mut guard)
                });
                let v = zip_with(v, a, |v, a| v.guarded_add(a.mul_fraction(h), &mut guard));
                let x = zip_with(x, v, |x, v| x.guarded_add(v.mul_fraction(h), &mut guard));
                (x, v)
            };
        }
        guard.is_clear()
    }
}

/// (f(aₓ, bₓ), f(a_y, b_y), f(a_z, b_z)).
#[inline(always)]
fn zip_with<R: Real>(a: Vec3<R>, b: Vec3<R>, mut f: impl FnMut(R, R) -> R) -> Vec3<R> {
    Vec3::new(f(a.x, b.x), f(a.y, b.y), f(a.z, b.z))
}

#[cfg(vector_kernels)]
mod kernel;
#[cfg(test)]
mod tests;
