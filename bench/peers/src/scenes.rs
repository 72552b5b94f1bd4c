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
/// that come to rest with sleeping on.
pub const SCENES: [Scene; 5] = [
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
];

/// The fluid scene: a cube of `n`³ particles `spacing` (m) apart in a tank of the same
/// footprint, 1.5 × as high; `steps` timed steps of `dt` (s) after `warm_steps`.
pub struct FluidScene {
    pub n: u32,
    pub spacing: f32,
    pub dt: f32,
    pub warm_steps: u32,
    pub steps: u32,
}

impl FluidScene {
    /// Side of the cube and the tank, m.
    pub fn side(&self) -> f32 {
        self.spacing * self.n as f32
    }

    /// Height of the tank, m.
    pub fn height(&self) -> f32 {
        1.5 * self.side()
    }

    /// The fluid at the start: the lattice sites of the cube, x fastest, then y, then z.
    pub fn fluid(&self) -> Vec<[f32; 3]> {
        let inner = sites(0.0, self.side(), self.spacing);
        let mut points = Vec::new();
        for &z in &inner {
            for &y in &inner {
                for &x in &inner {
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
        let (dx, side, height) = (self.spacing, self.side(), self.height());
        let thickness = 2.0 * dx;
        let outer = sites(-thickness, side + thickness, dx);
        let inner = sites(0.0, side, dx);
        let rise = sites(0.0, height, dx);
        let layers = sites(0.0, thickness, dx);
        let mut points = Vec::new();
        for &z in &outer {
            for &depth in &layers {
                for &x in &outer {
                    points.push([x, -depth, z]);
                }
            }
        }
        for &z in &outer {
            for &y in &rise {
                for &depth in &layers {
                    points.push([-depth, y, z]);
                    points.push([side + depth, y, z]);
                }
            }
        }
        for &depth in &layers {
            for &y in &rise {
                for &x in &inner {
                    points.push([x, y, -depth]);
                    points.push([x, y, side + depth]);
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

/// `water`: 8000 particles 1 cm apart, steps of 5 ms (salva3d's setup in issue #8).
pub const WATER: FluidScene = FluidScene {
    n: 20,
    spacing: 0.01,
    dt: 0.005,
    warm_steps: 20,
    steps: 10,
};

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
