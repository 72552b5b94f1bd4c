//! fixstep in the browser: the JavaScript API of the `fixstep-web` wasm package (built for
//! `wasm32-unknown-unknown` by `scripts/web-build.sh` with `wasm-bindgen`; see
//! `docs/web.md`).
//!
//! A [`Session`] runs one scene (a built-in one or RON text): step it, give it commands,
//! read its bodies, soft vertices and particles as typed arrays that look straight into the
//! module's memory, snapshot and restore it as bytes, print its checksum exactly as
//! `fixstep run` does, and write what it ran as a replay. [`verify_replay`] simulates a
//! replay file again, as `fixstep verify` does. Errors are JavaScript `Error`s whose message
//! is the line the `fixstep` command would print.

pub mod session;
pub mod shape_mesh;
pub mod verdict;

use fixstep::world::Handle;
use js_sys::{Float32Array, Uint32Array};
use wasm_bindgen::prelude::*;

/// The built-in scenes' names, in `fixstep scenes` order.
#[wasm_bindgen]
pub fn scenes() -> Vec<String> {
    fixstep_scenes::BUILTIN_SCENES
        .iter()
        .map(|(name, _)| (*name).to_owned())
        .collect()
}

/// The one-line description of the built-in scene `name`, if there is one.
#[wasm_bindgen(js_name = sceneDescription)]
pub fn scene_description(name: &str) -> Option<String> {
    fixstep_scenes::BUILTIN_SCENES
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, description)| (*description).to_owned())
}

/// The vector kernels this module was built with: `simd128` or `scalar`.
#[wasm_bindgen]
pub fn kernels() -> String {
    if cfg!(target_feature = "simd128") {
        "simd128".to_owned()
    } else {
        "scalar".to_owned()
    }
}

/// What [`verify_replay`] found.
#[wasm_bindgen(getter_with_clone)]
#[derive(Clone, Debug)]
pub struct Verdict {
    /// `ok` or `desync`.
    pub verdict: String,
    /// Ticks simulated (ok) or the tick of the first checkpoint that differs (desync).
    pub tick: f64,
    /// The first subsystem whose sub-checksum differs (`unknown` when none does; empty
    /// when ok).
    pub subsystem: String,
    /// The first object whose digest differs, such as `2v0` (`unknown` when none does;
    /// empty when ok).
    pub object: String,
    /// The recorded checksum, 16 hex digits.
    pub expected: String,
    /// The checksum simulated here, 16 hex digits.
    pub got: String,
    /// The line `fixstep verify` prints.
    pub line: String,
}

/// Simulates the replay file `bytes` again and compares every checkpoint, as
/// `fixstep verify` does; `origin` (a file name) starts the messages. Throws an `Error`
/// naming the section and the byte offset when the bytes are not a valid replay.
#[wasm_bindgen(js_name = verifyReplay)]
pub fn verify_replay(bytes: &[u8], origin: &str) -> Result<Verdict, JsError> {
    let v = verdict::verify_bytes(bytes, origin).map_err(|e| JsError::new(&e))?;
    Ok(Verdict {
        verdict: v.verdict,
        tick: v.tick as f64,
        subsystem: v.subsystem,
        object: v.object,
        expected: v.expected,
        got: v.got,
        line: v.line,
    })
}

/// A rigid body's shape as triangles in its own frame, with its kind.
#[wasm_bindgen]
#[derive(Clone, Debug)]
pub struct BodyMesh {
    mesh: shape_mesh::TriangleMesh,
    kind: u8,
    sleeping: bool,
}

#[wasm_bindgen]
impl BodyMesh {
    /// x, y, z (m, body frame) per vertex (a copy).
    #[wasm_bindgen(getter)]
    pub fn positions(&self) -> Float32Array {
        Float32Array::from(self.mesh.positions.as_slice())
    }

    /// Three vertex numbers per triangle, counter-clockwise seen from outside (a copy).
    #[wasm_bindgen(getter)]
    pub fn indices(&self) -> Uint32Array {
        Uint32Array::from(self.mesh.indices.as_slice())
    }

    /// 0 static, 1 kinematic, 2 dynamic.
    #[wasm_bindgen(getter)]
    pub fn kind(&self) -> u8 {
        self.kind
    }

    /// Whether the body was asleep when the mesh was taken.
    #[wasm_bindgen(getter)]
    pub fn sleeping(&self) -> bool {
        self.sleeping
    }
}

/// One scene running: see the [crate documentation](crate).
///
/// The typed arrays of `bodyPoses`, `softPositions`, `fluidPositions` and
/// `particlePositions` are views into the module's memory: read them before the next call
/// on any session (a call may move that memory).
#[wasm_bindgen]
#[derive(Debug)]
pub struct Session(session::Session);

