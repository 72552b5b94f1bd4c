#!/usr/bin/env bash
# The live page's acceptance test (run by scripts/test.sh): builds the wasm package
# (scripts/web-build.sh), installs Debian's `chromium` with apt-get when missing (as root;
# never a downloaded browser), serves the repository on 127.0.0.1 and drives the page
# headless over the DevTools protocol (scripts/web-test.mjs, Node >= 20). It fails unless
#   - pyramid, cloth and dam_break at ?scene=NAME&ticks=N show in #checksum the checksum
#     that `fixstep run NAME --ticks N` prints natively;
#   - every file in replays/, dropped on the page, verifies with the verdict `ok`;
#   - a screenshot of the pyramid is not blank;
#   - two clicks on the stack's boxes are recorded, and the replay the page downloads
#     passes the native `fixstep verify`;
#   - half a replay dropped on the page shows an error naming the section and the offset;
#   - parkour's characters and pond's water are drawn, and move with the world;
#   - the page `fixstep render pond.replay --html` writes, opened from file://, plays to the
#     checksum `fixstep run pond` prints;
#   - the console has no error and nothing is thrown uncaught.
# Usage: scripts/web-test.sh [OUT_DIR]   (default: a temporary folder, removed on success)
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-target}

out=${1:-$(mktemp -d)}
browser=${CHROMIUM:-chromium}
started=$SECONDS

if ! command -v "$browser" >/dev/null; then
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y chromium >/dev/null
  else
    echo "web-test: no $browser; install Debian's chromium package" >&2
    exit 2
  fi
fi

# The release profile: the page's bits are those of every profile, and the `wasm` profile's
# single codegen unit with fat LTO (the small download) takes minutes longer to build.
WASM_PROFILE=${WASM_PROFILE:-release} ./scripts/web-build.sh
# The native command, in the test profile that scripts/test.sh has built already.
cargo build --locked --quiet -p fixstep-cli
fixstep=$CARGO_TARGET_DIR/debug/fixstep

scenes=(pyramid:60 cloth:30 dam_break:10)
declare -A native
for pair in "${scenes[@]}"; do
  name=${pair%%:*} ticks=${pair##*:}
  native[$name]=$("$fixstep" run "$name" --ticks "$ticks" | sed -n 's/^checksum: //p')
done

port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 scripts/web-serve.py "$port" . >"$out/server.log" 2>&1 &
server=$!
trap 'kill "$server" 2>/dev/null || true' EXIT
for _ in $(seq 50); do
  curl -fs "http://127.0.0.1:$port/web/index.html" >/dev/null 2>&1 && break
  sleep 0.1
done

replays=$(cd replays && ls -- *.replay | paste -sd,)
"$fixstep" render replays/pond.replay --ticks 60 --html "$out/pond.html" \
  --web "http://127.0.0.1:$port/web/" >/dev/null
live_native=$("$fixstep" run pond --ticks 60 | sed -n 's/^checksum: //p')
status=0
node --experimental-websocket --no-warnings scripts/web-test.mjs "$browser" \
  "http://127.0.0.1:$port" "$out" "$(IFS=,; echo "${scenes[*]}")" "$replays" "$out/pond.html" \
  | tee "$out/results.txt" || status=1

for pair in "${scenes[@]}"; do
  name=${pair%%:*} ticks=${pair##*:}
  got=$(awk -v n="$name" '$1 == "checksum" && $2 == n { print $4 }' "$out/results.txt")
  if [[ $got != "${native[$name]}" ]]; then
    echo "web-test: FAIL: $name after $ticks ticks: page $got, native ${native[$name]}" >&2
    status=1
  fi
done
live=$(awk '$1 == "live-page" { print $3 }' "$out/results.txt")
if [[ $live != "$live_native" ]]; then
  echo "web-test: FAIL: the written live page ends at $live, native $live_native" >&2
  status=1
fi
recorded=$(awk '$1 == "recorded" { print $2 }' "$out/results.txt")
if [[ -z $recorded ]] || ! "$fixstep" verify "$recorded"; then
  echo "web-test: FAIL: the replay recorded in the page does not verify natively" >&2
  status=1
fi
if [[ $status -ne 0 ]]; then
  echo "web-test: FAIL ($out)" >&2
  exit 1
fi
count=$(grep -c '^replay ' "$out/results.txt")
[[ $# -ge 1 ]] || rm -rf "$out"
echo "web-test: ok: checksums as native, $count replays verified, clicks recorded and verified natively, characters and water drawn, the written live page as native ($((SECONDS - started)) s)"
