//! Built-in scenes of joints that must neither make nor lose energy (issue \[energy\]): a
//! heavy top precessing on a ball joint, and a wrecking ball on a rope of rods. Every
//! constant is an exact ratio or an integer, and the top's precession goes through the
//! scalar's own `sqrt` and `sin_cos`, so the presets are the same bits on every machine.

use super::rigid::ground;
use fixstep::math::{Quat, Real, Vec3};
use fixstep::rigid::joints::{JointDesc, JointKind, JointsDesc};
use fixstep::rigid::{BodyDesc, Grid, RigidDesc, Shape, SolverSettings};

/// `num/den` in the scalar format.
fn ratio<R: Real>(num: i64, den: i64) -> R {
    R::from_ratio(num, den)
}

/// The heavy top's pivot, m above the ground.
const PIVOT_HEIGHT: i32 = 1;

/// A heavy symmetric top: a disc (solid cylinder, radius 0.3 m, 10 cm thick, 1000 kg/m³,
/// 28.3 kg) whose centre lies l = 0.5 m from a ball joint on a static post, along the
/// disc's axis (body y), tilted 30° from the vertical toward +x, spinning at ω₃ = 60 rad/s
/// about its axis and started in steady precession: ω = Ω ŷ + (ω₃ − Ω cos θ) e₃, with Ω the
/// slow root of m g l = Ω (I₃ ω₃ − I₁ Ω cos θ) (I₁ about the pivot, `gravity` m/s² down).
pub fn top<R: Real>(gravity: R) -> (RigidDesc<R>, JointsDesc<R>) {
    let (radius, half_height, arm) = (ratio(3, 10), ratio(1, 20), R::HALF);
    let spin = R::from_int(60);
    let shape = Shape::Cylinder {
        radius,
        half_height,
    };
    let density = R::from_int(1000);
    let mass = shape.mass_properties(density);
    let (m, i1, i3) = (
        mass.mass,
        mass.inertia.cols[0].x + mass.mass * arm * arm,
        mass.inertia.cols[1].y,
    );
    let tilt = R::PI / R::from_int(6);
    let (sin, cos) = tilt.sin_cos();
    // The slow root of I₁ cos θ Ω² − I₃ ω₃ Ω + m g l = 0.
    let (a, b, c) = (i1 * cos, i3 * spin, m * gravity * arm);
    let precession = (b - (b * b - R::from_int(4) * a * c).sqrt()) / (R::TWO * a);
    let axis = Vec3::new(sin, cos, R::ZERO);
    let pivot = Vec3::new(R::ZERO, R::from_int(PIVOT_HEIGHT), R::ZERO);
    let omega = Vec3::Y * precession + axis * (spin - precession * cos);
    let mut disc = BodyDesc::new(shape, pivot + axis * arm);
    disc.orientation = Quat::from_axis_angle(Vec3::Z, -tilt);
    disc.density = density;
    disc.angular_velocity = omega;
    disc.velocity = omega.cross(axis * arm);
    let post = BodyDesc::new(
        Shape::Cylinder {
            radius: ratio(1, 20),
            half_height: R::HALF,
        },
        Vec3::new(R::ZERO, R::HALF, R::ZERO),
    )
    .fixed();
    let rigid = RigidDesc {
        bodies: vec![ground(), post, disc],
        solver: SolverSettings {
            sleeping: false,
            ..SolverSettings::default()
        },
        ..RigidDesc::default()
    };
    let ball = JointDesc::new(JointKind::Ball, 1, 2, pivot);
    (rigid, JointsDesc::new(vec![ball]))
}

/// A wrecking ball: a steel ball (radius 0.5 m, 7800 kg/m³, 4.1 t) on a rope of six rods of
/// 1 m joined by five steel beads (radius 0.15 m, 110 kg each), hung from a static hook 8 m
/// up and released with the rope straight at 60° from the vertical toward −x; at the bottom
/// of its swing it meets a wall of 12 unit boxes (3 high, 4 wide) standing on the ground.
pub fn wrecking_ball<R: Real>() -> (RigidDesc<R>, JointsDesc<R>) {
    let links: u32 = 6;
    let hook = Vec3::new(R::ZERO, R::from_int(8), R::ZERO);
    let (sin, cos) = (R::PI / R::from_int(3)).sin_cos();
    // From the hook down along the rope, 1 m per rod.
    let down = Vec3::new(-sin, -cos, R::ZERO);
    let steel = R::from_int(7800);
    let hook_body = BodyDesc::new(
        Shape::Sphere {
            radius: ratio(1, 10),
        },
        hook,
    )
    .fixed();
    let mut bodies = vec![ground(), hook_body];
    for k in 1..links {
        let mut bead = BodyDesc::new(
            Shape::Sphere {
                radius: ratio(15, 100),
            },
            hook + down * R::from_int(k as i32),
        );
        bead.density = steel;
        bodies.push(bead);
    }
    let mut ball = BodyDesc::new(
        Shape::Sphere { radius: R::HALF },
        hook + down * R::from_int(links as i32),
    );
    ball.density = steel;
    let mut wall = BodyDesc::new(
        Shape::Box {
            half_extents: Vec3::splat(R::HALF),
        },
        Vec3::new(ratio(6, 5), R::HALF, ratio(-3, 2)),
    );
    wall.grid = Some(Grid {
        count: (1, 3, 4),
        spacing: Vec3::splat(R::ONE),
    });
    bodies.extend([ball, wall]);
    let rigid = RigidDesc {
        bodies,
        solver: SolverSettings::default(),
        ..RigidDesc::default()
    };
    // Body 1 is the hook, 2..=6 the beads, 7 the ball: rod k joins body k + 1 to k + 2.
    let rods = (0..links)
        .map(|k| {
            let top = hook + down * R::from_int(k as i32);
            JointDesc::new(JointKind::Rod { length: None }, k + 1, k + 2, top)
                .with_anchor_b(top + down)
        })
        .collect();
    (rigid, JointsDesc::new(rods))
}
