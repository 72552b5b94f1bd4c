//! The world: simulated state, its subsystems, and the tick.

use serde::{Deserialize, Serialize};

use super::character_coupling::step_characters;
use super::checksum::Checksum;
use super::divergence::{Divergence, DivergenceMonitor};
use super::fluid_coupling::step_fluid_with_bodies;
use super::health::{Health, SaturationSite};
use super::particle_coupling::step_colliding_particles;
use super::soft_coupling::step_rigid_and_soft;
use super::stage::StageTimings;
use super::stage_watch::StageWatch;
use super::water_coupling::apply_float_forces;
use crate::character::CharacterSystem;
use crate::fluid::FluidSystem;
use crate::math::rng::Pcg32;
use crate::math::saturation::count_saturations;
use crate::math::state_hash::StateHasher;
use crate::math::{Fx, Real, Vec3};
use crate::parallel::Pool;
use crate::particles::ParticleSystem;
use crate::rigid::proxies::Proxies;
use crate::rigid::{Event, RigidSystem};
use crate::soft::SoftSystem;
use crate::types::{
    Command, Handle, Metrics, Part, PlayerInput, SceneError, Stage, StepContext, Subsystem, Target,
    TickInput, check_rates,
};
use crate::water::WaterSystem;

/// The version of the simulated state. It names the physics as much as the layout: bump it
/// whenever a change alters any committed checksum, re-record `replays/`
/// (`scripts/rerecord.sh`) and say why in `CHANGELOG.md`, which lists every version.
///
/// 2: the rigid solver visits its contacts in batches of eight that share no moving body
/// (so that a batch can be solved side by side) rather than one by one in contact order.
///
/// 3: DFSPH runs a divergence-free solve before its constant-density solve, and both iterate
/// until no particle is predicted more than 10 % compressed (stable at the time-step limit
/// and at a loose tolerance).
///
/// 4: rigid friction once per contact (two tangent rows at the centre of its points and a
/// twist row, Rapier's default model: contacts carry one friction and one twist impulse
/// instead of tangent impulses per point), 5 solver substeps by default instead of 4 (the
/// tall `pyramid` came to rest only by chance with 4), and `Quat::integrate` renormalising
/// by two Newton steps instead of a square root and divisions.
///
/// 5: contact recycling (`contact_recycle_distance`, default 1 mm): a box or capsule pair
/// that has moved less than that relative to its last narrowphase carries its contact
/// points with the bodies instead of recomputing them; the contacts' recycling frames are
/// state (snapshots, checksums), and the rigid solver settings gain the distance.
///
/// 6: restitution acts on the speed of the impact (gravity's share of the step included),
/// giving the next flight e² times the height of the last (`rigid::solver::bounce`).
///
/// 7: joints aim at the end of each substep (a second-order drift term for ball anchors and
/// distance rows), jointed bodies' inverse inertias turn with them every substep and their
/// gyroscopic term is solved with their joints; bounces that reach chains of touching
/// bodies are resolved contact by contact, the largest closing speed first
/// (`rigid::solver::contact_constraint::BounceChains`).
///
/// 8: a ball joint's centripetal drift term is taken from the velocities the positions were
/// just integrated with (it was fixed when the joint was built), and a jointed body's
/// gyroscopic term takes one more Newton step after the last relax pass: a spinning heavy
/// top precesses within 0.6 % of the exact rate at 5 substeps (was −1.9 %).
pub const STATE_VERSION: u32 = 8;

/// The RNG stream of the world's generator (the seed comes from the scene).
const RNG_STREAM: u64 = 0x6669_7873_7465_7021; // "fixstep!"

/// Settings that inputs may change during a run, so they are part of the state.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Settings<R: Real = Fx> {
    /// Gravitational acceleration, m/s².
    pub gravity: Vec3<R>,
    /// Ticks per simulated second.
    pub tick_rate: u32,
    /// Substeps per tick; each advances the subsystems by 1 / (tick_rate · substeps) s.
    pub substeps: u32,
}

