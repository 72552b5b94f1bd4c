//! Multithreaded stepping that keeps the thread count out of the bits.
//!
//! A [`World`](crate::world::World) owns a [`Pool`] of worker threads (feature `parallel`,
//! on by default; [`World::set_threads`](crate::world::World::set_threads)). Its step runs
//! on the pool ([`Pool::run`]), and the stages hand their loops to the helpers below, which
//! split the loop across the workers when called on one and are a plain loop otherwise: with
//! one thread (the default), without the feature, or on wasm32, they cost nothing.
//!
//! **The rule that keeps the thread count out of the result.** A helper gives each item to
//! one call of its closure, which may read shared data and write only that item (its own
//! slot, its own output): no item sees another item's result of the same loop, so the items
//! may run in any order, on any thread, in any grouping, and give the same bits. Where a loop
//! sums (energies, metrics), it cuts the items into chunks whose size comes from the data
//! ([`fold_chunks`]), never from the thread count, and folds the chunks' partial results in
//! chunk order. No helper uses `unsafe`.
//!
//! Saturations counted on a worker ([`crate::math::saturation`], per thread) are handed back
//! to the thread that called the helper, so a tick reports the same count on any number of
//! threads.

use std::ops::Range;

#[cfg(feature = "parallel")]
use crate::math::saturation::{add_saturations, isolate_saturations};

/// The environment variable that sets a new world's thread count.
pub const THREADS_VARIABLE: &str = "FIXSTEP_THREADS";

/// The most threads a pool may have.
pub const MAX_THREADS: usize = 1024;

/// The thread count `FIXSTEP_THREADS` asks for: unset or empty is 1, `0` is every core
/// ([`resolve_threads`]), otherwise a count from 1 to [`MAX_THREADS`]; an error says why
/// another value is not one. The library ignores a bad value (one thread); the `fixstep`
/// command refuses it (exit 2).
pub fn threads_from_env() -> Result<usize, String> {
    let value = std::env::var(THREADS_VARIABLE).unwrap_or_default();
    if value.is_empty() {
        return Ok(1);
    }
    parse_threads(&value).map_err(|why| format!("environment variable {THREADS_VARIABLE}: {why}"))
}

/// A thread count as written by a user: `0` (every core) or 1 to [`MAX_THREADS`].
pub fn parse_threads(value: &str) -> Result<usize, String> {
    match value.trim().parse::<usize>() {
        Ok(n) if n <= MAX_THREADS => Ok(n),
        _ => Err(format!(
            "`{value}` is not a thread count (0 for every core, or 1 to {MAX_THREADS})"
        )),
    }
}

/// The thread count a program chose for the worlds it builds from now on
/// ([`set_default_threads`]); `usize::MAX` while it chose none.
static DEFAULT_THREADS: std::sync::atomic::AtomicUsize =
    std::sync::atomic::AtomicUsize::new(usize::MAX);

/// Sets the thread count of the worlds built from now on in this process (0: every core),
/// in place of `FIXSTEP_THREADS` (the `fixstep` command's `--threads`). A world's own
/// [`World::set_threads`](crate::world::World::set_threads) still overrides it.
pub fn set_default_threads(threads: usize) {
    DEFAULT_THREADS.store(
        threads.min(MAX_THREADS),
        std::sync::atomic::Ordering::Relaxed,
    );
}

/// The thread count a new world starts with: the program's [`set_default_threads`], else
/// `FIXSTEP_THREADS` ([`threads_from_env`]; 1 when it is unset or not a count).
pub fn default_threads() -> usize {
    match DEFAULT_THREADS.load(std::sync::atomic::Ordering::Relaxed) {
        usize::MAX => threads_from_env().unwrap_or(1),
        threads => threads,
    }
}

/// `threads`, with 0 meaning the processor's cores (1 where they cannot be told).
pub fn resolve_threads(threads: usize) -> usize {
    match threads {
        0 => std::thread::available_parallelism().map_or(1, usize::from),
        n => n.min(MAX_THREADS),
    }
}

