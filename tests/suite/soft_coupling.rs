//! Soft bodies coupled to rigid bodies (issue [coupling]): a crate on a 10-link rope swings
//! with the period of the equivalent compound pendulum; a sphere dropped into a hanging
//! cloth exchanges equal and opposite impulses with it and does not pass through; a cloth
//! lands on every shape without entering it; the `flag` scene, restored mid-contact,
//! continues bit for bit.

use fixstep::math::{Fx, Quat, Real, Vec3};
use fixstep::rigid::{
    BodyDesc, BodyKind, ConvexHull, HeightField, Part, QueryFilter, RigidDesc, Shape, TriMesh,
};
use fixstep::scene::Scene;
use fixstep::soft::{
    BodyAttachmentDesc, BodyContactsDesc, SoftBodyDesc, SoftDesc, SoftModel, SoftShape,
    XpbdSettings,
};
use fixstep::world::{Handle, TickInput, World};

fn v(x: f64, y: f64, z: f64) -> Vec3<Fx> {
    Vec3::new(Fx::from_f64(x), Fx::from_f64(y), Fx::from_f64(z))
}

fn soft_body(shape: SoftShape<Fx>, mass: f64, tethers: bool) -> SoftBodyDesc<Fx> {
    SoftBodyDesc {
        shape,
        model: SoftModel::Xpbd {
            stretch_compliance: Fx::ZERO,
            bend_compliance: Some(Fx::ONE),
            volume_compliance: None,
            tethers,
        },
        mass: Fx::from_f64(mass),
        pins: Vec::new(),
        attachments: Vec::new(),
        body_attachments: Vec::new(),
        body_contacts: None,
        velocity: Vec3::ZERO,
        damping: Fx::ZERO,
        radius: Fx::from_ratio(1, 100),
        wind: Vec3::ZERO,
        drag: Fx::ZERO,
    }
}

fn soft(bodies: Vec<SoftBodyDesc<Fx>>) -> SoftDesc<Fx> {
    SoftDesc {
        bodies,
        colliders: Vec::new(),
        solver: XpbdSettings::default(),
    }
}

/// The crate pendulum: a rope of 10 links and `rope_mass` kg, pinned at (0, 3, 0) and
/// released `angle` rad from the vertical in the xy plane, tied by its last vertex to the
/// lid centre of a cube of side `side` m and density 300 kg/m³, turned with the rope.
fn pendulum(length: f64, side: f64, rope_mass: f64, angle: f64) -> Scene<Fx> {
    let (s, c) = angle.sin_cos();
    let top = v(0.0, 3.0, 0.0);
    let end = v(length * s, 3.0 - length * c, 0.0);
    let reach = length + side / 2.0;
    let mut load = BodyDesc::new(
        Shape::Box {
            half_extents: v(side / 2.0, side / 2.0, side / 2.0),
        },
        v(reach * s, 3.0 - reach * c, 0.0),
    );
    load.orientation = Quat {
        w: Fx::from_f64((angle / 2.0).cos()),
        x: Fx::ZERO,
        y: Fx::ZERO,
        z: Fx::from_f64((angle / 2.0).sin()),
    };
    load.density = Fx::from_int(300);
    let mut rope = soft_body(
        SoftShape::Rope {
            start: top,
            end,
            links: 10,
        },
        rope_mass,
        true,
    );
    rope.pins = vec![0];
    rope.body_attachments = vec![BodyAttachmentDesc {
        body: 0,
        vertices: vec![10],
        compliance: Fx::ZERO,
    }];
    let mut scene = Scene::empty("pendulum");
    scene.rigid = Some(RigidDesc {
        bodies: vec![load],
        ..RigidDesc::default()
    });
    scene.soft = Some(soft(vec![rope]));
    scene
}

