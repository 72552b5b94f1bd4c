//! A hull's mass properties (placeholder until the volume integrals land).

use super::hull::ConvexHull;
use crate::math::Real;
use crate::rigid::mass::MassProperties;

impl<R: Real> ConvexHull<R> {
    /// The mass properties of the hull filled at `density` (kg/m³).
    pub fn mass_properties(&self, _density: R) -> MassProperties<R> {
        MassProperties::ZERO
    }
}
