//! Damaged and foreign replay files: `fixstep verify` exits 2 with one line naming the file
//! and the problem, never panics; a changed checksum is a desync (exit 1).

use crate::replay_support::{Layout, Run, TempPath, fixstep, rewrite_header, sample_bytes};
use fixstep::replay::format::PREAMBLE_LEN;
use fixstep::replay::{Replay, ReplayErrorKind, Section, VerifyOutcome, content_hash, verify};
use fixstep::world::STATE_VERSION;

const TWO_POW_60: u64 = 1 << 60;

/// Writes `bytes` to a temporary replay and runs `fixstep verify` on it.
fn verify_bytes(bytes: &[u8]) -> (Run, TempPath) {
    let file = TempPath::with_bytes("damaged.replay", bytes);
    (fixstep(&["verify", file.str()]), file)
}

/// `fixstep verify` on `bytes` fails with exit 2 and a line naming the file and `parts`.
fn assert_rejected(bytes: &[u8], parts: &[&str]) {
    let (run, file) = verify_bytes(bytes);
    let mut all = vec![file.str()];
    all.extend_from_slice(parts);
    run.assert_error(&all);
    assert!(run.stdout.is_empty(), "{}", run.stdout);
}

/// The sample cut to `len` bytes is rejected as truncated in `section` at offset `len`.
fn assert_truncated(len: usize, section: &str) {
    let bytes = sample_bytes();
    assert!(len < bytes.len());
    let expected = format!("truncated in the {section} at byte offset {len}: ");
    assert_rejected(&bytes[..len], &[&expected, "more bytes needed"]);
}

fn layout() -> (Vec<u8>, Layout) {
    let bytes = sample_bytes();
    let layout = Layout::of(&bytes);
    (bytes, layout)
}

fn write_u64(bytes: &mut [u8], at: usize, value: u64) {
    bytes[at..at + 8].copy_from_slice(&value.to_le_bytes());
}

// Truncation at every section boundary and in the middle of every section.

#[test]
fn truncated_inside_magic() {
    assert_truncated(5, "preamble (magic and format version)");
}

#[test]
fn truncated_inside_format_version() {
    assert_truncated(10, "preamble (magic and format version)");
}

#[test]
fn truncated_at_header_start() {
    assert_truncated(PREAMBLE_LEN, "header");
}

#[test]
fn truncated_in_the_middle_of_the_header() {
    let (_, layout) = layout();
    assert_truncated((PREAMBLE_LEN + layout.header_end) / 2, "header");
}

#[test]
fn truncated_before_the_header_hash() {
    let (_, layout) = layout();
    assert_truncated(layout.header_end, "header");
}

#[test]
fn truncated_inside_the_header_hash() {
    let (_, layout) = layout();
    assert_truncated(layout.header_end + 4, "header");
}

#[test]
fn truncated_at_scene_start() {
    let (_, layout) = layout();
    assert_truncated(layout.scene, "scene section");
}

#[test]
fn truncated_in_the_middle_of_the_scene() {
    let (_, layout) = layout();
    assert_truncated((layout.scene + layout.inputs) / 2, "scene section");
}

#[test]
fn truncated_at_inputs_start() {
    let (_, layout) = layout();
    assert_truncated(layout.inputs, "inputs section");
}

#[test]
fn truncated_in_the_middle_of_the_inputs() {
    let (_, layout) = layout();
    assert_truncated((layout.inputs + layout.checksums) / 2, "inputs section");
}

#[test]
fn truncated_at_checksums_start() {
    let (_, layout) = layout();
    assert_truncated(layout.checksums, "checksums section");
}

#[test]
fn truncated_in_the_middle_of_the_checksums() {
    let (bytes, layout) = layout();
    assert_truncated((layout.checksums + bytes.len()) / 2, "checksums section");
}

#[test]
fn truncated_by_one_byte() {
    let bytes = sample_bytes();
    assert_truncated(bytes.len() - 1, "checksums section");
}

#[test]
fn every_prefix_is_an_error_and_none_panics() {
    let bytes = sample_bytes();
    for len in 0..bytes.len() {
        assert!(
            Replay::from_bytes(&bytes[..len], "prefix").is_err(),
            "a {len}-byte prefix was accepted"
        );
    }
}

// One flipped bit.

#[test]
fn bit_flipped_in_the_header() {
    let (mut bytes, _) = layout();
    // The low byte of `ticks` (header offset 24 + 6 for the "I32F32" scalar).
    bytes[PREAMBLE_LEN + 30] ^= 0x04;
    assert_rejected(&bytes, &["header is corrupted (content hash mismatch)"]);
}

