//! Sets `cfg(vector_kernels)` on the targets where `math::wide` has backends (x86-64:
//! AVX-512 and AVX2; aarch64: NEON; wasm32 built with `+simd128`: simd128), so that the
//! kernels and their dispatch compile there and nowhere else.

fn main() {
    // The outcome depends only on the target and its features (a change of either rebuilds
    // everything anyway): without this, any change to any file of the package would rerun
    // the script and recompile the engine.
    println!("cargo::rerun-if-changed=build.rs");
    println!("cargo::rustc-check-cfg=cfg(vector_kernels)");
    let arch = std::env::var("CARGO_CFG_TARGET_ARCH").unwrap_or_default();
    let features = std::env::var("CARGO_CFG_TARGET_FEATURE").unwrap_or_default();
    let simd128 = arch == "wasm32" && features.split(',').any(|f| f == "simd128");
    if matches!(arch.as_str(), "x86_64" | "aarch64") || simd128 {
        println!("cargo::rustc-cfg=vector_kernels");
    }
}