/// Everything that determines the future of a world. Snapshots copy it whole; checksums
/// hash it canonically.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct WorldState<R: Real = Fx> {
    /// Ticks completed since the scene was loaded.
    pub tick: u64,
    /// Gravity, tick rate and substeps.
    pub settings: Settings<R>,
    /// The world's seeded generator; subsystems draw from it in stage order.
    pub rng: Pcg32,
    /// A running hash of every [`Command::Payload`] applied, with its tick and player.
    pub payload_digest: u64,
    /// Particles, when the scene has any.
    pub particles: Option<ParticleSystem<R>>,
    /// Rigid bodies, when the scene has any.
    pub rigid: Option<RigidSystem<R>>,
    /// Soft bodies, when the scene has any.
    pub soft: Option<SoftSystem<R>>,
    /// The fluid, when the scene has one.
    pub fluid: Option<FluidSystem<R>>,
    /// Kinematic characters, when the scene has any.
    pub characters: Option<CharacterSystem<R>>,
    /// The water surface, when the scene has one.
    pub water: Option<WaterSystem<R>>,
}

impl<R: Real> WorldState<R> {
    /// Checks the invariants a world relies on, for a state that comes from outside (a
    /// snapshot); the error names the offending field.
    pub fn validate(&self) -> Result<(), SceneError> {
        check_rates(self.settings.tick_rate, self.settings.substeps)
            .map_err(|e| e.within("settings"))?;
        for subsystem in self.subsystems().into_iter().flatten() {
            subsystem
                .validate()
                .map_err(|e| e.within(subsystem.part().name()))?;
        }
        Ok(())
    }

    /// The first object of `stage`'s subsystem holding a value at the edge of the numeric
    /// range ([`Subsystem::saturated_object`]), with the subsystem's part; `None` when the
    /// scene has no such subsystem or no object does.
    fn saturated_object(&self, stage: Stage) -> Option<(Part, Handle)> {
        self.subsystems()
            .into_iter()
            .flatten()
            .find(|s| s.stage() == stage)
            .and_then(|s| s.saturated_object().map(|handle| (s.part(), handle)))
    }

    /// The subsystems, in [`Stage`] order, `None` where the scene has none. With
    /// [`WorldState::split_mut`] and [`WorldState::keep_unsimulated`], the place that lists
    /// the subsystem fields: a new subsystem is added there.
    pub fn subsystems(&self) -> [Option<&dyn Subsystem<R>>; 6] {
        [
            self.particles.as_ref().map(|s| s as &dyn Subsystem<R>),
            self.rigid.as_ref().map(|s| s as &dyn Subsystem<R>),
            self.soft.as_ref().map(|s| s as &dyn Subsystem<R>),
            self.fluid.as_ref().map(|s| s as &dyn Subsystem<R>),
            self.characters.as_ref().map(|s| s as &dyn Subsystem<R>),
            self.water.as_ref().map(|s| s as &dyn Subsystem<R>),
        ]
    }

    /// The settings and the generator beside the mutable subsystems in [`Stage`] order
    /// (`None` where absent), borrowed apart so that a stage can step with both.
    fn split_mut(&mut self) -> (&Settings<R>, &mut Pcg32, SubsystemsMut<'_, R>) {
        let subsystems = [
            self.particles.as_mut().map(|s| s as &mut dyn Subsystem<R>),
            self.rigid.as_mut().map(|s| s as &mut dyn Subsystem<R>),
            self.soft.as_mut().map(|s| s as &mut dyn Subsystem<R>),
            self.fluid.as_mut().map(|s| s as &mut dyn Subsystem<R>),
            self.characters.as_mut().map(|s| s as &mut dyn Subsystem<R>),
            self.water.as_mut().map(|s| s as &mut dyn Subsystem<R>),
        ];
        (&self.settings, &mut self.rng, subsystems)
    }

    /// Gives each subsystem present in both `self` (restored from a snapshot) and `current`
    /// what `current` keeps outside the simulated state ([`Subsystem::restore_from`]),
    /// taking `current`'s subsystems.
    fn keep_unsimulated(&mut self, current: &mut Self) {
        keep_unsimulated(&mut self.particles, current.particles.take());
        keep_unsimulated(&mut self.rigid, current.rigid.take());
        keep_unsimulated(&mut self.soft, current.soft.take());
        keep_unsimulated(&mut self.fluid, current.fluid.take());
        keep_unsimulated(&mut self.characters, current.characters.take());
        keep_unsimulated(&mut self.water, current.water.take());
    }
}

