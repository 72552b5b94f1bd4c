//! The scenes every engine builds, and what one run of an engine on them returns.

/// A rigid-body scene every engine builds: its name, the steps one run takes, and whether
/// bodies may fall asleep.
#[derive(Clone, Copy)]
pub struct Scene {
    pub name: &'static str,
    pub steps: u32,
    pub sleeping: bool,
}

/// The rigid-body scenes: issue #6's benchmark table, sleeping off, then the two scenes
/// that come to rest with sleeping on, then issue #35's landing: 1000 hulls and 1000
/// balls dropped on a 256 × 256 heightfield (`hills`) and on the same terrain as a
/// triangle mesh (`hills_mesh`), sleeping off.
pub const SCENES: [Scene; 7] = [
    Scene {
        name: "pyramid",
        steps: 500,
        sleeping: false,
    },
    Scene {
        name: "balls",
        steps: 500,
        sleeping: false,
    },
    Scene {
        name: "falling",
        steps: 1000,
        sleeping: false,
    },
    Scene {
        name: "pyramid",
        steps: 500,
        sleeping: true,
    },
    Scene {
        name: "balls",
        steps: 500,
        sleeping: true,
    },
    Scene {
        name: "hills",
        steps: 300,
        sleeping: false,
    },
    Scene {
        name: "hills_mesh",
        steps: 300,
        sleeping: false,
    },
];

/// How fixstep runs a fluid scene: DFSPH's tolerance on the mean predicted compression,
/// the substeps per step (with a CFL number, the most) and the CFL number of adaptive
/// substeps (0: the fixed count).
#[derive(Clone, Copy)]
pub struct FixstepFluid {
    pub tolerance: f32,
    pub substeps: u32,
    pub cfl: f32,
}

impl FixstepFluid {
    /// The settings as the table names them.
    pub fn label(&self) -> String {
        let substeps = if self.cfl == 0.0 {
            format!("{} substeps", self.substeps)
        } else {
            format!(
                "adaptive substeps at CFL {}, at most {}",
                self.cfl, self.substeps
            )
        };
        format!("tolerance {} %, {substeps}", 100.0 * self.tolerance)
    }
}

/// fixstep's tolerance (`FluidDesc::max_density_error`'s default), 0.05 %.
pub const FIXSTEP_TOLERANCE: f32 = 0.0005;

/// salva3d's default tolerance (`DFSPHSolver::max_density_error`), 5 %.
pub const SALVA_TOLERANCE: f32 = 0.05;

/// A fluid scene: a block of fluid on the lattice sites of `[0, block]` (m) resting in the
/// corner of an open tank `[0, tank]` lined with two layers of boundary particles, particles
/// `spacing` (m) apart; `steps` timed steps of `dt` (s) after `warm_steps`. fixstep runs once
/// per entry of `fixstep` (the first is the reference of the ratios and the `f64` run):
/// the fixed count is the fewest its time-step limit 0.2 H/u allows (u = c/10 = 2 m/s).
/// salva3d 0.11 takes one substep per step whatever the flow: its CFL control is switched
/// off (`TimestepManager::compute_substep` returns the whole step).
pub struct FluidScene {
    pub name: &'static str,
    pub spacing: f32,
    pub block: [f32; 3],
    pub tank: [f32; 3],
    pub dt: f32,
    pub warm_steps: u32,
    pub steps: u32,
    pub fixstep: &'static [FixstepFluid],
}

/// Martin & Moyce's column width a = 2.25 in, m.
pub const DAM_WIDTH: f32 = 0.05715;

