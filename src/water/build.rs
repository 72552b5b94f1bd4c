//! Checking a [`WaterDesc`] and compiling it into a [`WaterSystem`].

use super::desc::{MAX_WATER_CELLS, MAX_WATER_SUBSTEPS, WaterDesc, WaterParticleFloat};
use super::system::{WaterSettings, WaterSystem, WaveScratch};
use super::waves::wave_substeps;
use crate::math::{Real, Vec3};
use crate::types::SceneError;

impl<R: Real> WaterSystem<R> {
    /// Checks `desc` and builds the still surface, for world substeps of `dt` seconds under
    /// `gravity` (m/s², which sets the wave speed when the scene gives none). Errors name
    /// the offending field.
    pub fn from_desc(desc: &WaterDesc<R>, dt: R, gravity: Vec3<R>) -> Result<Self, SceneError> {
        let (columns, rows) = desc.cells;
        if columns == 0 || rows == 0 {
            return Err(SceneError::new(
                "cells",
                format!("needs at least one column and one row (got ({columns}, {rows}))"),
            ));
        }
        let cells = u64::from(columns) * u64::from(rows);
        if cells > MAX_WATER_CELLS {
            return Err(SceneError::new(
                "cells",
                format!("at most {MAX_WATER_CELLS} cells (got {columns} × {rows} = {cells})"),
            ));
        }
        let metres = |n: i32| R::from_int(n);
        SceneError::check_range(
            "cell_size",
            desc.cell_size,
            R::from_ratio(1, 1000),
            metres(1000),
            "m",
        )?;
        SceneError::check_range(
            "depth",
            desc.depth,
            R::from_ratio(1, 1000),
            metres(10_000),
            "m",
        )?;
        SceneError::check_range("damping", desc.damping, R::ZERO, metres(1000), "1/s")?;
        SceneError::check_range("density", desc.density, R::ONE, metres(100_000), "kg/m³")?;
        let extent = |n: u32| desc.cell_size * R::from_int(n as i32);
        let far = |o: R, n: u32| (o.abs() + extent(n)) <= metres(100_000);
        if !far(desc.origin.x, columns)
            || !far(desc.origin.z, rows)
            || desc.origin.y.abs() > metres(100_000)
        {
            return Err(SceneError::new(
                "origin",
                "the grid must lie within 100 km of the world's origin",
            ));
        }
        let wave_speed = match desc.wave_speed {
            Some(c) => {
                SceneError::check_range(
                    "wave_speed",
                    c,
                    R::from_ratio(1, 1000),
                    metres(1000),
                    "m/s",
                )?;
                c
            }
            None => (gravity.length() * desc.depth).sqrt(),
        };
        if wave_speed <= R::ZERO {
            return Err(SceneError::new(
                "wave_speed",
                "absent, and √(|g| · depth) is 0: give a wave speed or a gravity",
            ));
        }
        let substeps = wave_substeps(wave_speed, dt, desc.cell_size).ok_or_else(|| {
            SceneError::new(
                "cell_size",
                format!(
                    "too small for a wave speed of {wave_speed} m/s: a substep of {dt} s would \
                     need more than {MAX_WATER_SUBSTEPS} wave steps (c · h / cell_size ≤ 1/2)"
                ),
            )
        })?;
        let step = dt / R::from_int(substeps as i32);
        if desc.damping * step > R::from_ratio(1, 2) {
            return Err(SceneError::new(
                "damping",
                format!(
                    "too strong for wave steps of {step} s: damping · step must be at most 1/2 \
                     (got {})",
                    desc.damping * step
                ),
            ));
        }
        for (k, float) in desc.particles.iter().enumerate() {
            check_float(float).map_err(|e| e.within(&format!("particles[{k}]")))?;
            if desc.particles[..k].iter().any(|f| f.group == float.group) {
                return Err(SceneError::new(
                    format!("particles[{k}].group"),
                    format!("group {} is listed twice", float.group),
                ));
            }
        }
        if let Some(bodies) = &desc.bodies {
            SceneError::check_range("bodies.drag", bodies.drag, R::ZERO, metres(1000), "1/s")?;
            SceneError::check_range(
                "bodies.angular_drag",
                bodies.angular_drag,
                R::ZERO,
                metres(1000),
                "1/s",
            )?;
        }
        let settings = WaterSettings {
            origin: desc.origin,
            columns,
            rows,
            cell_size: desc.cell_size,
            depth: desc.depth,
            wave_speed,
            damping: desc.damping,
            density: desc.density,
            border: desc.border,
            substeps,
            particles: desc.particles.clone(),
            bodies: desc.bodies,
        };
        let (n, m) = (columns as usize, rows as usize);
        Ok(Self {
            settings,
            heights: vec![R::ZERO; n * m],
            flow_x: vec![R::ZERO; (n - 1) * m],
            flow_z: vec![R::ZERO; n * (m - 1)],
            scratch: WaveScratch::default(),
        })
    }

    /// Checks the invariants the step relies on, for a state from outside (a snapshot):
    /// array lengths that match the grid, settings within the ranges a scene may give.
    pub fn validate(&self) -> Result<(), SceneError> {
        let s = &self.settings;
        let (n, m) = (s.columns as usize, s.rows as usize);
        if n == 0 || m == 0 || (n as u64) * (m as u64) > MAX_WATER_CELLS {
            return Err(SceneError::new(
                "settings.columns",
                "a grid of no or too many cells",
            ));
        }
        if self.heights.len() != n * m {
            return Err(SceneError::new("heights", "one height per cell"));
        }
        if self.flow_x.len() != (n - 1) * m || self.flow_z.len() != n * (m - 1) {
            return Err(SceneError::new("flow_x", "one flow per inner edge"));
        }
        if s.substeps == 0 || s.substeps > MAX_WATER_SUBSTEPS {
            return Err(SceneError::new(
                "settings.substeps",
                format!("must be 1 to {MAX_WATER_SUBSTEPS}"),
            ));
        }
        if s.cell_size <= R::ZERO || s.wave_speed <= R::ZERO || s.depth <= R::ZERO {
            return Err(SceneError::new(
                "settings",
                "cell size, wave speed and depth must be positive",
            ));
        }
        for (k, float) in s.particles.iter().enumerate() {
            check_float(float).map_err(|e| e.within(&format!("settings.particles[{k}]")))?;
        }
        Ok(())
    }

    /// Takes `restored`'s state (a snapshot's); the surface keeps nothing else.
    pub fn restore_from(&mut self, restored: Self) {
        *self = restored;
    }
}

/// A particle group's column: volume and height positive, drag not negative.
fn check_float<R: Real>(float: &WaterParticleFloat<R>) -> Result<(), SceneError> {
    let big = R::from_int(1000);
    SceneError::check_range(
        "volume",
        float.volume,
        R::from_ratio(1, 1_000_000),
        big,
        "m³",
    )?;
    SceneError::check_range("height", float.height, R::from_ratio(1, 1000), big, "m")?;
    SceneError::check_range("drag", float.drag, R::ZERO, big, "1/s")
}
