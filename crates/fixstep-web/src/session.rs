//! One scene running in the page: its world fed its script and the page's own commands, which
//! the session keeps, to write the run as a replay that `fixstep verify` accepts.

use core::mem;

use fixstep::math::{Fx, Real, Vec3};
use fixstep::replay::{DEFAULT_CHECKSUM_EVERY, Recorder, Replay, scene_id};
use fixstep::rigid::BodyKind;
use fixstep::scene::{Scene, Simulation, parse_scene};
use fixstep::world::checksum::hex;
use fixstep::world::{
    Command, Handle, PlayerInput, SceneId, Target, TickInput, World, decode_snapshot,
    encode_snapshot,
};

use super::shape_mesh::{TriangleMesh, shape_mesh};

/// The player whose commands the page gives (merged after the script's own commands of
/// that player, as [`Simulation::step_with`] does).
pub const PAGE_PLAYER: u8 = 0;

/// A running scene and what it was fed.
#[derive(Debug)]
pub struct Session {
    scene: Scene<Fx>,
    scene_id: SceneId,
    simulation: Simulation<Fx>,
    /// Every non-empty input fed so far (script and page), canonical, in tick order.
    fed: Vec<TickInput<Fx>>,
    /// The page's commands for the next tick.
    pending: Vec<Command<Fx>>,
    /// The ticks at which the page gave commands.
    page_ticks: Vec<u64>,
    /// Live bodies last listed by [`Session::body_poses`].
    handles: Vec<Handle>,
    /// Bumped whenever `handles` changes.
    layout: u32,
    /// The floats the last position view shows.
    buffer: Vec<f32>,
    /// The ticks and final checksum of the replay the session plays, if it plays one.
    recorded: Option<(u64, u64)>,
}

/// The water surface's grid: `columns` × `rows` cells of `cell_size` (m), the first cell's
/// corner at `origin` (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WaterGrid {
    /// Cells along x.
    pub columns: u32,
    /// Cells along z.
    pub rows: u32,
    /// A cell's side, m.
    pub cell_size: f64,
    /// The grid's corner, m; heights are measured from its y.
    pub origin: [f64; 3],
}

impl Session {
    /// The built-in scene `name` at tick 0.
    pub fn builtin(name: &str) -> Result<Self, String> {
        let scene = fixstep_scenes::builtin_scene::<Fx>(name).ok_or_else(|| {
            format!("no built-in scene named `{name}` (see fixstep_web.scenes())")
        })?;
        Self::new(scene)
    }

    /// The scene written in RON `text` (a scene file's content) at tick 0; errors name
    /// `origin`, the line and the column.
    pub fn from_ron(text: &str, origin: &str) -> Result<Self, String> {
        Self::new(parse_scene::<Fx>(text, origin).map_err(|e| e.to_string())?)
    }

    /// `scene` at tick 0, fed its script as `fixstep run` feeds it (each input's players in
    /// canonical order, without players or ticks that give no command), so that the
    /// checksum after N ticks is the one `fixstep run NAME --ticks N` prints.
    pub fn new(scene: Scene<Fx>) -> Result<Self, String> {
        let script = scene.script.clone();
        Self::with_inputs(scene, script)
    }

    /// The replay file `bytes` at tick 0, fed its recorded inputs: stepped to its last tick,
    /// its checksum is the replay's final one. Errors name `origin`, the section and the
    /// byte offset.
    pub fn from_replay(bytes: &[u8], origin: &str) -> Result<Self, String> {
        let replay = Replay::from_bytes(bytes, origin).map_err(|e| e.to_string())?;
        let mut session = Self::with_inputs(replay.scene().clone(), replay.inputs().to_vec())?;
        session.recorded = Some((replay.ticks(), replay.final_checksum()));
        Ok(session)
    }

