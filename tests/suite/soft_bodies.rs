//! Soft bodies: the acceptance tests of XPBD and spring-mass networks, with tolerances
//! from physics.

use fixstep::math::{Fx, Pcg32, Real, Vec3};
use fixstep::particles::Integrator;
use fixstep::scene::Scene;
use fixstep::soft::{SoftBodyDesc, SoftDesc, SoftModel, SoftShape, XpbdSettings};
use fixstep::world::{TickInput, World};
use fixstep_scenes::builtin_scene;

fn idle(tick: u64) -> TickInput<Fx> {
    TickInput {
        tick,
        players: Vec::new(),
    }
}

fn run(world: &mut World<Fx>, ticks: u64) {
    for _ in 0..ticks {
        let tick = world.tick();
        world.step(&idle(tick));
    }
}

/// A body of one link from a pinned vertex at the origin straight down `length` m, the
/// free vertex weighing `vertex_mass` kg.
fn pendulum(model: SoftModel<Fx>, length: Fx, vertex_mass: Fx) -> SoftBodyDesc<Fx> {
    let mut body = fixstep_scenes::soft::body(
        SoftShape::Rope {
            start: Vec3::ZERO,
            end: Vec3::new(Fx::ZERO, -length, Fx::ZERO),
            links: 1,
        },
        model,
        vertex_mass * Fx::TWO,
    );
    body.pins = vec![0];
    body
}

fn scene_with(soft: SoftDesc<Fx>, tick_rate: u32) -> Scene<Fx> {
    let mut scene = Scene::empty("test");
    scene.tick_rate = tick_rate;
    scene.soft = Some(soft);
    scene
}

/// XPBD: a 1 kg mass hanging on a distance constraint of compliance α = 10⁻³ m/N settles
/// at a stretch α m g, whatever the step and the iteration count (Macklin et al. 2016).
#[test]
fn hanging_mass_stretches_by_compliance_times_weight() {
    let alpha = 1e-3;
    let g = 9.81;
    for tick_rate in [60u32, 240] {
        for iterations in [1u32, 10] {
            let mut body = pendulum(
                SoftModel::Xpbd {
                    stretch_compliance: Fx::from_f64(alpha),
                    bend_compliance: None,
                    volume_compliance: None,
                    tethers: false,
                },
                Fx::ONE,
                Fx::ONE,
            );
            body.damping = Fx::from_int(5);
            let soft = SoftDesc {
                bodies: vec![body],
                colliders: Vec::new(),
                solver: XpbdSettings {
                    substeps: 1,
                    iterations,
                },
            };
            let mut world = scene_with(soft, tick_rate).build().unwrap();
            run(&mut world, u64::from(tick_rate) * 20);
            let soft = world.soft().unwrap();
            let length = (soft.position(1).unwrap() - soft.position(0).unwrap())
                .length()
                .to_f64();
            let stretch = length - 1.0;
            let expected = alpha * 1.0 * g;
            let error = (stretch - expected).abs() / expected;
            assert!(
                error < 0.01,
                "dt 1/{tick_rate}, {iterations} iterations: stretch {stretch:.6} m, \
                 α m g = {expected:.6} m ({:.3}% off)",
                error * 100.0
            );
        }
    }
}

/// The `cloth` scene at its default settings: after 5 s no edge is stretched by 1% or
/// more, and the mechanical energy never exceeds its starting value.
#[test]
fn cloth_does_not_stretch_and_does_not_gain_energy() {
    let mut world = builtin_scene::<Fx>("cloth").unwrap().build().unwrap();
    let start = world.metrics().total_energy();
    for _ in 0..300 {
        let tick = world.tick();
        world.step(&idle(tick));
        let energy = world.metrics().total_energy();
        assert!(
            energy <= start + 1e-6 * start.abs(),
            "tick {tick}: energy {energy:.6} J above the start {start:.6} J"
        );
    }
    let m = world.metrics();
    assert!(
        m.max_stretch < 0.01,
        "max stretch {:.4}% after 5 s",
        m.max_stretch * 100.0
    );
    assert_eq!(world.saturations_total(), 0);
}

