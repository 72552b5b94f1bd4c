//! Tests of `StateHasher`: XXH3-64 reference vectors, independence from how the bytes are
//! split into writes, the little-endian encodings, and golden values.

use fixstep::math::{Fx, FxI48F16, Real, StateHasher, Vec3};

/// `XSUM_fillTestBuffer` of the reference `cli/xsum_sanity_check.c`.
fn sanity_buffer(len: usize) -> Vec<u8> {
    const PRIME32: u64 = 2_654_435_761;
    const PRIME64: u64 = 11_400_714_785_074_694_797;
    let mut byte_gen = PRIME32;
    (0..len)
        .map(|_| {
            let byte = (byte_gen >> 56) as u8;
            byte_gen = byte_gen.wrapping_mul(PRIME64);
            byte
        })
        .collect()
}

/// The seed-0 rows of `XSUM_XXH3_testdata` in `cli/xsum_sanity_check.c` of
/// <https://github.com/Cyan4973/xxHash>, covering every XXH3 length class (empty, 1–3, 4–8,
/// 9–16, 17–32, 33–64, 65–96, 129–240, one block, several blocks, stripe and block
/// boundaries). Cross-checked with the `xxhash` Python package (libxxhash 0.8.4).
const XXH3_VECTORS: [(usize, u64); 13] = [
    (0, 0x2D06800538D394C2),
    (1, 0xC44BDFF4074EECDB),
    (6, 0x27B56A84CD2D7325),
    (12, 0xA713DAF0DFBB77E7),
    (24, 0xA3FE70BF9D3510EB),
    (48, 0x397DA259ECBA1F11),
    (80, 0xBCDEFBBB2C47C90A),
    (195, 0xCD94217EE362EC3A),
    (403, 0xCDEB804D65C6DEA4),
    (512, 0x617E49599013CB6B),
    (2048, 0xDD59E2C3A5F038E0),
    (2240, 0x6E73A90539CF2948),
    (2367, 0xCB37AEB9E5D361ED),
];

fn hash_bytes(bytes: &[u8]) -> u64 {
    let mut h = StateHasher::new();
    h.write_bytes(bytes);
    h.finish()
}

/// Writes `bytes` through every typed write: pieces of 1, 4, 8 bytes and short slices, in a
/// fixed rotation, so that values straddle the internal buffer boundary at every offset.
fn hash_mixed(bytes: &[u8]) -> u64 {
    let mut h = StateHasher::new();
    let mut rest = bytes;
    let mut turn = 0;
    while !rest.is_empty() {
        let take = [1, 8, 4, 3, 8, 1, 8, 300][turn % 8].min(rest.len());
        let (piece, tail) = rest.split_at(take);
        match piece.len() {
            1 => h.write_u8(piece[0]),
            4 => h.write_u32(u32::from_le_bytes(piece.try_into().unwrap())),
            8 if turn % 2 == 0 => h.write_u64(u64::from_le_bytes(piece.try_into().unwrap())),
            8 => h.write_i64(i64::from_le_bytes(piece.try_into().unwrap())),
            _ => h.write_bytes(piece),
        }
        rest = tail;
        turn += 1;
    }
    h.finish()
}

#[test]
fn empty_input_is_the_xxh3_of_nothing() {
    assert_eq!(StateHasher::new().finish(), 0x2D06800538D394C2);
    assert_eq!(StateHasher::default().finish(), 0x2D06800538D394C2);
}

#[test]
fn matches_the_reference_xxh3_vectors() {
    for (len, expected) in XXH3_VECTORS {
        let data = sanity_buffer(len);
        assert_eq!(hash_bytes(&data), expected, "one write of {len} bytes");
        assert_eq!(hash_mixed(&data), expected, "mixed writes of {len} bytes");

        let mut h = StateHasher::new();
        for &byte in &data {
            h.write_u8(byte);
        }
        assert_eq!(h.finish(), expected, "{len} single-byte writes");
    }
}

#[test]
fn result_does_not_depend_on_how_writes_are_split() {
    let data = sanity_buffer(5000);
    let whole = hash_bytes(&data);
    for chunk in [
        1, 2, 3, 7, 8, 63, 64, 100, 255, 256, 257, 1023, 1024, 1025, 4999,
    ] {
        let mut h = StateHasher::new();
        for piece in data.chunks(chunk) {
            h.write_bytes(piece);
        }
        assert_eq!(h.finish(), whole, "chunks of {chunk}");
    }
    // A large slice arriving while the buffer is partly full.
    let mut h = StateHasher::new();
    h.write_bytes(&data[..5]);
    h.write_bytes(&data[5..4000]);
    h.write_bytes(&data[4000..]);
    assert_eq!(h.finish(), whole);
    assert_eq!(hash_mixed(&data), whole);
}

/// One write into a hasher.
type Write = fn(&mut StateHasher);