/// The fluid scenes.
pub const FLUID_SCENES: [FluidScene; 2] = [
    // `water`: a cube of 20³ particles 1 cm apart settling on the floor of a tank of the
    // same footprint, 1.5 × as high (salva3d's setup in issue #8); timed after 20 steps.
    FluidScene {
        name: "water",
        spacing: 0.01,
        block: [0.2, 0.2, 0.2],
        tank: [0.2, 0.3, 0.2],
        dt: 0.005,
        warm_steps: 20,
        steps: 10,
        fixstep: &[
            FixstepFluid {
                tolerance: FIXSTEP_TOLERANCE,
                substeps: 3,
                cfl: 0.0,
            },
            FixstepFluid {
                tolerance: SALVA_TOLERANCE,
                substeps: 3,
                cfl: 0.0,
            },
        ],
    },
    // `dam_break`: Martin & Moyce's column, a wide and 2a high at the back wall of a tank
    // 0.3 m long and 0.15 m high, 20 particles across a and 10 deep (8000 particles), as
    // fixstep's built-in `dam_break` at a finer spacing; the whole collapse is timed, 22
    // steps to T = t·√(2g/a) ≈ 2.
    FluidScene {
        name: "dam_break",
        spacing: DAM_WIDTH / 20.0,
        block: [DAM_WIDTH, 2.0 * DAM_WIDTH, 10.0 * DAM_WIDTH / 20.0],
        tank: [0.3, 0.15, 10.0 * DAM_WIDTH / 20.0],
        dt: 0.005,
        warm_steps: 0,
        steps: 22,
        fixstep: &[
            FixstepFluid {
                tolerance: FIXSTEP_TOLERANCE,
                substeps: 9,
                cfl: 0.0,
            },
            FixstepFluid {
                tolerance: FIXSTEP_TOLERANCE,
                substeps: 9,
                cfl: 0.2,
            },
            FixstepFluid {
                tolerance: SALVA_TOLERANCE,
                substeps: 9,
                cfl: 0.0,
            },
            FixstepFluid {
                tolerance: SALVA_TOLERANCE,
                substeps: 9,
                cfl: 0.2,
            },
            FixstepFluid {
                tolerance: SALVA_TOLERANCE,
                substeps: 9,
                cfl: 0.3,
            },
        ],
    },
];

impl FluidScene {
    /// The fluid at the start: the lattice sites of the block, x fastest, then y, then z.
    pub fn fluid(&self) -> Vec<[f32; 3]> {
        let dx = self.spacing;
        let mut points = Vec::new();
        for &z in &sites(0.0, self.block[2], dx) {
            for &y in &sites(0.0, self.block[1], dx) {
                for &x in &sites(0.0, self.block[0], dx) {
                    points.push([x, y, z]);
                }
            }
        }
        points
    }

    /// The tank's boundary particles, as fixstep samples them (`src/fluid/boundary.rs`):
    /// two layers one spacing apart outside the floor (under the walls too) and the four
    /// walls.
    pub fn walls(&self) -> Vec<[f32; 3]> {
        let dx = self.spacing;
        let [length, height, depth] = self.tank;
        let thickness = 2.0 * dx;
        let outer_x = sites(-thickness, length + thickness, dx);
        let outer_z = sites(-thickness, depth + thickness, dx);
        let inner_x = sites(0.0, length, dx);
        let rise = sites(0.0, height, dx);
        let layers = sites(0.0, thickness, dx);
        let mut points = Vec::new();
        for &z in &outer_z {
            for &layer in &layers {
                for &x in &outer_x {
                    points.push([x, -layer, z]);
                }
            }
        }
        for &z in &outer_z {
            for &y in &rise {
                for &layer in &layers {
                    points.push([-layer, y, z]);
                    points.push([length + layer, y, z]);
                }
            }
        }
        for &layer in &layers {
            for &y in &rise {
                for &x in &inner_x {
                    points.push([x, y, -layer]);
                    points.push([x, y, depth + layer]);
                }
            }
        }
        points
    }
}

/// The lattice sites `lo + (i + ½)·spacing` below `hi`.
fn sites(lo: f32, hi: f32, spacing: f32) -> Vec<f32> {
    let count = ((hi - lo) / spacing).round() as usize;
    (0..count)
        .map(|i| lo + (i as f32 + 0.5) * spacing)
        .collect()
}

/// One run of a rigid scene: mean ms per step, and the positions (m) of the dynamic bodies
/// before the first step and after the last, in the order they were created.
pub struct RigidRun {
    pub ms: f64,
    pub start: Vec<[f64; 3]>,
    pub end: Vec<[f64; 3]>,
}

/// One run of the fluid scene: mean ms per step of the timed steps, and the fluid
/// particles' positions (m) after them.
pub struct FluidRun {
    pub ms: f64,
    pub positions: Vec<[f64; 3]>,
}
