//! The scene description of particle contacts and links (Millington's mass-aggregate
//! engine): what a scene says under `particles: Some((contacts: Some((...))))`.
//!
//! ```ron
//! contacts: Some((
//!     radius: 0.3,
//!     restitution: 0.2,
//!     planes: [(normal: (x: 0.0, y: 1.0, z: 0.0), offset: 0.0, restitution: 0.5)],
//!     links: [
//!         Rod(a: 0, b: 1, length: 0.8),
//!         Cable(a: 1, b: 2, max_length: 0.5, restitution: 0.1),
//!     ],
//!     iterations: 256,
//! ))
//! ```

use serde::{Deserialize, Serialize};

use crate::math::{Fx, Real, Vec3};

/// The most links a scene may have.
pub const MAX_LINKS: usize = 1 << 16;
/// The most planes a scene may have.
pub const MAX_PLANES: usize = 64;
/// The most contact resolutions per step a scene may ask for.
pub const MAX_ITERATIONS: u32 = 1 << 16;
/// The contact resolutions per step of a scene that does not say.
pub const DEFAULT_ITERATIONS: u32 = 256;

/// Contacts between particles, with planes, and hard links, resolved after every step
/// (see [`contacts`](super::contacts)).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct ContactsDesc<R: Real = Fx> {
    /// Every particle's radius for contacts, m (≥ 0). Particles of different groups touch
    /// when their centres are closer than 2 × radius (those of one group never touch each
    /// other: a group is one rope or bridge); a particle touches a plane when its centre is
    /// closer to it than the radius. 0 (the default): points, and no particle–particle
    /// contacts.
    #[serde(default)]
    pub radius: R,
    /// e in [0, 1] of particle–particle contacts. Default 0.5.
    #[serde(default = "half")]
    pub restitution: R,
    /// Planes the particles rest on and bounce off.
    #[serde(default)]
    pub planes: Vec<ContactPlaneDesc<R>>,
    /// Rods and cables between particles of the scene's `particles` list.
    #[serde(default)]
    pub links: Vec<LinkDesc<R>>,
    /// The most contact resolutions per step (1 to [`MAX_ITERATIONS`]). Default
    /// [`DEFAULT_ITERATIONS`]. Chains of links with heavy loads need many: each resolution
    /// fixes one contact and disturbs its neighbours.
    #[serde(default = "default_iterations")]
    pub iterations: u32,
}

impl<R: Real> Default for ContactsDesc<R> {
    /// Points, e = 0.5, no planes, no links.
    fn default() -> Self {
        Self {
            radius: R::ZERO,
            restitution: half(),
            planes: Vec::new(),
            links: Vec::new(),
            iterations: DEFAULT_ITERATIONS,
        }
    }
}

/// A fixed plane {x : n̂·x = offset}; particles stay on the side n̂ points to.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct ContactPlaneDesc<R: Real = Fx> {
    /// Normal (any non-zero length), out of the solid side.
    pub normal: Vec3<R>,
    /// Distance of the plane from the origin along the unit normal, m.
    #[serde(default)]
    pub offset: R,
    /// e in [0, 1]. Default 0.5.
    #[serde(default = "half")]
    pub restitution: R,
}

/// A hard link between two particles of the scene's `particles` list, resolved as a contact
/// each step.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub enum LinkDesc<R: Real = Fx> {
    /// Keeps the two particles exactly `length` m apart (> 0): pulls when longer, pushes
    /// when shorter, without bouncing.
    Rod {
        /// One end (index in `particles`).
        a: u32,
        /// The other end (≠ `a`).
        b: u32,
        /// ℓ, m.
        length: R,
    },
    /// Keeps the two particles at most `max_length` m apart (> 0): pulls when longer
    /// (bouncing back with restitution e), slack when shorter.
    Cable {
        /// One end (index in `particles`).
        a: u32,
        /// The other end (≠ `a`).
        b: u32,
        /// ℓ_max, m.
        max_length: R,
        /// e in [0, 1]. Default 0.
        #[serde(default)]
        restitution: R,
    },
}

fn default_iterations() -> u32 {
    DEFAULT_ITERATIONS
}

fn half<R: Real>() -> R {
    R::HALF
}
