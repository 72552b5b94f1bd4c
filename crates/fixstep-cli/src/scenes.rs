//! `fixstep scenes`: the built-in scenes, one per line, `NAME  description`.

use super::output::print_line;
use super::status::Status;
use fixstep_scenes::BUILTIN_SCENES;

/// Lists the built-in scenes.
pub fn scenes() -> Result<Status, String> {
    for (name, description) in BUILTIN_SCENES {
        print_line(&format!("{name}  {description}"))?;
    }
    Ok(Status::Ok)
}
