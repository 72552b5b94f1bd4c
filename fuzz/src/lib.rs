//! What each fuzz target does with its bytes. The targets in `fuzz_targets/` call these, and
//! `tests/suite/fuzz_regressions.rs` in the fixstep package runs every kept input through
//! them, so a crash found once stays fixed.
//!
//! Each function must return normally for any input: an error is a fine answer, a panic,
//! an abort, a hang or an unbounded allocation is a bug. Where the input is accepted, the
//! function also checks the properties that must hold for every accepted input, and returns
//! true (the seeds must all be accepted, or they would seed nothing).

use fixstep::codec;
use fixstep::fluid::FluidSystem;
use fixstep::math::{Fx, Real};
use fixstep::replay::{InputFeed, Replay, scene_id, scene_section, verify};
use fixstep::scene::parse_scene;
use fixstep::world::{TickInput, World, decode_snapshot, encode_snapshot};

/// The most ticks any target simulates.
pub const MAX_TICKS: u64 = 64;

/// The most work a target's run may do, as the sum over its ticks of [`load`]: a scene
/// past it runs fewer ticks (at least one; `world_step` at least one before its snapshot
/// and one after), so that a huge one (4096 spheres grown until each overlaps some eighty
/// others: 0.4 s a tick in release, several seconds in a fuzz build) or one that grows (an
/// emitter filling a fluid) takes seconds, not the fuzzer's time-out. A hang within a
/// tick still times out.
pub const MAX_WORK: usize = 100_000;

/// The most work one tick may take, in the elements [`worst_tick`] counts: about a second
/// in release. A world whose worst tick is larger is not run (its scene is refused here):
/// the work bound below stops a run only between ticks, and a scene such as a dam break of
/// 256 world substeps of 10 fluid substeps, each iterating to its limit, takes ten
/// seconds a tick.
pub const MAX_TICK_WORK: usize = 2_000_000_000;

/// The most work the next tick of `world` may take: [`load`] with every fluid substep
/// iterating to its `max_iterations`.
fn worst_tick(world: &World<Fx>) -> usize {
    let fluid = world.fluid().map_or(0, |f| {
        let s = f.settings();
        let passes = (s.max_iterations as usize).saturating_add(1);
        f.len()
            .saturating_mul(32)
            .saturating_mul(passes)
            .saturating_add(grid_cells(f))
            .saturating_mul(s.substeps.max(1) as usize)
    });
    let substeps = world.settings().substeps.max(1) as usize;
    load(world).saturating_add(fluid.saturating_mul(substeps))
}

/// The cells of the fluid's neighbour grid, cubes of half the kernel support over the tank,
/// which a rebuild of the grid visited each fluid substep until the grid's fill came to
/// cover only the box the particles occupy (2026-11-27): since then an over-estimate, kept
/// as a bound so that the inputs accepted stay those of before (counted in `f64`: an
/// estimate in the harness, not a value of the step).
fn grid_cells(fluid: &FluidSystem<Fx>) -> usize {
    let s = fluid.settings();
    let cell = (s.spacing * s.support).to_f64() / 2.0;
    let (lower, upper) = (s.tank.min, s.tank.max);
    [(lower.x, upper.x), (lower.y, upper.y), (lower.z, upper.z)]
        .into_iter()
        .fold(1usize, |cells, (lower, upper)| {
            let along = ((upper.to_f64() - lower.to_f64()) / cell).clamp(0.0, 1e12) + 3.0;
            cells.saturating_mul(along as usize)
        })
}

/// The work of one tick of `world`, counted in elements the step visits, once per
/// substep: rigid bodies and their contacts (as the last step left them), fluid particles
/// (times 32, about their neighbours, and times the passes over them its last step made:
/// one per fluid substep, at most, plus its solver iterations, up to DFSPH's
/// `max_iterations` a substep) and particle slots.
fn load(world: &World<Fx>) -> usize {
    let rigid = world
        .rigid()
        .map_or(0, |r| r.body_count().saturating_add(r.contact_count()));
    let fluid = world.fluid().map_or(0, |f| {
        let fluid_substeps = f.settings().substeps.max(1) as usize;
        let passes = fluid_substeps.saturating_add(f.last_iterations() as usize);
        f.len()
            .saturating_mul(32)
            .saturating_mul(passes)
            .saturating_add(grid_cells(f).saturating_mul(fluid_substeps))
    });
    let particles = world.particles().map_or(0, |p| p.slot_count());
    let substeps = world.settings().substeps.max(1) as usize;
    rigid
        .saturating_add(fluid)
        .saturating_add(particles)
        .saturating_mul(substeps)
}

/// A replay file's bytes: decoding never panics; an accepted replay encodes back to the
/// same bytes (one encoding per replay), and a short one verifies without a panic.
pub fn replay_decode(data: &[u8]) -> bool {
    let Ok(replay) = Replay::from_bytes(data, "fuzz") else {
        return false;
    };
    let again = replay.to_bytes().expect("an accepted replay encodes");
    assert_eq!(again, data, "an accepted replay has exactly one encoding");
    if replay.ticks() <= MAX_TICKS {
        let _ = verify(&replay);
    }
    true
}

