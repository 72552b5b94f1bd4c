//! The command line, as clap sees it. This interface is a contract: scripts and tests use it.

#[cfg(feature = "net")]
use std::net::SocketAddr;
use std::path::PathBuf;

#[cfg(feature = "net")]
use clap::builder::TypedValueParser as _;
use clap::{Args, Parser, Subcommand};

use super::count_arg::Count;
use fixstep_viewer::View;

/// Deterministic fixed-point physics: run scenes, record and verify replays.
///
/// With no command, runs the showcase scene.
#[derive(Debug, Parser)]
#[command(name = "fixstep", version)]
pub struct Cli {
    /// What to do (default: `run showcase`).
    #[command(subcommand)]
    pub command: Option<Command>,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// List the built-in scenes.
    Scenes,
    /// Run a scene, print stage timings and the final checksum.
    Run(RunArgs),
    /// Simulate replays again and compare every checkpoint (exit 1 on a desync, 2 on a bad
    /// file).
    Verify {
        /// Replay files.
        #[arg(required = true, value_name = "FILE.replay")]
        files: Vec<PathBuf>,
        /// Threads: 0 for every core (default: `FIXSTEP_THREADS`, else 1). With two or
        /// more, the files are verified side by side, their lines printed in argument order.
        #[arg(long, value_name = "N", value_parser = fixstep::parallel::parse_threads)]
        threads: Option<usize>,
    },
    /// Describe a replay: header, scene, ticks, checkpoints.
    Info {
        /// A replay file.
        #[arg(value_name = "FILE.replay")]
        file: PathBuf,
    },
    /// Record replays again with this build (after a deliberate change to the physics).
    Rerecord {
        /// Replay files, rewritten in place.
        #[arg(required = true, value_name = "FILE.replay")]
        files: Vec<PathBuf>,
    },
    /// Draw a replay or a scene: PNG frames, an animated GIF and an interactive
    /// DIR/index.html player.
    Render(RenderArgs),
    /// Simulate a scene or a replay to a tick and ask the world a question: the first body
    /// a ray or a moving shape hits, or the bodies a shape overlaps; one JSON object a line.
    ///
    /// A hit is `{"body":"3v0","distance":D,"point":[X,Y,Z],"normal":[X,Y,Z]}` (m, the
    /// normal out of the body hit), a miss `{"hit":false}`. SHAPE is `sphere:R`,
    /// `box:HX,HY,HZ` (half extents) or `capsule:R,H` (H the half height of its segment,
    /// along y), axis-aligned, in m.
    Query(QueryArgs),
    /// Play a scene with other peers over UDP (GGRS), headless, with bot or scripted inputs:
    /// prints `checksum: <hex>` last on success, exits 1 on a desync.
    #[cfg(feature = "net")]
    Peer(PeerArgs),
    /// Measure the integrators: accuracy against exact solutions, and stability limits.
    Bench {
        /// Which benchmark.
        #[command(subcommand)]
        benchmark: BenchCommand,
    },
}

/// The benchmarks of `fixstep bench`.
#[derive(Debug, Subcommand)]
pub enum BenchCommand {
    /// Error and time of five problems × seven integrators × four formats × a step sweep:
    /// writes DIR/accuracy.csv and DIR/work-precision.svg, prints the measured orders.
    Accuracy {
        /// Output directory (created if missing).
        #[arg(long, value_name = "DIR", default_value = "bench-out")]
        out: PathBuf,
        /// Fewer halvings of the step and one run per point (seconds instead of a minute).
        #[arg(long)]
        quick: bool,
    },
    /// Largest stable ωh of each integrator on the undamped and damped spring, against
    /// theory: writes DIR/stability.csv and prints the table.
    Stability {
        /// Output directory (created if missing).
        #[arg(long, value_name = "DIR", default_value = "bench-out")]
        out: PathBuf,
    },
    /// Implicit against semi-implicit Euler on a stiff 64×64 spring-mass cloth, each at the
    /// largest stable step it takes: prints the steps and the time per simulated second.
    Cloth,
}

