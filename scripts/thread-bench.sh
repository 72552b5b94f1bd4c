#!/usr/bin/env bash
# The speed-up of N threads against 1, same binary, same run (issue [parallel]): `balls`,
# ten pyramids of 20,160 boxes, `dam_break` and a 128x128 cloth stepped in alternating
# rounds (examples/thread_bench.rs), then `fixstep verify replays/*.replay` at
# --threads 1 and N, alternating. Prints one table of medians; exits 1 if a checksum
# differs between the counts.
#   ./scripts/thread-bench.sh [THREADS] [ROUNDS] [CASE ...]   (default 2 threads, 5 rounds)
# CASE: balls, pyramids20k, dam_break, cloth128, verify (default every case).
# Run it on an otherwise idle machine: the figures are wall-clock times.
set -euo pipefail
cd "$(dirname "$0")/.."
threads=${1:-2}
rounds=${2:-5}
shift $(( $# < 2 ? $# : 2 ))
for n in "$threads" "$rounds"; do
  if [[ ! $n =~ ^[1-9][0-9]*$ ]]; then
    echo "error: THREADS and ROUNDS must be positive whole numbers, not \`$n\`" >&2
    exit 2
  fi
done
cases=("$@")
wants() { [[ ${#cases[@]} -eq 0 ]] || [[ " ${cases[*]} " == *" $1 "* ]]; }

cargo build --release --locked -p fixstep --example thread_bench -p fixstep-cli >&2
steps=()
for c in "${cases[@]}"; do [[ $c != verify ]] && steps+=("$c"); done
if [[ ${#cases[@]} -eq 0 || ${#steps[@]} -gt 0 ]]; then
  target/release/examples/thread_bench "$threads" "$rounds" "${steps[@]}"
else
  echo "| case | 1 thread | $threads threads | speed-up | same checksum |"
  echo "|---|---|---|---|---|"
fi
if wants verify; then
  one=() many=()
  for _ in $(seq "$rounds"); do
    for n in 1 "$threads"; do
      start=$(date +%s.%N)
      target/release/fixstep verify --threads "$n" replays/*.replay >/dev/null
      end=$(date +%s.%N)
      if [[ $n == 1 ]]; then one+=("$(echo "$end - $start" | bc)"); else many+=("$(echo "$end - $start" | bc)"); fi
    done
  done
  median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int(NR/2)+1]}'; }
  m1=$(median "${one[@]}") mn=$(median "${many[@]}")
  printf '| verify replays/*.replay (s) | %.2f | %.2f | %.2f× | yes |\n' "$m1" "$mn" "$(echo "$m1 / $mn" | bc -l)"
fi
