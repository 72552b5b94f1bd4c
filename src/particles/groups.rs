//! Group restrictions: a force generator may act on one particle group only.

/// True when a generator restricted to `restriction` acts on a particle of `group`.
#[inline(always)]
pub(crate) fn applies_to(restriction: Option<u16>, group: u16) -> bool {
    restriction.is_none_or(|g| g == group)
}
