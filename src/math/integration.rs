//! Time integration of point masses: the schemes a scene may choose, and the kick–drift
//! update that several of them (and the soft bodies' spring-mass model) share.

use core::fmt;

use serde::{Deserialize, Serialize};

use super::{Real, Vec3};

/// An integration scheme, chosen per particle system in the scene.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Integrator {
    /// Forward Euler: x ← x + h v, v ← v + h a(x, v). First order; its energy grows by
    /// (1 + (ωh)²) per step on an oscillator, so it never conserves anything. For comparison.
    ExplicitEuler,
    /// Symplectic (semi-implicit) Euler: v ← v + h a(x, v), then x ← x + h v. First order,
    /// one evaluation per step, bounded energy on an oscillator while ωh < 2.
    #[default]
    SemiImplicitEuler,
    /// Position (Störmer–)Verlet: x_{n+1} = 2x_n − x_{n−1} + h² a(x_n, v_n), started by
    /// x₁ = x₀ + h v₀ + ½ h² a₀. The velocity is reconstructed as
    /// v_{n+1} = (x_{n+1} − x_n)/h + ½ h a_n (exact for constant a). Second order,
    /// symplectic, one evaluation per step. Since (x_n − x_{n−1})/h is a mid-step velocity,
    /// the scheme restarts from (x, v) whenever the forcing jumps (a spawn, a velocity
    /// change, an external force applied or cleared, a gravity change), so that a force
    /// acting for a tick delivers exactly its impulse. In fixed point the h² a term rounds to
    /// zero below ½ ulp / h², so accelerations smaller than that are lost.
    StormerVerlet,
    /// Velocity Verlet (kick–drift–kick): v_{n+½} = v_n + ½ h a_n, x_{n+1} = x_n + h v_{n+½},
    /// a_{n+1} = a(x_{n+1}, v_{n+½}), v_{n+1} = v_{n+½} + ½ h a_{n+1}. Second order,
    /// symplectic. a_{n+1} is kept for the next step, so it costs one evaluation per step
    /// unless something invalidates it (a command, a spawn, a death, a gravity change, the
    /// end of a tick with external forces), which costs one more.
    VelocityVerlet,
    /// Leapfrog in drift–kick–drift form: x_{n+½} = x_n + ½ h v_n,
    /// v_{n+1} = v_n + h a(x_{n+½}, v_n), x_{n+1} = x_{n+½} + ½ h v_{n+1}. Second order,
    /// symplectic, one evaluation per step and no stored acceleration (the kick–drift–kick
    /// form is [`Integrator::VelocityVerlet`]).
    Leapfrog,
    /// Classical fourth-order Runge–Kutta on (x, v), with forces evaluated at its four
    /// stages. Fourth order, four evaluations per step, slightly dissipative.
    Rk4,
    /// Backward (implicit) Euler on the springs and dampers (Baraff & Witkin 1998):
    /// (M + h C + h² K) Δv = h (f(x, v) − h K v), v ← v + Δv, x ← x + h v, with K and C the
    /// springs' stiffness and damping matrices (and linear drags in C); other forces act
    /// explicitly. First order, one evaluation and one linear solve per step
    /// ([`implicit_springs`](super::implicit_springs)), stable on springs at any step, and
    /// dissipative: an undamped oscillator loses the factor 1/(1 + (ωh)²) of its energy per
    /// step.
    ImplicitEuler,
}

impl Integrator {
    /// Every scheme, in declaration order.
    pub const ALL: [Self; 7] = [
        Self::ExplicitEuler,
        Self::SemiImplicitEuler,
        Self::StormerVerlet,
        Self::VelocityVerlet,
        Self::Leapfrog,
        Self::Rk4,
        Self::ImplicitEuler,
    ];

    /// Global order of accuracy p: the error at a fixed time shrinks as hᵖ.
    pub const fn order(self) -> u32 {
        match self {
            Self::ExplicitEuler | Self::SemiImplicitEuler | Self::ImplicitEuler => 1,
            Self::StormerVerlet | Self::VelocityVerlet | Self::Leapfrog => 2,
            Self::Rk4 => 4,
        }
    }

    /// Whether the scheme is symplectic (bounded energy error, no drift, for conservative
    /// forces and a stable step).
    pub const fn is_symplectic(self) -> bool {
        matches!(
            self,
            Self::SemiImplicitEuler | Self::StormerVerlet | Self::VelocityVerlet | Self::Leapfrog
        )
    }

    /// The scheme's name as written in scene files.
    pub const fn name(self) -> &'static str {
        match self {
            Self::ExplicitEuler => "ExplicitEuler",
            Self::SemiImplicitEuler => "SemiImplicitEuler",
            Self::StormerVerlet => "StormerVerlet",
            Self::VelocityVerlet => "VelocityVerlet",
            Self::Leapfrog => "Leapfrog",
            Self::Rk4 => "Rk4",
            Self::ImplicitEuler => "ImplicitEuler",
        }
    }

    /// The number that stands for the scheme in the state hash (its position in
    /// [`Integrator::ALL`]).
    pub(crate) const fn code(self) -> u32 {
        self as u32
    }
}

impl fmt::Display for Integrator {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// For every movable point mass (inverse mass not 0): v ← v + h_kick·a, then x ← x + h_drift·v (the new v), with
/// a (m/s²) from `accelerations` and the steps in s. All slices cover the same slots.
pub fn kick_then_drift<R: Real>(
    accelerations: &[Vec3<R>],
    inv_masses: &[R],
    velocities: &mut [Vec3<R>],
    positions: &mut [Vec3<R>],
    h_kick: R,
    h_drift: R,
) {
    let particles = accelerations
        .iter()
        .zip(inv_masses)
        .zip(velocities.iter_mut().zip(positions.iter_mut()));
    for ((&a, &inv_mass), (v, x)) in particles {
        if inv_mass != R::ZERO {
            *v = v.add_scaled(a, h_kick);
            *x = x.add_scaled(*v, h_drift);
        }
    }
}
