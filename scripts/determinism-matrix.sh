#!/usr/bin/env bash
# The determinism matrix: build the engine's replay verifier (examples/verify_replays.rs,
# the verification of `fixstep verify` with the engine alone, so that a target compiles no
# tool crate) for every target this x86_64 Linux machine can run, and verify every replay in
# replays/ with it (it re-simulates each replay and compares every checkpoint checksum bit
# for bit).
#
#   scripts/determinism-matrix.sh [--targets LIST] [--no-install] [--strict]
#
# Targets (default: all, in this order):
#   host-debug     x86_64, debug profile (overflow checks, debug assertions, opt-level 1)
#   host-release   x86_64, release profile
#   host-native    x86_64, release, -C target-cpu=native (FMA/AVX as the CPU allows)
#   host-avx2      host-release's binary with FIXSTEP_SIMD=avx2 (its AVX2 kernels, none of
#                  its AVX-512 ones: what an x86-64 processor without AVX-512 runs)
#   host-scalar    host-release's binary with FIXSTEP_SIMD=scalar (no kernels at all)
#   host-threads4  host-release's binary with FIXSTEP_THREADS=4 (each world on 4 threads)
#   i686           32-bit x86, run natively
#   aarch64        64-bit ARM under qemu-user, with its NEON kernels
#   aarch64-scalar aarch64's binary with FIXSTEP_SIMD=scalar (no kernels)
#   s390x          64-bit big-endian IBM Z under qemu-user
#   wasm32-wasip1  WebAssembly under Node's node:wasi (or the PyPI wasmtime)
#   wasm32-simd128 the same built with +simd128, with its simd128 kernels
#   miri-s390x     s390x interpreted by nightly Miri, on replays/tiny.replay only
#
# Installs what a target needs when it is missing (idempotent): rustup targets; Debian's
# libc6-dev-i386 lib32gcc-12-dev gcc-aarch64-linux-gnu libc6-dev-arm64-cross
# gcc-s390x-linux-gnu libc6-dev-s390x-cross qemu-user; nightly with miri and rust-src.
# A target whose tools cannot be had is a SKIP (a FAIL with --strict). --no-install only
# probes. Ends with one row per target; exit status 1 if any replay fails to verify on any
# target (or a build fails), 0 otherwise. Logs: target/determinism-matrix/*.log.
set -euo pipefail
cd "$(dirname "$0")/.."

ALL=host-debug,host-release,host-native,host-avx2,host-scalar,host-threads4,i686,aarch64,aarch64-scalar,s390x,wasm32-wasip1,wasm32-simd128,miri-s390x
SELECTED=$ALL INSTALL=1 STRICT=0
while [[ $# -gt 0 ]]; do
  case $1 in
    --targets) SELECTED=${2:?--targets needs a list}; shift 2 ;;
    --no-install) INSTALL=0; shift ;;
    --strict) STRICT=1; shift ;;
    -h|--help) sed -n '2,30p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "error: unknown argument \`$1\` (see --help)" >&2; exit 2 ;;
  esac
