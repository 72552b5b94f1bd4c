//! Rigid-body sections of the built-in scenes. Every constant is an exact ratio or an
//! integer, so the presets are the same bits on every machine.

use fixstep::math::{Quat, Real, Vec3};
use fixstep::rigid::ConvexHull;
use fixstep::rigid::Material;
use fixstep::rigid::Shape;
use fixstep::rigid::{BodyDesc, BodyKind, Grid, RigidDesc, SolverSettings};

/// `num/den` in the scalar format.
fn ratio<R: Real>(num: i64, den: i64) -> R {
    R::from_ratio(num, den)
}

/// The static ground: the half-space y ≤ 0.
pub fn ground<R: Real>() -> BodyDesc<R> {
    BodyDesc::new(
        Shape::Plane {
            normal: Vec3::Y,
            offset: R::ZERO,
        },
        Vec3::ZERO,
    )
    .fixed()
}

/// A unit cube (half extents ½ m) of density 1000 kg/m³ (1000 kg).
fn unit_box<R: Real>(position: Vec3<R>) -> BodyDesc<R> {
    BodyDesc::new(
        Shape::Box {
            half_extents: Vec3::splat(R::HALF),
        },
        position,
    )
}

/// A 2D pyramid of unit cubes on the ground, `base` cubes in the bottom row and one fewer
/// in each row above (base 20: 210 cubes), the cubes of a row 1 m apart, resting exactly on
/// each other.
pub fn pyramid<R: Real>(base: u32) -> RigidDesc<R> {
    let mut bodies = vec![ground()];
    for row in 0..base {
        let count = base - row;
        let mut body = unit_box(Vec3::new(
            R::from_ratio(-(i64::from(count) - 1), 2),
            R::HALF + R::from_int(row as i32),
            R::ZERO,
        ));
        body.grid = Some(Grid {
            count: (count, 1, 1),
            spacing: Vec3::new(R::ONE, R::ZERO, R::ZERO),
        });
        bodies.push(body);
    }
    RigidDesc {
        bodies,
        solver: SolverSettings::default(),
        ..RigidDesc::default()
    }
}

/// `height` unit cubes stacked on the ground, each resting exactly on the one below.
pub fn stack<R: Real>(height: u32) -> RigidDesc<R> {
    let mut body = unit_box(Vec3::new(R::ZERO, R::HALF, R::ZERO));
    body.grid = Some(Grid {
        count: (1, height, 1),
        spacing: Vec3::Y,
    });
    RigidDesc {
        bodies: vec![ground(), body],
        solver: SolverSettings::default(),
        ..RigidDesc::default()
    }
}

/// `n`³ balls of radius ½ m on a lattice 1.1 m apart, dropped into an open box: a floor and
/// four walls (static boxes 1 m thick) enclosing 20 m × 20 m, 20 m high. Sleeping off, as in
/// the benchmark this scene reproduces.
pub fn balls<R: Real>(n: u32) -> RigidDesc<R> {
    let wall = |centre: Vec3<R>, half: Vec3<R>| {
        BodyDesc::new(Shape::Box { half_extents: half }, centre).fixed()
    };
    let ten = R::from_int(10);
    let half_height = R::from_int(10);
    let mut bodies = vec![
        wall(
            Vec3::new(R::ZERO, -R::HALF, R::ZERO),
            Vec3::new(R::from_int(11), R::HALF, R::from_int(11)),
        ),
        wall(
            Vec3::new(-ten - R::HALF, half_height, R::ZERO),
            Vec3::new(R::HALF, half_height, R::from_int(11)),
        ),
        wall(
            Vec3::new(ten + R::HALF, half_height, R::ZERO),
            Vec3::new(R::HALF, half_height, R::from_int(11)),
        ),
        wall(
            Vec3::new(R::ZERO, half_height, -ten - R::HALF),
            Vec3::new(ten, half_height, R::HALF),
        ),
        wall(
            Vec3::new(R::ZERO, half_height, ten + R::HALF),
            Vec3::new(ten, half_height, R::HALF),
        ),
    ];
    let spacing = ratio::<R>(11, 10);
    let start = -(spacing * R::from_int(n as i32 - 1)) * R::HALF;
    let mut ball = BodyDesc::new(
        Shape::Sphere { radius: R::HALF },
        Vec3::new(start, R::from_int(1), start),
    );
    ball.grid = Some(Grid {
        count: (n, n, n),
        spacing: Vec3::splat(spacing),
    });
    bodies.push(ball);
    RigidDesc {
        bodies,
        solver: SolverSettings {
            sleeping: false,
            ..SolverSettings::default()
        },
        ..RigidDesc::default()
    }
}

/// `count` balls falling freely from a lattice (no ground, no contacts): the cost of a
/// body that only integrates.
pub fn falling<R: Real>(count: u32) -> RigidDesc<R> {
    let mut ball = BodyDesc::new(Shape::Sphere { radius: R::HALF }, Vec3::ZERO);
    ball.grid = Some(Grid {
        count: (count, 1, 1),
        spacing: Vec3::new(R::TWO, R::ZERO, R::ZERO),
    });
    RigidDesc {
        bodies: vec![ball],
        solver: SolverSettings {
            sleeping: false,
            ..SolverSettings::default()
        },
        ..RigidDesc::default()
    }
}