    /// `scene` at tick 0, fed `script` (the scene's script or a replay's inputs).
    fn with_inputs(scene: Scene<Fx>, mut script: Vec<TickInput<Fx>>) -> Result<Self, String> {
        let name = scene.name.clone();
        let world = scene.build().map_err(|e| format!("{name}: {e}"))?;
        if let Some(particles) = world.particles() {
            particles
                .check_user_forces()
                .map_err(|e| format!("{name}: {}", e.within("particles")))?;
        }
        let scene_id =
            scene_id(&scene).map_err(|e| format!("{name}: cannot encode the scene: {e}"))?;
        for input in &mut script {
            input.canonicalize();
            input.players.retain(|p| !p.commands.is_empty());
        }
        script.retain(|input| !input.is_empty());
        Ok(Self {
            scene,
            scene_id,
            simulation: Simulation::resume(world, script),
            fed: Vec::new(),
            pending: Vec::new(),
            page_ticks: Vec::new(),
            handles: Vec::new(),
            layout: 0,
            buffer: Vec::new(),
            recorded: None,
        })
    }

    /// The ticks and the final checksum of the replay this session plays
    /// ([`Session::from_replay`]); `None` for a scene.
    pub fn recorded(&self) -> Option<(u64, u64)> {
        self.recorded
    }

    /// The scene.
    pub fn scene(&self) -> &Scene<Fx> {
        &self.scene
    }

    /// The world.
    pub fn world(&self) -> &World<Fx> {
        self.simulation.world()
    }

    /// The world's checksum as `fixstep run` prints it: 16 lowercase hex digits.
    pub fn checksum(&self) -> String {
        hex(self.world().checksum().total)
    }

    /// Queues `command` for the next tick, from [`PAGE_PLAYER`].
    pub fn queue(&mut self, command: Command<Fx>) {
        self.pending.push(command);
    }

    /// Queues the commands written in RON `text`, a list such as
    /// `[ApplyImpulse(target: Body((index: 3, generation: 0)), impulse: (x: 0, y: 5, z: 0), point: None)]`.
    pub fn queue_ron(&mut self, text: &str) -> Result<(), String> {
        let options = ron::Options::default()
            .with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
        let commands: Vec<Command<Fx>> = options
            .from_str(text)
            .map_err(|e| format!("commands: {e}"))?;
        self.pending.extend(commands);
        Ok(())
    }

    /// Queues an impulse on the live body `handle` that changes its velocity by `speed`
    /// (m/s) along `direction` (any length), applied at `point` (m, world frame):
    /// J = m · speed · d̂ (N·s). False, and nothing queued, when the body is gone or not
    /// dynamic.
    pub fn queue_push(
        &mut self,
        handle: Handle,
        direction: [f64; 3],
        point: [f64; 3],
        speed: f64,
    ) -> bool {
        let Some(rigid) = self.world().rigid() else {
            return false;
        };
        let (Some(BodyKind::Dynamic), Some(mass)) = (rigid.kind(handle), rigid.mass(handle)) else {
            return false;
        };
        let length = direction.iter().map(|c| c * c).sum::<f64>().sqrt();
        if !(length > 0.0 && speed.is_finite() && point.iter().all(|c| c.is_finite())) {
            return false;
        }
        let j = mass.to_f64() * speed / length;
        self.queue(Command::ApplyImpulse {
            target: Target::Body(handle),
            impulse: Vec3::from_f64(direction[0] * j, direction[1] * j, direction[2] * j),
            point: Some(Vec3::from_f64(point[0], point[1], point[2])),
        });
        true
    }

    /// Runs one tick: the scene's script for this tick, then the queued commands.
    pub fn step(&mut self) {
        let tick = self.world().tick();
        let commands = mem::take(&mut self.pending);
        let players = if commands.is_empty() {
            Vec::new()
        } else {
            vec![PlayerInput {
                player: PAGE_PLAYER,
                commands,
            }]
        };
        let mut input = TickInput {
            tick,
            players: self
                .simulation
                .scripted()
                .map(|s| s.players.clone())
                .unwrap_or_default(),
        };
        input.players.extend_from_slice(&players);
        input.canonicalize();
        if players.is_empty() {
            self.simulation.step();
        } else {
            self.simulation.step_with(&players);
            self.page_ticks.push(tick);
        }
        if !input.is_empty() {
            self.fed.push(input);
        }
    }

