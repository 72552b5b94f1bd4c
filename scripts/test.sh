#!/usr/bin/env bash
# The project's test command (README "Testing"): formatting, lints, every test in the test
# profile (debug arithmetic checks on) and again in release, the determinism matrix on the
# host (debug, release) and i686, and the fuzz smoke run (every seed and kept crash through
# every fuzz target, then 15 s of fuzzing per target). It ends with one line totalling both
# test runs: `tests: N passed, N failed`.
set -euo pipefail
cd "$(dirname "$0")/.."

cargo fmt --all -- --check
cargo clippy --all-targets --locked -- -D warnings

log=$(mktemp)
trap 'rm -f "$log"' EXIT
cargo test --locked 2>&1 | tee "$log"
cargo test --locked --release 2>&1 | tee -a "$log"

./scripts/determinism-matrix.sh --targets host-debug,host-release,i686 --strict
./scripts/fuzz.sh smoke 15

awk '/^test result:/ { passed += $4; failed += $6 }
     END { printf "tests: %d passed, %d failed\n", passed, failed }' "$log"
