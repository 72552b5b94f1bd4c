//! Rigid bodies and joints of the built-in joint scenes. Every constant is an exact ratio or
//! an integer, and angles go through the scalar's own `sin_cos`/`asin`, so the presets are
//! the same bits on every machine.

use super::rigid::ground;
use fixstep::math::{Quat, Real, Vec3};
use fixstep::rigid::Material;
use fixstep::rigid::Shape;
use fixstep::rigid::joints::{JointDesc, JointGrid, JointKind, JointsDesc, Limits, Motor, Spring};
use fixstep::rigid::{BodyDesc, Grid, RigidDesc, SolverSettings};

/// `num/den` in the scalar format.
fn ratio<R: Real>(num: i64, den: i64) -> R {
    R::from_ratio(num, den)
}

/// A chain link: a capsule along the body's y axis, 1 m from tip to tip (radius 0.1 m,
/// segment 0.8 m), 29.3 kg at the default density. Its joints sit at the tips.
pub fn chain_link<R: Real>() -> Shape<R> {
    Shape::Capsule {
        radius: ratio(1, 10),
        half_height: ratio(2, 5),
    }
}

/// Distance between a chain link's two joints, m.
pub fn chain_link_length<R: Real>() -> R {
    R::ONE
}

/// `links` chain links held by ball joints, the first to a static anchor (a small static
/// sphere) at (0, height, 0), released horizontal along +x: link k lies between x = k and
/// x = k + 1. The ground plane lies below.
pub fn chain<R: Real>(links: u32, height: R) -> (RigidDesc<R>, JointsDesc<R>) {
    let anchor = BodyDesc::new(
        Shape::Sphere {
            radius: ratio(1, 10),
        },
        Vec3::new(R::ZERO, height, R::ZERO),
    )
    .fixed();
    let mut link = BodyDesc::new(chain_link(), Vec3::new(R::HALF, height, R::ZERO));
    // The capsule's y axis turned onto x.
    link.orientation = Quat::from_axis_angle(Vec3::Z, -R::FRAC_PI_2);
    link.grid = Some(Grid {
        count: (links, 1, 1),
        spacing: Vec3::X,
    });
    let rigid = RigidDesc {
        bodies: vec![ground(), anchor, link],
        solver: SolverSettings::default(),
        ..RigidDesc::default()
    };
    // Body 1 is the anchor, bodies 2.. the links.
    let first = JointDesc::new(JointKind::Ball, 1, 2, Vec3::new(R::ZERO, height, R::ZERO));
    let mut rest = JointDesc::new(JointKind::Ball, 2, 3, Vec3::new(R::ONE, height, R::ZERO));
    rest.grid = Some(JointGrid {
        count: (links.saturating_sub(1), 1, 1),
        stride_a: (1, 0, 0),
        stride_b: (1, 0, 0),
        spacing: Vec3::X,
    });
    let mut list = vec![first];
    if links > 1 {
        list.push(rest);
    }
    (rigid, JointsDesc::new(list))
}

