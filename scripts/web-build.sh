#!/usr/bin/env bash
# Builds the fixstep-web wasm package into web/pkg/ (an npm-style package folder:
# package.json, README.md, fixstep_web.js, fixstep_web.d.ts, fixstep_web_bg.wasm), for the
# live page web/index.html. Built for wasm32-unknown-unknown with the simd128 kernels
# (RUSTFLAGS="-C target-feature=+simd128"); with --scalar also without them, into
# web/pkg/scalar/ (the page loads it with ?kernels=scalar).
# Built in the `wasm` profile (Cargo.toml: small rather than fastest), or the cargo profile
# WASM_PROFILE names (the same bits in every profile; `release` builds faster). Adds the rustup
# target when missing, and installs wasm-bindgen-cli, exactly the version of the
# wasm-bindgen crate in Cargo.lock, from source with cargo into target/tools when missing
# (no prebuilt binary is downloaded).
# Usage: scripts/web-build.sh [--scalar]
set -euo pipefail
cd "$(dirname "$0")/.."
target=${CARGO_TARGET_DIR:-target}
profile=${WASM_PROFILE:-wasm}

scalar=0
for a in "$@"; do
  case $a in
    --scalar) scalar=1 ;;
    -h|--help) sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "error: unknown argument \`$a\` (see --help)" >&2; exit 2 ;;
  esac
done

if command -v rustup >/dev/null \
   && ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
  rustup target add wasm32-unknown-unknown
fi

# The wasm-bindgen crate's version, as Cargo.lock pins it.
version=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/[^0-9.]/, ""); print; exit }' Cargo.lock)
tools=$PWD/$target/tools
bindgen=$tools/bin/wasm-bindgen
if [[ ! -x $bindgen ]] || [[ $("$bindgen" --version) != "wasm-bindgen $version" ]]; then
  echo "web-build: installing wasm-bindgen-cli $version into $tools (once; a few minutes)" >&2
  # --locked first; the registry mirror may lack a dependency version the CLI's lock file
  # names, and then cargo resolves it again (same CLI version).
  cargo install --locked --version "$version" wasm-bindgen-cli --root "$tools" \
    || cargo install --version "$version" wasm-bindgen-cli --root "$tools"
fi

build() { # build OUT_DIR TARGET_SUBDIR [RUSTFLAGS]
  RUSTFLAGS="${RUSTFLAGS:-} ${3:-}" cargo build --profile "$profile" --locked -p fixstep-web \
    --target wasm32-unknown-unknown --target-dir "$target/$2"
  "$bindgen" --target web --remove-name-section --remove-producers-section --out-dir "$1" \
    "$target/$2/wasm32-unknown-unknown/$profile/fixstep_web.wasm"
}

rm -rf web/pkg
build web/pkg web-simd128 "-C target-feature=+simd128"
cp crates/fixstep-web/npm/package.json crates/fixstep-web/npm/README.md web/pkg/
if [[ $scalar -eq 1 ]]; then
  build web/pkg/scalar web-scalar
fi
echo "web-build: web/pkg ($(gzip -9c web/pkg/fixstep_web_bg.wasm | wc -c) bytes of wasm gzipped)"