#[test]
fn bit_flipped_in_the_header_hash() {
    let (mut bytes, layout) = layout();
    bytes[layout.header_end + 3] ^= 0x80;
    assert_rejected(&bytes, &["header is corrupted (content hash mismatch)"]);
}

#[test]
fn bit_flipped_in_the_scene() {
    let (mut bytes, layout) = layout();
    bytes[(layout.scene + layout.inputs) / 2] ^= 0x10;
    assert_rejected(
        &bytes,
        &["scene section is corrupted (content hash mismatch)"],
    );
}

#[test]
fn bit_flipped_in_the_inputs() {
    let (mut bytes, layout) = layout();
    bytes[(layout.inputs + layout.checksums) / 2] ^= 0x01;
    assert_rejected(
        &bytes,
        &["inputs section is corrupted (content hash mismatch)"],
    );
}

#[test]
fn bit_flipped_in_a_checksum_total_is_a_desync() {
    let (mut bytes, layout) = layout();
    // Checkpoint 1 is at tick 60: tick (8 bytes), then the total.
    bytes[layout.checkpoints[1] + 8 + 2] ^= 0x20;
    let (run, file) = verify_bytes(&bytes);
    assert_eq!(run.code, 1, "{run:?}");
    let line = run.stdout.trim_end();
    let prefix = format!("desync {} at tick 60: expected ", file.str());
    assert!(line.starts_with(&prefix), "{line}");
    assert!(
        line.ends_with("(subsystem unknown, first differing id unknown)"),
        "{line}"
    );
    assert!(run.stderr.is_empty(), "{}", run.stderr);
}

#[test]
fn bit_flipped_in_a_part_checksum_names_the_part() {
    let (mut bytes, layout) = layout();
    let replay = Replay::from_bytes(&bytes, "sample").expect("valid");
    let checkpoint = &replay.checkpoints()[2];
    assert_eq!(checkpoint.tick, 120);
    let last_part = checkpoint.parts.len() - 1;
    let (part, _) = checkpoint.parts[last_part];
    // tick, total, part count, then (u32 part, u64 sum) pairs.
    let at = layout.checkpoints[2] + 24 + last_part * 12 + 4;
    bytes[at] ^= 0x01;
    let (run, file) = verify_bytes(&bytes);
    assert_eq!(run.code, 1, "{run:?}");
    let expected = format!(
        "desync {} at tick 120: expected {total:016x} got {total:016x} (subsystem {part}, \
         first differing id unknown; the totals agree, so the recorded checkpoint was altered)",
        file.str(),
        total = checkpoint.total
    );
    assert_eq!(run.stdout.trim_end(), expected);

    let damaged = Replay::from_bytes(&bytes, "damaged").expect("structurally valid");
    match verify(&damaged).expect("the scene builds") {
        VerifyOutcome::Desync {
            tick,
            part: reported,
            first_differing_id,
            ..
        } => {
            assert_eq!(tick, 120);
            assert_eq!(reported, Some(part));
            assert_eq!(first_differing_id, None);
        }
        other => panic!("expected a desync, got {other:?}"),
    }
}

#[test]
fn any_flipped_bit_before_the_checksums_is_an_error_and_none_panics() {
    let (bytes, layout) = layout();
    for at in 0..bytes.len() {
        let mut damaged = bytes.clone();
        damaged[at] ^= 1 << (at % 8);
        let result = Replay::from_bytes(&damaged, "flipped");
        if at < layout.checksums {
            assert!(
                result.is_err(),
                "flipping a bit of byte {at} went unnoticed"
            );
        }
    }
}

// Foreign files and versions.

#[test]
fn wrong_magic() {
    let (mut bytes, _) = layout();
    bytes[..8].copy_from_slice(b"NOTAREPL");
    assert_rejected(&bytes, &["not a fixstep replay (magic \"NOTAREPL\""]);
}

#[test]
fn random_bytes() {
    let mut state = 0x1234_5678_9abc_def0_u64;
    let bytes: Vec<u8> = (0..4096)
        .map(|_| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state as u8
        })
        .collect();
    assert_rejected(&bytes, &["not a fixstep replay"]);
}

#[test]
fn future_format_version() {
    let (mut bytes, _) = layout();
    bytes[8..12].copy_from_slice(&2u32.to_le_bytes());
    assert_rejected(
        &bytes,
        &["replay format version 2; this build reads version 1"],
    );
}

#[test]
fn future_state_version() {
    let (mut bytes, mut layout) = layout();
    layout.header.state_version = STATE_VERSION + 1;
    rewrite_header(&mut bytes, &layout.header);
    let expected = format!(
        "recorded with engine state version {}; this build simulates version {STATE_VERSION}",
        STATE_VERSION + 1
    );
    assert_rejected(&bytes, &[&expected]);
}

