//! The values of `fixstep query`'s arguments: which query, its shape, points and
//! directions, distance and mask, checked before anything is simulated.
//!
//! Every error names its argument (`--ray: ...`), so that it is one clear `error:` line.

use super::args::QueryArgs;
use fixstep::math::{Fx, Real, Vec3};
use fixstep::rigid::Shape;

/// The largest coordinate, size or distance a query takes, m: the bound the engine puts
/// on the sizes and positions of a scene's bodies.
pub const MAX_MAGNITUDE: f64 = 100_000.0;

/// How far a ray or a cast travels without `--max`, m.
pub const DEFAULT_MAX_DISTANCE: f64 = 1000.0;

/// The shape kinds, as the messages list them.
const SHAPE_KINDS: &str = "sphere:R, box:HX,HY,HZ or capsule:R,H";

/// What to ask the world.
#[derive(Debug, Clone, PartialEq)]
pub enum QueryKind {
    /// The first body along a ray.
    Ray {
        /// Where the ray starts, m.
        origin: Vec3<Fx>,
        /// Its direction (not zero; any length).
        direction: Vec3<Fx>,
    },
    /// The first body a shape moving in a straight line hits.
    Cast {
        /// The shape (axis-aligned).
        shape: Shape<Fx>,
        /// Where its centre starts, m.
        from: Vec3<Fx>,
        /// The direction it moves in (not zero; any length).
        direction: Vec3<Fx>,
    },
    /// The bodies a shape overlaps.
    Overlap {
        /// The shape (axis-aligned).
        shape: Shape<Fx>,
        /// Where its centre is, m.
        at: Vec3<Fx>,
    },
}

/// A query, read from the arguments.
#[derive(Debug, Clone, PartialEq)]
pub struct QuerySpec {
    /// What to ask.
    pub kind: QueryKind,
    /// How far a ray or a cast travels, m.
    pub max_distance: Fx,
    /// The layers of the bodies the query sees.
    pub mask: u32,
}

impl QuerySpec {
    /// The query `args` describe, or an error naming the argument that is wrong.
    pub fn from_args(args: &QueryArgs) -> Result<Self, String> {
        let given: Vec<&str> = [
            ("--ray", args.ray.is_some()),
            ("--cast", args.cast.is_some()),
            ("--overlap", args.overlap.is_some()),
        ]
        .into_iter()
        .filter_map(|(name, given)| given.then_some(name))
        .collect();
        match given.as_slice() {
            [] => return Err("give a query: --ray, --cast or --overlap".to_owned()),
            [_] => {}
            several => {
                return Err(format!(
                    "{}: give only one of --ray, --cast and --overlap",
                    several.join(" and ")
                ));
            }
        }
        only_with("--from", args.from.is_some(), "--cast", args.cast.is_some())?;
        only_with("--dir", args.dir.is_some(), "--cast", args.cast.is_some())?;
        only_with(
            "--at",
            args.at.is_some(),
            "--overlap",
            args.overlap.is_some(),
        )?;
        if args.max.is_some() && args.overlap.is_some() {
            return Err("--max: only with --ray or --cast (an overlap has no distance)".into());
        }

        let kind = if let Some(ray) = &args.ray {
            let [ox, oy, oz, dx, dy, dz] =
                numbers("--ray", ray, ["OX", "OY", "OZ", "DX", "DY", "DZ"])?;
            QueryKind::Ray {
                origin: Vec3::from_f64(ox, oy, oz),
                direction: direction("--ray", [dx, dy, dz])?,
            }
        } else if let Some(cast) = &args.cast {
            let from = required("--from", "X,Y,Z", args.from.as_deref())?;
            let dir = required("--dir", "DX,DY,DZ", args.dir.as_deref())?;
            QueryKind::Cast {
                shape: shape("--cast", cast)?,
                from: point("--from", from)?,
                direction: direction("--dir", numbers("--dir", dir, ["DX", "DY", "DZ"])?)?,
            }
        } else {
            let overlap = args.overlap.as_deref().unwrap_or_default();
            let at = required("--at", "X,Y,Z", args.at.as_deref())?;
            QueryKind::Overlap {
                shape: shape("--overlap", overlap)?,
                at: point("--at", at)?,
            }
        };
        let max_distance = match &args.max {
            Some(text) => size("--max", "D", number("--max", "D", text)?)?,
            None => Fx::from_f64(DEFAULT_MAX_DISTANCE),
        };
        let mask = args.mask.as_deref().map_or(Ok(u32::MAX), mask)?;
        Ok(Self {
            kind,
            max_distance,
            mask,
        })
    }
}