impl<R: Real> WorldState<R> {
    /// One tick of the subsystem of `stage`, if the scene has it, on its own.
    fn step_alone(&mut self, stage: Stage, watch: &mut StageWatch, dt: R) {
        let (settings, rng, subsystems) = self.split_mut();
        if let Some(subsystem) = subsystems
            .into_iter()
            .flatten()
            .find(|s| s.stage() == stage)
        {
            watch.run(stage, || step_subsystem(subsystem, settings, rng, dt));
        }
    }

    /// The rigid and soft stages, when some soft body touches or is tied to the rigid
    /// bodies: steps them together ([`soft_coupling`](super::soft_coupling)) and returns
    /// true; otherwise does nothing and returns false.
    fn step_coupled_soft(
        &mut self,
        watch: &mut StageWatch,
        dt: R,
        proxies: &mut Proxies<R>,
    ) -> bool {
        let (Some(rigid), Some(soft)) = (&mut self.rigid, &mut self.soft) else {
            return false;
        };
        if !soft.couples() {
            return false;
        }
        step_rigid_and_soft(
            rigid,
            soft,
            proxies,
            (&self.settings, &mut self.rng, dt),
            |stage, f| watch.run(stage, f),
        );
        true
    }

    /// The fluid stage, when the fluid meets the rigid bodies: steps it with them in the
    /// fluid ([`fluid_coupling`](super::fluid_coupling)) and returns true; otherwise does
    /// nothing and returns false.
    fn step_coupled_fluid(&mut self, watch: &mut StageWatch, dt: R) -> bool {
        let (Some(fluid), Some(rigid)) = (&mut self.fluid, &mut self.rigid) else {
            return false;
        };
        let Some(filter) = fluid.settings().bodies else {
            return false;
        };
        step_fluid_with_bodies(
            fluid,
            rigid,
            filter,
            (&self.settings, &mut self.rng, dt),
            |stage, f| watch.run(stage, f),
        );
        true
    }

    /// The particle stage, when some particle group collides with the rigid bodies: steps
    /// it with the bodies in view ([`particle_coupling`](super::particle_coupling)) and
    /// returns true; otherwise does nothing and returns false.
    fn step_coupled_particles(&mut self, watch: &mut StageWatch, substep_dt: R) -> bool {
        let (Some(particles), Some(rigid)) = (&mut self.particles, &mut self.rigid) else {
            return false;
        };
        if !particles.collides() {
            return false;
        }
        watch.run(Stage::Particles, || {
            step_colliding_particles(particles, rigid, &self.settings, &mut self.rng, substep_dt);
        });
        true
    }
}

/// `restored`, rebuilt on `current` so that it keeps `current`'s registered user forces,
/// scratch memory and warnings, when both are present.
fn keep_unsimulated<R: Real, S: Subsystem<R>>(restored: &mut Option<S>, current: Option<S>) {
    *restored = match (current, restored.take()) {
        (Some(mut current), Some(state)) => {
            current.restore_from(state);
            Some(current)
        }
        (_, state) => state,
    };
}

/// The mutable subsystems of a state in [`Stage`] order, `None` where absent.
type SubsystemsMut<'a, R> = [Option<&'a mut dyn Subsystem<R>>; 6];

/// Per-part lists of (object handle, 32-bit state digest), in [`Part`] order.
pub type ObjectDigests = Vec<(Part, Vec<(Handle, u32)>)>;

