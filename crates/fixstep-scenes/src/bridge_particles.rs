//! `bridge_particles`: a mass-aggregate rope bridge (Millington's particle engine): two
//! rails of particles joined along each rail by cables and across by rods (the planks),
//! pinned at both ends, walked across by a heavy particle pushed along by the script. The
//! walker rests on the rails through particle–particle contacts (every particle has a
//! 0.38 m contact radius, so that it cannot slip between the rails; one group never
//! touches itself), and a ground plane catches
//! anything that falls.

use fixstep::math::{Real, Vec3};
use fixstep::particles::{
    ContactPlaneDesc, ContactsDesc, ForceDesc, Integrator, LinkDesc, ParticleDesc, ParticlesDesc,
};
use fixstep::world::{Command, Handle, PlayerInput, Target, TickInput};

/// Particles along each rail, both ends pinned.
pub const RAIL_PARTICLES: u32 = 11;
/// The walker's index in the particle list (after both rails).
pub const WALKER: u32 = 2 * RAIL_PARTICLES;
/// Ticks the script pushes the walker for.
pub const PUSH_TICKS: u64 = 270;

/// The bridge and its walker. Rails at z = ±0.4 m from x = −2.5 m to 2.5 m, a particle of
/// 1 kg every 0.5 m joined to the next by a cable 0.51 m long (so the rails sag), the two
/// rails joined at each station by a 0.8 m rod; the walker starts above
/// the first plank. Semi-implicit Euler, gravity, light linear drag (0.05 kg/s) and on the
/// 5 kg walker (group 1) a heavier one (8 kg/s, so that the push walks it at about 2 m/s
/// on the level), a ground plane at y = −3 m with e = 0.3, particle–particle restitution
/// 0.1, 1024 contact resolutions per step (a heavy particle on light ones needs many).
pub fn bridge_particles<R: Real>() -> ParticlesDesc<R> {
    let half_width = R::from_ratio(2, 5);
    let mut particles = Vec::new();
    for z in [-half_width, half_width] {
        for i in 0..RAIL_PARTICLES {
            let x = R::from_ratio(i64::from(i) - 5, 2);
            let end = i == 0 || i == RAIL_PARTICLES - 1;
            particles.push(ParticleDesc {
                position: Vec3::new(x, R::ZERO, z),
                velocity: Vec3::ZERO,
                mass: if end { R::ZERO } else { R::ONE },
                group: 0,
                lifetime: R::ZERO,
            });
        }
    }
    particles.push(ParticleDesc {
        position: Vec3::new(R::from_ratio(-21, 10), R::from_ratio(1, 2), R::ZERO),
        velocity: Vec3::ZERO,
        mass: R::from_int(5),
        group: 1,
        lifetime: R::ZERO,
    });
    let mut links = Vec::new();
    for rail in 0..2 {
        let first = rail * RAIL_PARTICLES;
        for i in first..first + RAIL_PARTICLES - 1 {
            links.push(LinkDesc::Cable {
                a: i,
                b: i + 1,
                max_length: R::from_ratio(51, 100),
                restitution: R::ZERO,
            });
        }
    }
    for i in 1..RAIL_PARTICLES - 1 {
        links.push(LinkDesc::Rod {
            a: i,
            b: i + RAIL_PARTICLES,
            length: R::from_ratio(4, 5),
        });
    }
    ParticlesDesc {
        integrator: Integrator::SemiImplicitEuler,
        capacity: WALKER + 1,
        particles,
        forces: vec![
            ForceDesc::Gravity {
                scale: R::ONE,
                group: None,
            },
            ForceDesc::LinearDrag {
                coefficient: R::from_ratio(1, 20),
                group: None,
            },
            ForceDesc::LinearDrag {
                coefficient: R::from_int(8),
                group: Some(1),
            },
        ],
        contacts: Some(ContactsDesc {
            radius: R::from_ratio(38, 100),
            restitution: R::from_ratio(1, 10),
            planes: vec![ContactPlaneDesc {
                normal: Vec3::new(R::ZERO, R::ONE, R::ZERO),
                offset: R::from_int(-3),
                restitution: R::from_ratio(3, 10),
            }],
            links,
            iterations: 1024,
        }),
        ..ParticlesDesc::default()
    }
}

/// The walk: a 15 N push along +x on the walker at every tick of the first
/// [`PUSH_TICKS`].
pub fn bridge_particles_script<R: Real>() -> Vec<TickInput<R>> {
    (0..PUSH_TICKS)
        .map(|tick| TickInput {
            tick,
            players: vec![PlayerInput {
                player: 0,
                commands: vec![Command::ApplyForce {
                    target: Target::Particle(Handle::new(WALKER, 0)),
                    force: Vec3::new(R::from_int(15), R::ZERO, R::ZERO),
                    point: None,
                }],
            }],
        })
        .collect()
}