/// The small-amplitude period (s) of the rigid pendulum the rope and crate make when the
/// rope is taut and straight: a uniform rod of length L and mass m_r, and a cube of side a
/// and mass m hung by its lid's centre, pivoting about the rod's top under g = 9.81 m/s²:
/// T = 2π √(I / (g (m_r L/2 + m d))), I = m_r L²/3 + m (a²/6 + d²), d = L + a/2.
fn compound_period(length: f64, side: f64, rope_mass: f64) -> f64 {
    let mass = 300.0 * side.powi(3);
    let d = length + side / 2.0;
    let inertia = rope_mass * length * length / 3.0 + mass * (side * side / 6.0 + d * d);
    let moment = 9.81 * (rope_mass * length / 2.0 + mass * d);
    2.0 * core::f64::consts::PI * (inertia / moment).sqrt()
}

#[test]
fn a_crate_on_a_rope_swings_with_the_compound_pendulum_period() {
    let (length, side, rope_mass, angle) = (1.0, 0.3, 0.1, 10f64.to_radians());
    let scene = pendulum(length, side, rope_mass, angle);
    let mut world = scene.build().expect("builds");
    let crate_body = Handle::new(0, 0);
    let mut previous = world
        .rigid()
        .unwrap()
        .position(crate_body)
        .unwrap()
        .x
        .to_f64();
    let mut crossings = Vec::new();
    for tick in 1..=480u64 {
        world.step(&TickInput::default());
        let x = world
            .rigid()
            .unwrap()
            .position(crate_body)
            .unwrap()
            .x
            .to_f64();
        if previous < 0.0 && x >= 0.0 {
            crossings.push((tick as f64 - 1.0 + previous / (previous - x)) / 60.0);
        }
        previous = x;
    }
    assert!(crossings.len() >= 3, "too few swings: {crossings:?}");
    let measured = (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
    // The finite amplitude lengthens the period by θ₀²/16 (0.2 % at 10°).
    let expected = compound_period(length, side, rope_mass) * (1.0 + angle * angle / 16.0);
    let error = (measured - expected).abs() / expected;
    assert!(
        error < 0.03,
        "period {measured:.4} s, compound pendulum {expected:.4} s ({:.2} %)",
        error * 100.0
    );
}

/// A 1.6 m cloth of 17 × 17 vertices and 1 kg, pinned by its corners with its vertices
/// drawn in to 80 % (so it hangs slack), and a 2 kg ball of radius 0.2 m dropped into it
/// from 0.8 m above.
fn hammock() -> (Scene<Fx>, World<Fx>) {
    let mut ball = BodyDesc::new(
        Shape::Sphere {
            radius: Fx::from_f64(0.2),
        },
        v(0.03, 1.8, 0.02),
    );
    ball.density = Fx::from_int(60);
    let mut cloth = soft_body(
        SoftShape::Cloth {
            origin: v(-0.8, 1.0, -0.8),
            u: v(1.6, 0.0, 0.0),
            v: v(0.0, 0.0, 1.6),
            columns: 17,
            rows: 17,
        },
        1.0,
        true,
    );
    cloth.pins = vec![0, 16, 272, 288];
    cloth.radius = Fx::from_f64(0.05);
    cloth.body_contacts = Some(BodyContactsDesc::default());
    let mut scene = Scene::empty("hammock");
    scene.rigid = Some(RigidDesc {
        bodies: vec![ball],
        ..RigidDesc::default()
    });
    scene.soft = Some(soft(vec![cloth]));
    let mut world = scene.build().expect("builds");
    let soft = world.soft_mut().expect("soft");
    for i in 0..soft.vertex_count() {
        let p = soft.position(i).unwrap();
        let drawn = Vec3::new(p.x * Fx::from_f64(0.8), p.y, p.z * Fx::from_f64(0.8));
        soft.set_position(i, drawn);
    }
    (scene, world)
}

/// Momentum: over 1.5 s the ball's momentum changes by its weight's impulse plus exactly
/// the opposite of the impulse it gave the cloth; with the cloth's own balance (its free
/// vertices' momentum changes by their weight's impulse, the ball's push and the pins'
/// reactions), the total momentum of cloth and ball changes by the weights' impulse and the
/// pins' reactions alone. And nothing passes through: no vertex ever enters the ball, and
/// the ball stays above the cloth.
#[test]
fn a_ball_dropped_into_a_hanging_cloth_conserves_momentum_and_stays_on_it() {
    let (_, mut world) = hammock();
    let ball = Handle::new(0, 0);
    let mass = world.rigid().unwrap().mass(ball).unwrap().to_f64();
    let g = 9.81;
    let ticks = 90;
    let mut pushed = 0.0; // Σ impulse of the ball on the cloth, N·s (y)
    let velocity = |w: &World<Fx>| w.rigid().unwrap().linear_velocity(ball).unwrap().y.to_f64();
    let start = velocity(&world);
    for _ in 0..ticks {
        world.step(&TickInput::default());
        pushed += world.soft().unwrap().rigid_impulse().y.to_f64();
        let centre = world.rigid().unwrap().position(ball).unwrap().to_f64();
        let soft = world.soft().unwrap();
        let mut lowest_under: f64 = f64::MAX;
        for p in soft.positions() {
            let p = p.to_f64();
            let d = ((p[0] - centre[0]).powi(2)
                + (p[1] - centre[1]).powi(2)
                + (p[2] - centre[2]).powi(2))
            .sqrt();
            assert!(d > 0.2, "a vertex entered the ball: {d} m from its centre");
            if (p[0] - centre[0]).hypot(p[2] - centre[2]) < 0.1 {
                lowest_under = lowest_under.min(p[1]);
            }
        }
        if lowest_under < f64::MAX {
            assert!(lowest_under < centre[1], "the ball passed the cloth");
        }
    }
    let change = mass * (velocity(&world) - start);
    let expected = -mass * g * ticks as f64 / 60.0 - pushed;
    assert!(
        pushed < -1.0,
        "the ball barely touched the cloth: {pushed} N·s"
    );
    assert!(
        (change - expected).abs() < 0.01 * pushed.abs(),
        "ball momentum change {change:.5} N·s, weight and cloth {expected:.5} N·s (cloth took {pushed:.5})"
    );
}

/// A body of `shape` whose top is at y = 0 near the origin.
fn static_shape(shape: Shape<Fx>, centre_y: f64) -> BodyDesc<Fx> {
    let mut body = BodyDesc::new(shape, v(0.0, centre_y, 0.0));
    body.kind = BodyKind::Static;
    body
}

#[test]
fn a_cloth_lands_on_every_shape_without_entering_it() {
    let cube: Vec<Vec3<Fx>> = [-0.3, 0.3]
        .iter()
        .flat_map(|&x| [-0.3, 0.3].map(move |y| (x, y)))
        .flat_map(|(x, y)| [-0.3, 0.3].map(move |z| v(x, y, z)))
        .collect();
    let flat = |n: usize| -> Vec<Fx> { vec![Fx::ZERO; n * n] };
    let shapes = vec![
        (
            "box",
            static_shape(
                Shape::Box {
                    half_extents: v(0.4, 0.2, 0.4),
                },
                -0.2,
            ),
        ),
        (
            "sphere",
            static_shape(
                Shape::Sphere {
                    radius: Fx::from_f64(0.3),
                },
                -0.3,
            ),
        ),
        (
            "capsule",
            static_shape(
                Shape::Capsule {
                    radius: Fx::from_f64(0.2),
                    half_height: Fx::from_f64(0.2),
                },
                -0.4,
            ),
        ),
        (
            "cylinder",
            static_shape(
                Shape::Cylinder {
                    radius: Fx::from_f64(0.3),
                    half_height: Fx::from_f64(0.2),
                },
                -0.2,
            ),
        ),
        (
            "cone",
            static_shape(
                Shape::Cone {
                    radius: Fx::from_f64(0.4),
                    half_height: Fx::from_f64(0.2),
                },
                -0.2,
            ),
        ),
        (
            "hull",
            static_shape(
                Shape::ConvexHull {
                    hull: ConvexHull::new(&cube).expect("a cube"),
                },
                -0.3,
            ),
        ),
        (
            "mesh",
            static_shape(
                Shape::TriMesh {
                    mesh: TriMesh::new(
                        vec![
                            v(-1.0, 0.0, -1.0),
                            v(1.0, 0.0, -1.0),
                            v(1.0, 0.0, 1.0),
                            v(-1.0, 0.0, 1.0),
                        ],
                        vec![[0, 2, 1], [0, 3, 2]],
                    )
                    .expect("a square"),
                },
                0.0,
            ),
        ),
        (
            "heightfield",
            static_shape(
                Shape::HeightField {
                    field: HeightField::new(5, 5, v(0.5, 1.0, 0.5), flat(5)).expect("flat"),
                },
                0.0,
            ),
        ),
        (
            "compound",
            static_shape(
                Shape::Compound {
                    parts: vec![
                        Part {
                            rotation: Quat::IDENTITY,
                            translation: v(-0.2, 0.0, 0.0),
                            shape: Shape::Box {
                                half_extents: v(0.2, 0.2, 0.4),
                            },
                        },
                        Part {
                            rotation: Quat::IDENTITY,
                            translation: v(0.2, 0.0, 0.0),
                            shape: Shape::Box {
                                half_extents: v(0.2, 0.2, 0.4),
                            },
                        },
                    ],
                },
                -0.2,
            ),
        ),
    ];
    for (name, body) in shapes {
        let mut cloth = soft_body(
            SoftShape::Cloth {
                origin: v(-0.3, 0.6, -0.3),
                u: v(0.6, 0.0, 0.0),
                v: v(0.0, 0.0, 0.6),
                columns: 7,
                rows: 7,
            },
            0.2,
            false,
        );
        cloth.radius = Fx::from_f64(0.02);
        cloth.body_contacts = Some(BodyContactsDesc::default());
        let mut scene = Scene::empty(name);
        scene.rigid = Some(RigidDesc {
            bodies: vec![body],
            ..RigidDesc::default()
        });
        scene.soft = Some(soft(vec![cloth]));
        let mut world = scene.build().unwrap_or_else(|e| panic!("{name}: {e}"));
        for _ in 0..45 {
            world.step(&TickInput::default());
        }
        let soft = world.soft().unwrap();
        let rigid = world.rigid().unwrap();
        let centre = soft.position(24).unwrap().y.to_f64();
        assert!(
            centre > -0.005,
            "{name}: the cloth's centre went through the top, to y = {centre}"
        );
        for (i, p) in soft.positions().iter().enumerate() {
            let inside = rigid
                .project_point(*p, Fx::ONE, &QueryFilter::default())
                .is_some_and(|hit| hit.inside);
            assert!(!inside, "{name}: vertex {i} is inside the shape at {p:?}");
        }
    }
}

#[test]
fn flag_restored_mid_contact_continues_like_an_uninterrupted_run() {
    // At tick 130 the flag is sweeping the crate.
    crate::restore_support::restored_mid_run_continues("flag", 200, 130);
}

/// Removing the body a rope is tied to lets the rope go: it falls on, hanging from its pin.
#[test]
fn a_tie_to_a_removed_body_lets_go() {
    use fixstep::world::{Command, PlayerInput, Target};
    let scene = pendulum(1.0, 0.3, 0.1, 0.0);
    let mut world = scene.build().expect("builds");
    for tick in 0..120u64 {
        let mut input = TickInput::default();
        if tick == 30 {
            input.players.push(PlayerInput {
                player: 0,
                commands: vec![Command::Remove {
                    target: Target::Body(Handle::new(0, 0)),
                }],
            });
        }
        world.step(&input);
    }
    assert_eq!(world.rigid().unwrap().body_count(), 0);
    let soft = world.soft().unwrap();
    let end = soft.position(10).unwrap().to_f64();
    // Hanging straight down from (0, 3, 0), 1 m long, after the pull of the crate is gone.
    assert!((end[1] - 2.0).abs() < 0.05, "the rope's end is at {end:?}");
}
