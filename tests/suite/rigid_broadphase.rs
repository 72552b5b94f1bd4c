//! The sort-and-sweep broadphase against brute force: the same pairs, in ascending order,
//! without duplicates, whatever the boxes (duplicated coordinates, touching, zero size,
//! negative, a long ground slab), the flags (all inactive, mixed, absent slots) and the
//! history of the broadphase (fresh, warmed on other frames, moving boxes across frames,
//! bodies added and removed).

use fixstep::math::{Fx, FxI48F16, Pcg32, Real, Vec3};
use fixstep::rigid::Aabb;
use fixstep::rigid::broadphase::BroadPhase;
use proptest::prelude::*;

/// One frame of input: boxes and their flags.
#[derive(Clone, Debug)]
struct Frame<R: Real> {
    boxes: Vec<Aabb<R>>,
    active: Vec<bool>,
    present: Vec<bool>,
}

/// Every qualifying pair by testing all of them, in ascending order.
fn brute<R: Real>(f: &Frame<R>) -> Vec<(u32, u32)> {
    let mut pairs = Vec::new();
    for a in 0..f.boxes.len() {
        for b in a + 1..f.boxes.len() {
            if f.present[a]
                && f.present[b]
                && (f.active[a] || f.active[b])
                && f.boxes[a].overlaps(&f.boxes[b])
            {
                pairs.push((a as u32, b as u32));
            }
        }
    }
    pairs
}

/// The broadphase's answer for one frame.
fn sweep<R: Real>(bp: &mut BroadPhase<R>, f: &Frame<R>) -> Vec<(u32, u32)> {
    let mut out = vec![(7, 7)]; // stale content must be cleared
    bp.find_pairs(&f.boxes, &f.active, &f.present, &mut out);
    out
}

/// A box from integer quarters: lower corner `min/4`, size `size/4` (m).
fn quarter_box<R: Real>(min: [i32; 3], size: [i32; 3]) -> Aabb<R> {
    let q = |v: i32| R::from_ratio(i64::from(v), 4);
    Aabb {
        min: Vec3::new(q(min[0]), q(min[1]), q(min[2])),
        max: Vec3::new(
            q(min[0] + size[0]),
            q(min[1] + size[1]),
            q(min[2] + size[2]),
        ),
    }
}

/// One box description for proptest: lower corner and size in quarters on a small grid
/// (so coordinates repeat and boxes touch), active flag, and a draw that makes ~10 % of
/// the slots absent.
type BoxSpec = ([i32; 3], [i32; 3], bool, u8);

fn box_spec() -> impl Strategy<Value = BoxSpec> {
    (
        [-8i32..8, -8i32..8, -8i32..8],
        [0i32..5, 0i32..5, 0i32..5],
        any::<bool>(),
        0u8..10,
    )
}

fn frame_from<R: Real>(specs: &[BoxSpec]) -> Frame<R> {
    Frame {
        boxes: specs.iter().map(|s| quarter_box(s.0, s.1)).collect(),
        active: specs.iter().map(|s| s.2).collect(),
        present: specs.iter().map(|s| s.3 != 0).collect(),
    }
}

/// A random frame from the crate's generator: `n` boxes of size up to `max_size` quarters
/// in a cube of `extent` quarters, awake with probability `awake_per_10`/10.
fn random_frame<R: Real>(
    rng: &mut Pcg32,
    n: usize,
    extent: u32,
    max_size: u32,
    awake_per_10: u32,
) -> Frame<R> {
    let mut f = Frame {
        boxes: Vec::new(),
        active: Vec::new(),
        present: Vec::new(),
    };
    for _ in 0..n {
        let min = [0; 3].map(|_: i32| rng.below(extent) as i32 - (extent / 2) as i32);
        let size = [0; 3].map(|_: i32| rng.below(max_size + 1) as i32);
        f.boxes.push(quarter_box(min, size));
        f.active.push(rng.below(10) < awake_per_10);
        f.present.push(rng.below(20) != 0);
    }
    f
}