/// `cloth` and `curtain` (its rail slid by its script) while they swing: from 0.5 s to
/// 10 s, at every tick, no edge is stretched by more than 1% (the `max_stretch` metric that
/// `fixstep run --metrics` writes every tick).
#[test]
fn cloth_and_curtain_stay_within_one_percent_while_swinging() {
    for name in ["cloth", "curtain"] {
        let scene = builtin_scene::<Fx>(name).unwrap();
        let mut world = scene.build().unwrap();
        let mut feed = fixstep::replay::InputFeed::new(&scene.script);
        let half_second = u64::from(scene.tick_rate) / 2;
        let mut worst = (0.0, 0);
        while world.tick() < u64::from(scene.tick_rate) * 10 {
            let tick = world.tick();
            world.step(feed.at(tick));
            let stretch = world.metrics().max_stretch;
            if world.tick() >= half_second && stretch > worst.0 {
                worst = (stretch, world.tick());
            }
        }
        assert!(
            worst.0 <= 0.01,
            "{name}: max edge stretch {:.3}% at tick {}",
            worst.0 * 100.0,
            worst.1
        );
        assert_eq!(world.saturations_total(), 0, "{name}");
    }
}

/// ω² of the slowest small-swing mode of `links` equal point masses m hanging on massless
/// inextensible links of length ℓ from a fixed point: the smallest eigenvalue of the
/// symmetric tridiagonal matrix with diagonal (T_j + T_{j+1})/(mℓ) and off-diagonal
/// −T_{j+1}/(mℓ), T_j = (links − j + 1) m g the tension of link j (counted from the top),
/// T_{links+1} = 0. Returns ω² (1/s²) and the mode shape (horizontal displacements).
fn hanging_chain_mode(links: usize, link_length: f64, g: f64) -> (f64, Vec<f64>) {
    let tension = |j: usize| (links + 1 - j) as f64 * g / link_length; // T_j/(mℓ), j = 1..=links
    let diagonal: Vec<f64> = (1..=links)
        .map(|j| tension(j) + if j < links { tension(j + 1) } else { 0.0 })
        .collect();
    let off: Vec<f64> = (1..links).map(|j| -tension(j + 1)).collect();
    // Inverse iteration: solve A y = x by the Thomas algorithm.
    let mut x = vec![1.0; links];
    let mut lambda = 0.0;
    for _ in 0..200 {
        let mut c = vec![0.0; links];
        let mut d = vec![0.0; links];
        for i in 0..links {
            let lower = if i > 0 { off[i - 1] } else { 0.0 };
            let denominator = diagonal[i] - lower * if i > 0 { c[i - 1] } else { 0.0 };
            c[i] = if i + 1 < links {
                off[i] / denominator
            } else {
                0.0
            };
            d[i] = (x[i] - lower * if i > 0 { d[i - 1] } else { 0.0 }) / denominator;
        }
        let mut y = vec![0.0; links];
        for i in (0..links).rev() {
            y[i] = d[i] - if i + 1 < links { c[i] * y[i + 1] } else { 0.0 };
        }
        let norm = y.iter().map(|v| v * v).sum::<f64>().sqrt();
        let dot: f64 = x.iter().zip(&y).map(|(a, b)| a * b).sum();
        let xx: f64 = x.iter().map(|v| v * v).sum();
        lambda = xx / dot;
        x = y.iter().map(|v| v / norm).collect();
    }
    (lambda, x)
}

/// The `rope` preset (20 links) released at a small angle swings at the frequency of the
/// slowest mode of the discrete hanging chain of 20 links, within 1%.
#[test]
fn rope_swings_at_the_hanging_chain_frequency() {
    let links = 20;
    let length = 2.0;
    let g = 9.81;
    let (omega_squared, mode) = hanging_chain_mode(links, length / links as f64, g);
    let omega = omega_squared.sqrt();

    let mut scene = builtin_scene::<Fx>("rope").unwrap();
    let angle: f64 = 0.05;
    let soft = scene.soft.as_mut().unwrap();
    let top = Vec3::new(Fx::ZERO, Fx::from_int(3), Fx::ZERO);
    soft.bodies[0].shape = SoftShape::Rope {
        start: top,
        end: top + Vec3::from_f64(length * angle.sin(), -length * angle.cos(), 0.0),
        links: links as u32,
    };
    let mut world = scene.build().unwrap();
    let coordinate = |world: &World<Fx>| -> f64 {
        let x = world.soft().unwrap().positions();
        (1..=links).map(|j| mode[j - 1] * x[j].x.to_f64()).sum()
    };
    let mut crossings = Vec::new();
    let mut previous = coordinate(&world);
    let rate = 60.0;
    for _ in 0..(20 * 60) {
        let tick = world.tick();
        world.step(&idle(tick));
        let q = coordinate(&world);
        if previous > 0.0 && q <= 0.0 || previous < 0.0 && q >= 0.0 {
            let fraction = previous / (previous - q);
            crossings.push((tick as f64 + fraction) / rate);
        }
        previous = q;
    }
    assert!(
        crossings.len() >= 10,
        "only {} zero crossings",
        crossings.len()
    );
    let half_periods = (crossings.len() - 1) as f64;
    let period = 2.0 * (crossings[crossings.len() - 1] - crossings[0]) / half_periods;
    let measured = 2.0 * std::f64::consts::PI / period;
    let error = (measured - omega).abs() / omega;
    assert!(
        error < 0.01,
        "ω = {measured:.5} rad/s, the hanging chain's {omega:.5} rad/s ({:.3}% off)",
        error * 100.0
    );
}