#[test]
fn older_state_version_asks_for_a_re_recording() {
    let (mut bytes, mut layout) = layout();
    layout.header.state_version = STATE_VERSION - 1;
    rewrite_header(&mut bytes, &layout.header);
    let expected = format!(
        "recorded with engine state version {}; this build simulates version {STATE_VERSION} \
         — re-record it (scripts/rerecord.sh)",
        STATE_VERSION - 1
    );
    assert_rejected(&bytes, &[&expected]);
}

#[test]
fn another_scalar_format() {
    let (mut bytes, mut layout) = layout();
    layout.header.scalar = "I48F16".to_owned();
    rewrite_header(&mut bytes, &layout.header);
    assert_rejected(&bytes, &["\"I48F16\"", "\"I32F32\""]);
}

// Length fields.

#[test]
fn scene_len_of_two_pow_60_is_caught_by_the_header_hash() {
    let (mut bytes, layout) = layout();
    write_u64(&mut bytes, layout.header_end - 32, TWO_POW_60);
    assert_rejected(&bytes, &["header is corrupted (content hash mismatch)"]);
}

#[test]
fn scene_len_of_two_pow_60_with_a_valid_header_hash() {
    let (mut bytes, mut layout) = layout();
    layout.header.scene_len = TWO_POW_60;
    rewrite_header(&mut bytes, &layout.header);
    let at = format!("header at byte offset {}", layout.header_end - 32);
    assert_rejected(
        &bytes,
        &[
            &at,
            "scene section length 1152921504606846976 exceeds the 268435456-byte limit",
        ],
    );
}

#[test]
fn inputs_len_of_two_pow_60_with_a_valid_header_hash() {
    let (mut bytes, mut layout) = layout();
    layout.header.inputs_len = TWO_POW_60;
    rewrite_header(&mut bytes, &layout.header);
    assert_rejected(
        &bytes,
        &["inputs section length 1152921504606846976 exceeds the 268435456-byte limit"],
    );
}

#[test]
fn scene_len_past_the_end_of_the_file() {
    let (mut bytes, mut layout) = layout();
    let extra = bytes.len() - layout.scene;
    layout.header.scene_len = extra as u64 + 1000;
    rewrite_header(&mut bytes, &layout.header);
    let expected = format!(
        "truncated in the scene section at byte offset {}: 1000 more bytes needed",
        bytes.len()
    );
    assert_rejected(&bytes, &[&expected]);
}

#[test]
fn vec_length_of_two_pow_60_inside_the_inputs() {
    let (mut bytes, mut layout) = layout();
    write_u64(&mut bytes, layout.inputs, TWO_POW_60);
    layout.header.inputs_hash = content_hash(&bytes[layout.inputs..layout.checksums]);
    rewrite_header(&mut bytes, &layout.header);
    let expected = format!(
        "inputs section at byte offset {}: does not decode: a length or value runs past the \
         end of the section",
        layout.inputs
    );
    assert_rejected(&bytes, &[&expected]);
}

#[test]
fn string_length_of_two_pow_60_inside_the_scene() {
    let (mut bytes, mut layout) = layout();
    // The scene starts with its name: a u64 length, then the bytes.
    write_u64(&mut bytes, layout.scene, TWO_POW_60);
    layout.header.scene_hash = content_hash(&bytes[layout.scene..layout.inputs]);
    rewrite_header(&mut bytes, &layout.header);
    assert_rejected(
        &bytes,
        &[
            "scene section at byte offset",
            "exceeds the 268435456-byte limit",
        ],
    );
}

#[test]
fn vec_length_of_two_pow_60_in_the_checksums() {
    let (mut bytes, layout) = layout();
    write_u64(&mut bytes, layout.checksums, TWO_POW_60);
    let expected = format!(
        "truncated in the checksums section at byte offset {}",
        bytes.len()
    );
    assert_rejected(&bytes, &[&expected]);
}

#[test]
fn scalar_name_length_of_two_pow_60() {
    let (mut bytes, _) = layout();
    write_u64(&mut bytes, PREAMBLE_LEN + 4, TWO_POW_60);
    assert_rejected(
        &bytes,
        &["header at byte offset 16: scalar name length 1152921504606846976"],
    );
}

#[test]
fn checksum_every_of_zero() {
    let (mut bytes, mut layout) = layout();
    layout.header.checksum_every = 0;
    rewrite_header(&mut bytes, &layout.header);
    assert_rejected(&bytes, &["checksum_every is 0"]);
}

#[test]
fn a_missing_checkpoint() {
    let (mut bytes, layout) = layout();
    let count = layout.checkpoints.len() as u64;
    write_u64(&mut bytes, layout.checksums, count - 1);
    bytes.truncate(*layout.checkpoints.last().expect("checkpoints"));
    assert_rejected(
        &bytes,
        &[
            "checksums section",
            "3 checkpoints, expected 4 for 130 ticks",
        ],
    );
}

