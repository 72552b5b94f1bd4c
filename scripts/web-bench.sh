#!/usr/bin/env bash
# Steps per second of pyramid, balls and cloth in headless Chromium, wasm with and without
# simd128 (scripts/web-build.sh --scalar), beside the native `fixstep run NAME --ticks N`
# (its wall time) on the same machine; the page's load to first frame; the package's wasm
# gzipped. FIXSTEP=path uses that native binary instead of building the release one;
# SCALAR=0 builds and measures only the simd128 package.
# Usage: scripts/web-bench.sh [NAME:TICKS ...]   (default pyramid:500 balls:100 cloth:300)
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-target}
scenes=("$@")
[[ ${#scenes[@]} -gt 0 ]] || scenes=(pyramid:500 balls:100 cloth:300)

if [[ ${SCALAR:-1} == 0 ]]; then ./scripts/web-build.sh >&2; else ./scripts/web-build.sh --scalar >&2; fi
if [[ -z ${FIXSTEP:-} ]]; then
  cargo build --release --locked --quiet -p fixstep-cli
  FIXSTEP=$CARGO_TARGET_DIR/release/fixstep
fi
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 scripts/web-serve.py "$port" . >/dev/null 2>&1 &
server=$!
trap 'kill "$server" 2>/dev/null || true' EXIT
sleep 1

echo "# $(date -u +%F), $(git rev-parse --short HEAD), $(chromium --version), load $(cut -d' ' -f1 /proc/loadavg)"
for pair in "${scenes[@]}"; do
  name=${pair%%:*} ticks=${pair##*:}
  ms=$("$FIXSTEP" run "$name" --ticks "$ticks" | sed -n 's/.* \([0-9.]*\) ms wall$/\1/p')
  echo "steps $name native $ticks $ms"
done
node --experimental-websocket --no-warnings scripts/web-bench.mjs chromium \
  "http://127.0.0.1:$port" "$(IFS=,; echo "${scenes[*]}")"
echo "wasm-gzipped $(gzip -9c web/pkg/fixstep_web_bg.wasm | wc -c) bytes"
