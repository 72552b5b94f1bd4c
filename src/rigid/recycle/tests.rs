//! Contact recycling against the narrowphase it replaces.

use super::*;
use crate::math::Fx;
use crate::rigid::contact::{ContactKey, NO_FRAME};
use crate::rigid::narrowphase::collide;

fn v(x: f64, y: f64, z: f64) -> Vec3<Fx> // ok-det: test input
{
    Vec3::from_f64(x, y, z)
}

fn unit_box() -> Shape<Fx> {
    Shape::Box {
        half_extents: v(0.5, 0.5, 0.5),
    }
}

/// A box resting on a box, the upper one turned by `turn` rad about y and sunk 5 mm; both
/// then placed at `offset` and turned by `tilt` rad about the axis (1, 2, 3): the same
/// relative pose for every `offset` and `tilt`.
fn stacked(offset: Vec3<Fx>, tilt: f64, turn: f64) -> [(Transform<Fx>, Quat<Fx>); 2] // ok-det: test input
{
    let whole = Quat::from_axis_angle(v(1.0, 2.0, 3.0).normalize_or_zero(), Fx::from_f64(tilt));
    let upper = Quat::from_axis_angle(v(0.0, 1.0, 0.0), Fx::from_f64(turn));
    let lower_at = offset;
    let upper_at = offset + whole.rotate(v(0.01, 0.995, -0.02));
    [
        (Transform::from_pose(lower_at, whole), whole),
        (Transform::from_pose(upper_at, whole * upper), whole * upper),
    ]
}

fn pose<'a>(pair: &'a [(Transform<Fx>, Quat<Fx>); 2]) -> PairPose<'a, Fx> {
    PairPose {
        xf_a: &pair[0].0,
        q_a: pair[0].1,
        xf_b: &pair[1].0,
        q_b: pair[1].1,
    }
}

fn manifold(pair: &[(Transform<Fx>, Quat<Fx>); 2]) -> Manifold<Fx> {
    let margin = Fx::from_ratio(2, 100);
    collide(&unit_box(), &pair[0].0, &unit_box(), &pair[1].0, margin)
}

fn contact(found: &Manifold<Fx>) -> Contact<Fx> {
    let key = ContactKey {
        body_a: 1,
        body_b: 2,
        part_a: 0,
        part_b: 0,
    };
    Contact::from_manifold(key, found, None)
}

/// The largest distance between matching points of two contacts, and between their
/// separations, m (the points matched by feature id, every id found).
fn mismatch(a: &Contact<Fx>, b: &Contact<Fx>) -> (f64, f64) // ok-det: test report
{
    assert_eq!(a.count, b.count);
    let mut worst = (0.0f64, 0.0f64);
    for p in a.points() {
        let q = b
            .points()
            .iter()
            .find(|q| q.id == p.id)
            .expect("the same features");
        let d = (p.point - q.point).to_f64();
        let distance = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        let gap = (p.separation - q.separation).to_f64().abs();
        worst = (worst.0.max(distance), worst.1.max(gap));
    }
    worst
}

/// Carried at the pose it was found at, a contact is the narrowphase's up to the rounding
/// of two rotations (a few 2⁻³² m).
#[test]
fn carried_in_place_is_the_narrowphase_contact() {
    let pair = stacked(v(3.0, -2.0, 7.5), 0.7, 0.3);
    let found = manifold(&pair);
    assert_eq!(found.count, 4, "a face on a face");
    let fresh = contact(&found);
    let frame = pose(&pair).frame(&found);
    let carried = pose(&pair).carried(&fresh, &frame);
    let (points, gaps) = mismatch(&fresh, &carried);
    assert!(points < 1e-8 && gaps < 1e-8, "{points} m, {gaps} m");
    let normal = (fresh.normal - carried.normal).to_f64();
    assert!(normal.iter().all(|c| c.abs() < 1e-8), "{normal:?}");
}

/// Two bodies moved and turned together keep their relative pose: the carried contact is
/// `near` and equals the narrowphase's at the new placement, up to rounding.
#[test]
fn a_pair_moved_together_carries_its_contact() {
    let before = stacked(v(0.0, 0.0, 0.0), 0.2, 0.3);
    let found = manifold(&before);
    let frame = pose(&before).frame(&found);
    let old = contact(&found);
    let after = stacked(v(-40.0, 12.0, 3.0), 1.9, 0.3);
    let distance = Fx::from_ratio(1, 1000);
    assert!(pose(&after).near(&frame, &unit_box(), distance));
    let carried = pose(&after).carried(&old, &frame);
    let fresh = contact(&manifold(&after));
    let (points, gaps) = mismatch(&fresh, &carried);
    assert!(points < 1e-7 && gaps < 1e-7, "{points} m, {gaps} m");
}