done
for t in ${SELECTED//,/ }; do
  [[ ",$ALL," == *",$t,"* ]] || { echo "error: unknown target \`$t\` (known: $ALL)" >&2; exit 2; }
done

LOGS=target/determinism-matrix
mkdir -p "$LOGS"
mapfile -t REPLAYS < <(ls replays/*.replay)
MIRI_REPLAY=replays/tiny.replay
SKIP_REASON=""

have() { command -v "$1" >/dev/null 2>&1; }
skip() { SKIP_REASON=$1; return 3; }

SUDO=()
[[ $(id -u) -ne 0 ]] && have sudo && SUDO=(sudo -n)
APT_UPDATED=0
apt_ensure() { # apt_ensure PKG...: installs the missing ones; fails if it cannot
  local missing=() p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
  done
  [[ ${#missing[@]} -eq 0 ]] && return 0
  [[ $INSTALL -eq 1 ]] && have apt-get || return 1
  if [[ $APT_UPDATED -eq 0 ]]; then
    "${SUDO[@]}" apt-get update -qq >"$LOGS/apt-update.log" 2>&1 || return 1
    APT_UPDATED=1
  fi
  DEBIAN_FRONTEND=noninteractive "${SUDO[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >"$LOGS/apt-install.log" 2>&1
}

rust_target_ensure() { # rust_target_ensure TRIPLE
  rustup target list --installed 2>/dev/null | grep -qx "$1" && return 0
  [[ $INSTALL -eq 1 ]] && have rustup || return 1
  rustup target add "$1" >"$LOGS/rustup-$1.log" 2>&1
}

# build LOG ARGS...: cargo build of the verifier, logged.
VERIFIER=examples/verify_replays
build() {
  local log=$1; shift
  cargo build --locked --quiet -p fixstep --example verify_replays "$@" \
    >"$LOGS/$log.build.log" 2>&1 \
    || { echo "build failed (see $LOGS/$log.build.log)"; return 1; }
}

# verify LOG RUNNER...: runs the verifier through RUNNER (a command prefix ending with the
# binary) on every replay, logging its output; the verify lines become the digest.
verify() {
  local log=$1; shift
  "$@" "${REPLAYS[@]}" >"$LOGS/$log.log" 2>&1
}

t_host_debug()   { build host-debug && verify host-debug target/debug/$VERIFIER; }
t_host_release() { build host-release --release && verify host-release target/release/$VERIFIER; }
t_host_avx2()    { build host-release --release && FIXSTEP_SIMD=avx2 verify host-avx2 target/release/$VERIFIER; }
t_host_scalar()  { build host-release --release && FIXSTEP_SIMD=scalar verify host-scalar target/release/$VERIFIER; }
t_host_threads4() { build host-release --release && FIXSTEP_THREADS=4 verify host-threads4 target/release/$VERIFIER; }
t_host_native() {
  CARGO_TARGET_DIR=target/matrix-native RUSTFLAGS="${RUSTFLAGS:-} -C target-cpu=native" \
    build host-native --release && verify host-native target/matrix-native/release/$VERIFIER
}

t_i686() {
  local t=i686-unknown-linux-gnu probe=$LOGS/m32probe
  rust_target_ensure $t || { skip "rust target $t unavailable"; return; }
  if ! echo 'int main(void){return 0;}' | cc -m32 -x c - -o "$probe" 2>/dev/null; then
    apt_ensure libc6-dev-i386 "lib32gcc-$(cc -dumpversion | cut -d. -f1)-dev" || true
    echo 'int main(void){return 0;}' | cc -m32 -x c - -o "$probe" 2>/dev/null \
      || { skip "cc -m32 cannot link (libc6-dev-i386, lib32gcc-N-dev)"; return; }
  fi
  "$probe" || { skip "this kernel cannot run 32-bit binaries"; return; }
  build i686 --release --target $t && verify i686 target/$t/release/$VERIFIER
}

qemu_target() { # qemu_target LOG TRIPLE GNU-PREFIX QEMU PKGS...
  local log=$1 t=$2 pfx=$3 qemu=$4; shift 4
  rust_target_ensure "$t" || { skip "rust target $t unavailable"; return; }
  if ! have "$pfx-gcc" || ! have "$qemu" || [[ ! -d /usr/$pfx/lib ]]; then apt_ensure "$@" || true; fi
  have "$pfx-gcc" || { skip "no cross linker $pfx-gcc"; return; }
  have "$qemu" || { skip "no $qemu (qemu-user)"; return; }
  local up; up=$(echo "$t" | tr 'a-z-' 'A-Z_')
  ( export "CARGO_TARGET_${up}_LINKER=$pfx-gcc"; build "$log" --release --target "$t" ) \
    && verify "$log" "$qemu" -L "/usr/$pfx" "target/$t/release/$VERIFIER"
}
t_aarch64() { qemu_target aarch64 aarch64-unknown-linux-gnu aarch64-linux-gnu qemu-aarch64 \
                gcc-aarch64-linux-gnu libc6-dev-arm64-cross qemu-user; }
t_aarch64_scalar() { FIXSTEP_SIMD=scalar qemu_target aarch64-scalar aarch64-unknown-linux-gnu \
                       aarch64-linux-gnu qemu-aarch64 gcc-aarch64-linux-gnu libc6-dev-arm64-cross \
                       qemu-user; }
t_s390x()   { qemu_target s390x s390x-unknown-linux-gnu s390x-linux-gnu qemu-s390x \
                gcc-s390x-linux-gnu libc6-dev-s390x-cross qemu-user; }

# wasm_target LOG DIR [RUSTFLAGS]: the verifier for wasm32-wasip1 into target DIR, built with
# RUSTFLAGS added, run under Node's WASI (or wasmtime).
wasm_target() {
  local log=$1 dir=$2 flags=${3:-} t=wasm32-wasip1 runner=()
  local wasm=$dir/wasm32-wasip1/release/$VERIFIER.wasm
  rust_target_ensure $t || { skip "rust target $t unavailable"; return; }
  if have node && node --no-warnings -e "new (require('node:wasi').WASI)({version:'preview1'})" 2>/dev/null; then
    runner=(node --no-warnings scripts/wasi-run.mjs "$wasm")
  elif python3 -c 'import wasmtime' 2>/dev/null; then
    runner=(python3 scripts/wasmtime-run.py "$wasm")
  else
    skip "neither Node >= 20 (node:wasi) nor the PyPI wasmtime module"; return
  fi
  CARGO_TARGET_DIR=$dir RUSTFLAGS="${RUSTFLAGS:-} $flags" build "$log" --release --target $t \
    && verify "$log" "${runner[@]}"
}
t_wasm32_wasip1()  { wasm_target wasm32-wasip1 target; }
t_wasm32_simd128() { wasm_target wasm32-simd128 target/matrix-simd128 "-C target-feature=+simd128"; }

t_miri_s390x() {
  if ! cargo +nightly miri --version >/dev/null 2>&1; then
    [[ $INSTALL -eq 1 ]] && have rustup || { skip "nightly miri not installed"; return; }
    rustup toolchain install nightly --profile minimal --component miri,rust-src \
      >"$LOGS/rustup-miri.log" 2>&1 || { skip "cannot install nightly miri"; return; }
  fi
  # Isolation off so that the interpreted program can read the replay file.
  MIRIFLAGS="-Zmiri-disable-isolation" \
    cargo +nightly miri run --quiet --target s390x-unknown-linux-gnu -p fixstep \
    --example verify_replays -- "$MIRI_REPLAY" >"$LOGS/miri-s390x.log" 2>&1
}

# The digest of a target's verify lines: equal digests mean equal checksums everywhere.
digest() { grep '^ok ' "$1" | sha256sum | cut -c1-12; }
# The final checksum of the tiny replay, which every target (Miri too) verifies.
tiny() { grep "^ok $MIRI_REPLAY " "$1" | cut -d' ' -f4; }

declare -a ROWS=()
FAILED=0 SKIPPED=0
for name in ${SELECTED//,/ }; do
  fn=t_${name//-/_}
  echo "==> $name"
  SKIP_REASON="" start=$SECONDS rc=0
  "$fn" || rc=$?
  secs=$((SECONDS - start)) log=$LOGS/$name.log
  case $rc in
    0) ok=$(grep -c '^ok ' "$log")
       total=${#REPLAYS[@]} d=$(digest "$log")
       [[ $name == miri-s390x ]] && total=1 d="(tiny only)"
       ROWS+=("$name|PASS|$ok/$total|$d|$(tiny "$log")|$secs|") ;;
    3) SKIPPED=$((SKIPPED + 1)); ROWS+=("$name|SKIP|-|-|-|$secs|$SKIP_REASON") ;;
    *) FAILED=$((FAILED + 1))
       ROWS+=("$name|FAIL|$(grep -c '^ok ' "$log" 2>/dev/null || echo 0)/${#REPLAYS[@]}|-|-|$secs|see $log")
       [[ -f $log ]] && sed 's/^/    /' "$log" | tail -20 ;;
  esac
done

echo
echo "determinism matrix, $(date -u +%Y-%m-%d), $(git rev-parse --short HEAD 2>/dev/null || echo '?')," \
  "${#REPLAYS[@]} replays (${REPLAYS[*]##*/}); miri-s390x: ${MIRI_REPLAY##*/}"
printf '| %-14s | %-6s | %-8s | %-12s | %-16s | %5s | %s |\n' target result verified digest \
  "tiny checksum" secs note
printf '|%s|%s|%s|%s|%s|%s|%s|\n' ---------------- -------- ---------- -------------- \
  ------------------ ------- ------
for r in "${ROWS[@]}"; do
  IFS='|' read -r n st ok d tc s note <<<"$r"
  printf '| %-14s | %-6s | %-8s | %-12s | %-16s | %5s | %s |\n' "$n" "$st" "$ok" "$d" "$tc" "$s" "$note"
done
echo "(digest: sha256 of the verifier's \`ok FILE TICKS CHECKSUM\` lines: equal digests,"
echo " equal bits; every target verifies every checkpoint against the committed replays)"
if (( FAILED > 0 )); then echo "FAILED on $FAILED target(s)"; exit 1; fi
if (( SKIPPED > 0 && STRICT == 1 )); then echo "SKIPPED $SKIPPED target(s) (--strict)"; exit 1; fi
echo "every replay verified on every runnable target ($SKIPPED skipped)"
