//! Tests of `Pcg32`: the reference PCG32 output, jump-ahead, bounded integers, reals,
//! directions and snapshots.

use fixstep::math::{Fx, FxI40F24, FxI48F16, Pcg32, Real, StateHasher, Vec3};

/// One round of the reference `check-pcg32` program (pcg-c `test-high/check-base.c`).
struct Round {
    numbers: [u32; 6],
    coins: &'static str,
    rolls: &'static str,
    cards: &'static str,
}

/// `test-high/expected/check-pcg32.out` of <https://github.com/imneme/pcg-c> (seed 42,
/// stream 54); its first line of numbers is also the output of pcg-c-basic's
/// `pcg32-demo` / `pcg32-global-demo`. Each round's "Again" line equals its numbers.
const REFERENCE: [Round; 5] = [
    Round {
        numbers: [
            0xa15c02b7, 0x7b47f409, 0xba1d3330, 0x83d2f293, 0xbfa4784b, 0xcbed606e,
        ],
        coins: "HHTTTHTHHHTHTTTHHHHHTTTHHHTHTHTHTTHTTTHHHHHHTTTTHHTTTTTHTTTTTTTHT",
        rolls: "3 4 1 1 2 2 3 2 4 3 2 4 3 3 5 2 3 1 3 1 5 1 4 1 5 6 4 6 6 2 6 3 3",
        cards: "Qd Ks 6d 3s 3d 4c 3h Td Kc 5c Jh Kd Jd As 4s 4h Ad Th Ac Jc 7s Qs \
                2s 7h Kh 2d 6c Ah 4d Qh 9h 6s 5s 2c 9c Ts 8d 9s 3c 8c Js 5d 2h 6h \
                7d 8s 9d 5h 8h Qc 7c Tc",
    },
    Round {
        numbers: [
            0x74ab93ad, 0x1c1da000, 0x494ff896, 0x34462f2f, 0xd308a3e5, 0x0fa83bab,
        ],
        coins: "HHHHHHHHHHTHHHTHTHTHTHTTTTHHTTTHHTHHTHTTHHTTTHHHHHHTHTTHTHTTTTTTT",
        rolls: "5 1 1 3 3 2 4 5 3 2 2 6 4 3 2 4 2 4 3 2 3 6 3 2 3 4 2 4 1 1 5 4 4",
        cards: "7d 2s 7h Td 8s 3c 3d Js 2d Tc 4h Qs 5c 9c Th 2c Jc Qd 9d Qc 7s 3s \
                5s 6h 4d Jh 4c Ac 4s 5h 5d Kc 8h 8d Jd 9s Ad 6s 6c Kd 2h 3h Kh Ts \
                Qh 9h 6d As 7c Ks Ah 8c",
    },
    Round {
        numbers: [
            0x39af5f9f, 0x04196b18, 0xc3c3eb28, 0xc076c60c, 0xc693e135, 0xf8f63932,
        ],
        coins: "HTTHHTTTTTHTTHHHTHTTHHTTHTHHTHTHTTTTHHTTTHHTHHTTHTTHHHTHHHTHTTTHT",
        rolls: "5 1 5 3 2 2 4 5 3 3 1 3 4 6 3 2 3 4 2 2 3 1 5 2 4 6 6 4 2 4 3 3 6",
        cards: "Kd Jh Kc Qh 4d Qc 4h 9d 3c Kh Qs 8h 5c Jd 7d 8d 3h 7c 8s 3s 2h Ks \
                9c 9h 2c 8c Ad 7s 4s 2s 5h 6s 4c Ah 7h 5s Ac 3d 5d Qd As Tc 6h 9s \
                2d 6c 6d Td Jc Ts Th Js",
    },
    Round {
        numbers: [
            0x55ce6851, 0x97a7726d, 0x17e10815, 0x58007d43, 0x962fb148, 0xb9bb55bd,
        ],
        coins: "HHTHHTTTTHTHHHHHTTHHHTTTHHTHTHTHTHHTTHTHHHHHHTHHTHHTHHTTTTHHTHHTT",
        rolls: "6 6 3 2 3 4 2 6 4 2 6 3 2 3 5 5 3 4 4 6 6 2 6 5 4 4 6 1 6 1 3 6 5",
        cards: "Qd 8h 5d 8s 8d Ts 7h Th Qs Js 7s Kc 6h 5s 4d Ac Jd 7d 7c Td 2c 6s \
                5h 6d 3s Kd 9s Jh Kh As Ah 9h 3c Qh 9c 2d Tc 9d 2s 3d Ks 4h Qc Ad \
                Jc 8c 2h 3h 4s 4c 5c 6c",
    },
    Round {
        numbers: [
            0xfcef7cd6, 0x1b488b5a, 0xd0daf7ea, 0x1d9a70f7, 0x241a37cf, 0x9a3857b7,
        ],
        coins: "HHHHTHHTTHTTHHHTTTHHTHTHTTTTHTTHTHTTTHHHTHTHTTHTTHTHHTHTHHHTHTHTT",
        rolls: "5 4 1 2 6 1 3 1 5 6 3 6 2 1 4 4 5 2 1 5 6 5 6 4 4 4 5 2 6 4 3 5 6",
        cards: "4d 9s Qc 9h As Qs 7s 4c Kd 6h 6s 2c 8c 5d 7h 5h Jc 3s 7c Jh Js Ks \
                Tc Jd Kc Th 3h Ts Qh Ad Td 3c Ah 2d 3d 5c Ac 8s 5s 9c 2h 6c 6d Kh \
                Qd 8d 7d 2s 8h 4h 9d 4s",
    },
];