/// Moves each box by up to ±`step` quarters with probability 1/2, flips some flags.
fn perturb<R: Real>(rng: &mut Pcg32, f: &mut Frame<R>, step: u32, flip_per_100: u32) {
    for i in 0..f.boxes.len() {
        if rng.below(2) == 0 {
            let d = [0; 3].map(|_: i32| rng.below(2 * step + 1) as i32 - step as i32);
            let shift = Vec3::new(
                R::from_ratio(i64::from(d[0]), 4),
                R::from_ratio(i64::from(d[1]), 4),
                R::from_ratio(i64::from(d[2]), 4),
            );
            f.boxes[i].min += shift;
            f.boxes[i].max += shift;
        }
        if rng.below(100) < flip_per_100 {
            f.active[i] = !f.active[i];
        }
        if rng.below(100) < flip_per_100 / 2 {
            f.present[i] = !f.present[i];
        }
    }
}

fn check_order(pairs: &[(u32, u32)]) {
    assert!(pairs.iter().all(|&(a, b)| a < b), "a < b in every pair");
    assert!(
        pairs.windows(2).all(|w| w[0] < w[1]),
        "ascending and unique"
    );
}

proptest! {
    #![proptest_config(crate::property_cases::fixed_cases(400))]

    /// A fresh broadphase gives exactly the brute-force pairs.
    #[test]
    fn fresh_matches_brute_force(specs in prop::collection::vec(box_spec(), 0..80)) {
        let f = frame_from::<Fx>(&specs);
        let pairs = sweep(&mut BroadPhase::new(), &f);
        check_order(&pairs);
        prop_assert_eq!(pairs, brute(&f));
    }

    /// Boxes with `min > max` along some axes (which no shape produces) still get exactly
    /// the pairs of `Aabb::overlaps`.
    #[test]
    fn inverted_boxes_match_brute_force(
        specs in prop::collection::vec(
            ([-8i32..8, -8i32..8, -8i32..8], [-3i32..5, -3i32..5, -3i32..5], any::<bool>(), 0u8..10),
            0..60,
        ),
    ) {
        let f = frame_from::<Fx>(&specs);
        prop_assert_eq!(sweep(&mut BroadPhase::new(), &f), brute(&f));
    }

    /// A broadphase warmed on unrelated frames gives the same pairs as a fresh one.
    #[test]
    fn history_does_not_matter(
        history in prop::collection::vec(prop::collection::vec(box_spec(), 0..60), 1..4),
        specs in prop::collection::vec(box_spec(), 0..60),
    ) {
        let f = frame_from::<Fx>(&specs);
        let mut warm = BroadPhase::new();
        for h in &history {
            sweep(&mut warm, &frame_from::<Fx>(h));
        }
        let fresh = sweep(&mut BroadPhase::new(), &f);
        prop_assert_eq!(sweep(&mut warm, &f), fresh.clone());
        // And again, now that the cache holds this very frame.
        prop_assert_eq!(sweep(&mut warm, &f), fresh);
    }

    /// The same over a run of frames where boxes move, wake, sleep, appear and vanish.
    #[test]
    fn moving_frames_match_brute_force(
        specs in prop::collection::vec(box_spec(), 0..80),
        seed in any::<u64>(),
        step in 0u32..6,
        flips in 0u32..30,
    ) {
        let mut rng = Pcg32::new(seed, 3);
        let mut f = frame_from::<Fx>(&specs);
        let mut bp = BroadPhase::new();
        for _ in 0..8 {
            let pairs = sweep(&mut bp, &f);
            check_order(&pairs);
            prop_assert_eq!(pairs, brute(&f));
            perturb(&mut rng, &mut f, step, flips);
        }
    }
}

