//! Scene queries beside Rapier (issue #34): rays and sphere overlaps on `balls` and
//! `pyramid` after the bodies have settled, the same queries for every engine.
//!
//! The queries come from a fixed seed through integer arithmetic only: every coordinate is
//! a whole number of 1/1024 m, which I32F32 and `f32` both hold exactly, so both engines are
//! asked exactly the same questions. Ray origins lie on the sides and top of the scene's box
//! grown by [`MARGIN`]; each ray points at a random point of the scene's box and reaches
//! [`MAX_DISTANCE`]. Sphere centres are random points of the scene's box, radii 0.5–1 m.
//!
//! Each engine queries the pile its own steps made ([`SETTLE_STEPS`] steps of 1/60 s,
//! sleeping off): those are the timed rows, with their hit/miss agreement with fixstep. The
//! piles differ (each engine settles its own), so Rapier also answers on a copy of
//! fixstep's bodies (the same shapes at fixstep's poses, its tree built by one collision
//! detection): there the answers can be compared ray by ray, body by body.

use crate::{fixstep_side, median, rapier_side};

/// Steps before the queries: `balls` falls into a pile in about two seconds.
pub const SETTLE_STEPS: u32 = 300;

/// Rays per round.
pub const RAYS: usize = 100_000;

/// Sphere overlaps per round.
pub const OVERLAPS: usize = 10_000;

/// How far each ray reaches, m.
pub const MAX_DISTANCE: i32 = 100;

/// How far the ray origins' box reaches past the scene's box, m.
pub const MARGIN: i32 = 5;

/// Subdivisions of a metre of every query coordinate.
pub const UNIT: i32 = 1024;

/// The seed of the queries.
const SEED: u64 = 0x0005_eed0_f1c5_7e95;

/// The scenes the queries run on.
pub const QUERY_SCENES: [&str; 2] = ["balls", "pyramid"];

/// A ray from `origin` towards `target`, in 1/[`UNIT`] m.
#[derive(Clone, Copy)]
pub struct RaySpec {
    pub origin: [i32; 3],
    pub target: [i32; 3],
}

/// A sphere of `radius` at `centre`, in 1/[`UNIT`] m.
#[derive(Clone, Copy)]
pub struct SphereSpec {
    pub centre: [i32; 3],
    pub radius: i32,
}

/// The queries of one scene.
pub struct QuerySet {
    pub rays: Vec<RaySpec>,
    pub spheres: Vec<SphereSpec>,
}

/// A ray's answer: the body hit (its slot, in creation order) and the distance, m.
pub type RayAnswer = Option<(u32, f64)>;

/// The answers of one engine and the seconds their queries took.
pub struct Answers<T> {
    pub seconds: f64,
    pub answers: Vec<T>,
}

/// One engine's scene, ready for queries.
pub trait Queries {
    /// Casts every ray of the set (converted to the engine's types beforehand).
    fn rays(&self) -> Answers<RayAnswer>;
    /// Every sphere overlap of the set: the slots of the bodies each touches, ascending.
    fn overlaps(&self) -> Answers<Vec<u32>>;
}

/// SplitMix64: a fixed sequence of 64-bit integers.
struct SplitMix(u64);

impl SplitMix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A whole number in `lo..=hi`.
    fn range(&mut self, lo: i32, hi: i32) -> i32 {
        let span = u64::try_from(i64::from(hi) - i64::from(lo) + 1).expect("lo ≤ hi");
        let offset = i64::try_from(self.next() % span).expect("a small span");
        i32::try_from(i64::from(lo) + offset).expect("within lo..=hi")
    }
}

/// The scene's box, in 1/[`UNIT`] m: where the bodies are (and the walls' inside).
fn scene_box(scene: &str) -> ([i32; 3], [i32; 3]) {
    let m = |v: f64| (v * f64::from(UNIT)) as i32;
    match scene {
        // The bodies and the inside of the walls: 20 × 20 m, 20 m high.
        "balls" => ([m(-10.0), m(0.0), m(-10.0)], [m(10.0), m(20.0), m(10.0)]),
        // 20 rows of unit cubes, base 20 m wide, one cube deep.
        "pyramid" => ([m(-10.0), m(0.0), m(-0.5)], [m(10.0), m(20.0), m(0.5)]),
        other => unreachable!("no queries on {other}"),
    }
}

