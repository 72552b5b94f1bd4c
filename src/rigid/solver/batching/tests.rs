//! The batching's promises: every constraint exactly once, independent blocks sharing no
//! moving body, at most eight to a block, full blocks out as soon as they fill.

use super::{Batching, OPEN};
use crate::rigid::solver::lanes::LANES;

/// Batches `pairs` (solver bodies; body 0 and odd bodies above 100 do not move) and
/// returns the blocks.
fn batch(bodies: usize, pairs: &[(u32, u32)]) -> Vec<(bool, Vec<u32>)> {
    let moves = |i: u32| i != 0 && !(i > 100 && i % 2 == 1);
    let mut batching = Batching::default();
    // Twice, to check that reuse starts clean.
    for _ in 0..2 {
        batching.start(bodies);
        for (k, &(a, b)) in pairs.iter().enumerate() {
            batching.add(k as u32, (a, moves(a)), (b, moves(b)));
        }
        batching.finish();
    }
    let blocks: Vec<(bool, Vec<u32>)> = batching
        .blocks()
        .map(|(independent, contacts)| (independent, contacts.to_vec()))
        .collect();
    // Every contact exactly once, at most eight to a block.
    let mut seen: Vec<u32> = blocks.iter().flat_map(|(_, c)| c.iter().copied()).collect();
    seen.sort_unstable();
    assert_eq!(seen, (0..pairs.len() as u32).collect::<Vec<_>>());
    for (independent, contacts) in &blocks {
        assert!(!contacts.is_empty() && contacts.len() <= LANES);
        if *independent {
            let mut moving: Vec<u32> = contacts
                .iter()
                .flat_map(|&k| [pairs[k as usize].0, pairs[k as usize].1])
                .filter(|&i| moves(i))
                .collect();
            let before = moving.len();
            moving.sort_unstable();
            moving.dedup();
            assert_eq!(moving.len(), before, "a moving body twice in {contacts:?}");
        }
    }
    blocks
}

#[test]
fn a_chain_fills_blocks_in_contact_order() {
    // A row of 40 bodies on the ground, each touching the next: contacts (0, i) and
    // (i, i + 1).
    let mut pairs = Vec::new();
    for i in 1..=40 {
        pairs.push((0, i));
        if i < 40 {
            pairs.push((i, i + 1));
        }
    }
    let blocks = batch(41, &pairs);
    assert!(blocks.iter().all(|(independent, _)| *independent));
    // The first block is full and made of the earliest contacts that fit together.
    assert_eq!(blocks[0].1.len(), LANES);
    assert_eq!(blocks[0].1[0], 0);
    // A full block goes out when its last contact arrives: full blocks come out in the
    // order of their last contacts.
    let lasts: Vec<u32> = blocks
        .iter()
        .filter(|(_, c)| c.len() == LANES)
        .map(|(_, c)| c[LANES - 1])
        .collect();
    assert!(lasts.windows(2).all(|w| w[0] < w[1]), "{lasts:?}");
}

#[test]
fn static_and_kinematic_bodies_are_shared_freely() {
    // Eight contacts with the static body and eight with one kinematic body (101): two
    // full independent blocks.
    let mut pairs: Vec<(u32, u32)> = (1..=8).map(|i| (0, i)).collect();
    pairs.extend((11..=18).map(|i| (i, 101)));
    let blocks = batch(102, &pairs);
    assert_eq!(
        blocks,
        vec![(true, (0..8).collect()), (true, (8..16).collect())]
    );
}

#[test]
fn a_body_in_too_many_contacts_overflows_into_dependent_blocks() {
    // One body touching 40 others: each open batch can take one of its contacts, so the
    // first OPEN go to the batches and the rest are set aside, in contact order.
    let pairs: Vec<(u32, u32)> = (2..42).map(|i| (1, i)).collect();
    let blocks = batch(42, &pairs);
    let aside: Vec<u32> = blocks
        .iter()
        .filter(|(independent, _)| !independent)
        .flat_map(|(_, c)| c.iter().copied())
        .collect();
    assert_eq!(aside, (OPEN as u32..40).collect::<Vec<_>>());
    assert_eq!(
        blocks
            .iter()
            .filter(|(independent, _)| *independent)
            .count(),
        OPEN
    );
}