#[test]
fn all_inactive_gives_nothing() {
    let mut rng = Pcg32::new(1, 1);
    let mut f = random_frame::<Fx>(&mut rng, 300, 40, 8, 0);
    assert!(
        !brute(&Frame {
            active: vec![true; 300],
            ..f.clone()
        })
        .is_empty()
    );
    assert!(sweep(&mut BroadPhase::new(), &f).is_empty());
    // One box wakes: exactly its overlaps appear.
    f.active[17] = true;
    f.present[17] = true;
    let mut bp = BroadPhase::new();
    let pairs = sweep(&mut bp, &f);
    assert_eq!(pairs, brute(&f));
    assert!(pairs.iter().all(|&(a, b)| a == 17 || b == 17));
}

#[test]
fn touching_and_zero_size_boxes_count() {
    // Two unit boxes sharing a face, a point box on their shared corner, a point box
    // duplicated, and an absent box overlapping everything.
    let f = Frame::<Fx> {
        boxes: vec![
            quarter_box([0, 0, 0], [4, 4, 4]),
            quarter_box([4, 0, 0], [4, 4, 4]),
            quarter_box([4, 4, 4], [0, 0, 0]),
            quarter_box([4, 4, 4], [0, 0, 0]),
            quarter_box([-8, -8, -8], [20, 20, 20]),
            quarter_box([9, 0, 0], [0, 0, 0]),
        ],
        active: vec![true, false, false, true, true, false],
        present: vec![true, true, true, true, false, true],
    };
    let pairs = sweep(&mut BroadPhase::new(), &f);
    assert_eq!(pairs, vec![(0, 1), (0, 2), (0, 3), (1, 3), (2, 3)]);
    assert_eq!(pairs, brute(&f));
}

#[test]
fn present_false_is_skipped_even_when_awake() {
    let f = Frame::<Fx> {
        boxes: vec![quarter_box([0, 0, 0], [4, 4, 4]); 4],
        active: vec![true; 4],
        present: vec![true, false, true, false],
    };
    assert_eq!(sweep(&mut BroadPhase::new(), &f), vec![(0, 2)]);
}

#[test]
fn long_resting_slab_under_many_awake_boxes() {
    // A ground slab (resting) sorted first, many resting boxes after it that end early,
    // and awake boxes spread over the slab: the backward walk must still find the slab.
    let mut rng = Pcg32::new(5, 9);
    let mut f = random_frame::<Fx>(&mut rng, 600, 400, 3, 2);
    f.boxes.push(quarter_box([-300, -40, -300], [600, 80, 600]));
    f.active.push(false);
    f.present.push(true);
    let mut bp = BroadPhase::new();
    let pairs = sweep(&mut bp, &f);
    assert_eq!(pairs, brute(&f));
    assert!(pairs.iter().filter(|p| p.1 == 600).count() > 10);
}

#[test]
fn large_random_sets_match_brute_force() {
    let mut rng = Pcg32::new(42, 7);
    for (n, extent, size, awake) in [
        (2000, 200, 12, 10),
        (2000, 200, 12, 1),
        (1500, 60, 8, 5),
        (500, 20, 20, 3),
    ] {
        let f = random_frame::<Fx>(&mut rng, n, extent, size, awake);
        let pairs = sweep(&mut BroadPhase::new(), &f);
        check_order(&pairs);
        assert_eq!(pairs, brute(&f), "n {n} extent {extent} size {size}");
    }
}

#[test]
fn count_changes_and_teleports_keep_the_cache_honest() {
    let mut rng = Pcg32::new(11, 13);
    let mut bp = BroadPhase::<Fx>::new();
    for (frame, n) in [400, 400, 410, 0, 50, 1200, 1190, 3, 800, 800]
        .into_iter()
        .enumerate()
    {
        // Every other frame is a fresh random layout (a full reshuffle of the order); the
        // others move the previous layout slightly.
        let f = if frame % 2 == 0 {
            random_frame(&mut rng, n, 100, 10, 4)
        } else {
            let mut f = random_frame(&mut Pcg32::new(frame as u64, 1), n, 100, 10, 4);
            perturb(&mut rng, &mut f, 2, 10);
            f
        };
        let pairs = sweep(&mut bp, &f);
        assert_eq!(pairs, brute(&f), "frame {frame}, n {n}");
        assert_eq!(pairs, sweep(&mut BroadPhase::new(), &f));
    }
}