/// Arguments of `fixstep run`.
#[derive(Debug, Args)]
pub struct RunArgs {
    /// A built-in scene name (see `fixstep scenes`) or a RON scene file.
    #[arg(value_name = "SCENE|FILE.ron", default_value = "showcase")]
    pub scene: String,
    /// Ticks to run (default: the scene's `ticks`).
    #[arg(long, value_name = "N", allow_negative_numbers = true,
          value_parser = Count::at_least("--ticks", 1))]
    pub ticks: Option<u64>,
    /// Seed of the world's generator, decimal or 0x-prefixed hex (default: the scene's).
    #[arg(long, value_name = "S", value_parser = parse_seed)]
    pub seed: Option<u64>,
    /// Write a replay of the run to this file.
    #[arg(long, value_name = "OUT.replay")]
    pub record: Option<PathBuf>,
    /// Write metrics as CSV to this file.
    #[arg(long, value_name = "OUT.csv")]
    pub metrics: Option<PathBuf>,
    /// Write the rigid bodies' state as CSV to this file:
    /// `tick,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz`, one row per live body in slot order
    /// (centre of mass in m, orientation, velocities in the world frame).
    #[arg(long, value_name = "OUT.csv")]
    pub bodies: Option<PathBuf>,
    /// Write every event of every tick as CSV to this file: `tick,event,a,b`
    /// (contact_begin, contact_end, sensor_enter, sensor_exit, joint_break; b is empty for
    /// joint_break, whose a is the joint).
    #[arg(long, value_name = "OUT.csv")]
    pub events: Option<PathBuf>,
    /// Write the --metrics and --bodies rows every K ticks (from tick 0, and after the last
    /// tick).
    #[arg(long, value_name = "K", default_value_t = 1, allow_negative_numbers = true,
          value_parser = Count::at_least("--every", 1))]
    pub every: u64,
    /// Save the world's final state as a snapshot file.
    #[arg(long, value_name = "OUT.snapshot")]
    pub snapshot: Option<PathBuf>,
    /// Continue from a snapshot of this scene instead of its first tick: the scene supplies
    /// the script (from the snapshot's tick on) and user forces, the snapshot the state.
    #[arg(long, value_name = "IN.snapshot", conflicts_with = "record")]
    pub from_snapshot: Option<PathBuf>,
    /// Threads to step on: 0 for every core (default: `FIXSTEP_THREADS`, else 1); the
    /// results are the same at any count.
    #[arg(long, value_name = "N", value_parser = fixstep::parallel::parse_threads)]
    pub threads: Option<usize>,
}

impl Default for RunArgs {
    /// `fixstep run showcase`.
    fn default() -> Self {
        Self {
            scene: "showcase".to_owned(),
            ticks: None,
            seed: None,
            record: None,
            metrics: None,
            bodies: None,
            events: None,
            every: 1,
            snapshot: None,
            from_snapshot: None,
            threads: None,
        }
    }
}

/// Arguments of `fixstep render`.
#[derive(Debug, Args)]
pub struct RenderArgs {
    /// A replay file (re-simulated with its inputs), a built-in scene name or a RON scene
    /// file (run with its script).
    #[arg(value_name = "REPLAY|SCENE")]
    pub input: String,
    /// Ticks to simulate (default: the replay's ticks, or the scene's `ticks`).
    #[arg(long, value_name = "N", allow_negative_numbers = true,
          value_parser = Count::at_least("--ticks", 1))]
    pub ticks: Option<u64>,
    /// Output directory (created if missing).
    #[arg(long, value_name = "DIR", default_value = "render-out")]
    pub out: PathBuf,
    /// Draw a frame every K ticks (and after the last tick).
    #[arg(long, value_name = "K", default_value_t = 1, allow_negative_numbers = true,
          value_parser = Count::at_least("--every", 1))]
    pub every: u64,
    /// The view of the pictures and the GIF, and the player's first view.
    #[arg(long, value_name = "iso|front|top", default_value = "iso", value_parser = parse_view)]
    pub view: View,
    /// Picture size in pixels, WIDTHxHEIGHT (each 16 to 4096).
    #[arg(long, value_name = "WxH", default_value = "640x480", value_parser = parse_size)]
    pub size: (u32, u32),
    /// One flat colour per body, no shading, outlines or anti-aliasing (to count bodies).
    #[arg(long)]
    pub flat: bool,
    /// Threads to step on: 0 for every core (default: `FIXSTEP_THREADS`, else 1); the
    /// results are the same at any count.
    #[arg(long, value_name = "N", value_parser = fixstep::parallel::parse_threads)]
    pub threads: Option<usize>,
    /// Instead of pictures, write the live 3D player (the page of `scripts/web.sh`, in
    /// WebAssembly) playing the run, as one page PAGE.html: a replay's bytes, or a scene's
    /// run recorded, embedded in it. It loads the player from --web.
    #[arg(long, value_name = "PAGE.html",
          conflicts_with_all = ["out", "every", "view", "size", "flat"])]
    pub html: Option<PathBuf>,
    /// With --html: the address of the live page's folder, ending in `/` (default
    /// `http://127.0.0.1:8000/`, where `scripts/web.sh` serves it).
    #[arg(long, value_name = "URL", requires = "html")]
    pub web: Option<String>,
}

