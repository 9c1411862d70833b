#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# How fast is seawire-decode? Builds the programs (Release, build/bench-programs), makes a large
# corpus from the sample logs (default 1,000,000 lines, not committed), and times
#   seawire-decode --format none   (frame, parse, decode every field of every message)
# against
#   seawire-xor-baseline           (split lines, check the XOR checksum, nothing else)
# with hyperfine when it is installed (else bash's time). The target: within 2x. Then the
# output formats against --format json: csv (a table per type, in build/bench-programs/csv),
# geojson and svg (the tracks), each targeted at most 1.5x json's time.
#   bench/programs.sh [lines]      SEAWIRE_JOBS=N for the build (default 1)
set -euo pipefail
root=$(cd -- "$(dirname -- "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
lines=${1:-1000000}
build=build/bench-programs
corpus=$build/corpus.nmea

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF -DSEAWIRE_BUILD_EXAMPLES=ON \
  >/dev/null
cmake --build "$build" -j "${SEAWIRE_JOBS:-1}" --target seawire-decode seawire-encode \
  seawire-xor-baseline
tools=$build/tools

# The family logs (not bad.nmea), over and over, to the wanted number of lines.
logs=(examples/data/{kingfisher,sandshark,robotx,anello,standard}.nmea)
per_round=$(cat "${logs[@]}" | wc -l)
rounds=$(((lines + per_round - 1) / per_round))
if [[ ! -f $corpus ]] || (($(wc -l <"$corpus") != rounds * per_round)); then
  for ((i = 0; i < rounds; i++)); do cat "${logs[@]}"; done >"$corpus"
fi
printf 'corpus: %s lines, %s bytes\n' "$(wc -l <"$corpus")" "$(wc -c <"$corpus")"

# Both must accept the whole corpus.
"$tools/seawire-xor-baseline" <"$corpus"
stats=$("$tools/seawire-decode" --format none --stats <"$corpus" 2>&1)
echo "${stats%%$'\n'*}"

if command -v hyperfine >/dev/null; then
  # hyperfine runs each command in a shell (stdout discarded), so stdin comes by redirection.
  hyperfine --warmup 2 --runs "${SEAWIRE_RUNS:-10}" \
    -n xor-baseline "$tools/seawire-xor-baseline < $corpus" \
    -n 'decode --format none' "$tools/seawire-decode --format none < $corpus" \
    -n 'decode --format json' "$tools/seawire-decode --format json < $corpus" \
    -n 'decode --format nmea' "$tools/seawire-decode --format nmea < $corpus" \
    -n 'decode --format csv' \
    "$tools/seawire-decode --format csv --output-dir $build/csv < $corpus" \
    -n 'decode --format geojson' "$tools/seawire-decode --format geojson < $corpus" \
    -n 'decode --format svg' "$tools/seawire-decode --format svg < $corpus"
else
  for cmd in seawire-xor-baseline "seawire-decode --format none" "seawire-decode --format json" \
    "seawire-decode --format csv --output-dir $build/csv" "seawire-decode --format geojson" \
    "seawire-decode --format svg"; do
    echo "== $cmd"
    time $tools/$cmd <"$corpus" >/dev/null
  done
fi