/// Replays `check-base.c`: six numbers, back six with `advance(-6)`, the same six again,
/// 65 coins (`below(2)`), 33 dice (`below(6) + 1`) and a Fisher–Yates deal (`below(i)`).
#[test]
fn reproduces_the_reference_check_pcg32_output() {
    let mut rng = Pcg32::new(42, 54);
    for (index, round) in REFERENCE.iter().enumerate() {
        let numbers: Vec<u32> = (0..6).map(|_| rng.next_u32()).collect();
        assert_eq!(numbers, round.numbers, "round {}: 32bit", index + 1);

        rng.advance(6u64.wrapping_neg());
        let again: Vec<u32> = (0..6).map(|_| rng.next_u32()).collect();
        assert_eq!(again, round.numbers, "round {}: Again", index + 1);

        let coins: String = (0..65)
            .map(|_| if rng.below(2) == 1 { 'H' } else { 'T' })
            .collect();
        assert_eq!(coins, round.coins, "round {}: Coins", index + 1);

        let rolls: Vec<String> = (0..33).map(|_| (rng.below(6) + 1).to_string()).collect();
        assert_eq!(rolls.join(" "), round.rolls, "round {}: Rolls", index + 1);

        let mut cards: Vec<u32> = (0..52).collect();
        for i in (2..=52u32).rev() {
            let chosen = rng.below(i) as usize;
            cards.swap(chosen, i as usize - 1);
        }
        let names: Vec<String> = cards
            .iter()
            .map(|&c| {
                let number = b"A23456789TJQK"[(c / 4) as usize] as char;
                let suit = b"hcds"[(c % 4) as usize] as char;
                format!("{number}{suit}")
            })
            .collect();
        let expected: Vec<&str> = round.cards.split_whitespace().collect();
        assert_eq!(names, expected, "round {}: Cards", index + 1);
    }
}

#[test]
fn new_is_usable_in_const_context() {
    const RNG: Pcg32 = Pcg32::new(42, 54);
    assert_eq!(RNG.clone().next_u32(), 0xa15c02b7);
}

#[test]
fn next_u64_is_first_draw_low_second_draw_high() {
    let mut a = Pcg32::new(42, 54);
    let mut b = Pcg32::new(42, 54);
    for _ in 0..100 {
        let low = b.next_u32() as u64;
        let high = b.next_u32() as u64;
        assert_eq!(a.next_u64(), low | high << 32);
    }
    assert_eq!(Pcg32::new(42, 54).next_u64(), 0x7b47f409_a15c02b7);
}