/// What happened during one tick, besides the state change. Not part of the state (but
/// derived from it: a re-simulated tick reports the same).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TickReport {
    /// Commands whose target did not exist.
    pub ignored_commands: u32,
    /// Fixed-point operations that saturated during the tick.
    pub saturations: u64,
    /// Where the tick's first saturation happened, when it had any.
    pub first_saturation: Option<SaturationSite>,
    /// Rigid steps of the tick whose broadphase found more than
    /// [`MAX_PAIRS`](crate::rigid::broadphase::MAX_PAIRS) overlapping boxes: they kept only
    /// the contacts with static bodies, so other bodies may have passed through each other
    /// ([`RigidSystem::capped_steps`](crate::rigid::RigidSystem::capped_steps)).
    pub capped_contact_steps: u32,
    /// Rigid-body joints that broke during the tick (which ones:
    /// [`RigidSystem::joint_events`]).
    pub broken_joints: u32,
    /// The tick's events in canonical order: contacts that began and ended, sensor
    /// overlaps that began and ended, joints that broke ([`crate::rigid::events`]).
    pub events: Vec<Event>,
}

/// A deterministic physics world.
///
/// A tick ([`World::step`]) runs these stages, in order:
/// 1. [`Stage::ApplyInputs`]: the tick's commands, players in ascending index, each player's
///    commands in order.
/// 2. [`Stage::Particles`]: per substep, emit, age, accumulate forces and integrate.
/// 3. [`Stage::Rigid`]: per substep, the rigid-body step (collide, wake, solve, sleep).
/// 4. [`Stage::Soft`]: per substep, the XPBD substeps and the spring-mass integration.
///    When soft bodies touch or are tied to rigid bodies, stages 3 and 4 alternate
///    substep by substep, the soft step pushing and pushed by the bodies
///    ([`soft_coupling`](super::soft_coupling)).
/// 5. [`Stage::Fluid`]: per substep, the fluid step (emit, neighbours, density, solve,
///    advect); a fluid that meets the rigid bodies sees them as sampled boundaries and
///    pushes them back, the rigid stage then stepping with it at the fluid's substep rate,
///    each rigid substep before the fluid's ([`fluid_coupling`](super::fluid_coupling)).
/// 6. [`Stage::Characters`]: once per tick, each kinematic character moves against the
///    bodies where they now are ([`character_coupling`](super::character_coupling)).
/// 7. [`Stage::Water`]: per substep, the water surface's wave steps. Its float forces
///    (buoyancy and drag on the particles and bodies in it) are applied to them right after
///    the inputs, held for the tick as a command's force is
///    ([`water_coupling`](super::water_coupling)).
/// 8. [`Stage::EndTick`]: clear per-tick force accumulators and advance the tick counter.
///
/// A stage whose subsystem is absent from the scene is skipped without a loop or an
/// allocation.
#[derive(Debug)]
pub struct World<R: Real = Fx> {
    state: WorldState<R>,
    /// Length of one substep, 1 / (tick_rate · substeps) s; derived from the settings.
    substep_dt: R,
    timings: Option<Box<StageTimings>>,
    /// Saturations and capped contacts so far (its divergence is the monitor's).
    health: Health,
    /// Warnings found when the world was built from a scene (see [`World::warnings`]).
    build_warnings: Vec<String>,
    divergence: Option<Box<DivergenceMonitor>>,
    /// The rigid bodies as the soft stage sees them (memory kept between ticks; not state).
    proxies: Proxies<R>,
    /// The threads the step runs on ([`World::set_threads`]; not state: no bit depends on it).
    pool: Pool,
}

impl<R: Real> World<R> {
    /// A world with no subsystems.
    pub fn new(settings: Settings<R>, seed: u64) -> Self {
        Self::from_state(WorldState {
            tick: 0,
            settings,
            rng: Pcg32::new(seed, RNG_STREAM),
            payload_digest: 0,
            particles: None,
            rigid: None,
            soft: None,
            fluid: None,
            characters: None,
            water: None,
        })
    }

    /// A world continuing from `state`.
    pub fn from_state(state: WorldState<R>) -> Self {
        let substep_dt = substep_dt(&state.settings);
        Self {
            state,
            substep_dt,
            timings: None,
            health: Health::default(),
            build_warnings: Vec::new(),
            divergence: None,
            proxies: Proxies::default(),
            pool: Pool::process_default(),
        }
    }