/// Worker threads a world steps on: none for one thread.
#[derive(Debug, Clone)]
pub struct Pool {
    threads: usize,
    #[cfg(feature = "parallel")]
    workers: Option<std::sync::Arc<rayon::ThreadPool>>,
}

impl Default for Pool {
    /// One thread: no workers.
    fn default() -> Self {
        Self {
            threads: 1,
            #[cfg(feature = "parallel")]
            workers: None,
        }
    }
}

impl Pool {
    /// A pool of `threads` threads (0: every core, [`resolve_threads`]). One thread, a build
    /// without the `parallel` feature, or a platform that cannot start threads (wasm32) gets
    /// no workers, and [`Pool::threads`] then says 1.
    pub fn new(threads: usize) -> Self {
        #[cfg(feature = "parallel")]
        {
            let threads = resolve_threads(threads);
            if threads >= 2
                && let Some(workers) = shared_workers(threads)
            {
                return Self {
                    threads,
                    workers: Some(workers),
                };
            }
        }
        #[cfg(not(feature = "parallel"))]
        let _ = threads;
        Self::default()
    }

    /// A pool of the thread count a new world starts with ([`default_threads`]).
    pub fn process_default() -> Self {
        Self::new(default_threads())
    }

    /// The threads the pool runs on (1 without workers).
    pub fn threads(&self) -> usize {
        self.threads
    }

    /// Runs `f` on one of the pool's workers, where the helpers of this module split their
    /// loops across the pool; without workers, runs `f` here. The saturations `f` counts are
    /// added to this thread's counter.
    pub fn run<T: Send>(&self, f: impl FnOnce() -> T + Send) -> T {
        #[cfg(feature = "parallel")]
        if let Some(workers) = &self.workers {
            let (value, saturations) = workers.install(|| isolate_saturations(f));
            add_saturations(saturations);
            return value;
        }
        f()
    }
}

/// The process's pool of `threads` workers, started on first use and shared by the worlds
/// that ask for that many (a verifier's hundred worlds start no thousand threads); `None`
/// where threads cannot be started.
#[cfg(feature = "parallel")]
fn shared_workers(threads: usize) -> Option<std::sync::Arc<rayon::ThreadPool>> {
    use std::sync::{Arc, Mutex, Weak};
    static POOLS: Mutex<Vec<(usize, Weak<rayon::ThreadPool>)>> = Mutex::new(Vec::new());
    let mut pools = POOLS
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner());
    pools.retain(|(_, pool)| pool.strong_count() > 0);
    if let Some(pool) = pools
        .iter()
        .find(|(n, _)| *n == threads)
        .and_then(|(_, pool)| pool.upgrade())
    {
        return Some(pool);
    }
    let pool = Arc::new(
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .thread_name(|i| format!("fixstep-{i}"))
            .build()
            .ok()?,
    );
    pools.push((threads, Arc::downgrade(&pool)));
    Some(pool)
}

/// Whether the helpers split their loops: on a worker of a pool of two threads or more.
#[inline]
pub fn splits() -> bool {
    #[cfg(feature = "parallel")]
    {
        rayon::current_thread_index().is_some() && rayon::current_num_threads() > 1
    }
    #[cfg(not(feature = "parallel"))]
    false
}

/// `f(i, &mut items[i])` for every item, in chunks of `chunk_len` items on the workers (the
/// loop splits only when [`splits`]). Each call may write only its item.
pub fn for_each_mut<T: Send>(items: &mut [T], chunk_len: usize, f: impl Fn(usize, &mut T) + Sync) {
    for_each_chunk_mut(items, chunk_len, |start, chunk| {
        for (i, item) in chunk.iter_mut().enumerate() {
            f(start + i, item);
        }
    });
}

