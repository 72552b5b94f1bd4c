//! Surface materials and how two of them combine at a contact.

use serde::{Deserialize, Serialize};

use crate::math::{Fx, Real};

/// How a body's surface behaves in contact.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct Material<R: Real = Fx> {
    /// Coulomb friction coefficient μ (dimensionless, ≥ 0). Default 0.6.
    #[serde(default = "default_friction")]
    pub friction: R,
    /// Coefficient of restitution e (0 to 1): the ratio of separating to approaching
    /// normal speed in a collision faster than the restitution threshold. Default 0.
    #[serde(default)]
    pub restitution: R,
}

fn default_friction<R: Real>() -> R {
    R::from_ratio(3, 5)
}

impl<R: Real> Default for Material<R> {
    fn default() -> Self {
        Self {
            friction: default_friction(),
            restitution: R::ZERO,
        }
    }
}

/// The friction coefficient of a contact between two materials: the geometric mean
/// μ = √(μ_a μ_b), as in Box2D and Jolt. A frictionless surface makes every contact it
/// touches frictionless, and two equal materials keep their own μ.
pub fn mix_friction<R: Real>(a: R, b: R) -> R {
    (a * b).sqrt()
}

/// The restitution of a contact between two materials: the larger of the two,
/// e = max(e_a, e_b), as in Box2D and Jolt, so a bouncy ball bounces on any floor.
pub fn mix_restitution<R: Real>(a: R, b: R) -> R {
    a.max(b)
}