/// A plank bridge: `planks` planks (1 m between hinges, 2 m wide, 10 cm thick, 200 kg)
/// hinged about z end to end along an arc of radius 30 m between two static pillars, the
/// hinges 10 m above the ground, each hinge with a little friction (a motor at speed 0 of
/// at most 50 N·m); then six boxes of 0.8 m dropped on it.
pub fn bridge<R: Real>(planks: u32) -> (RigidDesc<R>, JointsDesc<R>) {
    let radius = R::from_int(30);
    let top = R::from_int(10) + radius;
    // Central angle of one plank: 2 asin(ℓ/2R), ℓ = 1 m.
    let step = R::TWO * (R::HALF / radius).asin();
    let start = -(step * R::from_int(planks as i32)) * R::HALF;
    let vertex = |k: u32| {
        let (sin, cos) = (start + step * R::from_int(k as i32)).sin_cos();
        Vec3::new(radius * sin, top - radius * cos, R::ZERO)
    };
    let pillar = |at: Vec3<R>, side: R| {
        BodyDesc::new(
            Shape::Box {
                half_extents: Vec3::new(R::HALF, R::HALF, R::ONE),
            },
            Vec3::new(at.x + side * R::HALF, at.y, R::ZERO),
        )
        .fixed()
    };
    let mut bodies = vec![
        ground(),
        pillar(vertex(0), -R::ONE),
        pillar(vertex(planks), R::ONE),
    ];
    let mut list = Vec::new();
    let hinge = || JointKind::Hinge {
        limits: None,
        motor: Some(Motor {
            speed: R::ZERO,
            max_force: R::from_int(50),
        }),
        spring: None,
    };
    for k in 0..planks {
        let (a, b) = (vertex(k), vertex(k + 1));
        let along = b - a;
        let mut plank = BodyDesc::new(
            Shape::Box {
                half_extents: Vec3::new(R::HALF, ratio(1, 20), R::ONE),
            },
            (a + b) * R::HALF,
        );
        plank.orientation = Quat::from_axis_angle(Vec3::Z, along.y.atan2(along.x));
        bodies.push(plank);
        // Bodies: 0 ground, 1 left pillar, 2 right pillar, 3 + k plank k.
        let before = if k == 0 { 1 } else { 2 + k };
        list.push(JointDesc::new(hinge(), before, 3 + k, a).with_axis(Vec3::Z));
    }
    list.push(JointDesc::new(hinge(), 2 + planks, 2, vertex(planks)).with_axis(Vec3::Z));
    let mut load = BodyDesc::new(
        Shape::Box {
            half_extents: Vec3::splat(ratio(2, 5)),
        },
        Vec3::new(-R::from_int(5), R::from_int(14), R::ZERO),
    );
    load.density = R::from_int(500);
    load.grid = Some(Grid {
        count: (6, 1, 1),
        spacing: Vec3::new(R::TWO, R::ONE, R::ZERO),
    });
    bodies.push(load);
    (
        RigidDesc {
            bodies,
            solver: SolverSettings::default(),
            ..RigidDesc::default()
        },
        JointsDesc::new(list),
    )
}