// Files that are not replays at all.

#[test]
fn empty_file() {
    assert_rejected(&[], &["empty file, not a fixstep replay"]);
}

#[test]
fn a_directory() {
    let dir = TempPath::new("dir.replay");
    std::fs::create_dir(dir.path()).expect("create a directory");
    let run = fixstep(&["verify", dir.str()]);
    run.assert_error(&[dir.str(), "is a directory"]);
}

#[test]
fn a_nonexistent_path() {
    let missing = TempPath::new("missing.replay");
    let run = fixstep(&["verify", missing.str()]);
    run.assert_error(&[missing.str(), "cannot read"]);
}

#[test]
fn trailing_garbage() {
    let (mut bytes, _) = layout();
    let end = bytes.len();
    bytes.extend_from_slice(b"garbage");
    let expected = format!(
        "checksums section at byte offset {end}: 7 unexpected bytes after the end of the \
         file's last section"
    );
    assert_rejected(&bytes, &[&expected]);
}

#[test]
fn errors_carry_their_section() {
    let (bytes, layout) = layout();
    let error = Replay::from_bytes(&bytes[..layout.inputs + 3], "cut").expect_err("truncated");
    assert_eq!(error.origin, "cut");
    assert_eq!(
        error.kind,
        ReplayErrorKind::Truncated {
            section: Section::Inputs,
            offset: layout.inputs as u64 + 3,
            needed: format!("{} more bytes needed", layout.checksums - layout.inputs - 3),
        }
    );
}

// Several files: every file is reported, the exit code is the most severe.

#[test]
fn several_files_report_each_and_exit_with_the_worst() {
    let (bytes, layout) = layout();
    let good = TempPath::with_bytes("good.replay", &bytes);
    let mut desynced = bytes.clone();
    desynced[layout.checkpoints[1] + 8] ^= 1;
    let desynced = TempPath::with_bytes("desynced.replay", &desynced);
    let empty = TempPath::with_bytes("empty.replay", &[]);

    let run = fixstep(&["verify", good.str(), desynced.str()]);
    assert_eq!(run.code, 1, "{run:?}");
    let lines: Vec<&str> = run.stdout.lines().collect();
    assert_eq!(lines.len(), 2, "{}", run.stdout);
    assert!(lines[0].starts_with(&format!("ok {} 130 ", good.str())));
    assert!(lines[1].starts_with(&format!("desync {} at tick 60", desynced.str())));

    let run = fixstep(&["verify", empty.str(), good.str(), desynced.str()]);
    assert_eq!(run.code, 2, "{run:?}");
    assert_eq!(run.stdout.lines().count(), 2, "{}", run.stdout);
    assert_eq!(run.stderr.lines().count(), 1, "{}", run.stderr);
    assert!(run.stderr.contains(empty.str()));
}

#[test]
fn differing_object_digest_names_the_object() {
    let (mut bytes, layout) = layout();
    let replay = Replay::from_bytes(&bytes, "sample").expect("valid");
    let checkpoint = &replay.checkpoints()[2];
    let (part, objects) = &checkpoint.objects[0];
    assert!(objects.len() > 3, "the sample scene has particles");
    let (id, _) = objects[3];
    // tick, total, part count, parts (u32 + u64 each), object-part count, then the first
    // part's u32 tag and u64 count, then (u32 index, u32 generation, u32 digest) entries.
    let entries = layout.checkpoints[2] + 24 + checkpoint.parts.len() * 12 + 8 + 4 + 8;
    bytes[entries + 3 * 12 + 8] ^= 0x10;
    let (run, file) = verify_bytes(&bytes);
    assert_eq!(run.code, 1, "{run:?}");
    let expected = format!(
        "desync {} at tick 120: expected {total:016x} got {total:016x} (subsystem unknown, \
         first differing id {id}; the totals agree, so the recorded checkpoint was altered)",
        file.str(),
        total = checkpoint.total
    );
    assert_eq!(run.stdout.trim_end(), expected);
    assert_eq!(*part, fixstep::world::Part::Particles);
}

#[test]
fn a_part_index_out_of_range_in_the_checksums_reads_as_words() {
    let (mut bytes, layout) = layout();
    // The first checkpoint: tick, total, the parts' count, then the first part's index.
    let part_at = layout.checkpoints[0] + 24;
    bytes[part_at..part_at + 4].copy_from_slice(&1200u32.to_le_bytes());
    let expected = format!(
        "checksums section at byte offset {}: does not decode: invalid variant index 1200 \
         (expected 0 to 6)",
        layout.checksums
    );
    assert_rejected(&bytes, &[&expected]);
}
