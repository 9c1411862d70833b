#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# How long does seawire take to compile? Times each translation unit of bench/compile/ (-O2,
# C++20, the compiler given), best of N runs, and prints each against baseline.cpp (the standard
# headers any such file includes anyway), in one run on one machine; then the role decoders'
# files again with SEAWIRE_SEPARATE_COMPILATION (declared only) and the one file defining them:
#   bench/compile_time.sh [compiler] [runs]      e.g. bench/compile_time.sh clang++ 5
set -euo pipefail
root=$(cd -- "$(dirname -- "${BASH_SOURCE[0]}")/.." && pwd)
cxx=${1:-g++}
runs=${2:-3}
out=$(mktemp -d)
trap 'rm -rf -- "$out"' EXIT

# best_of <file> [flags...]: the shortest wall time of `runs` compiles, in seconds.
best_of() {
  local file=$1
  shift
  local best="" t i
  for ((i = 0; i < runs; i++)); do
    local start end
    start=$(date +%s.%N)
    "$cxx" -std=c++20 -O2 -I"$root/include" "$@" -c "$file" -o "$out/o.o"
    end=$(date +%s.%N)
    t=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", b - a }')
    if [[ -z $best ]] || awk -v t="$t" -v b="$best" 'BEGIN { exit !(t < b) }'; then best=$t; fi
  done
  echo "$best"
}

compiled=seawire_compiled.cpp
tus=(include_all decode_one encode_one role_decoder kingfisher_payload every_family)
separate=-DSEAWIRE_SEPARATE_COMPILATION
separate_tus=(role_decoder kingfisher_payload every_family)
# The name column is as wide as the longest name, so that the figures line up.
width=0
for name in baseline "${tus[@]}" "${separate_tus[@]/%/ (separate)}" "$compiled"; do
  if ((${#name} > width)); then width=${#name}; fi
done

echo "$("$cxx" --version | head -n 1); best of $runs"
base=$(best_of "$root/bench/compile/baseline.cpp")
printf '%-*s %6.2f s  %5s\n' "$width" baseline "$base" "1.0x"
row() {  # row <name> <file> [flags...]
  local name=$1 t
  shift
  t=$(best_of "$@")
  printf '%-*s %6.2f s  %4.1fx\n' "$width" "$name" "$t" \
    "$(awk -v t="$t" -v b="$base" 'BEGIN { print t / b }')"
}
for tu in "${tus[@]}"; do
  row "$tu" "$root/bench/compile/$tu.cpp"
done
for tu in "${separate_tus[@]}"; do
  row "$tu (separate)" "$root/bench/compile/$tu.cpp" "$separate"
done
row "$compiled" "$root/src/$compiled" "$separate"
