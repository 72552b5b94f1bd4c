//! Writes the fuzz seeds of the `handshake_decode` target: the handshake messages of a few
//! built-in scenes, from two and three players, saying each of the three [`Heard`]s. Run by
//! `scripts/fuzz.sh seeds` as `cargo run -p fixstep-net --example handshake_seeds -- DIR`.

use std::path::PathBuf;

use fixstep::math::Fx;
use fixstep::replay::scene_id;
use fixstep_net::{Heard, Hello};
use fixstep_scenes::builtin_scene;

/// Scenes whose messages are seeds: particles, rigid bodies, soft bodies, a fluid.
const SCENES: [&str; 4] = ["orbits", "stack", "cloth", "tank"];

fn main() {
    let dir = PathBuf::from(std::env::args().nth(1).expect("usage: handshake_seeds DIR"));
    std::fs::create_dir_all(&dir).expect("create the seed directory");
    for name in SCENES {
        let scene = builtin_scene::<Fx>(name).expect("a built-in scene");
        let hash = scene_id(&scene).expect("the scene encodes").hash;
        for (players, player, heard, tag) in [
            (2, 0, Heard::Nothing, "2-0-nothing"),
            (2, 1, Heard::You, "2-1-you"),
            (3, 2, Heard::Answer, "3-2-answer"),
        ] {
            let hello = Hello::new(hash, players, player, heard, name);
            std::fs::write(dir.join(format!("{name}-{tag}")), hello.encode())
                .expect("write a seed");
        }
    }
}