#[test]
fn streams_differ_and_clones_continue_identically() {
    let first = |mut rng: Pcg32| (0..8).map(|_| rng.next_u32()).collect::<Vec<_>>();
    assert_ne!(first(Pcg32::new(7, 1)), first(Pcg32::new(7, 2)));
    assert_ne!(first(Pcg32::new(7, 1)), first(Pcg32::new(8, 1)));

    let mut rng = Pcg32::new(7, 1);
    rng.next_u32();
    let fork = rng.clone();
    assert_eq!(fork, rng);
    assert_eq!(first(fork), first(rng));
}

#[test]
fn advance_equals_stepping() {
    for (seed, stream) in [(42, 54), (0, 0), (u64::MAX, u64::MAX), (0xdead_beef, 3)] {
        for delta in [0u64, 1, 2, 3, 7, 64, 1000, 12_345] {
            let mut jumped = Pcg32::new(seed, stream);
            let mut stepped = jumped.clone();
            jumped.advance(delta);
            for _ in 0..delta {
                stepped.next_u32();
            }
            assert_eq!(
                jumped, stepped,
                "seed {seed}, stream {stream}, delta {delta}"
            );
            assert_eq!(jumped.next_u32(), stepped.next_u32());
        }
    }
}

#[test]
fn advance_composes_and_goes_backwards() {
    let start = Pcg32::new(123, 456);

    let mut split = start.clone();
    split.advance(1 << 40);
    split.advance(0x1234_5678_9abc);
    let mut whole = start.clone();
    whole.advance((1 << 40) + 0x1234_5678_9abc);
    assert_eq!(split, whole);

    // The period is 2^64: going back k steps undoes k draws, and 2^64 − 1 steps then one more
    // step is the identity.
    let mut rng = start.clone();
    for _ in 0..1000 {
        rng.next_u32();
    }
    rng.advance(1000u64.wrapping_neg());
    assert_eq!(rng, start);

    let mut rng = start.clone();
    rng.advance(u64::MAX);
    rng.next_u32();
    assert_eq!(rng, start);
}

#[test]
fn below_stays_in_range() {
    let mut rng = Pcg32::new(2024, 7);
    for n in [
        1u32,
        2,
        3,
        6,
        7,
        10,
        1000,
        (1 << 31) - 1,
        1 << 31,
        (1 << 31) + 1,
        u32::MAX,
    ] {
        for _ in 0..2000 {
            assert!(rng.below(n) < n, "below({n})");
        }
    }
}

#[test]
fn below_one_is_zero_and_takes_one_draw() {
    let mut rng = Pcg32::new(5, 5);
    let mut reference = rng.clone();
    assert_eq!(rng.below(1), 0);
    reference.next_u32();
    assert_eq!(rng, reference);
}

#[test]
#[should_panic(expected = "bound must be positive")]
fn below_zero_panics() {
    Pcg32::new(1, 1).below(0);
}

/// Pearson's chi-square statistic of `counts` against equal expected counts.
fn chi_square(counts: &[u64]) -> f64 {
    let total: u64 = counts.iter().sum();
    let expected = total as f64 / counts.len() as f64;
    counts
        .iter()
        .map(|&c| (c as f64 - expected).powi(2) / expected)
        .sum()
}

#[test]
fn below_is_unbiased() {
    // 10 cells, 9 degrees of freedom: the 0.1 % critical value is 27.88.
    let mut rng = Pcg32::new(42, 54);
    let mut counts = [0u64; 10];
    for _ in 0..200_000 {
        counts[rng.below(10) as usize] += 1;
    }
    let chi2 = chi_square(&counts);
    assert!(chi2 < 27.88, "chi-square {chi2} for counts {counts:?}");

    // A bound just above 2^31 rejects almost half of the draws; a plain `r % n` would put
    // two thirds of the results in the lower half.
    let n = (1u32 << 31) + 1;
    let lower = (0..100_000).filter(|_| rng.below(n) < n / 2).count();
    assert!(
        (48_000..52_000).contains(&lower),
        "{lower} of 100000 in the lower half"
    );
}