/// Refuses `name` without `needs`.
fn only_with(name: &str, given: bool, needs: &str, needed: bool) -> Result<(), String> {
    if given && !needed {
        Err(format!("{name}: only with {needs}"))
    } else {
        Ok(())
    }
}

/// The text of an argument that the query needs.
fn required<'a>(name: &str, value: &str, text: Option<&'a str>) -> Result<&'a str, String> {
    text.ok_or_else(|| format!("{name}: missing: this query needs {name} {value}"))
}

/// One number, called `what` in messages: finite and within ±[`MAX_MAGNITUDE`].
fn number(arg: &str, what: &str, text: &str) -> Result<f64, String> {
    let text = text.trim();
    let value: f64 = text
        .parse()
        .map_err(|_| format!("{arg}: {what} `{text}` is not a number"))?;
    if !value.is_finite() {
        return Err(format!("{arg}: {what} `{text}` is not a finite number"));
    }
    if value.abs() > MAX_MAGNITUDE {
        return Err(format!(
            "{arg}: {what} {value} is out of range (at most {MAX_MAGNITUDE} m from 0)"
        ));
    }
    Ok(value)
}

/// `N` comma-separated numbers, called `names` in messages.
fn numbers<const N: usize>(arg: &str, text: &str, names: [&str; N]) -> Result<[f64; N], String> {
    let parts: Vec<&str> = text.split(',').collect();
    if parts.len() != N {
        return Err(format!(
            "{arg}: `{text}` has {} numbers, expected {N}: {}",
            parts.len(),
            names.join(",")
        ));
    }
    let mut values = [0.0; N];
    for ((value, part), name) in values.iter_mut().zip(parts).zip(names) {
        *value = number(arg, name, part)?;
    }
    Ok(values)
}

/// A point `X,Y,Z`, m.
fn point(arg: &str, text: &str) -> Result<Vec3<Fx>, String> {
    let [x, y, z] = numbers(arg, text, ["X", "Y", "Z"])?;
    Ok(Vec3::from_f64(x, y, z))
}

/// A direction of any length but zero (the engine makes it unit length, so distances are
/// in m).
fn direction(arg: &str, [x, y, z]: [f64; 3]) -> Result<Vec3<Fx>, String> {
    let direction = Vec3::from_f64(x, y, z);
    if direction == Vec3::ZERO {
        let why = if [x, y, z] == [0.0; 3] {
            "is zero"
        } else {
            "is too short: it rounds to zero in fixed point"
        };
        return Err(format!("{arg}: the direction ({x}, {y}, {z}) {why}"));
    }
    Ok(direction)
}

/// A size (radius, half extent, distance), m: above 0 in fixed point.
fn size(arg: &str, what: &str, value: f64) -> Result<Fx, String> {
    let fixed = Fx::from_f64(value);
    if fixed <= Fx::ZERO {
        return Err(format!("{arg}: {what} {value} must be above 0"));
    }
    Ok(fixed)
}

/// An axis-aligned shape: `sphere:R`, `box:HX,HY,HZ` or `capsule:R,H` (H the half height
/// of the capsule's segment, along y, 0 or more).
fn shape(arg: &str, text: &str) -> Result<Shape<Fx>, String> {
    let Some((kind, values)) = text.split_once(':') else {
        return Err(format!("{arg}: `{text}` is not a shape: use {SHAPE_KINDS}"));
    };
    match kind.trim() {
        "sphere" => {
            let [r] = numbers(arg, values, ["R"])?;
            Ok(Shape::Sphere {
                radius: size(arg, "R", r)?,
            })
        }
        "box" => {
            let [x, y, z] = numbers(arg, values, ["HX", "HY", "HZ"])?;
            Ok(Shape::Box {
                half_extents: Vec3::new(
                    size(arg, "HX", x)?,
                    size(arg, "HY", y)?,
                    size(arg, "HZ", z)?,
                ),
            })
        }
        "capsule" => {
            let [r, h] = numbers(arg, values, ["R", "H"])?;
            if h < 0.0 {
                return Err(format!("{arg}: H {h} (the half height) must be 0 or more"));
            }
            Ok(Shape::Capsule {
                radius: size(arg, "R", r)?,
                half_height: Fx::from_f64(h),
            })
        }
        other => Err(format!(
            "{arg}: unknown shape kind `{other}`: use {SHAPE_KINDS}"
        )),
    }
}

