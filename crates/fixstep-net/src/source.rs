//! Where a peer's own inputs come from: the bot, or a script read from a file.

use std::path::Path;

use fixstep::types::{MAX_INPUT_FILE_LEN, read_input_file};
use serde::{Deserialize, Serialize};

use super::bot::Bot;
use super::input::NetInput;

/// One scripted input: what the player does at `tick`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ScriptedInput {
    /// The tick the input applies at.
    pub tick: u64,
    /// The input.
    pub input: NetInput,
}

/// The source of a peer's inputs; both are pure functions of the tick, as rollback needs.
#[derive(Clone, Debug)]
pub enum InputSource {
    /// The deterministic bot.
    Bot(Bot),
    /// Inputs from a file, in ascending tick order; idle on ticks it does not list.
    Script(Vec<ScriptedInput>),
}

impl InputSource {
    /// Player `player`'s input for `tick`.
    pub fn input(&self, player: u8, tick: u64) -> NetInput {
        match self {
            Self::Bot(bot) => bot.input(player, tick),
            Self::Script(script) => script
                .binary_search_by_key(&tick, |s| s.tick)
                .map(|i| script[i].input)
                .unwrap_or_default(),
        }
    }
}

/// Reads a RON list of [`ScriptedInput`]s (a regular file of at most [`MAX_INPUT_FILE_LEN`]
/// bytes), such as
/// `[(tick: 30, input: (action: ImpulseBody, target: 3, impulse: (0, 160, 0)))]`; ticks must
/// increase.
pub fn read_script(path: &Path) -> Result<Vec<ScriptedInput>, String> {
    let bytes = read_input_file(path, MAX_INPUT_FILE_LEN, "a script file")
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let text = String::from_utf8(bytes).map_err(|e| {
        format!(
            "{}: byte offset {}: not valid UTF-8 text",
            path.display(),
            e.utf8_error().valid_up_to()
        )
    })?;
    let script: Vec<ScriptedInput> =
        ron::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?;
    for (i, pair) in script.windows(2).enumerate() {
        if pair[1].tick <= pair[0].tick {
            return Err(format!(
                "{}: [{}].tick: ticks must increase (got {} after {})",
                path.display(),
                i + 1,
                pair[1].tick,
                pair[0].tick
            ));
        }
    }
    Ok(script)
}
