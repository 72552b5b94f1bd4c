//! PLACEHOLDER — being replaced by the sqrt kernel work.
pub(crate) fn sqrt_bits(bits: i64, frac: u32) -> i64 {
    if bits <= 0 {
        return 0;
    }
    (((bits as u128) << frac).isqrt()) as i64
}
pub(crate) fn rsqrt_bits(bits: i64, frac: u32) -> i64 {
    super::fixed_scalar::div_bits(1 << frac, sqrt_bits(bits, frac), frac)
}
