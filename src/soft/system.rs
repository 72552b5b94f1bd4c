//! `SoftSystem`: the soft bodies of a world, stored as structure-of-arrays, and one step of
//! their motion.

use serde::{Deserialize, Serialize};

use super::body_coupling::{BodyContacts, CouplingScratch, Ties};
use super::collide::Collider;
use super::constraints::{
    Attachments, ColourRuns, DistanceFactors, Distances, Hinges, Tethers, Tetrahedra,
};
use super::desc::XpbdSettings;
use super::rigid_bodies::RigidBodies;
use super::spring_mass::Springs;
use crate::math::integration::Integrator;
use crate::math::{Fx, Real, Vec3};

/// The vertices of every soft body, body after body.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Vertices<R: Real> {
    /// x, m.
    pub position: Vec<Vec3<R>>,
    /// v, m/s.
    pub velocity: Vec<Vec3<R>>,
    /// m, kg.
    pub mass: Vec<R>,
    /// w = 1/m, 1/kg; 0 for a pinned vertex.
    pub inv_mass: Vec<R>,
}

impl<R: Real> Vertices<R> {
    /// Number of vertices.
    pub fn len(&self) -> usize {
        self.position.len()
    }
}

/// How a body is advanced.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) enum Model<R: Real> {
    /// By the XPBD solver, with every other XPBD body.
    Xpbd,
    /// By `integrator`, with the springs `springs.0..springs.1` of stiffness k (N/m) and
    /// damping c (N·s/m).
    SpringMass {
        integrator: Integrator,
        stiffness: R,
        damping: R,
        springs: (u32, u32),
    },
}

/// One body: its vertex range and the parameters shared by its vertices.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Body<R: Real> {
    /// Vertices `first..end`.
    pub first: u32,
    /// One past the last vertex.
    pub end: u32,
    pub model: Model<R>,
    /// Velocity damping c, 1/s.
    pub damping: R,
    /// Collision radius, m.
    pub radius: R,
    /// Air velocity, m/s.
    pub wind: Vec3<R>,
    /// Air drag per vertex, kg/s.
    pub drag: R,
    /// How the vertices touch the rigid bodies, if they do.
    pub contacts: Option<BodyContacts<R>>,
}

impl<R: Real> Body<R> {
    /// The body's vertex indices.
    pub fn range(&self) -> core::ops::Range<usize> {
        self.first as usize..self.end as usize
    }
}

/// Soft bodies: XPBD cloths, ropes and jellies, and spring-mass networks.
///
/// A step ([`SoftSystem::step`]) advances, in order:
/// 1. the XPBD bodies together, in `substeps` substeps (see [`xpbd`](super::xpbd));
/// 2. each spring-mass body with its integrator (see [`spring_mass`](super::spring_mass)).
///
/// Each part is skipped, without a loop, when no body uses it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct SoftSystem<R: Real = Fx> {
    pub(crate) settings: XpbdSettings,
    pub(crate) vertices: Vertices<R>,
    pub(crate) bodies: Vec<Body<R>>,
    pub(crate) distances: Distances<R>,
    pub(crate) hinges: Hinges<R>,
    pub(crate) tetrahedra: Tetrahedra<R>,
    pub(crate) attachments: Attachments<R>,
    /// Vertices tied to rigid bodies.
    pub(crate) ties: Ties<R>,
    pub(crate) tethers: Tethers<R>,
    pub(crate) springs: Springs<R>,
    pub(crate) colliders: Vec<Collider<R>>,
    /// Whether any body is XPBD.
    pub(crate) has_xpbd: bool,
    #[serde(skip)]
    pub(crate) scratch: Scratch<R>,
    /// Warnings found when the system was built (not state).
    #[serde(skip)]
    pub(crate) warnings: Vec<String>,
}

/// Per-step working memory and values derived from the state and the step length: never
/// part of the state, rebuilt when missing, equal to any other scratch. A clone starts
/// empty.
#[derive(Debug, Default)]
pub(crate) struct Scratch<R: Real> {
    /// The XPBD substep h the cached values below were computed for, s.
    pub substep: Option<R>,
    /// Positions at the start of the substep.
    pub previous: Vec<Vec3<R>>,
    /// Shares and relaxations of the distance rows.
    pub distance: DistanceFactors<R>,
    /// The distance rows' runs that share no vertex (built on a pool's first split pass).
    pub distance_runs: ColourRuns<2>,
    /// The bending rows' runs that share no vertex.
    pub hinge_runs: ColourRuns<4>,
    /// The chunks' copies of a run's moved vertices in a split pass, m.
    pub moved: Vec<Vec3<R>>,
    /// Whether tethers 8k..8k+8 are independent, for each k (see
    /// [`Tethers::independent_blocks`]).
    #[cfg(vector_kernels)]
    pub tether_blocks: Vec<bool>,
    /// Whether hinges 8k..8k+8 share no vertex, for each k (see
    /// [`Hinges::independent_blocks`]).
    #[cfg(vector_kernels)]
    pub hinge_blocks: Vec<bool>,
    /// wₖcₖ/D of each hinge, m.
    pub hinge_share: Vec<[R; 4]>,
    /// α̃/D of each hinge.
    pub hinge_relax: Vec<R>,
    /// w/D of each attachment row.
    pub attachment_share: Vec<R>,
    /// α̃/D of each attachment row.
    pub attachment_relax: Vec<R>,
    /// 1/h², 1/s².
    pub inv_h2: R,
    /// Each attachment target's displacement in the current substep, m.
    pub displacement: Vec<Vec3<R>>,
    /// a, m/s², of the spring-mass vertices.
    pub acceleration: Vec<Vec3<R>>,
    /// The implicit Euler system of a spring-mass body.
    pub implicit: crate::math::implicit_springs::ImplicitSprings<R>,
    /// Its vertices' masses, kg, 0 for pinned ones.
    pub implicit_masses: Vec<R>,
    /// The rigid bodies in view during a coupled step.
    pub coupling: CouplingScratch<R>,
}