/// One ragdoll's bodies (11: pelvis, torso, head, upper and lower arms, thighs, shins,
/// left before right) standing with its feet at `feet` and facing +x, and its joints (10),
/// whose body indices start at `first` (the index of its pelvis in the scene).
fn ragdoll<R: Real>(feet: Vec3<R>, first: u32) -> (Vec<BodyDesc<R>>, Vec<JointDesc<R>>) {
    let at = |x: i64, y: i64, z: i64| feet + Vec3::new(ratio(x, 100), ratio(y, 100), ratio(z, 100));
    let capsule = |radius: i64, half: i64, centre: Vec3<R>| {
        BodyDesc::new(
            Shape::Capsule {
                radius: ratio(radius, 100),
                half_height: ratio(half, 100),
            },
            centre,
        )
    };
    let pelvis = BodyDesc::new(
        Shape::Box {
            half_extents: Vec3::new(ratio(12, 100), ratio(10, 100), ratio(18, 100)),
        },
        at(0, 100, 0),
    );
    let torso = capsule(15, 20, at(0, 140, 0));
    let head = BodyDesc::new(
        Shape::Sphere {
            radius: ratio(12, 100),
        },
        at(0, 184, 0),
    );
    let mut bodies = vec![pelvis, torso, head];
    for side in [-1i64, 1] {
        bodies.push(capsule(6, 12, at(0, 146, 30 * side)));
        bodies.push(capsule(5, 12, at(0, 114, 30 * side)));
    }
    for side in [-1i64, 1] {
        bodies.push(capsule(8, 16, at(0, 66, 10 * side)));
        bodies.push(capsule(7, 16, at(0, 22, 10 * side)));
    }
    for body in &mut bodies {
        body.material = Material {
            friction: ratio(6, 10),
            restitution: R::ZERO,
        };
        body.density = R::from_int(1000);
    }
    let (pelvis, torso, head) = (first, first + 1, first + 2);
    let arm = |side: u32| first + 3 + 2 * side;
    let leg = |side: u32| first + 7 + 2 * side;
    // Joint friction as in Box2D's ragdoll: a torque of up to 30 N·m against any relative
    // turn (about what a thigh's weight exerts on the hip), so that a fallen ragdoll comes
    // to rest instead of rocking on a step's edge for ever.
    let friction = R::from_int(30);
    let cone = |swing: i64, twist: i64| JointKind::ConeTwist {
        swing: ratio(swing, 100),
        twist_lower: -ratio::<R>(twist, 100),
        twist_upper: ratio(twist, 100),
        friction,
    };
    let bend = |lower: i64, upper: i64| JointKind::Hinge {
        limits: Some(Limits {
            lower: ratio(lower, 100),
            upper: ratio(upper, 100),
        }),
        motor: Some(Motor {
            speed: R::ZERO,
            max_force: friction,
        }),
        spring: None,
    };
    let down = -Vec3::Y;
    let mut joints = vec![
        JointDesc::new(cone(40, 30), pelvis, torso, at(0, 114, 0)).with_axis(Vec3::Y),
        JointDesc::new(cone(50, 60), torso, head, at(0, 172, 0)).with_axis(Vec3::Y),
    ];
    for (side, z) in [(0u32, -30i64), (1, 30)] {
        joints.push(JointDesc::new(cone(150, 50), torso, arm(side), at(0, 160, z)).with_axis(down));
        joints.push(
            JointDesc::new(bend(0, 250), arm(side), arm(side) + 1, at(0, 130, z))
                .with_axis(Vec3::Z),
        );
    }
    for (side, z) in [(0u32, -10i64), (1, 10)] {
        joints.push(JointDesc::new(cone(100, 30), pelvis, leg(side), at(0, 88, z)).with_axis(down));
        joints.push(
            JointDesc::new(bend(-220, 0), leg(side), leg(side) + 1, at(0, 44, z))
                .with_axis(Vec3::Z),
        );
    }
    (bodies, joints)
}

/// `count` ragdolls falling down a flight of ten static steps (each 0.3 m high and 0.6 m
/// deep, 6 m wide, descending along +x from 3 m), dropped from above the top step one
/// after another along z, each tipped forward.
pub fn ragdolls<R: Real>(count: u32) -> (RigidDesc<R>, JointsDesc<R>) {
    let mut bodies = vec![ground()];
    for k in 0..10i64 {
        // Half the step's height, as one exact ratio (a rounded height halved would not
        // print back to the same bits in the scene file).
        let half = ratio::<R>(15 * (10 - k), 100);
        bodies.push(
            BodyDesc::new(
                Shape::Box {
                    half_extents: Vec3::new(ratio(30, 100), half, R::from_int(3)),
                },
                Vec3::new(ratio(60 * k + 30, 100), half, R::ZERO),
            )
            .fixed(),
        );
    }
    let mut list = Vec::new();
    for k in 0..count {
        let z = ratio(150 * i64::from(k) - 75 * i64::from(count - 1), 100);
        let feet = Vec3::new(ratio(30, 100), R::from_int(3) + R::from_int(k as i32), z);
        let first = bodies.len() as u32;
        let (mut doll, joints) = ragdoll(feet, first);
        let tip = Quat::from_axis_angle(Vec3::Z, -ratio::<R>(3, 10));
        for body in &mut doll {
            // Tipped forward about the feet.
            body.position = feet + tip.rotate(body.position - feet);
            body.orientation = tip;
        }
        let mut joints = joints;
        for joint in &mut joints {
            joint.anchor = feet + tip.rotate(joint.anchor - feet);
            joint.axis = tip.rotate(joint.axis);
        }
        bodies.extend(doll);
        list.extend(joints);
    }
    (
        RigidDesc {
            bodies,
            solver: SolverSettings::default(),
            ..RigidDesc::default()
        },
        JointsDesc::new(list),
    )
}