    /// Steps on `threads` threads from now on: 0 for every core, 1 for the calling thread
    /// alone. A world starts with [`parallel::default_threads`](crate::parallel::default_threads):
    /// the environment variable `FIXSTEP_THREADS`, else 1.
    /// The result is the same, bit for bit, at any count and after any change
    /// ([`crate::parallel`]); only the speed differs. Without the `parallel` feature, or where
    /// threads cannot be started (wasm32), the world keeps one thread.
    pub fn set_threads(&mut self, threads: usize) {
        self.pool = Pool::new(threads);
    }

    /// The threads the step runs on ([`World::set_threads`]).
    pub fn threads(&self) -> usize {
        self.pool.threads()
    }

    /// Adds a particle system (replacing any previous one).
    pub fn set_particles(&mut self, particles: ParticleSystem<R>) {
        self.state.particles = Some(particles);
    }

    /// Adds rigid bodies (replacing any previous ones).
    pub fn set_rigid(&mut self, rigid: RigidSystem<R>) {
        self.state.rigid = Some(rigid);
    }

    /// Adds soft bodies (replacing any previous ones).
    pub fn set_soft(&mut self, soft: SoftSystem<R>) {
        self.state.soft = Some(soft);
    }

    /// The soft bodies, if the scene has any.
    pub fn soft(&self) -> Option<&SoftSystem<R>> {
        self.state.soft.as_ref()
    }

    /// The soft bodies, mutable (for placing vertices before a run).
    pub fn soft_mut(&mut self) -> Option<&mut SoftSystem<R>> {
        self.state.soft.as_mut()
    }

    /// Warnings found when the world was built: mass ratios past 1:100 between rigid
    /// bodies that can touch or are jointed (see [`Scene::build`](crate::scene::Scene::build)),
    /// then soft-body networks past their stability bound, for the driver to report.
    pub fn warnings(&self) -> Vec<String> {
        let soft = self.state.soft.as_ref().map_or(&[][..], |s| s.warnings());
        self.build_warnings.iter().chain(soft).cloned().collect()
    }

    /// Adds a warning found while building the world from a scene.
    pub(crate) fn add_build_warning(&mut self, warning: String) {
        self.build_warnings.push(warning);
    }

    /// Adds a fluid (replacing any previous one).
    pub fn set_fluid(&mut self, fluid: FluidSystem<R>) {
        self.state.fluid = Some(fluid);
    }

    /// Adds kinematic characters (replacing any previous ones).
    pub fn set_characters(&mut self, characters: CharacterSystem<R>) {
        self.state.characters = Some(characters);
    }

    /// The kinematic characters, if the scene has any.
    pub fn characters(&self) -> Option<&CharacterSystem<R>> {
        self.state.characters.as_ref()
    }

    /// The fluid, if the scene has one.
    pub fn fluid(&self) -> Option<&FluidSystem<R>> {
        self.state.fluid.as_ref()
    }

    /// Adds a water surface (replacing any previous one).
    pub fn set_water(&mut self, water: WaterSystem<R>) {
        self.state.water = Some(water);
    }

    /// The water surface, if the scene has one.
    pub fn water(&self) -> Option<&WaterSystem<R>> {
        self.state.water.as_ref()
    }

    /// The rigid bodies, if the scene has any.
    pub fn rigid(&self) -> Option<&RigidSystem<R>> {
        self.state.rigid.as_ref()
    }

    /// The events of the last tick, in canonical order (the same as its
    /// [`TickReport::events`]); empty without rigid bodies.
    pub fn events(&self) -> &[Event] {
        self.state.rigid.as_ref().map_or(&[], |r| r.events())
    }

    /// The simulated state.
    pub fn state(&self) -> &WorldState<R> {
        &self.state
    }

    /// The particle system, if the scene has one.
    pub fn particles(&self) -> Option<&ParticleSystem<R>> {
        self.state.particles.as_ref()
    }

    /// The particle system, mutable (for registering user forces).
    pub fn particles_mut(&mut self) -> Option<&mut ParticleSystem<R>> {
        self.state.particles.as_mut()
    }

    /// Ticks completed.
    pub fn tick(&self) -> u64 {
        self.state.tick
    }

    /// Simulated time, tick / tick_rate seconds.
    pub fn time(&self) -> R {
        R::from_ratio(
            self.state.tick as i64,
            i64::from(self.state.settings.tick_rate),
        )
    }

