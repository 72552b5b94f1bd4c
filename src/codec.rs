//! The one binary encoding of fixstep: replay files and snapshots.
//!
//! bincode 2.0.1 with its serde bridge, little-endian fixed-width integers (every `u64` is 8
//! bytes, every length a `u64`), and a size limit. Fixed-width encoding is canonical: each
//! value has exactly one encoding, unlike bincode's default varints. A string or byte
//! length larger than the limit is refused before anything is allocated; a sequence length
//! is not checked against the limit on bincode's serde path, but serde preallocates at most
//! 1 MiB per sequence and decoding then runs out of bytes, so memory stays bounded (the
//! malformed-replay tests cover 2^60 lengths). Switching encodings later is a change to this
//! file alone.

use core::fmt;

use bincode::config::{Configuration, Fixint, Limit, LittleEndian};
use serde::Serialize;
use serde::de::DeserializeOwned;

/// The largest encoded value accepted or produced: 256 MiB.
pub const SIZE_LIMIT: usize = 256 << 20;

type Config = Configuration<LittleEndian, Fixint, Limit<SIZE_LIMIT>>;

fn config() -> Config {
    bincode::config::standard()
        .with_little_endian()
        .with_fixed_int_encoding()
        .with_limit::<SIZE_LIMIT>()
}

/// Why bytes could not be encoded or decoded.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CodecError(pub String);

impl fmt::Display for CodecError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for CodecError {}

/// Encodes `value` canonically.
pub fn encode<T: Serialize + ?Sized>(value: &T) -> Result<Vec<u8>, CodecError> {
    bincode::serde::encode_to_vec(value, config()).map_err(|e| CodecError(e.to_string()))
}

/// Decodes one value from the start of `bytes`; returns it with the number of bytes used.
pub fn decode_prefix<T: DeserializeOwned>(bytes: &[u8]) -> Result<(T, usize), CodecError> {
    bincode::serde::decode_from_slice(bytes, config()).map_err(|e| CodecError(describe(e)))
}

/// Decodes a value that must use exactly all of `bytes`.
pub fn decode_exact<T: DeserializeOwned>(bytes: &[u8]) -> Result<T, CodecError> {
    let (value, used) = decode_prefix(bytes)?;
    if used != bytes.len() {
        return Err(CodecError(format!(
            "{} unexpected bytes after the end of the value",
            bytes.len() - used
        )));
    }
    Ok(value)
}

/// A short, user-facing description of a decode failure.
fn describe(error: bincode::error::DecodeError) -> String {
    use bincode::error::DecodeError as E;
    match error {
        E::UnexpectedEnd { additional } => {
            format!("truncated: {additional} more bytes needed")
        }
        E::LimitExceeded => format!("a length field exceeds the {SIZE_LIMIT}-byte limit"),
        E::UnexpectedVariant {
            found, type_name, ..
        } => {
            format!("invalid variant {found} for {type_name}")
        }
        E::Utf8 { .. } => "a string is not valid UTF-8".to_owned(),
        E::InvalidBooleanValue(v) => format!("invalid boolean byte {v}"),
        E::OutsideUsizeRange(v) => format!("length {v} is out of range"),
        E::InvalidCharEncoding(bytes) => format!("invalid character bytes {bytes:02x?}"),
        E::ArrayLengthMismatch { required, found } => {
            format!("an array of {found} elements where {required} are required")
        }
        E::EmptyEnum { type_name } => format!("{type_name} has no variants to decode"),
        E::Other(text) => text.to_owned(),
        E::OtherString(text) => readable_serde_error(&text),
        other => format!("not a valid encoding ({other:?})"),
    }
}

/// serde's message for a value out of range, with the wording of the other decode errors:
/// "invalid value: integer `1200`, expected variant index 0 <= i < 7" becomes "invalid
/// variant index 1200 (expected 0 to 6)". Other messages are already plain text (they
/// come from serde or from the engine's own checks) and are kept.
fn readable_serde_error(text: &str) -> String {
    let variant = text
        .strip_prefix("invalid value: integer `")
        .and_then(|rest| rest.split_once("`, expected variant index 0 <= i < "));
    if let Some((found, count)) = variant
        && let Ok(count) = count.parse::<u64>()
        && count > 0
    {
        return format!(
            "invalid variant index {found} (expected 0 to {})",
            count - 1
        );
    }
    text.to_owned()
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde::Deserialize;

    #[derive(Debug, Deserialize)]
    enum Three {
        A,
        B,
        C,
    }

    #[test]
    fn an_out_of_range_variant_index_reads_as_text() {
        let error = decode_exact::<Three>(&1200u32.to_le_bytes()).expect_err("no variant 1200");
        assert_eq!(error.0, "invalid variant index 1200 (expected 0 to 2)");
        assert!(matches!(
            decode_exact::<Three>(&2u32.to_le_bytes()),
            Ok(Three::C)
        ));
        assert!(matches!(
            decode_exact::<Three>(&0u32.to_le_bytes()),
            Ok(Three::A)
        ));
        assert!(matches!(
            decode_exact::<Three>(&1u32.to_le_bytes()),
            Ok(Three::B)
        ));
    }

    /// A value whose own check refuses odd numbers (a serde custom error).
    #[derive(Debug, Deserialize)]
    #[serde(try_from = "u32")]
    struct Even(#[allow(dead_code)] u32);

    impl TryFrom<u32> for Even {
        type Error = String;
        fn try_from(value: u32) -> Result<Self, String> {
            if value.is_multiple_of(2) {
                Ok(Self(value))
            } else {
                Err(format!("{value} is odd"))
            }
        }
    }

    #[test]
    fn a_custom_message_keeps_its_text_without_the_wrapper() {
        let error = decode_exact::<Even>(&3u32.to_le_bytes()).expect_err("odd");
        assert_eq!(error.0, "3 is odd");
    }
}