    /// The ticks so far at which the page gave commands.
    pub fn page_ticks(&self) -> &[u64] {
        &self.page_ticks
    }

    /// The snapshot file of the world now (as `fixstep run --snapshot` writes it).
    pub fn snapshot(&self) -> Result<Vec<u8>, String> {
        encode_snapshot(&self.world().snapshot(), &self.scene_id)
            .map_err(|e| format!("cannot encode the snapshot: {e}"))
    }

    /// Restores a snapshot file of this scene; the inputs fed at or after its tick are
    /// forgotten (a rollback), and so are the queued commands.
    pub fn restore(&mut self, bytes: &[u8]) -> Result<(), String> {
        let snapshot = decode_snapshot::<Fx>(bytes).map_err(|e| format!("snapshot: {e}"))?;
        snapshot
            .scene
            .check_same(&self.scene_id)
            .map_err(|e| format!("snapshot: {e}"))?;
        self.simulation.world_mut().restore(&snapshot.state);
        let tick = self.world().tick();
        self.fed.retain(|input| input.tick < tick);
        self.page_ticks.retain(|&t| t < tick);
        self.pending.clear();
        Ok(())
    }

    /// The replay of the run from tick 0 to now (the bytes `fixstep run --record` writes for
    /// the same inputs), made by simulating the inputs fed again. Refused when that does not
    /// reach this world's checksum (after a restore of a snapshot from another run).
    pub fn replay(&self) -> Result<Vec<u8>, String> {
        let mut recorder = Recorder::new(&self.scene, DEFAULT_CHECKSUM_EVERY)
            .map_err(|e| format!("{}: {e}", self.scene.name))?;
        let ticks = self.world().tick();
        let mut fed = self.fed.iter().peekable();
        let empty = TickInput::default();
        for tick in 0..ticks {
            let input = fed.next_if(|input| input.tick == tick).unwrap_or(&empty);
            recorder.step(input);
        }
        if recorder.world().checksum().total != self.world().checksum().total {
            return Err(
                "the world was restored from a snapshot of another run: its inputs are not \
                 known, so no replay of it can be written"
                    .to_owned(),
            );
        }
        recorder
            .finish()
            .to_bytes()
            .map_err(|e| format!("cannot encode the replay: {e}"))
    }

    /// Lists the live rigid bodies (slot order) and returns their poses: x, y, z (m), then
    /// the orientation's x, y, z, w, seven numbers per body.
    pub fn body_poses(&mut self) -> &[f32] {
        let handles: Vec<Handle> = self
            .world()
            .rigid()
            .map(|rigid| rigid.handles().collect())
            .unwrap_or_default();
        if handles != self.handles {
            self.handles = handles;
            self.layout = self.layout.wrapping_add(1);
        }
        self.buffer.clear();
        if let Some(rigid) = self.simulation.world().rigid() {
            for &handle in &self.handles {
                let p = rigid.position(handle).unwrap_or_default().to_f64();
                let q = rigid
                    .orientation(handle)
                    .map_or([1.0, 0.0, 0.0, 0.0], |q| q.to_f64());
                self.buffer
                    .extend([p[0], p[1], p[2], q[1], q[2], q[3], q[0]].map(|c| c as f32));
            }
        }
        &self.buffer
    }

    /// A number that changes whenever the list of live bodies changes (a spawn, a removal).
    pub fn body_layout(&self) -> u32 {
        self.layout
    }

    /// The live bodies of the last [`Session::body_poses`], in its order.
    pub fn body_handles(&self) -> &[Handle] {
        &self.handles
    }

