//! Soft-body sections of the built-in scenes. Every constant is an exact ratio or an
//! integer, so the presets are the same bits on every machine.

use fixstep::math::{Quat, Real, Vec3};
use fixstep::particles::Integrator;
use fixstep::rigid::Shape;
use fixstep::soft::{
    AttachmentDesc, ColliderDesc, SoftBodyDesc, SoftDesc, SoftModel, SoftShape, XpbdSettings,
};
use fixstep::world::{Command, PlayerInput, Target, TickInput};

/// `num/den` in the scalar format.
fn ratio<R: Real>(num: i64, den: i64) -> R {
    R::from_ratio(num, den)
}

/// The static ground y ≤ 0, friction ½.
fn ground<R: Real>() -> ColliderDesc<R> {
    ColliderDesc {
        shape: Shape::Plane {
            normal: Vec3::Y,
            offset: R::ZERO,
        },
        position: Vec3::ZERO,
        orientation: Quat::IDENTITY,
        friction: R::HALF,
    }
}

/// A body of `shape` and `model` weighing `mass` kg, at rest, with the default radius and
/// no pins, attachments, damping or wind.
pub fn body<R: Real>(shape: SoftShape<R>, model: SoftModel<R>, mass: R) -> SoftBodyDesc<R> {
    SoftBodyDesc {
        shape,
        model,
        mass,
        pins: Vec::new(),
        attachments: Vec::new(),
        body_attachments: Vec::new(),
        body_contacts: None,
        velocity: Vec3::ZERO,
        damping: R::ZERO,
        radius: ratio(1, 100),
        wind: Vec3::ZERO,
        drag: R::ZERO,
    }
}

/// An inextensible XPBD cloth (stretch compliance 0, tethered to its pinned and attached
/// vertices) with a bending compliance of 1 /(N·m).
fn cloth_model<R: Real>() -> SoftModel<R> {
    SoftModel::Xpbd {
        stretch_compliance: R::ZERO,
        bend_compliance: Some(R::ONE),
        volume_compliance: None,
        tethers: true,
    }
}

/// A horizontal square cloth of `n` × `n` vertices, 1 m a side, 0.1 kg, at height 2 m,
/// pinned at its two corners on the x axis, falling and swinging under gravity, with a
/// velocity damping of ½ /s (the air) that lets it come to rest within seconds. 40 XPBD
/// substeps a tick keep every edge within 1% of its rest length while it swings (10 leave
/// 4.1%, 20 leave 1.4%).
pub fn cloth<R: Real>(n: u32) -> SoftDesc<R> {
    let mut cloth = pinned_cloth(Vec3::new(-R::HALF, R::TWO, R::ZERO), n, Vec::new());
    cloth.solver.substeps = 40;
    cloth
}

/// A horizontal square cloth of `n` × `n` vertices, 1 m a side along x and z from
/// `origin`, 0.1 kg, pinned at its two corners on the x edge, with a velocity damping of
/// ½ /s, among `colliders`.
fn pinned_cloth<R: Real>(origin: Vec3<R>, n: u32, colliders: Vec<ColliderDesc<R>>) -> SoftDesc<R> {
    let mut sheet = body(
        SoftShape::Cloth {
            origin,
            u: Vec3::X,
            v: Vec3::Z,
            columns: n,
            rows: n,
        },
        cloth_model(),
        ratio(1, 10),
    );
    sheet.pins = vec![0, n - 1];
    sheet.damping = R::HALF;
    SoftDesc {
        bodies: vec![sheet],
        colliders,
        solver: XpbdSettings::default(),
    }
}

/// The curtain's cloth: a 32 × 32 vertical sheet 2 m wide and 2 m tall hanging from a rail
/// at y = 3 m (its top row held by attachment target 0), blown by a 4 m/s wind along +z.
/// 80 XPBD substeps a tick keep every edge within 1% of its rest length while the rail
/// slides (10 leave 6.6%, 40 leave 1.5%).
pub fn curtain<R: Real>() -> SoftDesc<R> {
    let n = 32;
    let mut sheet = body(
        SoftShape::Cloth {
            origin: Vec3::new(-R::ONE, R::from_int(3), R::ZERO),
            u: Vec3::new(R::TWO, R::ZERO, R::ZERO),
            v: Vec3::new(R::ZERO, -R::TWO, R::ZERO),
            columns: n,
            rows: n,
        },
        cloth_model(),
        ratio(3, 10),
    );
    sheet.attachments = vec![AttachmentDesc {
        vertices: (0..n).collect(),
        compliance: R::ZERO,
    }];
    sheet.wind = Vec3::new(R::ZERO, R::ZERO, R::from_int(4));
    sheet.drag = ratio(1, 2000);
    sheet.damping = R::HALF;
    SoftDesc {
        bodies: vec![sheet],
        colliders: Vec::new(),
        solver: XpbdSettings {
            substeps: 80,
            ..XpbdSettings::default()
        },
    }
}