    /// The current settings.
    pub fn settings(&self) -> &Settings<R> {
        &self.state.settings
    }

    /// Starts collecting per-stage wall-clock timings (kept outside the state).
    pub fn enable_timing(&mut self) {
        self.timings.get_or_insert_with(Box::default);
    }

    /// Per-stage timings, when enabled.
    pub fn timings(&self) -> Option<&StageTimings> {
        self.timings.as_deref()
    }

    /// Starts checking for divergence now and every `every` ticks (see
    /// [`divergence`](super::divergence)): an O(particles) energy sum per check, outside the
    /// simulated state. The current state is the reference.
    pub fn enable_divergence_check(&mut self, every: u64) {
        let mut monitor = DivergenceMonitor::new(every);
        monitor.sample(&self.metrics());
        self.divergence = Some(Box::new(monitor));
    }

    /// The first divergence seen since the check was enabled.
    pub fn divergence(&self) -> Option<Divergence> {
        self.divergence.as_ref().and_then(|m| m.detected())
    }

    /// Saturations counted over every tick this world has run.
    pub fn saturations_total(&self) -> u64 {
        self.health.saturations
    }

    /// What the run so far has to warn about: saturations and where the first happened,
    /// ticks whose contacts were capped, and the divergence check's finding
    /// ([`super::health`]).
    pub fn health(&self) -> Health {
        Health {
            divergence: self.divergence(),
            ..self.health
        }
    }

    /// Advances one tick with the given inputs (their `tick` field is not checked here; a
    /// driver passes the inputs for [`World::tick`]), on the world's threads
    /// ([`World::set_threads`]).
    pub fn step(&mut self, input: &TickInput<R>) -> TickReport {
        let pool = std::mem::take(&mut self.pool);
        let report = pool.run(|| self.step_here(input));
        self.pool = pool;
        report
    }

    /// [`World::step`] on this thread, whose loops split across the pool when this thread
    /// is one of its workers.
    fn step_here(&mut self, input: &TickInput<R>) -> TickReport {
        let tick = self.state.tick;
        if let Some(rigid) = &mut self.state.rigid {
            rigid.begin_events(tick);
        }
        let mut watch = StageWatch::new(self.timings.take());
        let (ignored_commands, saturations) = count_saturations(|| {
            let ignored = watch.run(Stage::ApplyInputs, || self.apply_inputs(input));
            let dt = self.substep_dt;
            let state = &mut self.state;
            if let Some(water) = &state.water {
                watch.run(Stage::Water, || {
                    apply_float_forces(
                        water,
                        state.particles.as_mut(),
                        state.rigid.as_mut(),
                        &state.settings,
                    );
                });
            }
            if !state.step_coupled_particles(&mut watch, dt) {
                state.step_alone(Stage::Particles, &mut watch, dt);
            }
            if state.step_coupled_fluid(&mut watch, dt) {
                // The rigid bodies and the fluid alternated at the fluid's substep rate;
                // the soft bodies follow (a scene does not couple them too: it is refused
                // when built).
                state.step_alone(Stage::Soft, &mut watch, dt);
            } else {
                if !state.step_coupled_soft(&mut watch, dt, &mut self.proxies) {
                    state.step_alone(Stage::Rigid, &mut watch, dt);
                    state.step_alone(Stage::Soft, &mut watch, dt);
                }
                state.step_alone(Stage::Fluid, &mut watch, dt);
            }
            if let Some(characters) = &mut state.characters {
                let tick_dt = R::from_ratio(1, i64::from(state.settings.tick_rate));
                let gravity = state.settings.gravity;
                watch.run(Stage::Characters, || {
                    step_characters(characters, state.rigid.as_mut(), tick_dt, gravity);
                });
            }
            state.step_alone(Stage::Water, &mut watch, dt);
            watch.run(Stage::EndTick, || self.end_tick());
            ignored
        });
        self.timings = watch.timings;
        let first_saturation = watch.first_saturated.map(|stage| SaturationSite {
            tick,
            count: saturations,
            stage,
            object: self.state.saturated_object(stage),
        });
        let capped_contact_steps = self.state.rigid.as_ref().map_or(0, |r| r.capped_steps());
        self.health.add_tick(
            tick,
            saturations,
            first_saturation,
            capped_contact_steps > 0,
        );
        if let Some(monitor) = &self.divergence
            && self.state.tick.is_multiple_of(monitor.every)
        {
            let metrics = self.metrics();
            if let Some(monitor) = &mut self.divergence {
                monitor.sample(&metrics);
            }
        }
        let (broken_joints, events) = self.state.rigid.as_ref().map_or((0, Vec::new()), |r| {
            (r.joint_events().len() as u32, r.events().to_vec())
        });
        TickReport {
            ignored_commands,
            saturations,
            first_saturation,
            capped_contact_steps,
            broken_joints,
            events,
        }
    }