impl<R: Real> Clone for Scratch<R> {
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl<R: Real> PartialEq for Scratch<R> {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl<R: Real> SoftSystem<R> {
    /// Advances every body by `dt` seconds under `gravity` (m/s²). This is world substep
    /// `substep` of `substeps` in the tick: kinematic attachment targets move along a
    /// straight line from their place at the start of the tick to their goal, reached at the
    /// end of the last substep.
    pub fn step(&mut self, dt: R, gravity: Vec3<R>, substep: u32, substeps: u32) {
        self.step_with_bodies(dt, gravity, (substep, substeps), None);
    }

    /// [`step`](Self::step) with the rigid bodies in view, when some vertex touches or is
    /// tied to them ([`body_coupling`](super::body_coupling)).
    pub(crate) fn step_with_bodies(
        &mut self,
        dt: R,
        gravity: Vec3<R>,
        (substep, substeps): (u32, u32),
        bodies: Option<&mut dyn RigidBodies<R>>,
    ) {
        if substep == 0 {
            self.scratch.coupling.impulse = Vec3::ZERO;
        }
        if self.has_xpbd {
            self.step_xpbd(dt, gravity, (substep, substeps), bodies);
        }
        for b in 0..self.bodies.len() {
            if let Model::SpringMass { .. } = self.bodies[b].model {
                self.step_spring_mass(b, dt, gravity);
            }
        }
    }

    /// Ends the tick: every kinematic target is at its goal.
    pub fn end_tick(&mut self) {
        self.attachments.start.clone_from(&self.attachments.goal);
    }

    /// Puts `other`'s state in place, keeping this system's buffers and warnings.
    pub fn restore_from(&mut self, other: Self) {
        let scratch = core::mem::take(&mut self.scratch);
        let warnings = core::mem::take(&mut self.warnings);
        *self = other;
        self.scratch = scratch;
        self.scratch.substep = None;
        self.warnings = warnings;
    }

    /// The solver settings.
    pub fn settings(&self) -> &XpbdSettings {
        &self.settings
    }

    /// Number of vertices over all bodies.
    pub fn vertex_count(&self) -> usize {
        self.vertices.len()
    }

    /// Number of bodies.
    pub fn body_count(&self) -> usize {
        self.bodies.len()
    }

    /// The vertices of body `body`, as a range of vertex indices.
    pub fn body_vertices(&self, body: usize) -> Option<core::ops::Range<usize>> {
        self.bodies.get(body).map(Body::range)
    }

    /// Position of vertex `i`, m.
    pub fn position(&self, i: usize) -> Option<Vec3<R>> {
        self.vertices.position.get(i).copied()
    }

    /// Velocity of vertex `i`, m/s.
    pub fn velocity(&self, i: usize) -> Option<Vec3<R>> {
        self.vertices.velocity.get(i).copied()
    }

    /// Every vertex position, m.
    pub fn positions(&self) -> &[Vec3<R>] {
        &self.vertices.position
    }

    /// Moves vertex `i` to `position` (m) at rest, as if teleported (for example to start
    /// from a crumpled shape); false when there is no such vertex. Pinned vertices move too
    /// and stay pinned at their new place.
    pub fn set_position(&mut self, i: usize, position: Vec3<R>) -> bool {
        match (
            self.vertices.position.get_mut(i),
            self.vertices.velocity.get_mut(i),
        ) {
            (Some(x), Some(v)) => {
                *x = position;
                *v = Vec3::ZERO;
                true
            }
            _ => false,
        }
    }

    /// The vertex pairs of every XPBD distance row, then of every spring, in row order:
    /// the edges of the bodies' meshes.
    pub fn edges(&self) -> impl Iterator<Item = (u32, u32)> + '_ {
        let rows = self.distances.a.iter().zip(&self.distances.b);
        let springs = self.springs.a.iter().zip(&self.springs.b);
        rows.chain(springs).map(|(&a, &b)| (a, b))
    }

    /// Number of XPBD distance constraints.
    pub fn distance_count(&self) -> usize {
        self.distances.a.len()
    }

    /// Warnings found when the system was built: spring-mass networks whose stiffest mode
    /// is past the stability bound of their integrator at the world's step.
    pub fn warnings(&self) -> &[String] {
        &self.warnings
    }
}