/// The curtain's script: from tick 60 to 419, player 0 slides the rail along x in a
/// triangle wave, 0.5 m either side of its start over a 2 s period (1 m/s), one
/// `MoveKinematic` per tick for attachment target 0, whose first vertex starts at
/// (−1, 3, 0).
pub fn curtain_script<R: Real>() -> Vec<TickInput<R>> {
    (60u64..420)
        .map(|tick| {
            // Ticks into the wave, then 1 m/s for 30 ticks out, 60 back, 30 out again.
            let phase = ((tick - 59) % 120) as i64;
            let offset = match phase {
                0..=30 => phase,
                31..=90 => 60 - phase,
                _ => phase - 120,
            };
            TickInput {
                tick,
                players: vec![PlayerInput {
                    player: 0,
                    commands: vec![Command::MoveKinematic {
                        target: Target::SoftAttachment(0),
                        position: Vec3::new(-R::ONE + ratio(offset, 60), R::from_int(3), R::ZERO),
                    }],
                }],
            }
        })
        .collect()
}

/// A rope pendulum: `links` links, 2 m and 1 kg in all, hanging from (0, 3, 0) and
/// released horizontal along +x.
pub fn rope<R: Real>(links: u32) -> SoftDesc<R> {
    let top = Vec3::new(R::ZERO, R::from_int(3), R::ZERO);
    let mut line = body(
        SoftShape::Rope {
            start: top,
            end: top + Vec3::new(R::TWO, R::ZERO, R::ZERO),
            links,
        },
        SoftModel::Xpbd {
            stretch_compliance: R::ZERO,
            bend_compliance: None,
            volume_compliance: None,
            tethers: false,
        },
        R::ONE,
    );
    line.pins = vec![0];
    SoftDesc {
        bodies: vec![line],
        colliders: Vec::new(),
        solver: XpbdSettings {
            substeps: 20,
            iterations: 1,
        },
    }
}

/// A spring-mass jelly: a 0.5 m cube of 6 × 6 × 6 vertices, 1 kg, springs of k = 40 N/m
/// and c = 0.01 N·s/m on its 26-neighbour lattice (semi-implicit Euler, within its
/// stability bound at 600 Hz), dropped from 1 m onto the ground, tilted by its initial
/// spin-free sideways velocity of 0.5 m/s.
pub fn jelly<R: Real>() -> SoftDesc<R> {
    let mut cube = body(
        SoftShape::Lattice {
            origin: Vec3::new(-R::from_ratio(1, 4), R::ONE, -R::from_ratio(1, 4)),
            spacing: ratio(1, 10),
            count: (6, 6, 6),
        },
        SoftModel::SpringMass {
            integrator: Integrator::SemiImplicitEuler,
            stiffness: R::from_int(40),
            damping: ratio(1, 100),
        },
        R::ONE,
    );
    cube.velocity = Vec3::new(R::HALF, R::ZERO, R::ZERO);
    cube.radius = ratio(1, 50);
    SoftDesc {
        bodies: vec![cube],
        colliders: vec![ground()],
        solver: XpbdSettings::default(),
    }
}

/// The showcase's cloth: 12 × 12 vertices, 1 m a side, 0.1 kg, pinned at two corners at
/// x = −4.5 and −3.5 m, 3 m up, falling and swinging beside the rigid bodies, damped like
/// [`cloth`].
pub fn showcase<R: Real>() -> SoftDesc<R> {
    let origin = Vec3::new(-ratio::<R>(9, 2), R::from_int(3), R::ZERO);
    pinned_cloth(origin, 12, vec![ground()])
}
