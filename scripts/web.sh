#!/usr/bin/env bash
# The live page: builds the wasm package (scripts/web-build.sh) and serves web/ on
# 127.0.0.1 (scripts/web-serve.py: nothing but files), printing the address to open.
# Usage: scripts/web.sh [PORT]   (default 8000; scene by URL: /?scene=cloth)
set -euo pipefail
cd "$(dirname "$0")/.."
port=${1:-8000}
./scripts/web-build.sh
echo
echo "fixstep live page: http://127.0.0.1:$port/  (any scene: http://127.0.0.1:$port/?scene=cloth; Ctrl-C stops)"
exec python3 scripts/web-serve.py "$port" web
