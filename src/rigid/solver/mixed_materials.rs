//! The mixed friction and restitution of a contact's pair of materials
//! ([`mix_friction`], [`mix_restitution`]), remembered for the last pair met: in a scene
//! of one or a few materials the consecutive contacts of the preparation mostly share
//! their pair, and the square root of the friction mix is then taken once per run of
//! them instead of once per contact. A mix that saturates (μ_a μ_b out of range) is not
//! remembered, so that each contact still counts its saturation.

use crate::math::Real;
use crate::math::saturation::count_saturations;
use crate::rigid::material::{Material, mix_friction, mix_restitution};

/// The last pair of materials mixed and its mix (μ, e) (dimensionless).
#[derive(Clone, Copy, Debug)]
pub(super) struct MixedMaterials<R: Real> {
    last: Option<Remembered<R>>,
}

/// A pair of materials and its mix (μ, e).
type Remembered<R> = ([Material<R>; 2], (R, R));

impl<R: Real> MixedMaterials<R> {
    /// No pair met yet.
    pub const EMPTY: Self = Self { last: None };

    /// (μ, e) = (√(μ_a μ_b), max(e_a, e_b)) for materials `a` and `b`: the remembered mix
    /// when both are bit for bit the last pair's (the functions are pure, so the same
    /// bits in give the same bits out), computed otherwise, and remembered when it did not
    /// saturate.
    pub fn of(&mut self, a: &Material<R>, b: &Material<R>) -> (R, R) {
        let same = |x: &Material<R>, y: &Material<R>| {
            x.friction.canonical_bits() == y.friction.canonical_bits()
                && x.restitution.canonical_bits() == y.restitution.canonical_bits()
        };
        match self.last {
            Some(([la, lb], mix)) if same(&la, a) && same(&lb, b) => mix,
            _ => {
                let (mix, saturations) = count_saturations(|| {
                    (
                        mix_friction(a.friction, b.friction),
                        mix_restitution(a.restitution, b.restitution),
                    )
                });
                self.last = (saturations == 0).then_some(([*a, *b], mix));
                mix
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::MixedMaterials;
    use crate::math::saturation::count_saturations;
    use crate::math::{Fx, FxI48F16, Pcg32, Real};
    use crate::rigid::material::{Material, mix_friction, mix_restitution};

    /// Along a long random sequence of pairs from `pool` (so that pairs repeat, as in a
    /// scene, and change), each mix and its saturation count are those of the functions.
    fn matches_the_functions<R: Real>(pool: &[Material<R>]) {
        let mut rng = Pcg32::new(7, 11);
        let mut mixed = MixedMaterials::EMPTY;
        let (mut i, mut j) = (0, 0);
        for _ in 0..20_000 {
            if rng.below(4) == 0 {
                i = rng.below(pool.len() as u32) as usize;
                j = rng.below(pool.len() as u32) as usize;
            }
            let (a, b) = (&pool[i], &pool[j]);
            let (got, got_count) = count_saturations(|| mixed.of(a, b));
            let (want, want_count) = count_saturations(|| {
                (
                    mix_friction(a.friction, b.friction),
                    mix_restitution(a.restitution, b.restitution),
                )
            });
            let bits = |(f, e): (R, R)| (f.canonical_bits(), e.canonical_bits());
            assert_eq!(bits(got), bits(want), "{a:?} {b:?}");
            assert_eq!(got_count, want_count, "{a:?} {b:?}");
        }
    }

    /// A pool of materials: the default, frictionless, bouncy, tiny and huge friction
    /// (whose products saturate in fixed point), negative values, random ones and
    /// neighbours one ulp apart.
    fn pool<R: Real>() -> Vec<Material<R>> {
        let mut rng = Pcg32::new(3, 5);
        let material = |friction, restitution| Material {
            friction,
            restitution,
        };
        let mut pool = vec![
            Material::default(),
            material(R::ZERO, R::ZERO),
            material(R::ONE, R::ONE),
            material(R::EPSILON, R::from_ratio(1, 2)),
            material(R::MAX, R::ZERO),
            material(R::from_int(100_000), R::MAX),
            material(-R::ONE, -R::EPSILON),
        ];
        for _ in 0..6 {
            pool.push(material(rng.unit(), rng.unit()));
        }
        // Neighbours of (1, 1) one ulp apart in either field, which must not share its mix.
        pool.push(material(R::ONE + R::EPSILON, R::ONE));
        pool.push(material(R::ONE, R::ONE + R::EPSILON));
        pool
    }

    #[test]
    fn mixes_match_the_functions_with_their_saturations() {
        matches_the_functions::<Fx>(&pool());
        matches_the_functions::<FxI48F16>(&pool());
        let mut floats = pool::<f64>(); // ok-det: test of the f64 reference format
        floats.push(Material {
            friction: -0.0,
            restitution: -0.0,
        });
        floats.push(Material {
            friction: f64::NAN, // ok-det: test of the f64 reference format
            restitution: 0.5,
        });
        matches_the_functions::<f64>(&floats); // ok-det: test of the f64 reference format
    }

    /// Saturating mixes are not remembered: each one counts its own saturation.
    #[test]
    fn a_saturating_mix_counts_at_every_contact() {
        let huge = Material {
            friction: Fx::MAX,
            restitution: Fx::ZERO,
        };
        let mut mixed = MixedMaterials::EMPTY;
        let ((), count) = count_saturations(|| {
            for _ in 0..3 {
                mixed.of(&huge, &huge);
            }
        });
        assert_eq!(count, 3);
    }
}
