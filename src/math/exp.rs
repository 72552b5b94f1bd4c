//! PLACEHOLDER — being replaced by the exp/ln kernel work.
pub(crate) fn exp_bits(_x: i64, _frac: u32) -> i64 {
    todo!()
}
pub(crate) fn ln_bits(_x: i64, _frac: u32) -> i64 {
    todo!()
}
pub(crate) fn powf_bits(_x: i64, _y: i64, _frac: u32) -> i64 {
    todo!()
}