#[test]
fn same_flags_new_layout_is_resorted() {
    // Nobody joins or leaves either list, but every box moves far: the kept order is
    // useless and must be re-sorted (insertion sort running over budget, then a full sort).
    let mut rng = Pcg32::new(21, 5);
    let f = random_frame::<Fx>(&mut rng, 800, 100, 10, 5);
    let mut g = f.clone();
    g.boxes.reverse();
    let mut h = f.clone();
    h.boxes.rotate_left(1);
    let mut bp = BroadPhase::new();
    for frame in [&f, &g, &h, &f] {
        assert_eq!(sweep(&mut bp, frame), brute(frame));
    }
}

#[test]
fn sleeping_world_with_a_few_movers_over_many_frames() {
    // Most boxes rest; a few awake ones move each frame, and now and then one falls asleep
    // or wakes; the resting list must follow (and be re-sorted) exactly.
    let mut rng = Pcg32::new(3, 4);
    let mut f = random_frame::<Fx>(&mut rng, 1000, 120, 8, 1);
    let mut bp = BroadPhase::new();
    for frame in 0..40 {
        for i in 0..f.boxes.len() {
            if f.active[i] {
                let shift = Vec3::new(
                    Fx::from_ratio(i64::from(rng.below(3)) - 1, 8),
                    Fx::from_ratio(-1, 8),
                    Fx::ZERO,
                );
                f.boxes[i].min += shift;
                f.boxes[i].max += shift;
            }
        }
        if frame % 3 == 0 {
            let i = rng.below(1000) as usize;
            f.active[i] = !f.active[i];
        }
        if frame % 7 == 0 {
            // A resting box is moved onto an awake one without waking (a kinematic
            // teleport, say): the resting list must notice the new box.
            let from = rng.below(1000) as usize;
            let awake = (0..1000)
                .map(|k| (from + k) % 1000)
                .find(|&i| f.active[i] && f.present[i])
                .unwrap();
            let resting = (0..1000)
                .map(|k| (from + k) % 1000)
                .find(|&i| !f.active[i] && f.present[i])
                .unwrap();
            f.boxes[resting] = f.boxes[awake];
            assert!(brute(&f).contains(&(awake.min(resting) as u32, awake.max(resting) as u32)));
        }
        assert_eq!(sweep(&mut bp, &f), brute(&f), "frame {frame}");
    }
}

#[test]
fn collapsing_and_spreading_layouts() {
    // A wide cloud of boxes collapses onto a line along y and spreads out again, so the
    // strips chosen for the first frames become badly crowded and the layout is chosen
    // again; on the way, three boxes in four vanish for a while and come back.
    let mut rng = Pcg32::new(17, 2);
    let base = random_frame::<Fx>(&mut rng, 600, 60, 6, 6);
    let mut bp = BroadPhase::new();
    for frame in 0..24 {
        let mut f = base.clone();
        // Horizontal scale 1, 1/2, …, 1/2048, then back up.
        let shift = if frame < 12 { frame } else { 23 - frame };
        let scale = Fx::from_ratio(1, 1 << shift);
        for b in &mut f.boxes {
            for v in [&mut b.min, &mut b.max] {
                v.x *= scale;
                v.z *= scale;
            }
        }
        if (6..10).contains(&frame) {
            for (i, p) in f.present.iter_mut().enumerate() {
                *p &= i % 4 == 0;
            }
        }
        assert_eq!(sweep(&mut bp, &f), brute(&f), "frame {frame}");
    }
}