/// A spring-mass pendulum of one 1 kg vertex on a spring to a pin, at 60 Hz with
/// semi-implicit Euler and stiffness `k_h2_over_m` · m/h².
fn spring_pendulum(k_h2_over_m: f64) -> World<Fx> {
    let stiffness = k_h2_over_m * 3600.0;
    let mut body = pendulum(
        SoftModel::SpringMass {
            integrator: Integrator::SemiImplicitEuler,
            stiffness: Fx::from_f64(stiffness),
            damping: Fx::ZERO,
        },
        Fx::ONE,
        Fx::ONE,
    );
    body.velocity = Vec3::new(Fx::ZERO, -Fx::ONE, Fx::ZERO);
    let soft = SoftDesc {
        bodies: vec![body],
        colliders: Vec::new(),
        solver: XpbdSettings::default(),
    };
    scene_with(soft, 60).build().unwrap()
}

/// Semi-implicit Euler on a spring is stable while k h²/m < 4: just under the bound the
/// motion stays bounded and the build does not warn; just over it the build warns and the
/// divergence check reports the blow-up.
#[test]
fn spring_mass_stability_bound_is_warned_and_detected() {
    let mut stable = spring_pendulum(3.9);
    assert!(stable.warnings().is_empty(), "{:?}", stable.warnings());
    stable.enable_divergence_check(1);
    for _ in 0..600 {
        let tick = stable.tick();
        stable.step(&idle(tick));
        let y = stable.soft().unwrap().position(1).unwrap();
        assert!(y.length().to_f64() < 2.0, "tick {tick}: vertex at {y:?}");
    }
    assert!(stable.divergence().is_none());
    assert_eq!(stable.saturations_total(), 0);

    let mut unstable = spring_pendulum(4.1);
    assert_eq!(unstable.warnings().len(), 1);
    assert!(
        unstable.warnings()[0].contains("stability bound"),
        "{}",
        unstable.warnings()[0]
    );
    unstable.enable_divergence_check(1);
    run(&mut unstable, 120);
    let divergence = unstable.divergence().expect("divergence reported");
    assert!(
        divergence.tick < 60,
        "detected late, at tick {}",
        divergence.tick
    );
}

/// Stress: rigid cloth at a 1 s step, 10⁹ N/m springs, and a crumpled start. Nothing
/// panics; whatever leaves the numeric range is counted and reported.
#[test]
fn stress_cases_are_survived_or_reported() {
    // A huge step: the cloth at 1 tick per second stays finite and within range.
    let mut scene = builtin_scene::<Fx>("cloth").unwrap();
    scene.tick_rate = 1;
    let mut world = scene.build().unwrap();
    run(&mut world, 20);
    let m = world.metrics();
    assert!(
        world.saturations_total() == 0 && m.max_stretch < 0.5,
        "huge step: {} saturations, max stretch {}",
        world.saturations_total(),
        m.max_stretch
    );

    // 10⁹ N/m springs on the jelly: warned at build, then reported as diverged or
    // saturated.
    let mut scene = builtin_scene::<Fx>("jelly").unwrap();
    if let SoftModel::SpringMass { stiffness, .. } =
        &mut scene.soft.as_mut().unwrap().bodies[0].model
    {
        *stiffness = Fx::from_int(1_000_000_000);
    }
    let mut world = scene.build().unwrap();
    assert!(!world.warnings().is_empty());
    world.enable_divergence_check(1);
    run(&mut world, 60);
    assert!(world.divergence().is_some() || world.saturations_total() > 0);

    // A crumpled start: every cloth vertex thrown into a 5 cm ball; the inextensible
    // cloth unfolds without saturating.
    let mut world = builtin_scene::<Fx>("cloth").unwrap().build().unwrap();
    let mut rng = Pcg32::new(7, 1);
    let soft = world.soft_mut().unwrap();
    for i in 0..soft.vertex_count() {
        let mut offset = || Fx::from_ratio(i64::from(rng.next_u32() % 1000) - 500, 10_000);
        let p = Vec3::new(offset(), Fx::TWO + offset(), offset());
        soft.set_position(i, p);
    }
    world.enable_divergence_check(1);
    run(&mut world, 600);
    assert_eq!(world.saturations_total(), 0);
    assert!(world.divergence().is_none());
    let stretch = world.metrics().max_stretch;
    assert!(stretch < 0.05, "max stretch {stretch} after 10 s");
}

