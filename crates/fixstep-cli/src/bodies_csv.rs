//! The `--bodies` CSV file: the state of every live rigid body and every kinematic
//! character every K ticks (from tick 0, and after the last tick, like `--metrics`),
//! written atomically.

use std::path::Path;

use super::csv_file::CsvFile;
use fixstep::character::CharacterSystem;
use fixstep::math::{Fx, Real, Vec3};
use fixstep::world::World;

/// The columns: tick, the body's handle (`3v0`), its centre of mass (m), orientation
/// quaternion, linear velocity (m/s) and angular velocity (rad/s, world frame). A
/// character's row follows the bodies' with its handle after a `c` (`c0v0`), its centre,
/// the identity orientation, its own velocity and no angular velocity.
pub const BODIES_CSV_HEADER: &str = "tick,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz";

/// A bodies file being written.
#[derive(Debug)]
pub struct BodiesCsv {
    file: CsvFile,
    every: u64,
    last_tick: Option<u64>,
}

impl BodiesCsv {
    /// Starts the file at `path` with the CSV header; rows are due every `every` ticks.
    pub fn create(path: &Path, every: u64) -> Result<Self, String> {
        Ok(Self {
            file: CsvFile::create(path, BODIES_CSV_HEADER)?,
            every: every.max(1),
            last_tick: None,
        })
    }

    /// Writes the rows if they are due at the world's tick.
    pub fn tick(&mut self, world: &World<Fx>) -> Result<(), String> {
        if world.tick().is_multiple_of(self.every) {
            self.rows(world)?;
        }
        Ok(())
    }

    /// Writes the last rows (unless already written) and puts the file in place.
    pub fn finish(mut self, world: &World<Fx>) -> Result<(), String> {
        if self.last_tick != Some(world.tick()) {
            self.rows(world)?;
        }
        self.file.commit()
    }

    /// One row per live body, in slot order, then one per character, in index order.
    fn rows(&mut self, world: &World<Fx>) -> Result<(), String> {
        let tick = world.tick();
        self.last_tick = Some(tick);
        self.body_rows(world)?;
        let Some(characters) = world.characters() else {
            return Ok(());
        };
        for (i, c) in characters.characters().iter().enumerate() {
            let handle = CharacterSystem::<Fx>::handle(i);
            self.file.line(&format!(
                "{tick},c{handle},{},1,0,0,0,{},0,0,0",
                columns(c.position),
                columns(c.velocity)
            ))?;
        }
        Ok(())
    }

    /// One row per live body, in slot order; none in a world without rigid bodies.
    fn body_rows(&mut self, world: &World<Fx>) -> Result<(), String> {
        let tick = world.tick();
        let Some(rigid) = world.rigid() else {
            return Ok(());
        };
        for handle in rigid.handles() {
            // Every handle `handles` gives names a live body.
            let (Some(x), Some(q), Some(v), Some(w)) = (
                rigid.position(handle),
                rigid.orientation(handle),
                rigid.linear_velocity(handle),
                rigid.angular_velocity(handle),
            ) else {
                continue;
            };
            let [qw, qx, qy, qz] = q.to_f64();
            self.file.line(&format!(
                "{tick},{handle},{},{qw},{qx},{qy},{qz},{},{}",
                columns(x),
                columns(v),
                columns(w)
            ))?;
        }
        Ok(())
    }
}

/// `x,y,z` of a vector.
fn columns(v: Vec3<Fx>) -> String {
    format!("{},{},{}", v.x.to_f64(), v.y.to_f64(), v.z.to_f64())
}
