//! fixstep's built-in scenes, addressable by name: the samples a new user runs first, kept
//! apart from the engine as Box2D keeps its samples apart from its library.
//!
//! [`builtin_scene`] builds one by name; [`BUILTIN_SCENES`] lists them. The modules hold the
//! pieces the scenes are made of, per subsystem, for tests and benchmarks to reuse.

pub mod bridge_particles;
pub mod bullets;
pub mod debris;
pub mod flag;
pub mod fluid;
pub mod game;
pub mod harbour;
pub mod joints;
pub mod parkour;
pub mod particles;
pub mod pond;
pub mod rigid;
pub mod soft;
pub mod swings;
pub mod terrain;

use fixstep::fluid::FluidSolver;
use fixstep::math::Real;
use fixstep::scene::Scene;

/// Name and one-line description of every built-in scene, in listing order.
pub const BUILTIN_SCENES: [(&str, &str); 33] = [
    (
        "showcase",
        "everything fixstep simulates so far: emitters, springs, damping, rigid bodies stacking, bouncing and tumbling, a chain swinging, a motorised door, a cloth swinging and a water column collapsing",
    ),
    (
        "fountain",
        "emitters spraying particles up against gravity and quadratic drag",
    ),
    (
        "orbits",
        "bodies on Kepler-like orbits around a softened point mass",
    ),
    (
        "pyramid",
        "210 unit boxes in a pyramid of base 20 on the ground, standing and falling asleep",
    ),
    ("stack", "10 unit boxes stacked on the ground"),
    (
        "shooter",
        "a player fires spawned projectiles, on their own layer, at a wall of boxes; a sensor plate counts arrivals; the aim is a ray query",
    ),
    (
        "parkour",
        "three scripted kinematic characters: one climbs stairs, jumps a gap and is stopped by a slope too steep to climb, where a third walks into it and slides round it and a thrown ball bounces off it; the second pushes crates and rides a moving platform",
    ),
    (
        "bullets",
        "fast steel balls at a thin static wall, and bullets at a stack of boxes: continuous collision keeps them from passing through",
    ),
    (
        "terrain",
        "boxes, balls, cylinders and rocks tumble down a heightfield hill into a triangle-mesh bowl",
    ),
    (
        "debris",
        "an emitter sprays pellets at a stack of crates beside a ledge: the pellets bounce off every body and push the crates until the stack falls",
    ),
    (
        "flag",
        "a flag tied to the pole of a turning carousel sweeps into a crate swinging on a rope: cloth and rope push and are pushed by rigid bodies",
    ),
    (
        "harbour",
        "a turning paddle makes waves in a water tank: boxes and balls float and bob, a heavy crate sinks; the water pushes and is pushed by rigid bodies",
    ),
    (
        "pond",
        "height-field water: drops make rings that spread and bounce off the banks; corks, boxes and balls float and bob on them, a crate sinks",
    ),
    (
        "balls",
        "4096 balls dropped in a 16x16x16 lattice into an open box of 5 static boxes",
    ),
    (
        "falling",
        "1000 balls falling freely, with nothing to hit: the cost of integration alone",
    ),
    (
        "cradle",
        "Newton's cradle: a ball strikes a row of five elastic balls and the last one leaves",
    ),
    (
        "cradle_touching",
        "Newton's cradle with the five balls touching: the impulse passes through the row and the last ball leaves",
    ),
    (
        "incline",
        "blocks on 30 degree slopes: one slides at mu = 0.3, one sticks at mu = 0.6",
    ),
    (
        "spinner",
        "a box spun about its intermediate axis flips over and over (Dzhanibekov effect)",
    ),
    (
        "chain",
        "a chain of 20 capsule links on ball joints, hung from a fixed point and released horizontal",
    ),
    (
        "bridge",
        "a bridge of 20 hinged planks between two pillars, with six boxes dropped on it",
    ),
    (
        "ragdolls",
        "four ragdolls (capsules on cone-twist and hinge joints with limits) tumbling down stairs",
    ),
    (
        "top",
        "a heavy top on a ball joint, spinning at 60 rad/s and precessing steadily at 30 degrees of tilt",
    ),
    (
        "wrecking_ball",
        "a 4 t steel ball on a rope of six rods swings from 60 degrees into a wall of 12 boxes",
    ),
    (
        "falling_hinges",
        "Box2D's determinism scene in 3D: 4 towers of 30 boxes on limited, sprung hinges falling over",
    ),
    (
        "dam_break",
        "Martin & Moyce's collapsing water column (a = 57 mm, height 2a), 5 particles across a, in a thin 3D slab, DFSPH",
    ),
    (
        "tank",
        "125 particles of water at rest in a 10 cm cube, DFSPH",
    ),
    (
        "pour",
        "a jet of 216 water particles poured into an empty box, DFSPH",
    ),
    (
        "cloth",
        "a 32x32 inextensible XPBD cloth pinned at two corners, falling and swinging",
    ),
    (
        "curtain",
        "a 32x32 cloth blown by wind, its top edge slid to and fro on a rail by inputs",
    ),
    ("rope", "a 20-link XPBD rope pendulum released horizontal"),
    (
        "bridge_particles",
        "a mass-aggregate rope bridge: rails of particles joined by cables, planks of rods, walked across by a heavy particle resting on it through particle contacts",
    ),
    (
        "jelly",
        "a 6x6x6 spring-mass cube dropped on the ground, wobbling",
    ),
];