/// The queries of `scene`, the same on every call.
pub fn query_set(scene: &str) -> QuerySet {
    let mut random = SplitMix(SEED);
    let (lo, hi) = scene_box(scene);
    let margin = MARGIN * UNIT;
    // The origins' box: grown by the margin sideways and up, its floor the scene's floor.
    let olo = [lo[0] - margin, lo[1], lo[2] - margin];
    let ohi = [hi[0] + margin, hi[1] + margin, hi[2] + margin];
    let point_in = |random: &mut SplitMix, lo: [i32; 3], hi: [i32; 3]| {
        [0, 1, 2].map(|k| random.range(lo[k], hi[k]))
    };
    let rays = (0..RAYS)
        .map(|_| {
            let mut origin = point_in(&mut random, olo, ohi);
            // Onto one of the five faces: −x, +x, −z, +z or the top.
            match random.range(0, 4) {
                0 => origin[0] = olo[0],
                1 => origin[0] = ohi[0],
                2 => origin[2] = olo[2],
                3 => origin[2] = ohi[2],
                _ => origin[1] = ohi[1],
            }
            let target = point_in(&mut random, lo, hi);
            RaySpec { origin, target }
        })
        .collect();
    let spheres = (0..OVERLAPS)
        .map(|_| SphereSpec {
            centre: point_in(&mut random, lo, hi),
            radius: random.range(UNIT / 2, UNIT),
        })
        .collect();
    QuerySet { rays, spheres }
}

/// Coordinates in metres.
pub fn metres(v: [i32; 3]) -> [f64; 3] {
    v.map(|c| f64::from(c) / f64::from(UNIT))
}

/// The fraction of rays on which both engines hit, or both miss.
fn hit_agreement(a: &[RayAnswer], b: &[RayAnswer]) -> f64 {
    fraction(a, b, |x, y| x.is_some() == y.is_some())
}

/// The fraction of rays with the same body hit (or both misses), and of those with the
/// same body hit at distances within 1 mm.
fn body_agreement(a: &[RayAnswer], b: &[RayAnswer]) -> (f64, f64) {
    let same = |x: &RayAnswer, y: &RayAnswer| match (x, y) {
        (None, None) => true,
        (Some((p, _)), Some((q, _))) => p == q,
        _ => false,
    };
    let close = |x: &RayAnswer, y: &RayAnswer| match (x, y) {
        (Some((p, d)), Some((q, e))) => p == q && (d - e).abs() <= 1e-3,
        _ => false,
    };
    let hits = fraction(a, b, |x, y| same(x, y) && x.is_some());
    let within = fraction(a, b, close);
    (fraction(a, b, same), within / hits.max(f64::MIN_POSITIVE))
}

/// The fraction of the pairs of `a` and `b` on which `agree` holds.
fn fraction<T>(a: &[T], b: &[T], agree: impl Fn(&T, &T) -> bool) -> f64 {
    let count = a.iter().zip(b).filter(|(x, y)| agree(x, y)).count();
    count as f64 / a.len().max(1) as f64
}

/// One timed row: an engine's name, its per-round seconds and its last answers.
struct Row<T> {
    name: String,
    seconds: Vec<f64>,
    answers: Vec<T>,
}

impl<T> Row<T> {
    fn new(name: &str) -> Self {
        Self {
            name: name.into(),
            seconds: Vec::new(),
            answers: Vec::new(),
        }
    }

    fn record(&mut self, run: Answers<T>) {
        self.seconds.push(run.seconds);
        self.answers = run.answers;
    }
}