#[test]
fn unit_of_fx_is_exactly_the_draw() {
    let mut rng = Pcg32::new(42, 54);
    let mut reference = rng.clone();
    for _ in 0..1000 {
        let u: Fx = rng.unit();
        assert_eq!(u.to_bits(), reference.next_u32() as i64);
    }
    let mut rng = Pcg32::new(42, 54);
    assert_eq!(rng.unit::<Fx>(), Fx::from_bits(0xa15c02b7));
}

#[test]
fn unit_of_narrower_formats_takes_the_top_bits() {
    let mut rng = Pcg32::new(9, 9);
    let mut reference = rng.clone();
    for _ in 0..1000 {
        let u16: FxI48F16 = rng.unit();
        assert_eq!(u16.to_bits(), (reference.next_u32() >> 16) as i64);
        let u24: FxI40F24 = rng.unit();
        assert_eq!(u24.to_bits(), (reference.next_u32() >> 8) as i64);
    }
}

#[test]
fn unit_of_f64_uses_53_bits_of_next_u64() {
    let mut rng = Pcg32::new(9, 9);
    let mut reference = rng.clone();
    for _ in 0..1000 {
        let u: f64 = rng.unit();
        let k = reference.next_u64() >> 11;
        assert_eq!(u, k as f64 / (1u64 << 53) as f64);
        assert_eq!(u * (1u64 << 53) as f64, k as f64);
    }
}

#[test]
fn unit_is_in_the_half_open_unit_interval() {
    let mut rng = Pcg32::new(3, 4);
    for _ in 0..20_000 {
        let fx: Fx = rng.unit();
        assert!(fx >= Fx::ZERO && fx < Fx::ONE);
        let f: f64 = rng.unit();
        assert!((0.0..1.0).contains(&f));
    }
}

#[test]
fn unit_is_uniform() {
    // 16 equal bins, 15 degrees of freedom: the 0.1 % critical value is 37.70.
    let mut rng = Pcg32::new(11, 12);
    let mut counts = [0u64; 16];
    for _ in 0..160_000 {
        let u: Fx = rng.unit();
        counts[(u.to_bits() >> 28) as usize] += 1;
    }
    let chi2 = chi_square(&counts);
    assert!(chi2 < 37.70, "chi-square {chi2} for counts {counts:?}");
}

#[test]
fn range_is_half_open_and_covers_the_interval() {
    let mut rng = Pcg32::new(77, 1);
    let cases = [(-3.0, 5.5), (0.0, 1.0), (100.0, 100.25), (-1e6, -999_999.0)];
    for (lo, hi) in cases {
        let (lo_fx, hi_fx) = (Fx::from_f64(lo), Fx::from_f64(hi));
        let (mut min, mut max) = (Fx::MAX, Fx::MIN);
        for _ in 0..5000 {
            let v = rng.range(lo_fx, hi_fx);
            assert!(v >= lo_fx && v < hi_fx, "{v} not in [{lo_fx}, {hi_fx})");
            min = Ord::min(min, v);
            max = Ord::max(max, v);
            let f = rng.range(lo, hi);
            assert!(f >= lo && f < hi, "{f} not in [{lo}, {hi})");
        }
        let width = hi_fx - lo_fx;
        assert!(min - lo_fx < width * Fx::from_ratio(1, 100));
        assert!(hi_fx - max < width * Fx::from_ratio(1, 100));
    }
}

#[test]
fn range_of_tiny_or_empty_intervals() {
    let mut rng = Pcg32::new(5, 6);
    let lo = Fx::from_ratio(7, 3);
    for _ in 0..100 {
        assert_eq!(rng.range(lo, lo + Fx::EPSILON), lo);
        let v = rng.range(lo, lo + Fx::EPSILON * Fx::from_int(2));
        assert!(v == lo || v == lo + Fx::EPSILON);
    }
    let before = rng.clone();
    assert_eq!(rng.range(lo, lo), lo);
    assert_eq!(rng.range(lo, lo - Fx::ONE), lo);
    assert_eq!(rng, before, "an empty interval draws nothing");
}

