#!/usr/bin/env bash
# The sample pictures of the README: one per built-in scene, docs/scenes/NAME.png, the
# iso view after 120 ticks (2 s) at 400x300. Deterministic: the same build writes the
# same bytes. Run again after adding a built-in scene or changing how things are drawn.
set -euo pipefail
cd "$(dirname "$0")/.."

ticks=120
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p docs/scenes
cargo build --release --quiet
fixstep=${CARGO_TARGET_DIR:-target}/release/fixstep
"$fixstep" scenes | while read -r name _; do
    "$fixstep" render "$name" --ticks "$ticks" --every "$ticks" --size 400x300 \
        --out "$work/$name" >/dev/null
    cp "$work/$name/tick-$(printf %06d "$ticks").png" "docs/scenes/$name.png"
    echo "docs/scenes/$name.png"
done
