//! Sets `cfg(vector_kernels)` on the targets where `math::wide` has backends (x86-64:
//! AVX-512 and AVX2; aarch64: NEON), so that the kernels and their dispatch compile there
//! and nowhere else.

fn main() {
    println!("cargo::rustc-check-cfg=cfg(vector_kernels)");
    let arch = std::env::var("CARGO_CFG_TARGET_ARCH").unwrap_or_default();
    if matches!(arch.as_str(), "x86_64" | "aarch64") {
        println!("cargo::rustc-cfg=vector_kernels");
    }
}