/// Arguments of `fixstep query`. The query's values are text here and parsed by
/// [`crate::query_spec`], so that a bad one is one `error: --ARG: ...` line.
///
/// Give exactly one of `--ray`, `--cast` (with `--from` and `--dir`) and `--overlap` (with
/// `--at`). Shapes are axis-aligned: `sphere:R`, `box:HX,HY,HZ` (half extents) or
/// `capsule:R,H` (H the half height of its segment, along y); lengths in m.
#[derive(Debug, Args)]
pub struct QueryArgs {
    /// A built-in scene name, a RON scene file (run with its script) or a replay file
    /// (run with its recorded inputs).
    #[arg(value_name = "SCENE|FILE.ron|FILE.replay")]
    pub input: String,
    /// Simulate this many ticks before the query.
    #[arg(long, value_name = "N", default_value_t = 0, allow_negative_numbers = true,
          value_parser = Count::at_least("--tick", 0))]
    pub tick: u64,
    /// Cast a ray from (OX,OY,OZ) along (DX,DY,DZ) (any length but zero): prints the first
    /// hit, or `{"hit":false}`.
    #[arg(long, value_name = "OX,OY,OZ,DX,DY,DZ", allow_hyphen_values = true)]
    pub ray: Option<String>,
    /// Sweep a shape (sphere:R, box:HX,HY,HZ or capsule:R,H) from --from along --dir:
    /// prints the first hit, or `{"hit":false}`.
    #[arg(long, value_name = "SHAPE", allow_hyphen_values = true)]
    pub cast: Option<String>,
    /// Where a --cast shape starts (its centre).
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
    pub from: Option<String>,
    /// The direction a --cast shape moves in (any length but zero).
    #[arg(long, value_name = "DX,DY,DZ", allow_hyphen_values = true)]
    pub dir: Option<String>,
    /// Find the bodies a shape (sphere:R, box:HX,HY,HZ or capsule:R,H) placed at --at
    /// overlaps: prints `{"body":"3v0"}` for each, in ascending order.
    #[arg(long, value_name = "SHAPE", allow_hyphen_values = true)]
    pub overlap: Option<String>,
    /// Where an --overlap shape is (its centre).
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
    pub at: Option<String>,
    /// The longest distance a ray or a cast travels, m (default 1000).
    #[arg(long, value_name = "D", allow_hyphen_values = true)]
    pub max: Option<String>,
    /// Only bodies on one of these layers, a 32-bit mask in decimal or 0x hex (default: all).
    #[arg(long, value_name = "M", allow_hyphen_values = true)]
    pub mask: Option<String>,
}

/// A view name.
fn parse_view(text: &str) -> Result<View, String> {
    View::from_name(text).ok_or_else(|| format!("`{text}` is not a view: use iso, front or top"))
}

/// Smallest and largest picture side, px.
const SIDE: core::ops::RangeInclusive<u32> = 16..=4096;