/// A 32-bit layer mask: decimal, or hexadecimal after `0x`.
fn mask(text: &str) -> Result<u32, String> {
    let trimmed = text.trim();
    let parsed = match trimmed
        .strip_prefix("0x")
        .or_else(|| trimmed.strip_prefix("0X"))
    {
        Some(hex) => u32::from_str_radix(hex, 16),
        None => trimmed.parse(),
    };
    parsed.map_err(|e| {
        format!("--mask: `{text}` is not a mask from 0 to 0xffffffff (decimal or 0x hex): {e}")
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(input: &[&str]) -> Result<QuerySpec, String> {
        use clap::Parser;
        let cli = super::super::args::Cli::try_parse_from(
            ["fixstep", "query", "stack"].iter().chain(input),
        )
        .map_err(|e| e.to_string())?;
        match cli.command {
            Some(super::super::args::Command::Query(args)) => QuerySpec::from_args(&args),
            _ => unreachable!("a query"),
        }
    }

    #[test]
    fn a_ray_and_the_defaults() {
        let spec = args(&["--ray", "1,2,3,0,-2,0"]).expect("valid");
        assert_eq!(
            spec.kind,
            QueryKind::Ray {
                origin: Vec3::from_f64(1.0, 2.0, 3.0),
                direction: Vec3::from_f64(0.0, -2.0, 0.0),
            }
        );
        assert_eq!(spec.max_distance, Fx::from_int(1000));
        assert_eq!(spec.mask, u32::MAX);
    }

    #[test]
    fn shapes_and_masks() {
        let spec = args(&[
            "--cast",
            "capsule:0.5,1",
            "--from",
            "0,5,0",
            "--dir",
            "0,-1,0",
            "--mask",
            "0x10",
            "--max",
            "20",
        ])
        .expect("valid");
        assert_eq!(spec.mask, 16);
        assert_eq!(spec.max_distance, Fx::from_int(20));
        let QueryKind::Cast { shape, .. } = spec.kind else {
            panic!("a cast");
        };
        assert_eq!(
            shape,
            Shape::Capsule {
                radius: Fx::HALF,
                half_height: Fx::ONE
            }
        );
        let spec = args(&["--overlap", "box:1,2,3", "--at", "0,0,0"]).expect("valid");
        assert!(matches!(spec.kind, QueryKind::Overlap { .. }));
    }

    #[test]
    fn errors_name_the_argument() {
        for (input, expected) in [
            (
                &["--ray", "nan,0,0,0,-1,0"][..],
                "--ray: OX `nan` is not a finite number",
            ),
            (
                &["--ray", "0,0,0,0,inf,0"],
                "--ray: DY `inf` is not a finite number",
            ),
            (&["--ray", "0,0,0,0,0,0"], "--ray: the direction"),
            (
                &["--ray", "0,0,0"],
                "--ray: `0,0,0` has 3 numbers, expected 6",
            ),
            (
                &["--ray", "1e9,0,0,0,1,0"],
                "--ray: OX 1000000000 is out of range",
            ),
            (&["--ray", "0,0,0,0,1,0", "--mask", "-1"], "--mask: `-1`"),
            (
                &["--ray", "0,0,0,0,1,0", "--mask", "0x100000000"],
                "--mask:",
            ),
            (
                &["--ray", "0,0,0,0,1,0", "--max", "0"],
                "--max: D 0 must be above 0",
            ),
            (
                &["--cast", "cone:1", "--from", "0,0,0", "--dir", "0,1,0"],
                "--cast: unknown shape kind `cone`",
            ),
            (&["--cast", "sphere:1", "--from", "0,0,0"], "--dir: missing"),
            (
                &["--cast", "sphere:-1", "--from", "0,0,0", "--dir", "0,1,0"],
                "--cast: R -1 must be above 0",
            ),
            (&["--overlap", "sphere:1"], "--at: missing"),
            (
                &["--ray", "0,0,0,0,1,0", "--overlap", "sphere:1"],
                "--ray and --overlap: give only one",
            ),
            (&[], "give a query"),
            (
                &["--ray", "0,0,0,0,1,0", "--dir", "0,1,0"],
                "--dir: only with --cast",
            ),
            (
                &[
                    "--cast", "sphere:1", "--from", "0,0,0", "--dir", "0,1,0", "--at", "0,0,0",
                ],
                "--at: only with --overlap",
            ),
        ] {
            let error = args(input).expect_err(expected);
            assert!(error.starts_with(expected), "{input:?}: {error}");
        }
    }
}