    /// Body number `i` of [`Session::body_handles`]: its shape's mesh, its kind (0 static,
    /// 1 kinematic, 2 dynamic) and whether it sleeps.
    pub fn body(&self, i: usize) -> Option<(TriangleMesh, u8, bool)> {
        let rigid = self.world().rigid()?;
        let handle = *self.handles.get(i)?;
        let kind = match rigid.kind(handle)? {
            BodyKind::Static => 0,
            BodyKind::Kinematic => 1,
            BodyKind::Dynamic => 2,
        };
        Some((
            shape_mesh(rigid.shape(handle)?),
            kind,
            rigid.is_sleeping(handle)?,
        ))
    }

    /// The soft-body vertices: x, y, z (m) each.
    pub fn soft_positions(&mut self) -> &[f32] {
        self.buffer.clear();
        if let Some(soft) = self.simulation.world().soft() {
            flatten(soft.positions(), &mut self.buffer);
        }
        &self.buffer
    }

    /// The soft bodies' edges as pairs of vertex numbers.
    pub fn soft_edges(&self) -> Vec<u32> {
        self.world()
            .soft()
            .map(|soft| soft.edges().flat_map(|(a, b)| [a, b]).collect())
            .unwrap_or_default()
    }

    /// The fluid particles: x, y, z (m) each.
    pub fn fluid_positions(&mut self) -> &[f32] {
        self.buffer.clear();
        if let Some(fluid) = self.simulation.world().fluid() {
            flatten(fluid.positions(), &mut self.buffer);
        }
        &self.buffer
    }

    /// The live particles (particle subsystem): x, y, z (m) each.
    pub fn particle_positions(&mut self) -> &[f32] {
        self.buffer.clear();
        if let Some(particles) = self.simulation.world().particles() {
            let live = particles
                .positions()
                .iter()
                .zip(particles.alive())
                .filter(|(_, alive)| **alive);
            for (p, _) in live {
                self.buffer.extend(p.to_f64().map(|c| c as f32));
            }
        }
        &self.buffer
    }
}

impl Session {
    /// The characters' centres: x, y, z (m) each, in character order.
    pub fn character_positions(&mut self) -> &[f32] {
        self.buffer.clear();
        if let Some(characters) = self.simulation.world().characters() {
            for c in characters.characters() {
                self.buffer.extend(c.position.to_f64().map(|x| x as f32));
            }
        }
        &self.buffer
    }

    /// Character number `i`'s shape as triangles around its centre (characters never
    /// rotate).
    pub fn character_mesh(&self, i: usize) -> Option<TriangleMesh> {
        let c = self.world().characters()?.characters().get(i)?;
        Some(shape_mesh(&c.shape))
    }

    /// How many characters the world has.
    pub fn character_count(&self) -> usize {
        self.world()
            .characters()
            .map_or(0, |characters| characters.characters().len())
    }

    /// The water surface's grid, if the world has water.
    pub fn water_grid(&self) -> Option<WaterGrid> {
        let s = self.world().water()?.settings();
        Some(WaterGrid {
            columns: s.columns,
            rows: s.rows,
            cell_size: s.cell_size.to_f64(),
            origin: s.origin.to_f64(),
        })
    }

    /// The water surface's height above the grid's origin (m) at each cell centre, row by
    /// row (x fastest); empty without water.
    pub fn water_heights(&mut self) -> &[f32] {
        self.buffer.clear();
        if let Some(water) = self.simulation.world().water() {
            self.buffer
                .extend(water.heights().iter().map(|h| h.to_f64() as f32));
        }
        &self.buffer
    }
}

fn flatten(points: &[Vec3<Fx>], out: &mut Vec<f32>) {
    out.reserve(points.len() * 3);
    for p in points {
        out.extend(p.to_f64().map(|c| c as f32));
    }
}