/// The built-in scene called `name`.
pub fn builtin_scene<R: Real>(name: &str) -> Option<Scene<R>> {
    let (name, description) = BUILTIN_SCENES.iter().find(|(n, _)| *n == name)?;
    let mut scene = Scene::empty(name);
    scene.description = (*description).to_owned();
    scene.seed = 0x5eed;
    match *name {
        "showcase" => {
            scene.particles = Some(particles::showcase_particles());
            let mut bodies = rigid::showcase();
            let (jointed, showcase_joints) = joints::showcase(bodies.body_count());
            bodies.bodies.extend(jointed);
            scene.rigid = Some(bodies);
            scene.joints = Some(showcase_joints);
            scene.soft = Some(soft::showcase());
            scene.fluid = Some(fluid::showcase());
            scene.ticks = 600;
        }
        "fountain" => {
            scene.particles = Some(particles::fountain());
            scene.ticks = 600;
        }
        "orbits" => {
            scene.gravity = fixstep::math::Vec3::ZERO;
            scene.particles = Some(particles::orbits());
            scene.ticks = 1200;
        }
        "pyramid" => {
            scene.rigid = Some(rigid::pyramid(20));
            scene.ticks = 1000;
        }
        "stack" => {
            scene.rigid = Some(rigid::stack(10));
            scene.ticks = 420;
        }
        "shooter" => {
            scene.rigid = Some(game::shooter());
            scene.script = game::shooter_script();
            scene.ticks = 600;
        }
        "parkour" => {
            scene.rigid = Some(parkour::parkour_bodies());
            scene.characters = parkour::parkour_characters();
            scene.script = parkour::parkour_script();
            scene.ticks = 420;
        }
        "bullets" => {
            scene.rigid = Some(bullets::bullets());
            scene.ticks = 240;
        }
        "terrain" => {
            scene.rigid = Some(terrain::terrain());
            scene.ticks = 600;
        }
        "debris" => {
            scene.rigid = Some(debris::debris_bodies());
            scene.particles = Some(debris::debris_pellets());
            scene.ticks = 480;
        }
        "flag" => {
            scene.rigid = Some(flag::flag_bodies());
            scene.soft = Some(flag::flag_cloth());
            scene.ticks = 600;
        }
        "harbour" => {
            scene.rigid = Some(harbour::harbour_bodies());
            scene.fluid = Some(harbour::harbour_water());
            scene.ticks = 180;
        }
        "pond" => {
            scene.water_surface = Some(pond::pond_water());
            scene.particles = Some(pond::pond_corks());
            scene.rigid = Some(pond::pond_bodies());
            scene.script = pond::pond_script();
            scene.ticks = 300;
        }
        "balls" => {
            scene.rigid = Some(rigid::balls(16));
            scene.ticks = 500;
        }
        "falling" => {
            scene.rigid = Some(rigid::falling(1000));
            scene.ticks = 1000;
        }
        "cradle" => {
            scene.gravity = fixstep::math::Vec3::ZERO;
            scene.rigid = Some(rigid::cradle());
            scene.ticks = 180;
        }
        "cradle_touching" => {
            scene.gravity = fixstep::math::Vec3::ZERO;
            scene.rigid = Some(rigid::cradle_touching());
            scene.ticks = 120;
        }
        "incline" => {
            scene.rigid = Some(rigid::incline());
            scene.ticks = 180;
        }
        "spinner" => {
            scene.gravity = fixstep::math::Vec3::ZERO;
            scene.rigid = Some(rigid::spinner());
            scene.ticks = 600;
        }
        "chain" => {
            let (bodies, chain) = joints::chain(20, R::from_int(22));
            (scene.rigid, scene.joints) = (Some(bodies), Some(chain));
            scene.ticks = 600;
        }
        "bridge_particles" => {
            scene.particles = Some(bridge_particles::bridge_particles());
            scene.script = bridge_particles::bridge_particles_script();
            scene.ticks = 360;
        }
        "bridge" => {
            let (bodies, bridge) = joints::bridge(20);
            (scene.rigid, scene.joints) = (Some(bodies), Some(bridge));
            scene.ticks = 600;
        }
        "ragdolls" => {
            let (bodies, dolls) = joints::ragdolls(4);
            (scene.rigid, scene.joints) = (Some(bodies), Some(dolls));
            scene.ticks = 600;
        }
        "top" => {
            let (bodies, top) = swings::top(-scene.gravity.y);
            (scene.rigid, scene.joints) = (Some(bodies), Some(top));
            scene.ticks = 300;
        }
        "wrecking_ball" => {
            let (bodies, rope) = swings::wrecking_ball();
            (scene.rigid, scene.joints) = (Some(bodies), Some(rope));
            scene.ticks = 240;
        }
        "falling_hinges" => {
            let (bodies, hinges) = joints::falling_hinges(4, 30);
            (scene.rigid, scene.joints) = (Some(bodies), Some(hinges));
            scene.ticks = 600;
        }
        "dam_break" => {
            scene.fluid = Some(fluid::dam_break(5, 2, FluidSolver::Dfsph));
            scene.ticks = 12;
        }
        "tank" => {
            scene.fluid = Some(fluid::tank(5, FluidSolver::Dfsph));
            scene.ticks = 30;
        }
        "pour" => {
            scene.fluid = Some(fluid::pour(216));
            scene.ticks = 60;
        }
        "cloth" => {
            scene.soft = Some(soft::cloth(32));
            scene.ticks = 600;
        }
        "curtain" => {
            scene.soft = Some(soft::curtain());
            scene.script = soft::curtain_script();
            scene.ticks = 600;
        }
        "rope" => {
            scene.soft = Some(soft::rope(20));
            scene.ticks = 600;
        }
        "jelly" => {
            scene.soft = Some(soft::jelly());
            scene.substeps = 10;
            scene.ticks = 300;
        }
        _ => return None,
    }
    Some(scene)
}
