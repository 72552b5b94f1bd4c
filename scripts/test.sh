#!/usr/bin/env bash
# The project's test command (README "Testing"): formatting, lints, then every test in the
# test profile (debug arithmetic checks on) and again in release. It ends with one line
# totalling both runs: `tests: N passed, N failed`.
set -euo pipefail
cd "$(dirname "$0")/.."

cargo fmt --all -- --check
cargo clippy --all-targets --locked -- -D warnings

log=$(mktemp)
trap 'rm -f "$log"' EXIT
cargo test --locked 2>&1 | tee "$log"
cargo test --locked --release 2>&1 | tee -a "$log"

awk '/^test result:/ { passed += $4; failed += $6 }
     END { printf "tests: %d passed, %d failed\n", passed, failed }' "$log"
