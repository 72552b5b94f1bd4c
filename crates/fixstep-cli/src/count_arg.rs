//! Count arguments (`--ticks N`, `--every K`, …): a whole number in a range, and for
//! anything else one message that says what the option takes, `` `--ticks` takes a count
//! ≥ 1, not `-1` `` (negative numbers reach this parser instead of being read as options).

use std::ffi::OsStr;

use clap::builder::TypedValueParser;
use clap::error::ErrorKind;

/// The parser of a count option.
#[derive(Clone, Copy, Debug)]
pub struct Count {
    /// The option's name with its dashes, for the message.
    option: &'static str,
    /// The smallest count taken.
    min: u64,
    /// The largest count taken.
    max: u64,
}

impl Count {
    /// A count of at least `min` for `option`.
    pub const fn at_least(option: &'static str, min: u64) -> Self {
        Self {
            option,
            min,
            max: u64::MAX,
        }
    }

    /// A count from `min` to `max` for `option`.
    pub const fn within(option: &'static str, min: u64, max: u64) -> Self {
        Self { option, min, max }
    }

    /// What the option takes: `a count ≥ 1`, `a count from 1 to 60`.
    fn takes(&self) -> String {
        if self.max == u64::MAX {
            format!("a count ≥ {}", self.min)
        } else {
            format!("a count from {} to {}", self.min, self.max)
        }
    }
}

impl TypedValueParser for Count {
    type Value = u64;

    fn parse_ref(
        &self,
        _command: &clap::Command,
        _arg: Option<&clap::Arg>,
        value: &OsStr,
    ) -> Result<u64, clap::Error> {
        let text = value.to_string_lossy();
        match text.trim().parse::<u64>() {
            Ok(count) if (self.min..=self.max).contains(&count) => Ok(count),
            _ => Err(clap::Error::raw(
                ErrorKind::ValueValidation,
                format!("`{}` takes {}, not `{text}`\n", self.option, self.takes()),
            )),
        }
    }
}
