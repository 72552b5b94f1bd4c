#!/usr/bin/env bash
# Re-records everything derived from the engine's output, after a deliberate change that
# alters checksums (bump STATE_VERSION in src/world/pipeline.rs first):
#   - scenes/<builtin>.ron, serialised from the built-in scenes;
#   - replays/<builtin>.replay, one per built-in scene (`fixstep run NAME --record ...`);
#   - every other replay in replays/, from its own scene and inputs (`fixstep rerecord`).
# Review the diff, run ./scripts/test.sh, and commit the results together with the change.
set -euo pipefail
cd "$(dirname "$0")/.."

cargo build --release --locked
fixstep=${CARGO_TARGET_DIR:-target}/release/fixstep

FIXSTEP_BLESS=1 cargo test --release --locked --test tools -- \
  --exact cli_scene_files::builtin_scene_files_match_the_builtins

mkdir -p replays
builtins=()
while read -r name _; do
  builtins+=("$name")
  "$fixstep" run "$name" --record "replays/$name.replay" >/dev/null
  echo "recorded replays/$name.replay"
done < <("$fixstep" scenes)

for file in replays/*.replay; do
  name=$(basename "$file" .replay)
  if [[ ! " ${builtins[*]} " =~ " $name " ]]; then
    "$fixstep" rerecord "$file"
  fi
done

"$fixstep" verify replays/*.replay