/// Newton's cradle without strings, in zero gravity: five frictionless, perfectly elastic
/// balls of radius ½ m in a row along x with 0.1 m between neighbours, and a sixth
/// approaching the row from the left at 2 m/s. The gaps make each collision a two-body one,
/// as the small gaps of a real cradle do; [`cradle_touching`] presses the balls together.
pub fn cradle<R: Real>() -> RigidDesc<R> {
    cradle_row(1, 5, ratio(1, 10))
}

/// [`cradle`] with the five balls of the row touching (centres 1 m apart, radius ½ m): the
/// impulse must pass through the resting contacts of the row, in order, for the last ball
/// to leave with the striker's speed.
pub fn cradle_touching<R: Real>() -> RigidDesc<R> {
    cradle_row(1, 5, R::ZERO)
}

/// A stringless cradle in zero gravity: `strikers` touching balls at 2 m/s along x towards
/// `row` balls at rest, the row's neighbours `gap` m apart, all frictionless and perfectly
/// elastic spheres of radius ½ m. The strikers' front ball starts 1 m short of the row.
pub fn cradle_row<R: Real>(strikers: u32, row: u32, gap: R) -> RigidDesc<R> {
    let elastic = Material {
        friction: R::ZERO,
        restitution: R::ONE,
    };
    let mut resting = BodyDesc::new(Shape::Sphere { radius: R::HALF }, Vec3::ZERO);
    resting.material = elastic;
    resting.grid = Some(Grid {
        count: (row, 1, 1),
        spacing: Vec3::new(R::ONE + gap, R::ZERO, R::ZERO),
    });
    let mut striker = BodyDesc::new(
        Shape::Sphere { radius: R::HALF },
        Vec3::new(-R::from_int(strikers as i32 + 1), R::ZERO, R::ZERO),
    );
    striker.material = elastic;
    striker.velocity = Vec3::new(R::TWO, R::ZERO, R::ZERO);
    striker.grid = (strikers > 1).then_some(Grid {
        count: (strikers, 1, 1),
        spacing: Vec3::new(R::ONE, R::ZERO, R::ZERO),
    });
    RigidDesc {
        bodies: vec![striker, resting],
        solver: SolverSettings::default(),
        ..RigidDesc::default()
    }
}

/// The slope of the incline scene: 30° (sin 30° = ½ exactly, cos 30° = √3/2).
pub fn incline_angle<R: Real>() -> R {
    R::PI / R::from_int(6)
}

/// Two 30° slopes (static boxes rotated about z) side by side along z, and on each a unit
/// cube at rest: on the first both surfaces have μ = 0.3 (the cube slides at
/// g(sin θ − μ cos θ) ≈ 2.36 m/s²), on the second μ = 0.6 > tan 30° (it sticks).
pub fn incline<R: Real>() -> RigidDesc<R> {
    let angle = incline_angle::<R>();
    let tilt = Quat::from_axis_angle(Vec3::Z, angle);
    let (sin, cos) = angle.sin_cos();
    let mut bodies = Vec::new();
    for (k, friction) in [ratio::<R>(3, 10), ratio::<R>(6, 10)]
        .into_iter()
        .enumerate()
    {
        let z = R::from_int(3 * k as i32);
        let material = Material {
            friction,
            restitution: R::ZERO,
        };
        // The slope: 40 m long, 1 m thick, its top face through the origin.
        let normal = Vec3::new(-sin, cos, R::ZERO);
        let mut slope = BodyDesc::new(
            Shape::Box {
                half_extents: Vec3::new(R::from_int(20), R::HALF, R::ONE),
            },
            Vec3::new(R::ZERO, R::ZERO, z) - normal * R::HALF,
        )
        .fixed();
        slope.orientation = tilt;
        slope.material = material;
        // The cube resting on the top face, 5 m up the slope.
        let along = Vec3::new(cos, sin, R::ZERO);
        let mut cube =
            unit_box(Vec3::new(R::ZERO, R::ZERO, z) + along * R::from_int(5) + normal * R::HALF);
        cube.orientation = tilt;
        cube.material = material;
        bodies.push(slope);
        bodies.push(cube);
    }
    RigidDesc {
        bodies,
        solver: SolverSettings::default(),
        ..RigidDesc::default()
    }
}

/// Half extents of the spinner's box: its principal moments are distinct, with the middle
/// one about y.
pub fn spinner_half_extents<R: Real>() -> Vec3<R> {
    Vec3::new(ratio(1, 10), ratio(3, 10), ratio(5, 10))
}

/// A box spinning in zero gravity at 10 rad/s about its intermediate axis (y), perturbed by
/// 0.01 rad/s about x: it flips periodically (the Dzhanibekov effect).
pub fn spinner<R: Real>() -> RigidDesc<R> {
    let mut body = BodyDesc::new(
        Shape::Box {
            half_extents: spinner_half_extents(),
        },
        Vec3::ZERO,
    );
    body.angular_velocity = Vec3::new(ratio(1, 100), R::from_int(10), R::ZERO);
    body.kind = BodyKind::Dynamic;
    RigidDesc {
        bodies: vec![body],
        solver: SolverSettings {
            sleeping: false,
            ..SolverSettings::default()
        },
        ..RigidDesc::default()
    }
}