    /// Stage 1: applies commands, players in ascending index, commands in order. Returns
    /// how many commands had no target.
    fn apply_inputs(&mut self, input: &TickInput<R>) -> u32 {
        let mut ignored = 0;
        let mut apply = |player: &PlayerInput<R>| {
            for command in &player.commands {
                if !self.apply_command(player.player, command) {
                    ignored += 1;
                }
            }
        };
        if input.players.is_sorted_by_key(|p| p.player) {
            input.players.iter().for_each(&mut apply);
        } else {
            // Inputs not in canonical order (a hand-made file): sort, keeping each player's
            // entries in file order.
            let mut players: Vec<&PlayerInput<R>> = input.players.iter().collect();
            players.sort_by_key(|p| p.player);
            players.into_iter().for_each(apply);
        }
        ignored
    }

    /// Applies one command; false when its target does not exist.
    fn apply_command(&mut self, player: u8, command: &Command<R>) -> bool {
        match *command {
            Command::SetGravity { gravity } => {
                self.state.settings.gravity = gravity;
                if let Some(rigid) = &mut self.state.rigid {
                    rigid.wake_all();
                }
                true
            }
            Command::DisturbWater {
                x,
                z,
                height,
                radius,
            } => {
                let Some(water) = &mut self.state.water else {
                    return false;
                };
                water.disturb(x, z, height, radius);
                true
            }
            Command::Payload(value) => {
                let mut h = StateHasher::new();
                h.write_u64(self.state.payload_digest);
                h.write_u64(self.state.tick);
                h.write_u8(player);
                h.write_u32(value);
                self.state.payload_digest = h.finish();
                true
            }
            Command::ApplyForce {
                target: Target::Body(_),
                ..
            }
            | Command::ApplyImpulse {
                target: Target::Body(_),
                ..
            }
            | Command::SetVelocity {
                target: Target::Body(_),
                ..
            }
            | Command::Remove {
                target: Target::Body(_),
            }
            | Command::MoveKinematic {
                target: Target::Body(_),
                ..
            }
            | Command::Remove {
                target: Target::Joint(_),
            }
            | Command::SetMotor { .. }
            | Command::SpawnBody { .. }
            | Command::SpawnJoint { .. } => self
                .state
                .rigid
                .as_mut()
                .is_some_and(|r| r.apply_command(command)),
            Command::MoveCharacter { .. } => self
                .state
                .characters
                .as_mut()
                .is_some_and(|c| c.apply_command(command)),
            Command::MoveKinematic {
                target: Target::SoftAttachment(_),
                ..
            } => self
                .state
                .soft
                .as_mut()
                .is_some_and(|s| s.apply_command(command)),
            Command::ApplyForce {
                target: Target::SoftAttachment(_),
                ..
            }
            | Command::ApplyImpulse {
                target: Target::SoftAttachment(_),
                ..
            }
            | Command::SetVelocity {
                target: Target::SoftAttachment(_),
                ..
            }
            | Command::Remove {
                target: Target::SoftAttachment(_),
            }
            | Command::ApplyForce {
                target: Target::Joint(_),
                ..
            }
            | Command::ApplyImpulse {
                target: Target::Joint(_),
                ..
            }
            | Command::SetVelocity {
                target: Target::Joint(_),
                ..
            }
            | Command::MoveKinematic {
                target: Target::Joint(_),
                ..
            } => false,
            _ => self
                .state
                .particles
                .as_mut()
                .is_some_and(|p| p.apply_command(command)),
        }
    }