#[test]
fn integers_are_little_endian() {
    let cases: [(Write, &[u8]); 6] = [
        (|h| h.write_u8(0xab), &[0xab]),
        (|h| h.write_u32(0x0403_0201), &[1, 2, 3, 4]),
        (
            |h| h.write_u64(0x0807_0605_0403_0201),
            &[1, 2, 3, 4, 5, 6, 7, 8],
        ),
        (
            |h| h.write_i64(-2),
            &[0xfe, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff],
        ),
        (|h| h.write_len(0x0102), &[2, 1, 0, 0, 0, 0, 0, 0]),
        (|h| h.write_bytes(b"xyz"), b"xyz"),
    ];
    for (write, bytes) in cases {
        let mut h = StateHasher::new();
        write(&mut h);
        assert_eq!(h.finish(), hash_bytes(bytes), "{bytes:?}");
    }
}

#[test]
fn write_real_hashes_the_raw_bits_little_endian() {
    for bits in [
        0i64,
        1,
        -1,
        1 << 32,
        -(3 << 31),
        i64::MAX,
        i64::MIN,
        0x0123_4567_89ab_cdef,
    ] {
        let mut h = StateHasher::new();
        h.write_real(Fx::from_bits(bits));
        assert_eq!(
            h.finish(),
            hash_bytes(&bits.to_le_bytes()),
            "Fx bits {bits:#x}"
        );

        let mut h = StateHasher::new();
        h.write_real(FxI48F16::from_bits(bits));
        assert_eq!(
            h.finish(),
            hash_bytes(&bits.to_le_bytes()),
            "I48F16 bits {bits:#x}"
        );
    }
    // One and a half in I32F32 is 0x1_8000_0000.
    let mut h = StateHasher::new();
    h.write_real(Fx::from_ratio(3, 2));
    assert_eq!(
        h.finish(),
        hash_bytes(&[0, 0, 0, 0x80, 1, 0, 0, 0]),
        "1.5 as I32F32"
    );
    // f64 hashes its IEEE bits: -0.0 and 0.0 differ.
    let mut h = StateHasher::new();
    h.write_real(-0.0f64);
    assert_eq!(h.finish(), hash_bytes(&(1u64 << 63).to_le_bytes()));
}

#[test]
fn write_vec3_is_x_then_y_then_z() {
    let v = Vec3::new(Fx::from_int(1), Fx::from_int(-2), Fx::HALF);
    let mut by_vec = StateHasher::new();
    by_vec.write_vec3(v);
    let mut by_parts = StateHasher::new();
    by_parts.write_real(v.x);
    by_parts.write_real(v.y);
    by_parts.write_real(v.z);
    let (a, b) = (by_vec.finish(), by_parts.finish());
    assert_eq!(a, b);

    let mut swapped = StateHasher::new();
    swapped.write_vec3(Vec3::new(v.y, v.x, v.z));
    assert_ne!(swapped.finish(), a);
}

#[test]
fn clone_forks_the_stream() {
    let mut h = StateHasher::new();
    h.write_bytes(&sanity_buffer(3000));
    h.write_u8(7);
    let fork = h.clone();
    h.write_u8(1);
    let mut expected = sanity_buffer(3000);
    expected.push(7);
    assert_eq!(fork.finish(), hash_bytes(&expected));
    expected.push(1);
    assert_eq!(h.finish(), hash_bytes(&expected));
}

/// A fixed sequence of every kind of write. The bytes are
/// `010000002a00000000000000f9ffffffffffffffab00000080feffffff000000000100000000000000feff
/// ffff00000080000000000300000000000000616263000000000000008000c0feffffffffff` (80 bytes),
/// whose XXH3-64 per the `xxhash` Python package (libxxhash 0.8.4) is `0xC11D92E9EE789EF1`.
#[test]
fn golden_value_of_a_fixed_sequence() {
    let mut h = StateHasher::new();
    h.write_u32(1);
    h.write_u64(42);
    h.write_i64(-7);
    h.write_u8(0xab);
    h.write_real(Fx::from_ratio(-3, 2));
    h.write_vec3(Vec3::new(Fx::ONE, -Fx::TWO, Fx::HALF));
    h.write_len(3);
    h.write_bytes(b"abc");
    h.write_real(-0.0f64);
    h.write_real(FxI48F16::from_ratio(-5, 4));
    assert_eq!(h.finish(), 0xC11D92E9EE789EF1);
}

/// 1 MiB written as 131072 `i64`s, `i · 0x9E3779B97F4A7C15 (mod 2⁶⁴)`; the expected value is
/// the XXH3-64 of the same little-endian bytes per the `xxhash` Python package.
#[test]
fn golden_value_of_a_large_state() {
    let mut h = StateHasher::new();
    for i in 0..131_072u64 {
        h.write_i64(i.wrapping_mul(0x9E37_79B9_7F4A_7C15) as i64);
    }
    assert_eq!(h.finish(), 0x9B02BD3474FF9347);
}
