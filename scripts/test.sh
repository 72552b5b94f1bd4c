#!/usr/bin/env bash
# The project's test command (README "Testing"), over the whole workspace: formatting, lints,
# the engine crate's dependencies (no tool crate among them), the documentation (its links
# checked), every test in the test profile (debug arithmetic checks on), the engine's tests
# again in release (each run re-simulates every committed replay), the determinism matrix's
# i686 row, the lints for i686, the wasm package and the live page in headless Chromium
# (scripts/web-test.sh), and the fuzz smoke run (every seed and kept crash through every
# fuzz target, then 5 s of fuzzing per target). It ends with one line totalling both test
# runs: `tests: N passed, N failed`.
set -euo pipefail
cd "$(dirname "$0")/.."

cargo fmt --all -- --check
# The Bevy plugin (crates/fixstep-bevy) has a step of its own below: Bevy's build is the
# largest of the workspace.
cargo clippy --workspace --exclude fixstep-bevy --all-targets --locked -- -D warnings
./scripts/check-engine-deps.sh
# The developers' documentation, every intra-doc link resolved.
RUSTDOCFLAGS="-D warnings" cargo doc --workspace --exclude fixstep-bevy --locked --no-deps \
  --document-private-items

log=$(mktemp)
trap 'rm -f "$log"' EXIT
# The examples are not built here: clippy above checked them, and the matrix's row below
# builds and runs the replay verifier.
cargo test --workspace --exclude fixstep-bevy --locked --lib --bins --tests 2>&1 | tee "$log"
cargo test --workspace --exclude fixstep-bevy --locked --doc 2>&1 | tee -a "$log"
# The bounded-memory runs alone: a child's peak memory counts the spawning test process's
# own, which the other tests running beside it raise (tests/tools/cli_bounded_memory.rs).
cargo test -p fixstep-cli --locked --test tools -- --ignored cli_bounded_memory 2>&1 | tee -a "$log"
# Release arithmetic (wrapping where the checked operators would not catch it) matters to
# the engine, whose every tick the tools only call: its integration tests again, which
# re-simulate every committed replay and hold the heavy release-only cases. (Its unit tests
# compare the kernels with the scalar code bit for bit, which the debug run above does with
# every overflow checked.)
cargo test -p fixstep --locked --release --test suite 2>&1 | tee -a "$log"

# The Bevy plugin, in the same target folder: its lints, documentation and tests (two GGRS
# peers on 127.0.0.1 and sync tests, about 2 s). Bevy's crates (without default features)
# build once for the lints and once for the tests (docs/bevy.md, "Cost").
cargo clippy -p fixstep-bevy --all-targets --locked -- -D warnings
RUSTDOCFLAGS="-D warnings" cargo doc -p fixstep-bevy --locked --no-deps --document-private-items
cargo test -p fixstep-bevy --locked 2>&1 | tee -a "$log"

# The matrix's host rows would verify the committed replays a third and fourth time: both test
# runs above already re-simulate every one of them (tests/suite/replay_committed.rs) with exactly
# the host-debug and host-release settings (the test profile is the debug profile). So CI
# runs the one row that adds a target.
./scripts/determinism-matrix.sh --targets i686 --strict
# The engine's lints off x86_64 too (the row above installed the target): its code used only
# by the AVX-512 paths must not be dead elsewhere. The tool crates have no such paths.
cargo clippy -p fixstep --all-targets --locked --target i686-unknown-linux-gnu \
  --target-dir target/clippy-i686 -- -D warnings
# The wasm package and the live page in headless Chromium: the page's checksums are the
# native ones, every committed replay verifies in the browser (docs/web.md).
./scripts/web-test.sh
./scripts/fuzz.sh smoke 5

awk '/^test result:/ { passed += $4; failed += $6 }
     END { printf "tests: %d passed, %d failed\n", passed, failed }' "$log"