/// `f(start, chunk)` for consecutive chunks of `chunk_len` items (the last may be shorter),
/// each chunk starting at item `start`, when the loop splits ([`splits`]); otherwise one
/// call `f(0, items)` over the whole slice. Each call may write only its chunk, and an
/// item's result may not depend on where its chunk starts. For loops whose body wants a
/// slice (a vector kernel).
pub fn for_each_chunk_mut<T: Send>(
    items: &mut [T],
    chunk_len: usize,
    f: impl Fn(usize, &mut [T]) + Sync,
) {
    let chunk_len = chunk_len.max(1);
    #[cfg(feature = "parallel")]
    if items.len() > chunk_len && splits() {
        use rayon::prelude::*;
        let saturations: u64 = items
            .par_chunks_mut(chunk_len)
            .enumerate()
            .map(|(c, chunk)| isolate_saturations(|| f(c * chunk_len, chunk)).1)
            .sum();
        add_saturations(saturations);
        return;
    }
    #[cfg(not(feature = "parallel"))]
    let _ = chunk_len;
    f(0, items);
}

/// `f(i, &mut a[i], &mut b[i])` for every index of two slices of one length, in chunks of
/// `chunk_len` indices on the workers (the loop splits only when [`splits`]). Each call may
/// write only its two items.
pub fn for_each_zip_mut<A: Send, B: Send>(
    a: &mut [A],
    b: &mut [B],
    chunk_len: usize,
    f: impl Fn(usize, &mut A, &mut B) + Sync,
) {
    assert_eq!(a.len(), b.len(), "zipped slices of different lengths");
    let chunk_len = chunk_len.max(1);
    #[cfg(feature = "parallel")]
    if a.len() > chunk_len && splits() {
        use rayon::prelude::*;
        let saturations: u64 = a
            .par_chunks_mut(chunk_len)
            .zip(b.par_chunks_mut(chunk_len))
            .enumerate()
            .map(|(c, (a, b))| {
                isolate_saturations(|| {
                    for (i, (a, b)) in a.iter_mut().zip(b).enumerate() {
                        f(c * chunk_len + i, a, b);
                    }
                })
                .1
            })
            .sum();
        add_saturations(saturations);
        return;
    }
    #[cfg(not(feature = "parallel"))]
    let _ = chunk_len;
    for (i, (a, b)) in a.iter_mut().zip(b).enumerate() {
        f(i, a, b);
    }
}

/// `[f(0, chunk₀), f(chunk_len, chunk₁), …]` over consecutive chunks of `chunk_len` items
/// (the last may be shorter), in chunk order whatever ran where (the loop splits only when
/// [`splits`]). Each call may write only its chunk. The chunks, and so a reduction that folds
/// the results in order, depend on `chunk_len` only.
pub fn map_chunks_mut<T: Send, U: Send>(
    items: &mut [T],
    chunk_len: usize,
    f: impl Fn(usize, &mut [T]) -> U + Sync,
) -> Vec<U> {
    let chunk_len = chunk_len.max(1);
    #[cfg(feature = "parallel")]
    if items.len() > chunk_len && splits() {
        use rayon::prelude::*;
        let parts: Vec<(U, u64)> = items
            .par_chunks_mut(chunk_len)
            .enumerate()
            .map(|(c, chunk)| isolate_saturations(|| f(c * chunk_len, chunk)))
            .collect();
        let mut saturations = 0;
        let values = parts
            .into_iter()
            .map(|(value, s)| {
                saturations += s;
                value
            })
            .collect();
        add_saturations(saturations);
        return values;
    }
    items
        .chunks_mut(chunk_len)
        .enumerate()
        .map(|(c, chunk)| f(c * chunk_len, chunk))
        .collect()
}

/// `[f(0), f(1), …, f(n - 1)]`, in index order whatever ran where, in chunks of `chunk_len`
/// calls on the workers (the loop splits only when [`splits`]).
pub fn map_collect<T: Send>(n: usize, chunk_len: usize, f: impl Fn(usize) -> T + Sync) -> Vec<T> {
    let chunk_len = chunk_len.max(1);
    #[cfg(feature = "parallel")]
    if n > chunk_len && splits() {
        use rayon::prelude::*;
        let ranges: Vec<Range<usize>> = chunks(n, chunk_len).collect();
        let parts: Vec<(Vec<T>, u64)> = ranges
            .into_par_iter()
            .map(|range| isolate_saturations(|| range.map(&f).collect::<Vec<T>>()))
            .collect();
        let mut values = Vec::with_capacity(n);
        let mut saturations = 0;
        for (part, s) in parts {
            values.extend(part);
            saturations += s;
        }
        add_saturations(saturations);
        return values;
    }
    #[cfg(not(feature = "parallel"))]
    let _ = chunk_len;
    (0..n).map(f).collect()
}

