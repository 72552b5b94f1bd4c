use super::*;
use crate::math::saturation::{count_saturations, record_saturation};

#[test]
fn thread_counts_parse_with_their_bounds() {
    assert_eq!(parse_threads("0"), Ok(0));
    assert_eq!(parse_threads(" 8 "), Ok(8));
    assert_eq!(parse_threads("1024"), Ok(MAX_THREADS));
    for bad in ["", "-1", "two", "1025", "1.5"] {
        let why = parse_threads(bad).unwrap_err();
        assert!(why.contains("not a thread count"), "{bad}: {why}");
    }
    assert!(resolve_threads(0) >= 1);
    assert_eq!(resolve_threads(3), 3);
}

#[test]
fn chunks_cover_the_range_in_order() {
    let ranges: Vec<_> = chunks(10, 4).collect();
    assert_eq!(ranges, [0..4, 4..8, 8..10]);
    assert_eq!(chunks(0, 4).count(), 0);
}

/// Each helper gives the plain loop's result on 1, 2, 3 and 8 threads, and hands the
/// saturations its workers counted back to the caller.
#[test]
fn helpers_give_the_plain_loops_result_at_any_thread_count() {
    let n = 1000;
    let expected: Vec<u64> = (0..n as u64).map(|i| i * i + 7).collect();
    for threads in [1, 2, 3, 8] {
        let pool = Pool::new(threads);
        let ((mapped, folded, written), saturations) = count_saturations(|| {
            pool.run(|| {
                let mapped = map_collect(n, 16, |i| {
                    if i % 100 == 0 {
                        record_saturation();
                    }
                    (i as u64) * (i as u64) + 7
                });
                let folded = fold_chunks(
                    n,
                    64,
                    |range| range.map(|i| i as u64).sum::<u64>(),
                    0u64,
                    |a, part| a.wrapping_mul(31).wrapping_add(part),
                );
                let mut written = vec![0u64; n];
                for_each_mut(&mut written, 8, |i, x| *x = (i as u64) * (i as u64) + 7);
                for_each_chunk_mut(&mut written, 50, |start, chunk| {
                    for (k, &x) in chunk.iter().enumerate() {
                        let i = (start + k) as u64;
                        assert_eq!(x, i * i + 7);
                    }
                });
                let mut left = vec![0u64; n];
                let mut right = vec![0u64; n];
                for_each_zip_mut(&mut left, &mut right, 30, |i, l, r| {
                    *l = i as u64;
                    *r = 2 * i as u64;
                });
                assert!(left.iter().zip(&right).all(|(l, r)| 2 * l == *r));
                let sums = map_chunks_mut(&mut left, 64, |start, chunk| {
                    chunk.iter_mut().for_each(|x| *x += 1);
                    (start, chunk.iter().sum::<u64>())
                });
                assert_eq!(sums.len(), n.div_ceil(64));
                assert!(
                    sums.iter()
                        .enumerate()
                        .all(|(c, &(start, _))| start == c * 64)
                );
                assert_eq!(
                    sums.iter().map(|s| s.1).sum::<u64>(),
                    (1..=n as u64).sum::<u64>()
                );
                (mapped, folded, written)
            })
        });
        assert_eq!(mapped, expected, "{threads} threads");
        assert_eq!(written, expected, "{threads} threads");
        let serial = chunks(n, 64)
            .map(|r| r.map(|i| i as u64).sum::<u64>())
            .fold(0u64, |a, part| a.wrapping_mul(31).wrapping_add(part));
        assert_eq!(folded, serial, "{threads} threads");
        assert_eq!(saturations, 10, "{threads} threads");
    }
}

/// Jobs and sorted scatters give the plain loop's result on 1, 2, 3 and 8 threads, the
/// scatter's chunks falling on uneven index ranges, and count the jobs' saturations.
#[test]
fn jobs_and_scatters_give_the_plain_loops_result_at_any_thread_count() {
    let n = 10_000;
    // Every third index, written from slot 2·index + 1.
    let writes: Vec<(u32, u32)> = (0..n as u32)
        .filter(|i| i % 3 == 0)
        .map(|i| (i, 2 * i + 1))
        .collect();
    for threads in [1, 2, 3, 8] {
        let pool = Pool::new(threads);
        let ((items, doubled), saturations) = count_saturations(|| {
            pool.run(|| {
                let mut items = vec![0u64; n];
                scatter_sorted(&mut items, &writes, |x, slot| *x = slot as u64);
                let mut doubled = vec![0u64; n];
                let jobs: Vec<_> = doubled.chunks_mut(700).enumerate().collect();
                for_each_job(jobs, |(c, chunk)| {
                    record_saturation();
                    for (k, x) in chunk.iter_mut().enumerate() {
                        *x = 2 * (c * 700 + k) as u64;
                    }
                });
                (items, doubled)
            })
        });
        for (i, &x) in items.iter().enumerate() {
            let want = if i % 3 == 0 { 2 * i as u64 + 1 } else { 0 };
            assert_eq!(x, want, "{threads} threads, item {i}");
        }
        assert!(doubled.iter().enumerate().all(|(i, &x)| x == 2 * i as u64));
        assert_eq!(saturations, n.div_ceil(700) as u64, "{threads} threads");
    }
}

#[test]
fn one_thread_has_no_workers_and_does_not_split() {
    let pool = Pool::new(1);
    assert_eq!(pool.threads(), 1);
    assert!(!pool.run(splits));
    assert!(!splits());
}

#[cfg(all(feature = "parallel", not(target_arch = "wasm32")))]
#[test]
fn a_pool_of_two_splits_and_is_shared() {
    let a = Pool::new(2);
    let b = Pool::new(2);
    assert_eq!(a.threads(), 2);
    assert!(a.run(splits));
    let (Some(a), Some(b)) = (&a.workers, &b.workers) else {
        panic!("no workers");
    };
    assert!(std::sync::Arc::ptr_eq(a, b));
}
