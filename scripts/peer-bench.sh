#!/usr/bin/env bash
# fixstep beside Rapier 0.36 and salva3d 0.11 on identical scenes, in one run per Rapier mode
# (bench/peers, a package outside the fixstep workspace: the test command never builds
# the peers). Builds the comparison twice, with Rapier's default mode and with its
# enhanced-determinism mode, and prints one table for each: per scene and engine the
# median ms per step over ROUNDS interleaved runs, the ratio to fixstep I32F32 and a
# quality figure computed the same way for every engine.
#   ./scripts/peer-bench.sh [ROUNDS] [SCENE ...]     (default 5 rounds, every scene)
# SCENE also takes `queries` (rays and sphere overlaps on balls and pyramid, queries/s) and
# `filters` (fixstep's balls with non-default filters against the default).
# The first build downloads and compiles Rapier (a few minutes on two cores).
set -euo pipefail
cd "$(dirname "$0")/../bench/peers"

target=${CARGO_TARGET_DIR:-target}
cargo build --release --locked --target-dir "$target/default"
cargo build --release --locked --target-dir "$target/enhanced-determinism" \
  --features enhanced-determinism

echo "# Rapier default"
"$target/default/release/fixstep-peers" "$@"
echo
echo "# Rapier enhanced-determinism"
"$target/enhanced-determinism/release/fixstep-peers" "$@"
