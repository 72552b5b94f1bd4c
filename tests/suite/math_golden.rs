//! Golden values: a fixed computation that uses every math function, hashed.
//!
//! 10⁵ steps of a torque-free rigid body with a non-uniform inertia tensor, spinning and
//! damped, on I32F32. Each step uses the world inertia R·I·Rᵀ and its safe inverse, the
//! quaternion integrator, `sin_cos`, `atan2`, `asin`, `acos`, `sqrt`, `rsqrt`, `exp`, `ln`,
//! `powf`, `powi`, division and the RNG. The hash of the whole trajectory is committed: it
//! must be the same in the debug and release profiles and on every target. A change to any
//! kernel's bits changes it; such a change must be deliberate (bump the state version and
//! re-record the replays).

use fixstep::math::rng::Pcg32;
use fixstep::math::state_hash::StateHasher;
use fixstep::math::{Fx, Mat3, Quat, Real, Vec3};

const STEPS: u32 = 100_000;
/// Since state version 4 (`Quat::integrate` renormalises by two Newton steps).
const GOLDEN: u64 = 0x73e962fc6ad7c2a5;

fn trajectory_hash() -> u64 {
    let dt = Fx::from_ratio(1, 240);
    let body_inertia =
        Mat3::from_diagonal(Vec3::new(Fx::from_int(1), Fx::from_int(2), Fx::from_int(3)));
    // Damping as d^dt: 0.97 of the angular velocity kept per second.
    let damping = Fx::from_ratio(97, 100).powf(dt);
    let mut rng = Pcg32::new(0x601d, 7);
    let mut q = Quat::from_axis_angle(
        Vec3::new(Fx::ONE, Fx::TWO, Fx::from_int(3)).normalize_or_zero(),
        Fx::HALF,
    );
    let mut angular_momentum = Vec3::new(
        Fx::from_ratio(1, 100),
        Fx::from_int(4),
        Fx::from_ratio(-1, 10),
    );
    let mut h = StateHasher::new();
    for step in 0..STEPS {
        let r = q.to_mat3();
        let inverse_world = r.rotate_inertia(body_inertia).safe_inverse_symmetric();
        let omega = inverse_world * angular_momentum;
        q = q.integrate(omega, dt);
        angular_momentum *= damping;

        let (axis, angle) = q.to_axis_angle();
        let (s, c) = angle.sin_cos();
        let heading = omega.y.atan2(omega.x);
        let tilt = axis.z.asin() + axis.x.acos();
        let speed = omega.length();
        let inv_speed = (speed * speed + Fx::EPSILON).rsqrt();
        let decay = (-(Fx::from_int(step as i32 % 64)) * Fx::from_ratio(1, 8)).exp();
        let log = (speed + Fx::ONE).ln();
        let cube = (s + c).powi(3);
        let ratio = (log + Fx::ONE) / (decay + inv_speed);
        let jitter = rng.unit::<Fx>();

        for value in [
            s,
            c,
            heading,
            tilt,
            speed.sqrt(),
            inv_speed,
            decay,
            log,
            cube,
            ratio,
            jitter,
        ] {
            h.write_real(value);
        }
        h.write_real(q.w);
        h.write_vec3(q.vector());
        h.write_vec3(angular_momentum);
    }
    h.finish()
}

#[test]
fn golden_trajectory_hash_is_stable() {
    let hash = trajectory_hash();
    assert_eq!(hash, GOLDEN, "golden hash is {hash:#018x}");
}