/// Box2D's "FallingHinges" determinism scene in 3D: `columns` towers of `rows` boxes (half
/// extent h = 0.25 m, friction 0.3), box i of a tower at (x + 0.4 h·i, h + 2h·i), turned by
/// 0.1·i − 1 rad about z, and hinged about z to the box below with anchors that do not
/// meet at the start: the lower box's corner (h, h) and the upper box's point (0.4 h, −h),
/// which the joint pulls together at once; the hinges have limits −0.1π to 0.2π and a
/// spring of 0.5 Hz, damping ratio 0.5. The towers, 10 h apart, fall onto a static floor.
pub fn falling_hinges<R: Real>(columns: u32, rows: u32) -> (RigidDesc<R>, JointsDesc<R>) {
    let h = ratio::<R>(1, 4);
    let offset = h * ratio(2, 5);
    let floor = BodyDesc::new(
        Shape::Box {
            half_extents: Vec3::new(R::from_int(20), R::ONE, R::from_int(5)),
        },
        Vec3::new(R::ZERO, -R::ONE, R::ZERO),
    )
    .fixed();
    let mut bodies = vec![floor];
    let mut list = Vec::new();
    let dx = h * R::from_int(10);
    let x_root = -(dx * R::from_int(columns as i32 - 1)) * R::HALF;
    let kind = JointKind::Hinge {
        limits: Some(Limits {
            lower: -(R::PI * ratio(1, 10)),
            upper: R::PI * ratio(2, 10),
        }),
        motor: None,
        spring: Some(Spring {
            hertz: R::HALF,
            damping_ratio: R::HALF,
        }),
    };
    for j in 0..columns {
        let x = x_root + dx * R::from_int(j as i32);
        let mut below: Option<(u32, Vec3<R>)> = None;
        for i in 0..rows {
            let i_r = R::from_int(i as i32);
            let position = Vec3::new(x + offset * i_r, h + (h + h) * i_r, R::ZERO);
            let turn = Quat::from_axis_angle(Vec3::Z, ratio::<R>(i64::from(i), 10) - R::ONE);
            let mut body = BodyDesc::new(
                Shape::Box {
                    half_extents: Vec3::splat(h),
                },
                position,
            );
            body.orientation = turn;
            body.material = Material {
                friction: ratio(3, 10),
                restitution: R::ZERO,
            };
            let index = bodies.len() as u32;
            bodies.push(body);
            if let Some((lower, corner)) = below {
                let own = position + turn.rotate(Vec3::new(offset, -h, R::ZERO));
                list.push(
                    JointDesc::new(kind, lower, index, corner)
                        .with_anchor_b(own)
                        .with_axis(Vec3::Z),
                );
            }
            below = Some((index, position + turn.rotate(Vec3::new(h, h, R::ZERO))));
        }
    }
    (
        RigidDesc {
            bodies,
            solver: SolverSettings::default(),
            ..RigidDesc::default()
        },
        JointsDesc::new(list),
    )
}