/// Compliance 0 with many iterations: the rope stays inextensible to the fixed-point
/// resolution while it swings.
#[test]
fn rigid_rope_stays_inextensible() {
    let mut scene = builtin_scene::<Fx>("rope").unwrap();
    scene.soft.as_mut().unwrap().solver.iterations = 10;
    let mut world = scene.build().unwrap();
    for _ in 0..240 {
        let tick = world.tick();
        world.step(&idle(tick));
        assert!(world.metrics().max_stretch < 0.01);
    }
}

/// A short free rope (two vertices 1 cm apart along `along`, a unit vector, 10 g) let go at
/// `start` above `collider`, after `seconds`: its vertices' positions.
fn drop_on(
    collider: fixstep::soft::ColliderDesc<Fx>,
    start: Vec3<Fx>,
    along: Vec3<Fx>,
    seconds: u64,
) -> Vec<Vec3<Fx>> {
    let body = fixstep_scenes::soft::body(
        SoftShape::Rope {
            start,
            end: start + along * Fx::from_ratio(1, 100),
            links: 1,
        },
        SoftModel::Xpbd {
            stretch_compliance: Fx::ZERO,
            bend_compliance: None,
            volume_compliance: None,
            tethers: false,
        },
        Fx::from_ratio(1, 100),
    );
    let soft = SoftDesc {
        bodies: vec![body],
        colliders: vec![collider],
        solver: XpbdSettings::default(),
    };
    let mut world = scene_with(soft, 60).build().unwrap();
    run(&mut world, 60 * seconds);
    assert_eq!(world.saturations_total(), 0);
    world.soft().unwrap().positions().to_vec()
}

fn collider(
    shape: fixstep::rigid::Shape<Fx>,
    position: Vec3<Fx>,
    friction: Fx,
) -> fixstep::soft::ColliderDesc<Fx> {
    fixstep::soft::ColliderDesc {
        shape,
        position,
        orientation: fixstep::math::Quat::IDENTITY,
        friction,
    }
}

/// Vertices dropped on a plane, a sphere, a box and a capsule come to rest on top of them,
/// one vertex radius (1 cm) above the surface, to within 1 mm.
#[test]
fn vertices_rest_on_every_collider_shape() {
    use fixstep::rigid::Shape;
    let half = Fx::HALF;
    let above = |y: f64| Vec3::new(Fx::ZERO, Fx::from_f64(y), Fx::ZERO);
    let cases: [(Shape<Fx>, f64); 4] = [
        (
            Shape::Plane {
                normal: Vec3::Y,
                offset: Fx::ZERO,
            },
            0.0,
        ),
        (Shape::Sphere { radius: half }, 0.5),
        (
            Shape::Box {
                half_extents: Vec3::splat(half),
            },
            0.5,
        ),
        (
            Shape::Capsule {
                radius: half,
                half_height: half,
            },
            1.0,
        ),
    ];
    for (shape, top) in cases {
        let name = format!("{shape:?}");
        let positions = drop_on(
            collider(shape, Vec3::ZERO, Fx::ONE),
            above(top + 0.3),
            Vec3::X,
            3,
        );
        for p in positions {
            let height = p.y.to_f64() - top;
            assert!(
                (height - 0.01).abs() < 1e-3,
                "{name}: vertex at height {height:.5} m above the top (expected 0.01)"
            );
        }
    }
}

/// On a 30° slope (tan 30° = 0.577), a pair of vertices let go on the surface stays put
/// with μ = 1 and slides with μ = 0.1 as far as Coulomb friction says.
#[test]
fn friction_holds_or_lets_slide_on_a_slope() {
    use fixstep::rigid::Shape;
    let angle: f64 = 30f64.to_radians();
    let normal = Vec3::from_f64(-angle.sin(), angle.cos(), 0.0);
    let plane = |mu: Fx| {
        collider(
            Shape::Plane {
                normal,
                offset: Fx::ZERO,
            },
            Vec3::ZERO,
            mu,
        )
    };
    let down_slope = Vec3::from_f64(-angle.cos(), -angle.sin(), 0.0);
    let start = normal * Fx::from_ratio(1, 100);
    let held = drop_on(plane(Fx::ONE), start, down_slope, 2);
    let slid = drop_on(plane(Fx::from_ratio(1, 10)), start, down_slope, 2);
    let travel = |p: &[Vec3<Fx>]| (p[0] - start).length().to_f64();
    assert!(travel(&held) < 0.01, "μ = 1 moved {:.4} m", travel(&held));
    // Sliding from rest at a = g (sin 30° − 0.1 cos 30°) = 4.06 m/s² for 2 s: 8.1 m.
    let expected = 0.5 * 9.81 * (angle.sin() - 0.1 * angle.cos()) * 4.0;
    assert!(
        (travel(&slid) - expected).abs() < 0.05 * expected,
        "μ = 0.1 slid {:.3} m, Coulomb friction gives {expected:.3} m",
        travel(&slid)
    );
}