#[test]
fn unit_vector_has_unit_length() {
    let mut rng = Pcg32::new(31, 41);
    for _ in 0..2000 {
        let v: Vec3<Fx> = rng.unit_vector();
        let error = (v.length_squared() - Fx::ONE).abs();
        assert!(error < Fx::from_ratio(1, 1_000_000), "{v:?}");
        let f: Vec3<f64> = rng.unit_vector();
        assert!((f.length() - 1.0).abs() < 1e-12, "{f:?}");
    }
}

#[test]
fn unit_vector_is_deterministic() {
    let mut a = Pcg32::new(8, 8);
    let mut b = Pcg32::new(8, 8);
    for _ in 0..100 {
        assert_eq!(a.unit_vector::<Fx>(), b.unit_vector::<Fx>());
    }
    assert_eq!(a, b);
}

#[test]
fn unit_vector_is_isotropic() {
    // Octant counts: 7 degrees of freedom, 0.1 % critical value 24.32. The mean direction
    // of n uniform unit vectors has per-axis standard deviation 1/sqrt(3n).
    let n = 40_000;
    let mut rng = Pcg32::new(2718, 28);
    let mut counts = [0u64; 8];
    let mut sum = [0.0f64; 3];
    for _ in 0..n {
        let v: Vec3<Fx> = rng.unit_vector();
        let octant = (v.x < Fx::ZERO) as usize
            | ((v.y < Fx::ZERO) as usize) << 1
            | ((v.z < Fx::ZERO) as usize) << 2;
        counts[octant] += 1;
        for (s, c) in sum.iter_mut().zip(v.to_f64()) {
            *s += c;
        }
    }
    let chi2 = chi_square(&counts);
    assert!(chi2 < 24.32, "chi-square {chi2} for octants {counts:?}");
    let sigma = 1.0 / (3.0 * n as f64).sqrt();
    for s in sum {
        assert!(
            (s / n as f64).abs() < 4.0 * sigma,
            "mean component {}",
            s / n as f64
        );
    }
}

fn bincode_config() -> impl bincode::config::Config {
    bincode::config::standard().with_fixed_int_encoding()
}

#[test]
fn serde_round_trip_continues_the_sequence() {
    let mut rng = Pcg32::new(42, 54);
    for _ in 0..10 {
        rng.next_u32();
    }
    let bytes = bincode::serde::encode_to_vec(&rng, bincode_config()).unwrap();
    assert_eq!(bytes.len(), 16);
    let (mut restored, read): (Pcg32, usize) =
        bincode::serde::decode_from_slice(&bytes, bincode_config()).unwrap();
    assert_eq!(read, 16);
    assert_eq!(restored, rng);
    for _ in 0..100 {
        assert_eq!(restored.next_u32(), rng.next_u32());
    }
}

#[test]
fn serialized_form_is_state_then_increment_little_endian() {
    // pcg32_srandom_r(42, 54): increment 2 · 54 + 1 = 0x6d; state 0x185706b82c2e03f8
    // (from an independent Python transcription of pcg_basic.c).
    let bytes = bincode::serde::encode_to_vec(Pcg32::new(42, 54), bincode_config()).unwrap();
    let mut expected = 0x1857_06b8_2c2e_03f8u64.to_le_bytes().to_vec();
    expected.extend_from_slice(&0x6du64.to_le_bytes());
    assert_eq!(bytes, expected);
}

#[test]
fn hash_state_writes_state_then_increment() {
    let mut rng = Pcg32::new(1, 2);
    rng.next_u64();
    let mut from_rng = StateHasher::new();
    rng.hash_state(&mut from_rng);
    let mut from_bytes = StateHasher::new();
    from_bytes.write_bytes(&bincode::serde::encode_to_vec(&rng, bincode_config()).unwrap());
    assert_eq!(from_rng.finish(), from_bytes.finish());
}