/// `f(job)` for every job, on the workers when [`splits`] (a plain loop otherwise). Each
/// job owns what it writes (disjoint `&mut` pieces cut by the caller), so the jobs may run
/// in any order; the caller cuts them from the data, never from the thread count.
pub fn for_each_job<J: Send>(jobs: Vec<J>, f: impl Fn(J) + Sync) {
    #[cfg(feature = "parallel")]
    if jobs.len() > 1 && splits() {
        use rayon::prelude::*;
        let saturations: u64 = jobs
            .into_par_iter()
            .map(|job| isolate_saturations(|| f(job)).1)
            .sum();
        add_saturations(saturations);
        return;
    }
    jobs.into_iter().for_each(f);
}

/// The writes [`scatter_sorted`] hands to one call at a time.
pub const SCATTER_CHUNK: usize = 1024;

/// `f(&mut items[index], slot)` for every `(index, slot)` of `writes`, which are sorted by
/// strictly increasing index: on the workers when [`splits`], the writes cut into chunks
/// of [`SCATTER_CHUNK`] and `items` into the disjoint ranges they fall in.
pub fn scatter_sorted<T: Send>(
    items: &mut [T],
    writes: &[(u32, u32)],
    f: impl Fn(&mut T, usize) + Sync,
) {
    #[cfg(feature = "parallel")]
    if writes.len() > SCATTER_CHUNK && splits() {
        let mut jobs = Vec::with_capacity(writes.len().div_ceil(SCATTER_CHUNK));
        let mut rest = items;
        let mut base = 0;
        let mut chunks = writes.chunks(SCATTER_CHUNK).peekable();
        while let Some(chunk) = chunks.next() {
            let start = chunk[0].0 as usize;
            let end = chunks
                .peek()
                .map_or(base + rest.len(), |next| next[0].0 as usize);
            let (_, tail) = rest.split_at_mut(start - base);
            let (piece, tail) = tail.split_at_mut(end - start);
            rest = tail;
            base = end;
            jobs.push((start, piece, chunk));
        }
        for_each_job(jobs, |(start, piece, chunk)| {
            for &(index, slot) in chunk {
                f(&mut piece[index as usize - start], slot as usize);
            }
        });
        return;
    }
    for &(index, slot) in writes {
        f(&mut items[index as usize], slot as usize);
    }
}

/// The chunks of `0..n` that [`fold_chunks`] sums over: `chunk_len` indices each, the last
/// shorter; they depend on `n` and `chunk_len` only.
pub fn chunks(n: usize, chunk_len: usize) -> impl Iterator<Item = Range<usize>> {
    let chunk_len = chunk_len.max(1);
    (0..n.div_ceil(chunk_len)).map(move |c| c * chunk_len..((c + 1) * chunk_len).min(n))
}

/// A reduction in a fixed tree order: `part(range)` for each of [`chunks`]`(n, chunk_len)`
/// (in parallel when [`splits`]), then `init` folded with the parts in chunk order. The
/// result depends on `chunk_len`, never on the thread count.
pub fn fold_chunks<T: Send, A>(
    n: usize,
    chunk_len: usize,
    part: impl Fn(Range<usize>) -> T + Sync,
    init: A,
    fold: impl FnMut(A, T) -> A,
) -> A {
    let ranges: Vec<Range<usize>> = chunks(n, chunk_len).collect();
    map_collect(ranges.len(), 1, |c| part(ranges[c].clone()))
        .into_iter()
        .fold(init, fold)
}

#[cfg(test)]
mod tests;
