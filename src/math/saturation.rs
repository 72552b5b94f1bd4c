//! The saturation counter.
//!
//! Every fixed-point operation that leaves the representable range clamps to the nearest
//! bound and adds one to this counter; so does a division by zero. The world reads the
//! counter around a tick and reports it (the `saturations` metric). The counter is
//! diagnostic: it is kept per thread, outside the simulated state, and never enters a
//! checksum. It costs nothing on the common path, since it is only touched on saturation.

use std::cell::Cell;

use super::{Real, Vec3};

thread_local! {
    static SATURATIONS: Cell<u64> = const { Cell::new(0) };
}

/// Records one saturation event. Called only on the cold path of an operator.
#[cold]
#[inline(never)]
pub(crate) fn record_saturation() {
    SATURATIONS.with(|c| c.set(c.get().wrapping_add(1)));
}

/// The number of saturation events on this thread since it started or since the last
/// [`reset_saturation_count`].
pub fn saturation_count() -> u64 {
    SATURATIONS.with(Cell::get)
}

/// Sets this thread's saturation counter back to zero.
pub fn reset_saturation_count() {
    SATURATIONS.with(|c| c.set(0));
}

/// Adds `count` saturations, counted on other threads for work this thread asked for, to
/// this thread's counter ([`crate::parallel`]).
#[cfg_attr(not(feature = "parallel"), allow(dead_code))]
pub(crate) fn add_saturations(count: u64) {
    if count != 0 {
        SATURATIONS.with(|c| c.set(c.get().wrapping_add(count)));
    }
}

/// Runs `f` and returns its result with the number of saturations it caused on this
/// thread, leaving this thread's counter as it was before: for work done on a worker on
/// behalf of another thread, which adds the count to its own ([`add_saturations`]).
#[cfg_attr(not(feature = "parallel"), allow(dead_code))]
pub(crate) fn isolate_saturations<T>(f: impl FnOnce() -> T) -> (T, u64) {
    let before = saturation_count();
    let value = f();
    let after = saturation_count();
    SATURATIONS.with(|c| c.set(before));
    (value, after.wrapping_sub(before))
}

/// Runs `f` and returns its result with the number of saturations it caused on this thread.
pub fn count_saturations<T>(f: impl FnOnce() -> T) -> (T, u64) {
    let before = saturation_count();
    let value = f();
    (value, saturation_count().wrapping_sub(before))
}

/// Whether some component of `v` lies at the edge of the numeric range, where a saturating
/// operation leaves it ([`Real::MAX`] or [`Real::MIN`]; never for `f64`, whose range a
/// simulation does not reach). Diagnostic: it finds the object a saturation is reported
/// against.
pub fn at_range_edge<R: Real>(v: Vec3<R>) -> bool {
    [v.x, v.y, v.z]
        .into_iter()
        .any(|c| c == R::MAX || c == R::MIN)
}

/// The first slot among `slots` whose vectors in any of `columns` lie at the edge of the
/// numeric range ([`at_range_edge`]).
pub(crate) fn first_at_range_edge<R: Real>(
    slots: impl IntoIterator<Item = usize>,
    columns: &[&[Vec3<R>]],
) -> Option<usize> {
    slots
        .into_iter()
        .find(|&i| columns.iter().any(|column| at_range_edge(column[i])))
}

/// Narrows an `i128` to `i64`, saturating and counting when it does not fit. The common
/// case costs one comparison (the high half against the sign of the low half).
#[inline(always)]
pub(crate) fn saturate_i128(value: i128) -> i64 {
    let narrow = value as i64;
    if narrow as i128 == value {
        narrow
    } else {
        saturate_out_of_range(value)
    }
}

/// The saturated value of an `i128` outside the `i64` range, counted.
#[cold]
#[inline(never)]
fn saturate_out_of_range(value: i128) -> i64 {
    record_saturation();
    if value > 0 { i64::MAX } else { i64::MIN }
}
