//! The characters' canonical hash: the character count, then per character in index order
//! its shape (a code, 0 sphere, 1 capsule, 2 box, and its sizes), settings (max slope,
//! step height, snap distance, skin, jump speed, push mass, layers, mask), position,
//! velocity, desired velocity, jump flag, grounded flag, ground normal, ground body (a flag,
//! then index and generation), and the bodies touched (count, then index and generation
//! each). Scalars as their fixed-point bits, little-endian.

use super::system::{Character, CharacterSystem};
use crate::math::Real;
use crate::math::state_hash::StateHasher;
use crate::rigid::Shape;
use crate::types::Handle;

fn write_handle(h: &mut StateHasher, handle: Handle) {
    h.write_u32(handle.index);
    h.write_u32(handle.generation);
}

/// One character's canonical bytes.
pub(super) fn hash_character<R: Real>(c: &Character<R>, h: &mut StateHasher) {
    match &c.shape {
        Shape::Sphere { radius } => {
            h.write_u8(0);
            h.write_real(*radius);
        }
        Shape::Capsule {
            radius,
            half_height,
        } => {
            h.write_u8(1);
            h.write_real(*radius);
            h.write_real(*half_height);
        }
        Shape::Box { half_extents } => {
            h.write_u8(2);
            h.write_vec3(*half_extents);
        }
        _ => h.write_u8(255),
    }
    let s = &c.settings;
    for v in [
        s.max_slope,
        s.step_height,
        s.snap_distance,
        s.skin,
        s.jump_speed,
        s.push_mass,
    ] {
        h.write_real(v);
    }
    h.write_u32(s.filter.layers);
    h.write_u32(s.filter.mask);
    h.write_vec3(c.position);
    h.write_vec3(c.velocity);
    h.write_vec3(c.desired_velocity);
    h.write_u8(u8::from(c.jump));
    h.write_u8(u8::from(c.grounded));
    h.write_vec3(c.ground_normal);
    match c.ground_body {
        Some(body) => {
            h.write_u8(1);
            write_handle(h, body);
        }
        None => h.write_u8(0),
    }
    h.write_len(c.touching.len());
    for &body in &c.touching {
        write_handle(h, body);
    }
}

impl<R: Real> CharacterSystem<R> {
    /// The canonical hash of every character (see the [module](self)).
    pub fn hash_state(&self, h: &mut StateHasher) {
        h.write_len(self.characters.len());
        for c in &self.characters {
            hash_character(c, h);
        }
    }

    /// One 32-bit digest per character, in index order.
    pub fn slot_digests(&self) -> Vec<(crate::types::Handle, u32)> {
        self.characters
            .iter()
            .enumerate()
            .map(|(i, c)| {
                let mut h = StateHasher::new();
                hash_character(c, &mut h);
                (Self::handle(i), h.finish() as u32)
            })
            .collect()
    }
}
