//! The integration tests, one module per file, in one test binary: the engine's generic code
//! is then compiled and linked once for all of them rather than once per file (on this
//! 2-core machine, that took the release build of the tests after a change to the library
//! from 4.9 to 2.4 minutes). Run one file's tests with `cargo test --test suite FILE::`, for
//! example `cargo test --test suite rigid_scenes::`.

mod mesh_obj;
mod property_cases;

mod character_contacts;
mod character_determinism;
mod character_moves;
mod character_support;
mod fluid_bodies;
mod fluid_dam_break;
mod fluid_dfsph_large_step;
mod fluid_kernel;
mod fluid_neighbours;
mod fluid_scene;
mod fluid_tank;
mod fuzz_regressions;
mod math_golden;
mod math_linalg;
mod math_rng;
mod math_scalar;
mod math_sqrt_exp;
mod math_state_hash;
mod math_trig;
mod mesh_queries;
mod parallel_threads;
mod particles_collisions;
mod particles_commands;
mod particles_emitters;
mod particles_forces;
mod particles_implicit_euler;
mod particles_integrators;
mod particles_kepler;
mod particles_links;
mod particles_scene;
mod queries;
mod readme_limits;
mod replay_committed;
mod replay_snapshot;
mod replay_streaming;
mod restore_support;
mod rigid_bounce;
mod rigid_broadphase;
mod rigid_ccd;
mod rigid_convex_shapes;
mod rigid_cradle;
mod rigid_events;
mod rigid_friction;
mod rigid_gyroscopic;
mod rigid_hull;
mod rigid_joint_energy;
mod rigid_joints;
mod rigid_mass;
mod rigid_mesh;
mod rigid_narrowphase;
mod rigid_scenes;
mod scene_simulation;
mod soft_bodies;
mod soft_coupling;
mod soft_snapshot;
mod water;
mod world_core;
mod world_health;