/// A picture size `WxH`.
fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let bad = |why: &str| format!("`{text}` is not a picture size WIDTHxHEIGHT: {why}");
    let (w, h) = text
        .split_once(['x', 'X'])
        .ok_or_else(|| bad("no `x` between width and height"))?;
    let side = |part: &str, name: &str| -> Result<u32, String> {
        let value: u32 = part
            .trim()
            .parse()
            .map_err(|e| bad(&format!("the {name} `{part}` is not a whole number ({e})")))?;
        if SIDE.contains(&value) {
            Ok(value)
        } else {
            Err(bad(&format!(
                "the {name} {value} is outside {} to {} pixels",
                SIDE.start(),
                SIDE.end()
            )))
        }
    };
    Ok((side(w, "width")?, side(h, "height")?))
}

/// Arguments of `fixstep peer`.
#[cfg(feature = "net")]
#[derive(Debug, Args)]
pub struct PeerArgs {
    /// Local UDP port (0: any free port).
    #[arg(long, value_name = "P")]
    pub local_port: u16,
    /// A remote peer, HOST:PORT; give one per other player, in ascending player index.
    #[arg(long = "remote", value_name = "ADDR", required = true, value_parser = parse_address)]
    pub remotes: Vec<SocketAddr>,
    /// This peer's player index (the remotes take the other indices, in order).
    #[arg(long, value_name = "I", default_value_t = 0)]
    pub player_index: usize,
    /// A built-in scene name or a RON scene file; every peer must run the same.
    #[arg(long, value_name = "S", default_value = "showcase")]
    pub scene: String,
    /// Ticks to run (default: the scene's `ticks`).
    #[arg(long, value_name = "T", allow_negative_numbers = true,
          value_parser = Count::at_least("--ticks", 1))]
    pub ticks: Option<u64>,
    /// Lockstep: every tick waits for every peer's input (the default).
    #[arg(long, conflicts_with = "rollback")]
    pub lockstep: bool,
    /// Rollback: run ahead on predicted inputs, roll back on a misprediction.
    #[arg(long)]
    pub rollback: bool,
    /// Write the replay of the session (its confirmed inputs) to this file.
    #[arg(long, value_name = "OUT.replay")]
    pub record: Option<PathBuf>,
    /// Seed of the deterministic bot that plays for this peer (default: the player index).
    #[arg(long, value_name = "SEED", value_parser = parse_seed)]
    pub bot: Option<u64>,
    /// Play the inputs of this RON file instead of the bot: a list of
    /// `(tick: T, input: (action: ImpulseBody, target: 3, impulse: (0, 160, 0)))`.
    #[arg(long, value_name = "FILE.ron", conflicts_with = "bot")]
    pub inputs: Option<PathBuf>,
    /// Ticks between two desync checks.
    #[arg(long, value_name = "N", default_value_t = 10, allow_negative_numbers = true,
          value_parser = Count::within("--desync-every", 1, u64::from(u32::MAX))
              .map(|n| u32::try_from(n).unwrap_or(u32::MAX)))]
    pub desync_every: u32,
    /// Give up after this many seconds (synchronisation included).
    #[arg(long, value_name = "SECONDS", default_value_t = 60,
          value_parser = clap::value_parser!(u64).range(1..=86_400))]
    pub timeout: u64,
    /// Testing desync detection: once this peer has run TICK ticks, move a body by one ulp.
    #[arg(long, value_name = "TICK", hide = true)]
    pub nudge_at: Option<u64>,
    /// Threads to step on: 0 for every core (default: `FIXSTEP_THREADS`, else 1); the
    /// results are the same at any count.
    #[arg(long, value_name = "N", value_parser = fixstep::parallel::parse_threads)]
    pub threads: Option<usize>,
}

/// A peer address: `HOST:PORT`, resolved (the first address the name resolves to).
#[cfg(feature = "net")]
fn parse_address(text: &str) -> Result<SocketAddr, String> {
    use std::net::ToSocketAddrs;
    text.to_socket_addrs()
        .map_err(|e| format!("`{text}` is not a HOST:PORT address: {e}"))?
        .next()
        .ok_or_else(|| format!("`{text}` resolves to no address"))
}

/// A seed: decimal, or hexadecimal after `0x`.
fn parse_seed(text: &str) -> Result<u64, String> {
    let parsed = match text.strip_prefix("0x").or_else(|| text.strip_prefix("0X")) {
        Some(hex) => u64::from_str_radix(hex, 16),
        None => text.parse(),
    };
    parsed.map_err(|e| format!("`{text}` is not a 64-bit seed: {e}"))
}