#[wasm_bindgen]
impl Session {
    /// The built-in scene `name` at tick 0.
    pub fn builtin(name: &str) -> Result<Session, JsError> {
        session::Session::builtin(name)
            .map(Session)
            .map_err(|e| JsError::new(&e))
    }

    /// The scene written in RON `text` (a scene file) at tick 0; `origin` names it in errors.
    #[wasm_bindgen(js_name = fromRon)]
    pub fn from_ron(text: &str, origin: &str) -> Result<Session, JsError> {
        session::Session::from_ron(text, origin)
            .map(Session)
            .map_err(|e| JsError::new(&e))
    }

    /// The replay file `bytes` at tick 0, fed its recorded inputs (stepped to its last tick,
    /// its checksum is the replay's final one); `origin` names it in errors, which give the
    /// section and the byte offset of bad bytes.
    #[wasm_bindgen(js_name = fromReplay)]
    pub fn from_replay(bytes: &[u8], origin: &str) -> Result<Session, JsError> {
        session::Session::from_replay(bytes, origin)
            .map(Session)
            .map_err(|e| JsError::new(&e))
    }

    /// The ticks of the replay this session plays (`fromReplay`); undefined for a scene.
    #[wasm_bindgen(getter, js_name = recordedTicks)]
    pub fn recorded_ticks(&self) -> Option<f64> {
        self.0.recorded().map(|(ticks, _)| ticks as f64)
    }

    /// The final checksum the replay this session plays recorded, 16 hex digits;
    /// undefined for a scene.
    #[wasm_bindgen(getter, js_name = recordedChecksum)]
    pub fn recorded_checksum(&self) -> Option<String> {
        self.0
            .recorded()
            .map(|(_, checksum)| fixstep::world::checksum::hex(checksum))
    }

    /// The scene's name.
    #[wasm_bindgen(getter)]
    pub fn name(&self) -> String {
        self.0.scene().name.clone()
    }

    /// The scene's tick rate (Hz).
    #[wasm_bindgen(getter, js_name = tickRate)]
    pub fn tick_rate(&self) -> u32 {
        self.0.world().settings().tick_rate
    }

    /// The number of ticks the scene runs by default.
    #[wasm_bindgen(getter, js_name = sceneTicks)]
    pub fn scene_ticks(&self) -> f64 {
        self.0.scene().ticks as f64
    }

    /// The world's tick (the ticks run since tick 0).
    #[wasm_bindgen(getter)]
    pub fn tick(&self) -> f64 {
        self.0.world().tick() as f64
    }

    /// Runs `ticks` ticks, each with the scene's script; the queued commands go into the
    /// first.
    pub fn step(&mut self, ticks: u32) {
        for _ in 0..ticks {
            self.0.step();
        }
    }

    /// The world checksum, 16 hex digits, as `fixstep run NAME --ticks N` prints it.
    pub fn checksum(&self) -> String {
        self.0.checksum()
    }

    /// Queues, for the next tick, an impulse on body (`index`, `generation`) that changes its
    /// velocity by `speed` (m/s) along (`dx`, `dy`, `dz`), applied at the world point
    /// (`px`, `py`, `pz`) (m): `ApplyImpulse` with J = m · speed · d̂. False when the body
    /// is gone or not dynamic.
    #[wasm_bindgen(js_name = queueImpulse)]
    #[allow(clippy::too_many_arguments)]
    pub fn queue_impulse(
        &mut self,
        index: u32,
        generation: u32,
        dx: f64,
        dy: f64,
        dz: f64,
        px: f64,
        py: f64,
        pz: f64,
        speed: f64,
    ) -> bool {
        self.0.queue_push(
            Handle::new(index, generation),
            [dx, dy, dz],
            [px, py, pz],
            speed,
        )
    }

    /// Queues, for the next tick, the commands written in RON `text` (a list of the
    /// script's commands, such as `[SetGravity(gravity: (x: 0, y: -1, z: 0))]`).
    #[wasm_bindgen(js_name = queueCommands)]
    pub fn queue_commands(&mut self, text: &str) -> Result<(), JsError> {
        self.0.queue_ron(text).map_err(|e| JsError::new(&e))
    }

    /// How many ticks so far had commands from the page.
    #[wasm_bindgen(getter, js_name = commandTicks)]
    pub fn command_ticks(&self) -> u32 {
        self.0.page_ticks().len() as u32
    }

    /// The world as a snapshot file (the bytes `fixstep run --snapshot` writes).
    pub fn snapshot(&self) -> Result<Vec<u8>, JsError> {
        self.0.snapshot().map_err(|e| JsError::new(&e))
    }

    /// Restores a snapshot file of this scene (the inputs given at or after its tick are
    /// forgotten).
    pub fn restore(&mut self, bytes: &[u8]) -> Result<(), JsError> {
        self.0.restore(bytes).map_err(|e| JsError::new(&e))
    }