#[test]
fn new_layout_with_untouched_resting_boxes() {
    // The resting boxes never change, but many awake boxes arrive in a differently shaped
    // region, so the layout is chosen again: the resting list must follow it.
    let mut rng = Pcg32::new(23, 4);
    let resting = random_frame::<Fx>(&mut rng, 300, 80, 8, 0);
    let mut crowd = random_frame::<Fx>(&mut rng, 900, 80, 8, 10);
    for b in &mut crowd.boxes {
        // A thin slab across x and z, tall in y.
        b.min.y *= Fx::from_int(8);
        b.max.y *= Fx::from_int(8);
        b.min.x *= Fx::from_ratio(1, 16);
        b.max.x *= Fx::from_ratio(1, 16);
    }
    let mut bp = BroadPhase::new();
    for awake in [20, 900, 20, 900] {
        let mut f = resting.clone();
        f.boxes.extend_from_slice(&crowd.boxes[..awake]);
        f.active.extend(vec![true; awake]);
        f.present.extend(vec![true; awake]);
        assert_eq!(sweep(&mut bp, &f), brute(&f), "{awake} awake");
    }
}

#[test]
fn other_formats_match_brute_force() {
    let mut rng = Pcg32::new(8, 8);
    let f = random_frame::<f64>(&mut rng, 700, 80, 8, 5);
    let mut neg = f.clone();
    // Signed zeros and equal values in the reference format.
    neg.boxes[0].min.x = -0.0;
    neg.boxes[1].min.x = 0.0;
    neg.boxes[0].max.x = 0.0;
    neg.boxes[1].max.x = 0.5;
    neg.active[0] = true;
    neg.present[0] = true;
    neg.present[1] = true;
    for g in [f, neg] {
        assert_eq!(sweep(&mut BroadPhase::new(), &g), brute(&g));
    }
    let mut rng = Pcg32::new(8, 9);
    let h = random_frame::<FxI48F16>(&mut rng, 700, 80, 8, 5);
    assert_eq!(sweep(&mut BroadPhase::new(), &h), brute(&h));
}

#[test]
fn default_is_new() {
    let f = random_frame::<Fx>(&mut Pcg32::new(2, 2), 100, 30, 8, 5);
    assert_eq!(
        sweep(&mut BroadPhase::default(), &f),
        sweep(&mut BroadPhase::new(), &f)
    );
}

#[test]
#[should_panic(expected = "one active flag per box")]
fn mismatched_flags_panic() {
    let mut out = Vec::new();
    BroadPhase::<Fx>::new().find_pairs(
        &[quarter_box([0, 0, 0], [1, 1, 1])],
        &[],
        &[true],
        &mut out,
    );
}

/// Boxes piled on one spot overlap pairwise: past `MAX_PAIRS` pairs the call reports that it
/// stopped, with nothing in `out`, instead of filling memory.
#[test]
fn too_many_pairs_stop_the_scan() {
    use fixstep::rigid::broadphase::MAX_PAIRS;
    let n = 1000; // 499,500 pairs
    assert!(n * (n - 1) / 2 > MAX_PAIRS);
    let unit = Aabb {
        min: Vec3::splat(Fx::ZERO),
        max: Vec3::splat(Fx::ONE),
    };
    let mut out = Vec::new();
    let mut bp = BroadPhase::<Fx>::new();
    assert!(!bp.find_pairs(&vec![unit; n], &vec![true; n], &vec![true; n], &mut out));
    assert!(out.is_empty());
    // A smaller pile is reported in full by the same broadphase.
    let m = 700; // 244,650 pairs
    assert!(m * (m - 1) / 2 <= MAX_PAIRS);
    assert!(bp.find_pairs(&vec![unit; m], &vec![true; m], &vec![true; m], &mut out));
    assert_eq!(out.len(), m * (m - 1) / 2);
}
