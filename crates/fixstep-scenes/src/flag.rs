//! The `flag` scene: soft bodies coupled to rigid bodies. A kinematic carousel (a mast, an
//! arm and a pole 1.5 m out) turns at 0.8 rad/s; a cloth flag is tied along the pole and
//! trails behind it, colliding with the bodies it meets. Beside it, a crate hangs from a
//! fixed point on a 10-link rope tied to its lid and swings into the flag's path: the flag
//! pushes the crate and the crate dents the flag.

use fixstep::math::{Quat, Real, Vec3};
use fixstep::rigid::{BodyDesc, BodyKind, Part, RigidDesc, Shape};
use fixstep::soft::{
    BodyAttachmentDesc, BodyContactsDesc, SoftBodyDesc, SoftDesc, SoftModel, SoftShape,
    XpbdSettings,
};

use super::rigid::ground;
use super::soft::body;

/// `a/b` as a scalar.
fn ratio<R: Real>(a: i64, b: i64) -> R {
    R::from_ratio(a, b)
}

/// The bodies: 0 the ground; 1 the carousel, kinematic, turning about the vertical axis
/// through the origin at −0.8 rad/s (its pole, at x = 1.5 m, moves towards +z); 2 the
/// crate, a 30 cm box of 300 kg/m³ (8.1 kg), hanging 20° out from below (0, 4, 1.35) m.
pub fn flag_bodies<R: Real>() -> RigidDesc<R> {
    let upright = |x: R, radius: R| Part {
        rotation: Quat::IDENTITY,
        translation: Vec3::new(x, R::ZERO, R::ZERO),
        shape: Shape::Cylinder {
            radius,
            half_height: ratio(3, 2),
        },
    };
    let arm = Part {
        rotation: Quat::IDENTITY,
        translation: Vec3::new(ratio(3, 4), ratio(29, 20), R::ZERO),
        shape: Shape::Box {
            half_extents: Vec3::new(ratio(3, 4), ratio(1, 20), ratio(1, 20)),
        },
    };
    let mut carousel = BodyDesc::new(
        Shape::Compound {
            parts: vec![
                upright(R::ZERO, ratio(1, 10)),
                arm,
                upright(ratio(3, 2), ratio(1, 20)),
            ],
        },
        Vec3::new(R::ZERO, ratio(3, 2), R::ZERO),
    );
    carousel.kind = BodyKind::Kinematic;
    carousel.angular_velocity = Vec3::new(R::ZERO, -ratio::<R>(4, 5), R::ZERO);
    let (top, length, half) = rope_geometry::<R>();
    let (sin, cos) = (ratio::<R>(342, 1000), ratio::<R>(940, 1000));
    let down = Vec3::new(sin, -cos, R::ZERO);
    let mut load = BodyDesc::new(
        Shape::Box {
            half_extents: Vec3::splat(half),
        },
        top + down * (length + half),
    );
    // Turned 20° about z, so that its lid faces the rope.
    load.orientation = Quat {
        w: ratio(9848, 10000),
        x: R::ZERO,
        y: R::ZERO,
        z: ratio(1736, 10000),
    };
    load.density = R::from_int(300);
    RigidDesc {
        bodies: vec![ground(), carousel, load],
        ..RigidDesc::default()
    }
}

/// The rope's fixed end (m), its length (m) and the crate's half size (m).
fn rope_geometry<R: Real>() -> (Vec3<R>, R, R) {
    (
        Vec3::new(R::ZERO, R::from_int(4), ratio(27, 20)),
        ratio(6, 5),
        ratio(3, 20),
    )
}

/// The soft bodies: the flag, 1.2 m × 0.8 m, 13 × 9 vertices, 0.3 kg, its first column
/// tied to the pole, with air drag, touching every body; the rope, 10 links, 0.2 kg, pinned
/// at its top, tied to the crate's lid and tethered so that the crate cannot stretch it.
pub fn flag_cloth<R: Real>() -> SoftDesc<R> {
    let mut flag = body(
        SoftShape::Cloth {
            origin: Vec3::new(ratio(3, 2), ratio(29, 10), -ratio::<R>(13, 200)),
            u: Vec3::new(R::ZERO, R::ZERO, -ratio::<R>(6, 5)),
            v: Vec3::new(R::ZERO, -ratio::<R>(4, 5), R::ZERO),
            columns: 13,
            rows: 9,
        },
        SoftModel::Xpbd {
            stretch_compliance: R::ZERO,
            bend_compliance: Some(ratio(1, 2)),
            volume_compliance: None,
            tethers: false,
        },
        ratio(3, 10),
    );
    flag.body_attachments = vec![BodyAttachmentDesc {
        body: 1,
        vertices: (0..9).map(|j| j * 13).collect(),
        compliance: R::ZERO,
    }];
    flag.body_contacts = Some(BodyContactsDesc::default());
    flag.drag = ratio(1, 50);
    flag.radius = ratio(1, 50);
    let (top, length, _) = rope_geometry::<R>();
    let (sin, cos) = (ratio::<R>(342, 1000), ratio::<R>(940, 1000));
    let mut rope: SoftBodyDesc<R> = body(
        SoftShape::Rope {
            start: top,
            end: top + Vec3::new(sin, -cos, R::ZERO) * length,
            links: 10,
        },
        SoftModel::Xpbd {
            stretch_compliance: R::ZERO,
            bend_compliance: None,
            volume_compliance: None,
            tethers: true,
        },
        ratio(1, 5),
    );
    rope.pins = vec![0];
    rope.body_attachments = vec![BodyAttachmentDesc {
        body: 2,
        vertices: vec![10],
        compliance: R::ZERO,
    }];
    SoftDesc {
        bodies: vec![flag, rope],
        colliders: Vec::new(),
        solver: XpbdSettings::default(),
    }
}