/// The query table of every query scene, `rounds` interleaved rounds each.
pub fn table(rounds: usize, rapier: &str) {
    println!();
    println!(
        "| scene (after {SETTLE_STEPS} steps) | queries | engine | queries/s (median of {rounds}) | vs fixstep I32F32 | answers |"
    );
    println!("|---|---|---|---|---|---|");
    for scene in QUERY_SCENES {
        let set = query_set(scene);
        let fixstep = fixstep_side::queries(scene, &set);
        let rapier_own = rapier_side::queries(scene, &set);
        let rapier_copy = rapier_side::queries_on(&fixstep_side::bodies(&fixstep), &set);
        let engines: [(&str, &dyn Queries); 3] = [
            ("fixstep I32F32", &fixstep),
            (rapier, &rapier_own),
            (&format!("{rapier}, on fixstep's poses"), &rapier_copy),
        ];
        let mut rays: Vec<Row<RayAnswer>> = engines.iter().map(|(n, _)| Row::new(n)).collect();
        let mut spheres: Vec<Row<Vec<u32>>> = engines.iter().map(|(n, _)| Row::new(n)).collect();
        for _ in 0..rounds {
            for ((_, engine), row) in engines.iter().zip(&mut rays) {
                row.record(engine.rays());
            }
            for ((_, engine), row) in engines.iter().zip(&mut spheres) {
                row.record(engine.overlaps());
            }
        }
        let reference = &rays[0].answers;
        let hits = reference.iter().filter(|a| a.is_some()).count();
        let ray_notes = [
            format!("{:.1} % hit", 100.0 * hits as f64 / reference.len() as f64),
            format!(
                "hit/miss as fixstep on {:.2} % (its own pile)",
                100.0 * hit_agreement(reference, &rays[1].answers)
            ),
            {
                let (body, distance) = body_agreement(reference, &rays[2].answers);
                format!(
                    "hit/miss as fixstep on {:.3} %, the same body on {:.3} %, within 1 mm of its distance on {:.3} % of those",
                    100.0 * hit_agreement(reference, &rays[2].answers),
                    100.0 * body,
                    100.0 * distance
                )
            },
        ];
        print_rows(scene, &format!("{RAYS} rays"), &rays, &ray_notes, rounds);
        let reference = &spheres[0].answers;
        let touching = reference.iter().map(Vec::len).sum::<usize>();
        let any = |v: &Vec<u32>| !v.is_empty();
        let sphere_notes = [
            format!(
                "{:.2} bodies each on average",
                touching as f64 / reference.len() as f64
            ),
            format!(
                "some body / none as fixstep on {:.2} % (its own pile)",
                100.0 * fraction(reference, &spheres[1].answers, |a, b| any(a) == any(b))
            ),
            format!(
                "the same bodies as fixstep on {:.3} %",
                100.0 * fraction(reference, &spheres[2].answers, |a, b| a == b)
            ),
        ];
        print_rows(
            scene,
            &format!("{OVERLAPS} sphere overlaps"),
            &spheres,
            &sphere_notes,
            rounds,
        );
    }
}

fn print_rows<T>(scene: &str, what: &str, rows: &[Row<T>], notes: &[String], rounds: usize) {
    let count = what
        .split(' ')
        .next()
        .and_then(|n| n.parse::<f64>().ok())
        .expect("the count leads");
    let rates: Vec<f64> = rows
        .iter()
        .map(|row| count / median(&mut row.seconds.clone()))
        .collect();
    for ((row, rate), note) in rows.iter().zip(&rates).zip(notes) {
        debug_assert_eq!(row.seconds.len(), rounds);
        println!(
            "| `{scene}` | {what} | {} | {} | {:.2}× | {note} |",
            row.name,
            thousands(*rate),
            rate / rates[0]
        );
    }
}

/// A rate with thousands separators.
fn thousands(rate: f64) -> String {
    let digits = format!("{:.0}", rate);
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i) % 3 == 0 {
            out.push(',');
        }
        out.push(c);
    }
    out
}

/// A body's shape, for copying fixstep's bodies into another engine.
#[derive(Clone, Copy)]
pub enum BodyShape {
    /// A sphere of this radius, m.
    Ball(f64),
    /// A box of these half extents, m.
    Cuboid([f64; 3]),
    /// The ground: the half-space y ≤ this height, m.
    Ground(f64),
}

/// A body of fixstep's world: its shape and pose (orientation w, x, y, z), and whether it
/// is dynamic.
#[derive(Clone, Copy)]
pub struct PlacedBody {
    pub shape: BodyShape,
    pub position: [f64; 3],
    pub orientation: [f64; 4],
    pub dynamic: bool,
}