/// A RON scene file's bytes: parsing never panics; an accepted scene builds or is refused
/// with an error, and a built world runs.
pub fn scene_ron(data: &[u8]) -> bool {
    let Ok(text) = std::str::from_utf8(data) else {
        return false;
    };
    let Ok(scene) = parse_scene::<Fx>(text, "fuzz.ron") else {
        return false;
    };
    match scene.build() {
        Ok(world) => {
            run(world, &scene.script, MAX_TICKS / 8);
            true
        }
        Err(_) => false,
    }
}

/// An OBJ mesh file's bytes: reading never panics, and every refusal names the file.
pub fn mesh_obj(data: &[u8]) -> bool {
    let Ok(text) = std::str::from_utf8(data) else {
        return false;
    };
    match fixstep::rigid::mesh::read_obj::<Fx>(text, "fuzz.obj") {
        Ok(_) => true,
        Err(message) => {
            assert!(message.starts_with("fuzz.obj: "), "{message}");
            false
        }
    }
}

/// A snapshot file's bytes: decoding never panics; an accepted snapshot encodes back to the
/// same bytes and continues without a panic.
pub fn snapshot_decode(data: &[u8]) -> bool {
    let Ok(snapshot) = decode_snapshot::<Fx>(data) else {
        return false;
    };
    let again =
        encode_snapshot(&snapshot.state, &snapshot.scene).expect("an accepted snapshot encodes");
    assert_eq!(again, data, "an accepted snapshot has exactly one encoding");
    run(World::from_state(snapshot.state), &[], MAX_TICKS / 8);
    true
}

/// Any scene and inputs: a `u64` little-endian length L, then L bytes of a replay's scene
/// section ([`scene_section`]), then its inputs section. The world builds or is refused, then runs up to [`MAX_TICKS`] ticks
/// whatever the values (huge forces, zero or negative masses, degenerate springs,
/// coincident particles). Halfway, the state goes through a snapshot file and back, which
/// must be accepted, and restoring it must replay the second half to the same checksum.
/// After each half every rigid body's orientation must be unit.
pub fn world_step(data: &[u8]) -> bool {
    let Some((len, rest)) = data.split_first_chunk::<8>() else {
        return false;
    };
    let Some((scene_bytes, inputs_bytes)) = usize::try_from(u64::from_le_bytes(*len))
        .ok()
        .and_then(|len| rest.split_at_checked(len))
    else {
        return false;
    };
    let Ok(scene) = scene_section::decode_scene(scene_bytes) else {
        return false;
    };
    let inputs: Vec<TickInput<Fx>> = codec::decode_prefix(inputs_bytes)
        .map(|(inputs, _)| inputs)
        .unwrap_or_default();
    let Ok(mut world) = scene.build() else {
        return false;
    };
    if worst_tick(&world) > MAX_TICK_WORK {
        return false;
    }
    let mut feed = InputFeed::new(&inputs);
    // Each half runs until half the ticks or a third of the work (the second half runs
    // twice), at least one tick: the load may grow as the run goes (an emitter).
    let mut run_part = |world: &mut World<Fx>, first: u64, last: u64| {
        let mut work = 0usize;
        let mut tick = first;
        while tick < last && (tick == first || work <= MAX_WORK / 3) {
            world.step(feed.at(tick));
            work = work.saturating_add(load(world));
            tick += 1;
        }
        tick
    };
    let half = run_part(&mut world, 0, MAX_TICKS / 2);
    assert_unit_orientations(&world);
    let id = scene_id(&scene).expect("a decoded scene encodes");
    let bytes = encode_snapshot(&world.snapshot(), &id).expect("a running world encodes");
    let snapshot = decode_snapshot::<Fx>(&bytes)
        .expect("a running world's snapshot is valid")
        .state;
    let end_tick = run_part(&mut world, half, MAX_TICKS);
    assert_unit_orientations(&world);
    let end = world.checksum();
    world.restore(&snapshot);
    let mut feed = InputFeed::new(&inputs);
    for tick in half..end_tick {
        world.step(feed.at(tick));
    }
    assert_eq!(
        world.checksum(),
        end,
        "restoring a snapshot changed the run"
    );
    true
}

/// Every rigid body's orientation is a unit quaternion to within 2⁻¹⁶, however the world
/// ran: scenes normalise orientations, integration renormalises them at any spin
/// (`Quat::try_normalize` takes any nonzero length), and nothing else writes them.
fn assert_unit_orientations(world: &World<Fx>) {
    let Some(rigid) = world.rigid() else {
        return;
    };
    for handle in rigid.handles() {
        let q = rigid.orientation(handle).expect("a listed handle is live");
        let excess = (q.length_squared() - Fx::ONE).abs();
        assert!(
            excess <= Fx::from_ratio(1, 1 << 16),
            "body {handle:?}: orientation {q:?} is not unit (||q|² − 1| = {excess})"
        );
    }
}

/// Runs `ticks` ticks of `inputs`, or fewer once their [`load`] passes [`MAX_WORK`].
fn run(mut world: World<Fx>, inputs: &[TickInput<Fx>], ticks: u64) {
    if worst_tick(&world) > MAX_TICK_WORK {
        return;
    }
    let mut feed = InputFeed::new(inputs);
    let mut work = 0usize;
    for _ in 0..ticks {
        let tick = world.tick();
        world.step(feed.at(tick));
        work = work.saturating_add(load(&world));
        if work > MAX_WORK {
            break;
        }
    }
}
