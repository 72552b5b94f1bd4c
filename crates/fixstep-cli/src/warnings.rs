//! The warnings `run`, `render` and `verify` print about the world they step, one
//! `warning:` line each on standard error: what building it found (mass ratios, soft-body
//! stability: [`World::warnings`](fixstep::world::World::warnings)) and what running it
//! found ([`Health`]: saturations and where the first happened, capped contacts,
//! divergence).

use super::output::eprint_line;
use fixstep::rigid::broadphase::MAX_PAIRS;
use fixstep::world::{DivergenceScale, Health, Part, SaturationSite};

/// Ticks between two divergence checks (an O(points) energy sum each).
pub const DIVERGENCE_CHECK_EVERY: u64 = 10;

/// Prints each of `lines` as `warning: [ABOUT: ]LINE`; `about` names the input when a
/// command reads several (`verify`).
pub fn print_warnings(about: Option<&str>, lines: impl IntoIterator<Item = String>) {
    for line in warning_lines(about, lines) {
        eprint_line(&line);
    }
}

/// Each of `lines` as `warning: [ABOUT: ]LINE`, the lines [`print_warnings`] prints.
pub fn warning_lines(
    about: Option<&str>,
    lines: impl IntoIterator<Item = String>,
) -> impl Iterator<Item = String> {
    lines.into_iter().map(move |line| match about {
        Some(about) => format!("warning: {about}: {line}"),
        None => format!("warning: {line}"),
    })
}

/// The warnings of a run's health, in the order saturations, capped contacts, divergence;
/// none for a clean run.
pub fn health_warnings(health: &Health) -> Vec<String> {
    let mut lines = Vec::new();
    if let Some(site) = health.first_saturation {
        let later_object = match health.first_saturated_object {
            Some((tick, part, handle)) if tick != site.tick => format!(
                "; {} {handle} reached the range's edge at tick {tick}",
                object_noun(part)
            ),
            _ => String::new(),
        };
        lines.push(format!(
            "{} fixed-point saturations (values hit the numeric range); the first {}{later_object}",
            health.saturations,
            saturation_site(&site)
        ));
    }
    if let Some(tick) = health.first_capped_tick {
        let later = match health.capped_ticks - 1 {
            0 => String::new(),
            1 => " (and 1 later tick)".to_owned(),
            n => format!(" (and {n} later ticks)"),
        };
        lines.push(format!(
            "contacts capped at tick {tick}{later}: more than {MAX_PAIRS} overlapping pairs of \
             bodies; only contacts with static bodies were kept, so bodies may pass through \
             each other"
        ));
    }
    if let Some(d) = health.divergence {
        let growth = match d.scale {
            DivergenceScale::EnergyPerPoint => format!(
                "the energy per point grew from {:.3e} J to {:.3e} J",
                d.reference, d.energy_scale
            ),
            DivergenceScale::RigidEnergyGainPerKilogram => format!(
                "the rigid bodies gained {:.3e} J/kg of energy from a kinetic energy of \
                 {:.3e} J/kg",
                d.energy_scale, d.reference
            ),
        };
        lines.push(format!(
            "the simulation diverged at tick {}: {growth}; the step is too long for the \
             stiffest force, or the integrator is unstable (try more substeps)",
            d.tick
        ));
    }
    lines
}

/// `at tick T (N that tick), in the STAGE stage[, OBJECT at the range's edge]`.
fn saturation_site(site: &SaturationSite) -> String {
    let object = site.object.map_or(String::new(), |(part, handle)| {
        format!(
            ", {} {handle} holding a value at the range's edge",
            object_noun(part)
        )
    });
    format!(
        "at tick {} ({} that tick), in the {} stage{object}",
        site.tick,
        site.count,
        site.stage.name()
    )
}

/// What the objects of `part` are called in a message.
fn object_noun(part: Part) -> &'static str {
    match part {
        Part::Particles => "particle",
        Part::Rigid => "rigid body",
        Part::Soft => "soft-body vertex",
        Part::Fluid => "fluid particle",
        Part::Characters => "character",
        Part::Water => "water cell",
        Part::Core => "object",
    }
}
