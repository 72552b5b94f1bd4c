#!/usr/bin/env bash
# The player page in a real browser: renders a scene with `fixstep render`, opens its
# index.html in headless Chromium (Debian's `chromium` package, installed with apt-get
# when missing and running as root; never a downloaded browser), lets it play to tick 60
# (`?stop=60`, virtual time), takes a screenshot and fails unless
#   - the page reached tick 60 (the player sets <body data-tick="60">), and
#   - the canvas is not blank: at least 0.5 % of the canvas below its overlays (x 11 to
#     650, y 80 to 490 of the screenshot) is body or particle colour (saturated pixels; the
#     canvas background and the ground are grey).
# Usage: scripts/viewer-browser.sh [SCENE] [OUT_DIR]   (default: showcase, a temp dir)
# Not part of scripts/test.sh: CI may lack a browser.
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-target}

scene=${1:-showcase}
out=${2:-$(mktemp -d)}
browser=${CHROMIUM:-chromium}

if ! command -v "$browser" >/dev/null; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
        apt-get install -y chromium >/dev/null
    else
        echo "viewer-browser: no $browser; install Debian's chromium package" >&2
        exit 2
    fi
fi

cargo run --release --quiet -- render "$scene" --ticks 120 --every 2 --size 640x480 \
    --out "$out/render"
url="file://$(cd "$out/render" && pwd)/index.html?stop=60"
flags=(--headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=900,700
       --virtual-time-budget=5000)

"$browser" "${flags[@]}" --screenshot="$out/screenshot.png" "$url" 2>/dev/null
"$browser" "${flags[@]}" --dump-dom "$url" 2>/dev/null >"$out/dom.html"

if ! grep -q 'data-tick="60"' "$out/dom.html"; then
    echo "viewer-browser: FAIL: the player did not reach tick 60 ($out/dom.html)" >&2
    exit 1
fi

python3 - "$out/screenshot.png" <<'PY'
"""Fails unless at least 0.5 % of the canvas area is saturated colour."""
import struct
import sys
import zlib

data = open(sys.argv[1], "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
pos, idat, header = 8, b"", None
while pos < len(data):
    length, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + length]
    if kind == b"IHDR":
        header = struct.unpack(">IIBBBBB", body)
    elif kind == b"IDAT":
        idat += body
    pos += 12 + length
width, height, depth, colour_type, _, _, interlace = header
assert depth == 8 and interlace == 0 and colour_type in (2, 6), header
channels = 3 if colour_type == 2 else 4
raw = zlib.decompress(idat)
stride = width * channels
previous = bytearray(stride)
saturated = 0
for y in range(height):
    line = raw[y * (stride + 1):(y + 1) * (stride + 1)]
    kind, row = line[0], bytearray(line[1:])
    for i in range(stride):
        a = row[i - channels] if i >= channels else 0
        b = previous[i]
        c = previous[i - channels] if i >= channels else 0
        if kind == 1:
            row[i] = (row[i] + a) & 255
        elif kind == 2:
            row[i] = (row[i] + b) & 255
        elif kind == 3:
            row[i] = (row[i] + (a + b) // 2) & 255
        elif kind == 4:
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            row[i] = (row[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    if 80 <= y < 490:
        for x in range(11 * channels, 650 * channels, channels):
            r, g, b = row[x], row[x + 1], row[x + 2]
            if max(r, g, b) - min(r, g, b) > 40:
                saturated += 1
    previous = row
share = saturated / ((650 - 11) * (490 - 80))
print(f"viewer-browser: screenshot {width}x{height}, {100 * share:.2f} % of the canvas in colour")
if share < 0.005:
    sys.exit("viewer-browser: FAIL: the canvas is blank")
PY
echo "viewer-browser: ok: the player reached tick 60 and drew it ($out/screenshot.png)"