    /// Stage 6: clears per-tick accumulators and advances the tick counter.
    fn end_tick(&mut self) {
        let (_, _, subsystems) = self.state.split_mut();
        for subsystem in subsystems.into_iter().flatten() {
            subsystem.end_tick();
        }
        self.state.tick += 1;
    }

    /// The checksum of the current state (see [`super::checksum`] for what is hashed).
    pub fn checksum(&self) -> Checksum {
        let mut parts = Vec::with_capacity(4);
        parts.push((Part::Core, self.core_checksum()));
        for subsystem in self.state.subsystems().into_iter().flatten() {
            let mut h = StateHasher::new();
            subsystem.hash_state(&mut h);
            parts.push((subsystem.part(), h.finish()));
        }
        let mut h = StateHasher::new();
        h.write_u32(STATE_VERSION);
        for (part, sum) in &parts {
            h.write_u8(part.code());
            h.write_u64(*sum);
        }
        Checksum {
            tick: self.state.tick,
            total: h.finish(),
            parts,
        }
    }

    /// Per-object digests of every subsystem that has objects, in [`Part`] order: one
    /// 32-bit digest per slot in ascending slot index (see
    /// [`ParticleSystem::slot_digests`]). Used to name the first differing object when
    /// only a recording, not the other state, is at hand.
    pub fn object_digests(&self) -> ObjectDigests {
        self.state
            .subsystems()
            .into_iter()
            .flatten()
            .map(|subsystem| (subsystem.part(), subsystem.slot_digests()))
            .collect()
    }

    fn core_checksum(&self) -> u64 {
        let s = &self.state;
        let mut h = StateHasher::new();
        h.write_u64(s.tick);
        h.write_vec3(s.settings.gravity);
        h.write_u32(s.settings.tick_rate);
        h.write_u32(s.settings.substeps);
        s.rng.hash_state(&mut h);
        h.write_u64(s.payload_digest);
        h.finish()
    }

    /// Reporting figures for the current state, as `f64`.
    pub fn metrics(&self) -> Metrics {
        let mut m = Metrics {
            tick: self.state.tick,
            time: self.time().to_f64(),
            saturations: self.health.saturations,
            diverged: self.divergence().is_some(),
            ..Metrics::default()
        };
        for subsystem in self.state.subsystems().into_iter().flatten() {
            subsystem.add_metrics(self.state.settings.gravity, &mut m);
        }
        m
    }

    /// A copy of the complete state, to restore later.
    pub fn snapshot(&self) -> WorldState<R> {
        self.state.clone()
    }

    /// Puts the world back in the snapshotted state. Registered user forces are kept.
    pub fn restore(&mut self, snapshot: &WorldState<R>) {
        let mut state = snapshot.clone();
        state.keep_unsimulated(&mut self.state);
        self.substep_dt = substep_dt(&state.settings);
        self.state = state;
    }
}

/// One tick of one subsystem: [`Subsystem::begin_tick`], then
/// [`Subsystem::step`] once per substep of `substep_dt` seconds.
fn step_subsystem<R: Real>(
    subsystem: &mut dyn Subsystem<R>,
    settings: &Settings<R>,
    rng: &mut Pcg32,
    substep_dt: R,
) {
    subsystem.begin_tick();
    let mut context = step_context(settings, rng, substep_dt);
    for substep in 0..settings.substeps {
        context.substep = substep;
        subsystem.step(&mut context);
    }
}

/// The context of a tick's first substep of `dt` seconds under `settings`.
pub(super) fn step_context<'a, R: Real>(
    settings: &Settings<R>,
    rng: &'a mut Pcg32,
    dt: R,
) -> StepContext<'a, R> {
    StepContext {
        dt,
        gravity: settings.gravity,
        rng,
        substep: 0,
        substeps: settings.substeps,
    }
}

/// 1 / (tick_rate · substeps) seconds.
fn substep_dt<R: Real>(settings: &Settings<R>) -> R {
    R::from_ratio(
        1,
        i64::from(settings.tick_rate) * i64::from(settings.substeps),
    )
}
