#!/usr/bin/env bash
# The project's test command (README "Testing"): formatting, lints, then every test in the
# test profile (debug arithmetic checks on) and again in release.
set -euo pipefail
cd "$(dirname "$0")/.."

cargo fmt --all -- --check
cargo clippy --all-targets --locked -- -D warnings
cargo test --locked
cargo test --locked --release
