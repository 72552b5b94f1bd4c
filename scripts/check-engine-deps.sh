#!/usr/bin/env bash
# The engine crate carries nothing a game doesn't need: `cargo tree -p fixstep -e normal`
# must list none of the tools' dependencies, and the engine must compile without its
# default features (no RON). Exits 1, naming what leaked in, otherwise 0.
set -euo pipefail
cd "$(dirname "$0")/.."

tools='clap|plotters|tiny-skia|gif|png|ggrs|bevy|bevy_ggrs|proptest|criterion|fixstep-cli|fixstep-viewer|fixstep-net|fixstep-bench|fixstep-scenes|fixstep-bevy'
leaked=$(cargo tree --locked -p fixstep -e normal --prefix none | awk '{print $1}' \
  | grep -xE "$tools" | sort -u || true)
if [ -n "$leaked" ]; then
  echo "engine dependencies: the fixstep crate pulls in tool crates: $(echo "$leaked" | tr '\n' ' ')" >&2
  exit 1
fi
cargo check --locked --quiet -p fixstep --no-default-features
echo "engine dependencies: $(cargo tree --locked -p fixstep -e normal --depth 1 --prefix none | tail -n +2 | awk '{print $1}' | sort -u | tr '\n' ' ')"
