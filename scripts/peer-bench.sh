#!/usr/bin/env bash
# fixstep beside Rapier 0.36 and salva3d 0.11 on identical scenes, in one run per Rapier mode
# (bench/peers, a package outside the fixstep workspace: the test command never builds
# the peers). Builds the comparison twice, with Rapier's default mode and with its
# enhanced-determinism mode, and prints one table for each: per scene and engine the
# median ms per step over ROUNDS interleaved runs, the ratio to fixstep I32F32 and a
# quality figure computed the same way for every engine.
#   ./scripts/peer-bench.sh [ROUNDS] [SCENE ...]          (default 5 rounds, every scene)
#   ./scripts/peer-bench.sh --wasm [ROUNDS] [SCENE ...]
#   ./scripts/peer-bench.sh --threads N [ROUNDS] [SCENE ...]
# SCENE also takes `queries` (rays and sphere overlaps on balls and pyramid, queries/s) and
# `filters` (fixstep's balls with non-default filters against the default) and `characters`
# (1000 characters among 10,000 boxes beside Rapier's KinematicCharacterController) and `energy`
# (energy drift of pendulums, a spinning hinge wheel and a touching cradle; no timing).
# --wasm: what a browser game pays. Builds the comparison for wasm32-wasip1, with Rapier's
# enhanced-determinism mode only (its cross-platform mode, the one fixstep is compared
# with), once plain and once with RUSTFLAGS="-C target-feature=+simd128" (fixstep's
# simd128 kernels; every crate compiled for simd128), into $target/wasm-plain and
# $target/wasm-simd128, and runs each under Node's WASI (scripts/wasi-run.mjs; needs
# Node >= 20 and `rustup target add wasm32-wasip1`). FIXSTEP_SIMD reaches the wasm
# program (`scalar` caps the simd128 build's kernels).
# $target is ${CARGO_TARGET_DIR:-target}, relative to bench/peers.
# --threads N: both engines on threads (Rapier's `parallel` feature on rayon, fixstep's
# pool), built once into $target/parallel and run at 1 thread, then at N
# (RAYON_NUM_THREADS and FIXSTEP_THREADS), in Rapier's default mode.
# The first build downloads and compiles Rapier (a few minutes on two cores).
set -euo pipefail

wasm=0 threads=0 args=()
while [[ $# -gt 0 ]]; do
  a=$1; shift
  case $a in
    --wasm) wasm=1 ;;
    --threads)
      threads=${1:-}; shift || true
      if [[ ! $threads =~ ^[1-9][0-9]*$ ]]; then
        echo "error: --threads takes a positive whole number, not \`$threads\`" >&2
        exit 2
      fi ;;
    -h|--help) sed -n '2,26p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "error: unknown option \`$a\` (see --help)" >&2; exit 2 ;;
    *) args+=("$a") ;;
  esac
done
if [[ ${#args[@]} -gt 0 && ! ${args[0]} =~ ^[1-9][0-9]*$ ]]; then
  echo "error: ROUNDS must be a positive whole number, not \`${args[0]}\` (see --help)" >&2
  exit 2
fi
cd "$(dirname "$0")/../bench/peers"

target=${CARGO_TARGET_DIR:-target}
if [[ $threads -gt 0 ]]; then
  cargo build --release --locked --target-dir "$target/parallel" --features parallel
  for n in 1 "$threads"; do
    echo "# Rapier parallel and fixstep, $n thread(s)"
    RAYON_NUM_THREADS=$n FIXSTEP_THREADS=$n "$target/parallel/release/fixstep-peers" "${args[@]}"
    echo
  done
  exit 0
fi
if [[ $wasm -eq 0 ]]; then
  cargo build --release --locked --target-dir "$target/default"
  cargo build --release --locked --target-dir "$target/enhanced-determinism" \
    --features enhanced-determinism

  echo "# Rapier default"
  "$target/default/release/fixstep-peers" "${args[@]}"
  echo
  echo "# Rapier enhanced-determinism"
  "$target/enhanced-determinism/release/fixstep-peers" "${args[@]}"
  exit 0
fi

if ! command -v node >/dev/null 2>&1 \
   || ! node --no-warnings -e "new (require('node:wasi').WASI)({version:'preview1'})" 2>/dev/null; then
  echo "error: --wasm needs Node >= 20 (node:wasi) on the PATH" >&2
  exit 2
fi
if command -v rustup >/dev/null 2>&1 \
   && ! rustup target list --installed | grep -qx wasm32-wasip1; then
  echo "error: --wasm needs the wasm32-wasip1 target: rustup target add wasm32-wasip1" >&2
  exit 2
fi
build_wasm() { # build_wasm DIR [RUSTFLAGS]
  RUSTFLAGS="${RUSTFLAGS:-} ${2:-}" cargo build --release --locked --target wasm32-wasip1 \
    --target-dir "$target/$1" --features enhanced-determinism
}
build_wasm wasm-plain
build_wasm wasm-simd128 "-C target-feature=+simd128"

run_wasm() { # run_wasm BUILD: BUILD's table under a heading
  local heading="# wasm32-wasip1 ($1), Rapier enhanced-determinism, Node $(node --version)"
  echo "$heading${FIXSTEP_SIMD:+, FIXSTEP_SIMD=$FIXSTEP_SIMD}"
  node --no-warnings ../../scripts/wasi-run.mjs \
    "$target/wasm-$1/wasm32-wasip1/release/fixstep-peers.wasm" "${args[@]}"
}
run_wasm plain
echo
run_wasm simd128
