//! The scene builder's mass-ratio warnings: pairs of dynamic rigid bodies whose masses
//! differ by more than [`MAX_MASS_RATIO`] and that can touch or are jointed.
//!
//! An iterative solver such as fixstep's (and Box2D's and Rapier's, whose manuals give the
//! same advice) cannot hold a heavy body on a light one: a 100 t box sinks through a 1 kg
//! box, and a light body between two heavy ones is squeezed out. A joint between such
//! bodies stretches and jitters.
//!
//! "Can touch" is decided conservatively, from what the scene says rather than from where
//! the bodies happen to start: two dynamic bodies can touch when neither is a sensor and
//! their collision filters let them collide ([`CollisionFilter::interacts`]), wherever they
//! are. Where they will be is known only by running the scene (a heavy body dropped from a
//! height lands on whatever is below), so a test of their positions at build would miss
//! the case the warning is for. Static and kinematic bodies have infinite mass and are
//! never part of a pair.
//!
//! The pairs are listed in a fixed order (joints first, in joint slot order; then touching
//! pairs by the light body's slot, then by filter and the heavy body's mass and slot), at most
//! [`LISTED_PAIRS`] of them, then one line with the count of the rest. Counting costs a
//! binary search per light body and filter class, not a test per pair of bodies.

use crate::math::Real;
use crate::rigid::RigidSystem;
use crate::rigid::desc::BodyKind;
use crate::rigid::filter::CollisionFilter;

/// The largest mass ratio between two bodies that can touch or are jointed that builds
/// without a warning: 1:100. Box2D and Rapier advise 1:1000, but fixstep's contacts give
/// way sooner: a heavy box sinks 1 cm into a light one at 1:100, 6 cm at 1:500, and passes
/// through it from about 1:700 (`tests/suite/readme_limits.rs`).
pub const MAX_MASS_RATIO: f64 = 100.0; // ok-det: reporting

/// The most pairs named; the rest are counted.
pub const LISTED_PAIRS: usize = 5;

/// One pair past the ratio: the light body's slot and mass, the heavy body's, and the joint
/// that ties them (`None` when they can touch).
struct HeavyPair {
    light: (usize, f64), // ok-det: reporting
    heavy: (usize, f64), // ok-det: reporting
    joint: Option<usize>,
}

/// The warnings of `rigid`'s mass ratios (see the [module](self) documentation), each
/// starting with the scene field it is about.
pub(crate) fn mass_ratio_warnings<R: Real>(rigid: &RigidSystem<R>) -> Vec<String> {
    let bodies = &rigid.bodies;
    let mass = |i: usize| bodies.mass[i].to_f64(); // ok-det: reporting
    let dynamic = |i: usize| bodies.alive[i] && bodies.kind[i] == BodyKind::Dynamic;
    let too_far = |light: usize, heavy: usize| mass(heavy) > MAX_MASS_RATIO * mass(light);

    let mut listed = Vec::new();
    let mut count = 0_u64;
    let joints = &rigid.joints;
    for j in joints.live() {
        let (a, b) = (joints.body_a[j] as usize, joints.body_b[j] as usize);
        if !(dynamic(a) && dynamic(b)) {
            continue;
        }
        let (light, heavy) = if mass(a) <= mass(b) { (a, b) } else { (b, a) };
        if too_far(light, heavy) {
            count += 1;
            if listed.len() < LISTED_PAIRS {
                listed.push(HeavyPair {
                    light: (light, mass(light)),
                    heavy: (heavy, mass(heavy)),
                    joint: Some(j),
                });
            }
        }
    }

    // The bodies that collide, grouped by filter; each group sorted by (mass, slot).
    let mut classes: Vec<(CollisionFilter, Vec<usize>)> = Vec::new();
    for i in (0..bodies.len()).filter(|&i| dynamic(i) && !bodies.sensor[i]) {
        let filter = bodies.filter[i];
        match classes.iter_mut().find(|(f, _)| *f == filter) {
            Some((_, members)) => members.push(i),
            None => classes.push((filter, vec![i])),
        }
    }
    for (_, members) in &mut classes {
        members.sort_by(|&a, &b| mass(a).total_cmp(&mass(b)).then(a.cmp(&b)));
    }
    for light in (0..bodies.len()).filter(|&i| dynamic(i) && !bodies.sensor[i]) {
        let filter = bodies.filter[light];
        for (_, members) in classes.iter().filter(|(f, _)| f.interacts(filter)) {
            let heavies = &members[members.partition_point(|&j| !too_far(light, j))..];
            count += heavies.len() as u64;
            let room = LISTED_PAIRS - listed.len();
            listed.extend(heavies.iter().take(room).map(|&heavy| HeavyPair {
                light: (light, mass(light)),
                heavy: (heavy, mass(heavy)),
                joint: None,
            }));
        }
    }

    let mut warnings: Vec<String> = listed.iter().map(describe).collect();
    let rest = count - listed.len() as u64;
    if rest > 0 {
        warnings.push(format!(
            "rigid.bodies: {rest} more pairs of bodies that can touch or are jointed have mass \
             ratios past 1:{MAX_MASS_RATIO}"
        ));
    }
    warnings
}

/// The warning line of one pair.
fn describe(pair: &HeavyPair) -> String {
    let (light, light_mass) = pair.light;
    let (heavy, heavy_mass) = pair.heavy;
    let ratio = heavy_mass / light_mass; // ok-det: reporting
    let bodies = format!(
        "bodies {light} ({}) and {heavy} ({})",
        kilograms(light_mass),
        kilograms(heavy_mass)
    );
    match pair.joint {
        Some(joint) => format!(
            "joints: joint {joint} ties {bodies}, a mass ratio of 1:{ratio:.0}, past \
             1:{MAX_MASS_RATIO}: the joint will stretch and jitter"
        ),
        None => format!(
            "rigid.bodies: {bodies} can touch, a mass ratio of 1:{ratio:.0}, past \
             1:{MAX_MASS_RATIO}: the heavy body may sink into or through the light one or \
             squeeze it out"
        ),
    }
}

/// A mass for a message: to the gram, or in scientific notation below a gram.
fn kilograms(mass: f64) -> String // ok-det: reporting
{
    if mass >= 1e-3 {
        format!("{} kg", (mass * 1e3).round() / 1e3)
    } else {
        format!("{mass:.1e} kg")
    }
}