/// A relative move within the distance is `near`; the carried separations then still
/// measure the gap of the same features, as the narrowphase does (the upper box's corners
/// to the lower box's face: exact for any slide along the face), and the points differ by
/// at most the move.
#[test]
fn a_small_relative_move_is_carried_within_the_distance() {
    let before = stacked(v(1.0, 2.0, 3.0), 0.4, 0.3);
    let found = manifold(&before);
    let frame = pose(&before).frame(&found);
    let old = contact(&found);
    let distance = Fx::from_ratio(1, 1000);
    // 0.3 mm along the face, 0.2 mm down, and a turn of 2·10⁻⁴ rad about y.
    let [(lower, q_lower), (upper, q_upper)] = before;
    let turn = Quat::from_axis_angle(v(0.0, 1.0, 0.0), Fx::from_f64(2e-4));
    let shift = q_lower.rotate(v(0.0003, -0.0002, 0.0));
    let moved = [
        (lower, q_lower),
        (
            Transform::from_pose(upper.translation + shift, q_upper * turn),
            q_upper * turn,
        ),
    ];
    assert!(pose(&moved).near(&frame, &unit_box(), distance));
    let carried = pose(&moved).carried(&old, &frame);
    let fresh = contact(&manifold(&moved));
    let (points, gaps) = mismatch(&fresh, &carried);
    assert!(gaps < 1e-7, "separations differ by {gaps} m");
    assert!(points < 1e-3, "points differ by {points} m");
}

/// Beyond the distance, by translation or by rotation, the pair is not `near`.
#[test]
fn a_move_beyond_the_distance_is_not_near() {
    let before = stacked(v(0.0, 0.0, 0.0), 0.0, 0.0);
    let frame = pose(&before).frame(&manifold(&before));
    let distance = Fx::from_ratio(1, 1000);
    let [(lower, q_lower), (upper, q_upper)] = before;
    let moved_by = |shift: Vec3<Fx>, angle: Fx| {
        let turn = Quat::from_axis_angle(v(1.0, 0.0, 0.0), angle);
        [
            (lower, q_lower),
            (
                Transform::from_pose(upper.translation + shift, q_upper * turn),
                q_upper * turn,
            ),
        ]
    };
    // |Δt| up to d/2, and 2 sin(Δθ/2)·ρ up to d/2 with ρ = √0.75 m: Δθ up to 5.8·10⁻⁴ rad.
    assert!(pose(&moved_by(v(0.0004, 0.0, 0.0), Fx::ZERO)).near(&frame, &unit_box(), distance));
    assert!(!pose(&moved_by(v(0.0006, 0.0, 0.0), Fx::ZERO)).near(&frame, &unit_box(), distance));
    assert!(pose(&moved_by(Vec3::ZERO, Fx::from_f64(5.5e-4))).near(&frame, &unit_box(), distance));
    assert!(!pose(&moved_by(Vec3::ZERO, Fx::from_f64(6.2e-4))).near(&frame, &unit_box(), distance));
}

/// Boxes and capsules recycle; spheres, planes and compounds do not.
#[test]
fn only_costly_convex_pairs_recycle() {
    let capsule = Shape::Capsule {
        radius: Fx::HALF,
        half_height: Fx::ONE,
    };
    let sphere = Shape::Sphere { radius: Fx::ONE };
    let plane = Shape::Plane {
        normal: v(0.0, 1.0, 0.0),
        offset: Fx::ZERO,
    };
    assert!(recyclable(&unit_box(), &unit_box()));
    assert!(recyclable(&unit_box(), &capsule));
    assert!(recyclable(&capsule, &capsule));
    assert!(!recyclable(&unit_box(), &sphere));
    assert!(!recyclable(&plane, &unit_box()));
    assert!(!recyclable(&Shape::Compound { parts: vec![] }, &unit_box()));
}

/// A loaded state whose contact names a frame it does not have is refused, by field.
#[test]
fn a_contact_naming_a_missing_frame_is_refused() {
    use crate::rigid::{BodyDesc, RigidDesc, RigidSystem};
    let desc = RigidDesc::<Fx> {
        bodies: vec![
            BodyDesc::new(unit_box(), v(0.0, 0.0, 0.0)),
            BodyDesc::new(unit_box(), v(0.0, 0.99, 0.0)),
        ],
        ..RigidDesc::default()
    };
    let mut system = RigidSystem::from_desc(&desc).expect("builds");
    system.step(Fx::from_ratio(1, 60), v(0.0, 0.0, 0.0));
    assert_eq!(system.contacts.len(), 1);
    assert_ne!(
        system.contacts[0].frame, NO_FRAME,
        "a box pair keeps a frame"
    );
    assert!(system.validate().is_ok());
    system.frames.clear();
    let error = system.validate().expect_err("refused").to_string();
    assert!(error.contains("contacts[0].frame"), "{error}");
}
