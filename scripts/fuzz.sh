#!/usr/bin/env bash
# Fuzzing fixstep's decoders and world with cargo-fuzz (libFuzzer), on stable Rust.
#
#   scripts/fuzz.sh seeds                 rebuild fuzz/seeds/ from replays/ and scenes/
#   scripts/fuzz.sh smoke [SECONDS]       run every seed and kept crash through every
#                                         target; then, if SECONDS is given, fuzz each
#                                         target for SECONDS
#   scripts/fuzz.sh run TARGET [SECONDS]  fuzz one target (default: until stopped)
#
# Targets: cli_args (fuzz/src/cli_args.rs), handshake_decode (fuzz_targets/handshake_decode.rs), mesh_obj, replay_decode,
# scene_ron, snapshot_decode, world_step (see fuzz/src/lib.rs).
# The working corpus is fuzz/corpus/TARGET (not committed), started from fuzz/seeds/TARGET.
# A crash lands in fuzz/artifacts/TARGET/; once fixed, copy it to fuzz/regressions/TARGET/,
# where `cargo test --test suite fuzz_regressions::` runs it for ever after.
#
# The targets are built with cargo itself, with the flags cargo-fuzz 0.13 gives `cargo fuzz
# run -s none` (libFuzzer's coverage instrumentation, no sanitizer, so stable works), less its
# single codegen unit: installing cargo-fuzz and compiling in one unit cost CI more than the
# fuzzing itself. With nightly and cargo-fuzz, `cargo +nightly fuzz run -s address TARGET`
# (in fuzz/) adds AddressSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."

TARGETS=(cli_args handshake_decode mesh_obj replay_decode scene_ron snapshot_decode world_step)

# libFuzzer's instrumentation, as cargo-fuzz 0.13 sets it by default on Linux.
FUZZ_RUSTFLAGS="-Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=4
  -Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table
  -Cllvm-args=-sanitizer-coverage-trace-compares -Cllvm-args=-sanitizer-coverage-stack-depth
  -Cllvm-args=-simplifycfg-branch-fold-threshold=0 --cfg fuzzing"
HOST=$(rustc -vV | sed -n 's/^host: //p')
# --target keeps the flags off build scripts; --locked builds the versions in fuzz/Cargo.lock.
build_targets() {
  (cd fuzz && RUSTFLAGS="$(echo $FUZZ_RUSTFLAGS)" cargo build --quiet --locked --release \
     --target "$HOST" --config 'profile.release.debug="line-tables-only"' --bins)
}

# The replay format (src/replay/format.rs): for the I32F32 header the scene section's length
# is the u64 at byte 54 and the section starts at byte 94, followed by the inputs section;
# world_step reads that length, then exactly those bytes.
SCENE_LEN_OFFSET=54
SCENE_OFFSET=94
# Scenes too large to make useful fuzz seeds (thousands of bodies).
SEEDLESS_SCENES=' balls falling pyramid '

seeds() {
  cargo build --release --quiet
  local bin=${CARGO_TARGET_DIR:-target}/release/fixstep dir f name
  for t in "${TARGETS[@]}"; do rm -rf "fuzz/seeds/$t"; mkdir -p "fuzz/seeds/$t"; done
  for f in replays/*.replay; do
    name=$(basename "$f" .replay)
    case "$SEEDLESS_SCENES" in *" $name "*) continue ;; esac
    cp "$f" "fuzz/seeds/replay_decode/$name"
    { head -c $((SCENE_LEN_OFFSET + 8)) "$f" | tail -c 8; tail -c +$((SCENE_OFFSET + 1)) "$f"; } \
      >"fuzz/seeds/world_step/$name"
  done
  for f in scenes/*.ron; do cp "$f" "fuzz/seeds/scene_ron/$(basename "$f" .ron)"; done
  for f in docs/scenes/*.obj; do cp "$f" "fuzz/seeds/mesh_obj/$(basename "$f" .obj)"; done
  for name in $("$bin" scenes | cut -d' ' -f1); do
    case "$SEEDLESS_SCENES" in *" $name "*) continue ;; esac
    for ticks in 1 45; do
      "$bin" run "$name" --ticks "$ticks" --snapshot "fuzz/seeds/snapshot_decode/$name-$ticks" >/dev/null
    done
  done
  cargo run --release --quiet -p fixstep-net --example handshake_seeds -- \
    fuzz/seeds/handshake_decode
  cli_seeds
  echo "seeds: $(find fuzz/seeds -type f | wc -l) files in fuzz/seeds/"
}

# The command lines cli_args starts from, arguments separated by NUL bytes: each command's
# usual forms, its refusals (bad counts, clashing outputs) and help.
cli_seeds() {
  local dir=fuzz/seeds/cli_args i=0 line
  while IFS= read -r line; do
    i=$((i + 1))
    printf '%s' "$line" | tr ' ' '\0' >"$dir/$(printf '%02d' "$i")"
  done <<'LINES'
run stack --ticks 60
run stack --ticks -1
run scenes/rigid.ron --record scenes/rigid.ron
run stack --record x.replay --metrics ./x.replay --every 0
run stack --bodies b.csv --events e.csv --snapshot s.snapshot --seed 7
run stack --from-snapshot s.snapshot --metrics s.snapshot
verify replays/stack.replay replays/cradle.replay
info replays/stack.replay
render stack --out frames --every 5 --size 320x240 --view top --flat
render stack --size 0x0 --view sideways
query stack --tick 10 --ray 0,5,0,0,-1,0 --max 20 --mask 3
query stack --cast capsule:0.1,0.5 --from 0,5,0 --dir 0,-1,0
query stack --overlap box:1,1,1 --at 0,0,0
peer --local-port 7122 --remote 127.0.0.1:7123 --player-index 1 --record p.replay --inputs p.replay
bench accuracy --quick
bench
--help
scenes --version
LINES
}

# run_target TARGET MODE: MODE `replay` runs the seeds and kept crashes once; a number
# fuzzes for that many seconds; `forever` fuzzes until stopped.
run_target() {
  local t=$1 mode=$2 limits=()
  local inputs=("corpus/$t" "seeds/$t")
  mkdir -p "fuzz/corpus/$t"
  # The kept inputs are replayed, and mutated only by an open-ended run (`run TARGET`
  # without seconds): a timed run (the test command's 5 s) that mutates a kept time-out
  # can find a variant slower still, failing the test command for a known reason that no
  # change under test caused.
  if [[ -d fuzz/regressions/$t && ( $mode == replay || $mode == forever ) ]]; then
    inputs+=("regressions/$t")
  fi
  case $mode in
    replay) limits=(-runs=0) ;;
    forever) ;;
    *) limits=(-max_total_time="$mode") ;;
  esac
  mkdir -p "fuzz/artifacts/$t"
  (cd fuzz && "target/$HOST/release/$t" -artifact_prefix="artifacts/$t/" "${inputs[@]}" \
     "${limits[@]}" -timeout=20 -rss_limit_mb=2048 -print_final_stats=1)
}

case "${1:-}" in
  seeds) seeds ;;
  smoke)
    build_targets
    for t in "${TARGETS[@]}"; do run_target "$t" replay; done
    if [[ -n ${2:-} ]]; then for t in "${TARGETS[@]}"; do run_target "$t" "$2"; done; fi
    echo "fuzz smoke: ${#TARGETS[@]} targets passed"
    ;;
  run)
    [[ -n ${2:-} ]] || { echo "usage: $0 run TARGET [SECONDS]" >&2; exit 2; }
    build_targets
    run_target "$2" "${3:-forever}"
    ;;
  *) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 2 ;;
esac