    /// The run from tick 0 to now as a replay file, which `fixstep verify` accepts.
    pub fn replay(&self) -> Result<Vec<u8>, JsError> {
        self.0.replay().map_err(|e| JsError::new(&e))
    }

    /// The live rigid bodies' poses, seven numbers each: x, y, z (m) and the orientation's
    /// x, y, z, w (the order of three.js). A view into the module's memory.
    #[wasm_bindgen(js_name = bodyPoses)]
    pub fn body_poses(&mut self) -> Float32Array {
        // SAFETY: the view is of a live buffer, and the caller reads it before the next call
        // into the module (the type's documentation), which alone could move or free it.
        unsafe { Float32Array::view(self.0.body_poses()) }
    }

    /// A number that changes when the list of live bodies changes (read after `bodyPoses`).
    #[wasm_bindgen(getter, js_name = bodyLayout)]
    pub fn body_layout(&self) -> u32 {
        self.0.body_layout()
    }

    /// The live bodies of the last `bodyPoses`, as index and generation pairs.
    #[wasm_bindgen(js_name = bodyHandles)]
    pub fn body_handles(&self) -> Uint32Array {
        let pairs: Vec<u32> = self
            .0
            .body_handles()
            .iter()
            .flat_map(|h| [h.index, h.generation])
            .collect();
        Uint32Array::from(pairs.as_slice())
    }

    /// Body number `i` of the last `bodyPoses`: its shape as triangles and its kind.
    #[wasm_bindgen(js_name = bodyMesh)]
    pub fn body_mesh(&self, i: u32) -> Option<BodyMesh> {
        self.0
            .body(i as usize)
            .map(|(mesh, kind, sleeping)| BodyMesh {
                mesh,
                kind,
                sleeping,
            })
    }

    /// The soft-body vertices, x, y, z (m) each. A view into the module's memory.
    #[wasm_bindgen(js_name = softPositions)]
    pub fn soft_positions(&mut self) -> Float32Array {
        // SAFETY: as in `body_poses`.
        unsafe { Float32Array::view(self.0.soft_positions()) }
    }

    /// The soft bodies' edges, pairs of vertex numbers (a copy).
    #[wasm_bindgen(js_name = softEdges)]
    pub fn soft_edges(&self) -> Uint32Array {
        Uint32Array::from(self.0.soft_edges().as_slice())
    }

    /// The fluid particles, x, y, z (m) each. A view into the module's memory.
    #[wasm_bindgen(js_name = fluidPositions)]
    pub fn fluid_positions(&mut self) -> Float32Array {
        // SAFETY: as in `body_poses`.
        unsafe { Float32Array::view(self.0.fluid_positions()) }
    }

    /// The live particles of the particle subsystem, x, y, z (m) each. A view into the
    /// module's memory.
    #[wasm_bindgen(js_name = particlePositions)]
    pub fn particle_positions(&mut self) -> Float32Array {
        // SAFETY: as in `body_poses`.
        unsafe { Float32Array::view(self.0.particle_positions()) }
    }

    /// How many characters the world has.
    #[wasm_bindgen(getter, js_name = characterCount)]
    pub fn character_count(&self) -> u32 {
        self.0.character_count() as u32
    }

    /// The characters' centres, x, y, z (m) each. A view into the module's memory.
    #[wasm_bindgen(js_name = characterPositions)]
    pub fn character_positions(&mut self) -> Float32Array {
        // SAFETY: as in `body_poses`.
        unsafe { Float32Array::view(self.0.character_positions()) }
    }

    /// Character number `i`'s shape as triangles around its centre (kind 1: it moves as
    /// told, never rotating).
    #[wasm_bindgen(js_name = characterMesh)]
    pub fn character_mesh(&self, i: u32) -> Option<BodyMesh> {
        self.0.character_mesh(i as usize).map(|mesh| BodyMesh {
            mesh,
            kind: 1,
            sleeping: false,
        })
    }

    /// The water surface's grid, `[columns, rows, cell size (m), origin x, y, z (m)]`;
    /// undefined without water. Cell (i, k)'s centre is at origin + ((i + ½)·size, height,
    /// (k + ½)·size).
    #[wasm_bindgen(js_name = waterGrid)]
    pub fn water_grid(&self) -> Option<Vec<f64>> {
        self.0.water_grid().map(|g| {
            vec![
                f64::from(g.columns),
                f64::from(g.rows),
                g.cell_size,
                g.origin[0],
                g.origin[1],
                g.origin[2],
            ]
        })
    }

    /// The water surface's height above the grid's origin (m) at each cell centre, row by
    /// row (x fastest). A view into the module's memory.
    #[wasm_bindgen(js_name = waterHeights)]
    pub fn water_heights(&mut self) -> Float32Array {
        // SAFETY: as in `body_poses`.
        unsafe { Float32Array::view(self.0.water_heights()) }
    }
}
