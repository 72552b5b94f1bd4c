//! PLACEHOLDER — being replaced by the trig kernel work.
pub(crate) fn sin_bits(_x: i64, _frac: u32) -> i64 {
    todo!()
}
pub(crate) fn cos_bits(_x: i64, _frac: u32) -> i64 {
    todo!()
}
pub(crate) fn sin_cos_bits(_x: i64, _frac: u32) -> (i64, i64) {
    todo!()
}
pub(crate) fn atan2_bits(_y: i64, _x: i64, _frac: u32) -> i64 {
    todo!()
}
pub(crate) fn asin_bits(_x: i64, _frac: u32) -> i64 {
    todo!()
}
pub(crate) fn acos_bits(_x: i64, _frac: u32) -> i64 {
    todo!()
}