/// The rigid part of the showcase, 10 m behind the particles (z = −10): a stack of four unit
/// cubes, three bouncy balls (e = 0.6) dropped on and beside it, a capsule tumbling down
/// from above, a dumbbell (a compound of two balls on a bar) landing on one end, a barrel
/// (a cylinder on its side) rolling in from the right and a cut gem (a convex hull) tumbling
/// down on the left, all on the ground plane y ≤ 0.
pub fn showcase<R: Real>() -> RigidDesc<R> {
    use fixstep::rigid::Part;
    let z = -R::from_int(10);
    let mut stack = unit_box(Vec3::new(R::ZERO, R::HALF, z));
    stack.grid = Some(Grid {
        count: (1, 4, 1),
        spacing: Vec3::Y,
    });
    let mut balls = BodyDesc::new(
        Shape::Sphere {
            radius: ratio(3, 10),
        },
        Vec3::new(-R::ONE, R::from_int(6), z),
    );
    balls.material.restitution = ratio(6, 10);
    balls.grid = Some(Grid {
        count: (3, 1, 1),
        spacing: Vec3::new(R::ONE, R::ONE, R::ZERO),
    });
    let mut capsule = BodyDesc::new(
        Shape::Capsule {
            radius: ratio(1, 4),
            half_height: ratio(1, 2),
        },
        Vec3::new(R::TWO, R::from_int(3), z),
    );
    capsule.orientation = Quat::from_axis_angle(Vec3::new(R::ONE, R::ZERO, R::ONE), R::ONE);
    capsule.angular_velocity = Vec3::new(R::ZERO, R::ZERO, R::from_int(3));
    let ball = |x: i32| Part {
        rotation: Quat::IDENTITY,
        translation: Vec3::new(R::from_ratio(i64::from(x), 2), R::ZERO, R::ZERO),
        shape: Shape::Sphere {
            radius: ratio(1, 4),
        },
    };
    let bar = Part {
        rotation: Quat::IDENTITY,
        translation: Vec3::ZERO,
        shape: Shape::Box {
            half_extents: Vec3::new(R::HALF, ratio(1, 20), ratio(1, 20)),
        },
    };
    let mut dumbbell = BodyDesc::new(
        Shape::Compound {
            parts: vec![ball(-1), bar, ball(1)],
        },
        Vec3::new(-R::from_int(3), R::TWO, z),
    );
    dumbbell.orientation = Quat::from_axis_angle(Vec3::Z, ratio(1, 2));
    // The barrel's axis along z; rolling without slipping, ω_z = −v_x / r.
    let mut barrel = BodyDesc::new(
        Shape::Cylinder {
            radius: ratio(2, 5),
            half_height: ratio(1, 2),
        },
        Vec3::new(R::from_int(6), ratio(2, 5), z),
    );
    barrel.orientation = Quat::from_axis_angle(Vec3::X, R::FRAC_PI_2);
    barrel.velocity = Vec3::new(-R::TWO, R::ZERO, R::ZERO);
    barrel.angular_velocity = Vec3::new(R::ZERO, R::ZERO, R::from_int(5));
    let mut gem = BodyDesc::new(
        Shape::ConvexHull {
            hull: ConvexHull::new(&gem_points()).expect("the gem's points span a volume"),
        },
        Vec3::new(-R::from_int(5), R::from_int(3), z),
    );
    gem.orientation = Quat::from_axis_angle(Vec3::new(R::ONE, R::ONE, R::ZERO), R::ONE);
    gem.angular_velocity = Vec3::new(R::ONE, R::ZERO, R::TWO);
    RigidDesc {
        bodies: vec![ground(), stack, balls, capsule, dumbbell, barrel, gem],
        solver: SolverSettings::default(),
        ..RigidDesc::default()
    }
}

/// A brilliant-cut gem about 0.8 m across: an octagonal table at y = 0.25, an octagonal
/// girdle of radius 0.4 at y = 0 and the culet (a point) at y = −0.45, in metres.
fn gem_points<R: Real>() -> Vec<Vec3<R>> {
    // cos and sin of k·45°, k = 0..8, to three decimals.
    const RING: [(i64, i64); 8] = [
        (1000, 0),
        (707, 707),
        (0, 1000),
        (-707, 707),
        (-1000, 0),
        (-707, -707),
        (0, -1000),
        (707, -707),
    ];
    let ring = |radius: i64, y: i64| {
        RING.iter().map(move |&(c, s)| {
            Vec3::new(
                R::from_ratio(c * radius, 1_000_000),
                R::from_ratio(y, 1000),
                R::from_ratio(s * radius, 1_000_000),
            )
        })
    };
    let culet = Vec3::new(R::ZERO, R::from_ratio(-450, 1000), R::ZERO);
    ring(250, 250)
        .chain(ring(400, 0))
        .chain(std::iter::once(culet))
        .collect()
}
