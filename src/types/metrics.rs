//! Reporting figures for a world at one tick, as `f64`. Never fed back into the simulation.
//!
//! Each subsystem adds its own figures ([`Subsystem::add_metrics`](super::Subsystem::add_metrics)).

/// One metrics row (`fixstep run --metrics`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Metrics {
    /// Ticks completed.
    pub tick: u64,
    /// Simulated time, s.
    pub time: f64, // ok-det: reporting
    /// Σ ½ m v², J.
    pub kinetic_energy: f64, // ok-det: reporting
    /// Gravitational, point-gravity and spring potential energy, J.
    pub potential_energy: f64, // ok-det: reporting
    /// Σ m v, kg·m/s.
    pub momentum: [f64; 3], // ok-det: reporting
    /// The largest speed of any simulated point, m/s.
    pub max_speed: f64, // ok-det: reporting
    /// Fixed-point saturations since the world was built.
    pub saturations: u64,
    /// Live particles, fluid particles included.
    pub particles: u64,
    /// The deepest overlap among the rigid contacts, m.
    pub max_penetration: f64, // ok-det: reporting
    /// Dynamic rigid bodies awake.
    pub awake_bodies: u64,
    /// Dynamic rigid bodies asleep.
    pub sleeping_bodies: u64,
    /// Mean fluid compression max(ρ/ρ₀ − 1, 0) over the fluid particles.
    pub density_error_avg: f64, // ok-det: reporting
    /// The largest fluid compression.
    pub density_error_max: f64, // ok-det: reporting
    /// The furthest x of a fluid particle touching the floor layer, from the tank's back
    /// wall, m.
    pub front_x: f64, // ok-det: reporting
    /// Fluid substeps in the last world substep (adaptive with a CFL number, else the
    /// scene's count; 0 without a fluid or before its first step).
    pub fluid_substeps: u32,
    /// Whether the divergence check has seen the energy blow up (see
    /// [`divergence`](crate::world::divergence)); false when the check is off.
    pub diverged: bool,
    /// The largest edge stretch max(0, ℓ/ℓ₀ − 1) of the soft bodies.
    pub max_stretch: f64, // ok-det: reporting
    /// The mean edge stretch of the soft bodies.
    pub mean_stretch: f64, // ok-det: reporting
    /// Live rigid-body joints.
    pub joints: u64,
    /// The largest joint error of the rigid-body joints, m
    /// ([`RigidSystem::joint_error`](crate::rigid::RigidSystem::joint_error)).
    pub max_joint_error: f64, // ok-det: reporting
    /// Soft-body vertices (not a CSV column; the divergence check counts them with the
    /// particles).
    pub soft_vertices: u64,
    /// The kinetic energy of the dynamic rigid bodies, J (not a CSV column; the divergence
    /// check watches their energy per kilogram).
    pub rigid_kinetic_energy: f64, // ok-det: reporting
    /// The potential energy of the dynamic rigid bodies, J (not a CSV column).
    pub rigid_potential_energy: f64, // ok-det: reporting
    /// The mass of the live dynamic rigid bodies, kg (not a CSV column).
    pub rigid_mass: f64, // ok-det: reporting
}

impl Metrics {
    /// The CSV header: the fixed columns, then one column per subsystem figure.
    pub const CSV_HEADER: &'static str = "tick,time,kinetic_energy,potential_energy,momentum_x,momentum_y,momentum_z,max_speed,saturations,particles,diverged,max_penetration,awake_bodies,sleeping_bodies,max_stretch,mean_stretch,density_error_avg,density_error_max,front_x,joints,max_joint_error,fluid_substeps";

    /// The row as CSV, in [`Metrics::CSV_HEADER`] order.
    pub fn csv_row(&self) -> String {
        format!(
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            self.tick,
            self.time,
            self.kinetic_energy,
            self.potential_energy,
            self.momentum[0],
            self.momentum[1],
            self.momentum[2],
            self.max_speed,
            self.saturations,
            self.particles,
            u8::from(self.diverged),
            self.max_penetration,
            self.awake_bodies,
            self.sleeping_bodies,
            self.max_stretch,
            self.mean_stretch,
            self.density_error_avg,
            self.density_error_max,
            self.front_x,
            self.joints,
            self.max_joint_error,
            self.fluid_substeps
        )
    }

    /// Total mechanical energy, J.
    pub fn total_energy(&self) -> f64 // ok-det: reporting
    {
        self.kinetic_energy + self.potential_energy
    }
}