/// The volume of a lattice of `n`³ vertices from its positions: the sum of the signed
/// volumes of the six Kuhn tetrahedra of every cell (corner 0, +e_a, +e_a+e_b, corner 7),
/// each signed by the parity of its axis order (the odd ones are mirror images).
fn lattice_volume(x: &[Vec3<Fx>], n: usize) -> f64 {
    let at = |i: usize, j: usize, k: usize| x[(k * n + j) * n + i].to_f64();
    let orders = [
        ([0, 1], 1.0),
        ([0, 2], -1.0),
        ([1, 0], -1.0),
        ([1, 2], 1.0),
        ([2, 0], 1.0),
        ([2, 1], -1.0),
    ];
    let mut total = 0.0;
    for k in 0..n - 1 {
        for j in 0..n - 1 {
            for i in 0..n - 1 {
                let corner =
                    |bits: usize| at(i + (bits & 1), j + ((bits >> 1) & 1), k + (bits >> 2));
                for ([a, b], sign) in orders {
                    let p = [
                        corner(0),
                        corner(1 << a),
                        corner((1 << a) | (1 << b)),
                        corner(7),
                    ];
                    let e = |m: usize| [p[m][0] - p[0][0], p[m][1] - p[0][1], p[m][2] - p[0][2]];
                    let (e1, e2, e3) = (e(1), e(2), e(3));
                    let cross = [
                        e2[1] * e3[2] - e2[2] * e3[1],
                        e2[2] * e3[0] - e2[0] * e3[2],
                        e2[0] * e3[1] - e2[1] * e3[0],
                    ];
                    total += sign * (e1[0] * cross[0] + e1[1] * cross[1] + e1[2] * cross[2]) / 6.0;
                }
            }
        }
    }
    total
}

/// A soft XPBD jelly (edges of compliance 10⁻² m/N) resting on the ground keeps its volume
/// within 1% with incompressible tetrahedra, and sags by more without them.
#[test]
fn volume_constraints_keep_a_soft_jelly_incompressible() {
    let n = 4;
    let volume_after = |volume_compliance: Option<Fx>| {
        let mut cube = fixstep_scenes::soft::body(
            SoftShape::Lattice {
                origin: Vec3::new(Fx::ZERO, Fx::from_ratio(1, 100), Fx::ZERO),
                spacing: Fx::from_ratio(1, 10),
                count: (n as u32, n as u32, n as u32),
            },
            SoftModel::Xpbd {
                stretch_compliance: Fx::from_ratio(1, 100),
                bend_compliance: None,
                volume_compliance,
                tethers: false,
            },
            Fx::ONE,
        );
        cube.damping = Fx::TWO;
        let soft = SoftDesc {
            bodies: vec![cube],
            colliders: vec![fixstep::soft::ColliderDesc {
                shape: fixstep::rigid::Shape::Plane {
                    normal: Vec3::Y,
                    offset: Fx::ZERO,
                },
                position: Vec3::ZERO,
                orientation: fixstep::math::Quat::IDENTITY,
                friction: Fx::ONE,
            }],
            solver: XpbdSettings::default(),
        };
        let mut world = scene_with(soft, 60).build().unwrap();
        run(&mut world, 180);
        assert_eq!(world.saturations_total(), 0);
        lattice_volume(world.soft().unwrap().positions(), n)
    };
    let rest = 0.3f64.powi(3);
    let kept = volume_after(Some(Fx::ZERO));
    let free = volume_after(None);
    assert!(
        (kept - rest).abs() < 0.01 * rest,
        "with volume constraints: {kept:.6} m³ against {rest:.6} m³"
    );
    assert!(
        (free - rest).abs() > (kept - rest).abs(),
        "without: {free:.6} m³, with: {kept:.6} m³, rest {rest:.6} m³"
    );
}