/// Box2D's joint-grid benchmark in 3D: an `n` × `n` grid of balls (radius 0.4 m, 1 m apart
/// in the x–y plane, row 0 on top), each joined by a ball joint midway to its neighbour above
/// and to its neighbour on the left (but for two static neighbours); the seven balls in the
/// middle of the top row are static. The grid hangs from them and falls into folds.
pub fn joint_grid<R: Real>(n: u32) -> (RigidDesc<R>, JointsDesc<R>) {
    let middle = n / 2;
    let mut bodies = Vec::new();
    let mut list = Vec::new();
    let index = |column: u32, row: u32| column * n + row;
    let is_static =
        |column: u32, row: u32| row == 0 && column + 3 >= middle && column <= middle + 3;
    for column in 0..n {
        for row in 0..n {
            let at = Vec3::new(
                R::from_int(column as i32),
                -R::from_int(row as i32),
                R::ZERO,
            );
            let mut ball = BodyDesc::new(
                Shape::Sphere {
                    radius: ratio(2, 5),
                },
                at,
            );
            if is_static(column, row) {
                ball = ball.fixed();
            }
            bodies.push(ball);
            if row > 0 {
                let above = at + Vec3::new(R::ZERO, R::HALF, R::ZERO);
                list.push(JointDesc::new(
                    JointKind::Ball,
                    index(column, row - 1),
                    index(column, row),
                    above,
                ));
            }
            if column > 0 && !(is_static(column - 1, row) && is_static(column, row)) {
                let left = at - Vec3::new(R::HALF, R::ZERO, R::ZERO);
                list.push(JointDesc::new(
                    JointKind::Ball,
                    index(column - 1, row),
                    index(column, row),
                    left,
                ));
            }
        }
    }
    (
        RigidDesc {
            bodies,
            solver: SolverSettings::default(),
            ..RigidDesc::default()
        },
        JointsDesc::new(list),
    )
}

/// The joints of the showcase, 4 m behind its other rigid bodies: an 8-link chain swinging
/// down from a static anchor at (4, 9, −14), released horizontal along +x, and a door on a
/// hinge at (−5.9, 1, −14) with a motor turning it at 1 rad/s. `first` is the index of the
/// first of these bodies in the showcase's rigid body list.
pub fn showcase<R: Real>(first: u32) -> (Vec<BodyDesc<R>>, JointsDesc<R>) {
    let z = -R::from_int(14);
    let top = Vec3::new(R::from_int(4), R::from_int(9), z);
    let anchor = BodyDesc::new(
        Shape::Sphere {
            radius: ratio(1, 10),
        },
        top,
    )
    .fixed();
    let mut link = BodyDesc::new(chain_link(), top + Vec3::new(R::HALF, R::ZERO, R::ZERO));
    link.orientation = Quat::from_axis_angle(Vec3::Z, -R::FRAC_PI_2);
    link.grid = Some(Grid {
        count: (8, 1, 1),
        spacing: Vec3::X,
    });
    let post = BodyDesc::new(
        Shape::Box {
            half_extents: Vec3::new(ratio(1, 10), R::ONE, ratio(1, 10)),
        },
        Vec3::new(-R::from_int(6), R::ONE, z),
    )
    .fixed();
    let door = BodyDesc::new(
        Shape::Box {
            half_extents: Vec3::new(ratio(3, 4), ratio(9, 10), ratio(1, 20)),
        },
        Vec3::new(-R::from_int(6) + ratio(17, 20), R::ONE, z),
    );
    let (anchor_i, link_i, post_i, door_i) = (first, first + 1, first + 9, first + 10);
    let mut links = JointDesc::new(JointKind::Ball, link_i, link_i + 1, top + Vec3::X);
    links.grid = Some(JointGrid {
        count: (7, 1, 1),
        stride_a: (1, 0, 0),
        stride_b: (1, 0, 0),
        spacing: Vec3::X,
    });
    let hinge = JointKind::Hinge {
        limits: None,
        motor: Some(Motor {
            speed: R::ONE,
            max_force: R::from_int(500),
        }),
        spring: None,
    };
    let list = vec![
        JointDesc::new(JointKind::Ball, anchor_i, link_i, top),
        links,
        JointDesc::new(
            hinge,
            post_i,
            door_i,
            Vec3::new(-R::from_int(6) + ratio(1, 10), R::ONE, z),
        )
        .with_axis(Vec3::Y),
    ];
    (vec![anchor, link, post, door], JointsDesc::new(list))
}
