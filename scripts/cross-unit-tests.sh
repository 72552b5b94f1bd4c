#!/usr/bin/env bash
# The engine's unit tests on the vector backends this x86_64 machine cannot run natively:
# aarch64 (NEON) under qemu-user and wasm32-wasip1 built with +simd128 under Node's WASI.
# Every kernel test runs through each backend the target has and with none, and compares
# the bits with the scalar code (as the x86-64 run does for AVX-512 and AVX2).
#
#   scripts/cross-unit-tests.sh [aarch64] [wasm32-simd128]     (default: both)
#
# Needs what the determinism matrix's aarch64 and wasm32 rows need (gcc-aarch64-linux-gnu,
# libc6-dev-arm64-cross, qemu-user, Node >= 20; `scripts/determinism-matrix.sh --targets
# aarch64,wasm32-simd128` installs them) and the rustup targets. Release builds: the tests
# run several times faster under emulation. About 3 and 2.5 minutes on the 2-core machine.
set -euo pipefail
cd "$(dirname "$0")/.."

targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=(aarch64 wasm32-simd128)
for t in "${targets[@]}"; do
    case $t in
      aarch64)
        CARGO_TARGET_AARCH64_UNKNOWN_LINUX_GNU_LINKER=aarch64-linux-gnu-gcc \
        CARGO_TARGET_AARCH64_UNKNOWN_LINUX_GNU_RUNNER="qemu-aarch64 -L /usr/aarch64-linux-gnu" \
          cargo test --locked -p fixstep --lib --release --target aarch64-unknown-linux-gnu ;;
      wasm32-simd128)
        # Node 20 at times crashes (SIGSEGV) tearing itself down after the test program
        # has returned, which cargo reports as a failed run; libtest's summary line, printed
        # before, then decides.
        log=$(mktemp)
        if ! CARGO_TARGET_WASM32_WASIP1_RUNNER="node --no-warnings $PWD/scripts/wasi-run.mjs" \
             RUSTFLAGS="${RUSTFLAGS:-} -C target-feature=+simd128" \
             cargo test --locked -p fixstep --lib --release --target wasm32-wasip1 \
             --target-dir target/matrix-simd128 2>&1 | tee "$log"; then
          grep -q '^test result: ok\.' "$log" && grep -q 'SIGSEGV' "$log" \
            || { rm -f "$log"; exit 1; }
          echo "note: the tests passed; Node crashed in its teardown afterwards"
        fi
        rm -f "$log" ;;
      *) echo "error: unknown target \`$t\` (known: aarch64, wasm32-simd128)" >&2; exit 2 ;;
    esac
done
