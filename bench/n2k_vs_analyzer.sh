#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# seawire-decode against canboat's analyzer on the same NMEA 2000 log, in one run: the CPU time
# (user + system) each takes to write the log as JSON to /dev/null, per frame, and the ratio.
#
#   bench/n2k_vs_analyzer.sh ANALYZER LOG [SEAWIRE_DECODE] [RUNS]
#
# ANALYZER        canboat's analyzer (run as `analyzer -json -si -camel -empty`, the form the
#                 test vectors use)
# LOG             a log both read: canboat PLAIN/FAST lines (what canboat's loggers write), or
#                 Yacht Devices RAW; candump -L is read by seawire only (canboat converts it
#                 first, candump2analyzer)
# SEAWIRE_DECODE  default: build/rel/tools/seawire-decode, then seawire-decode on PATH; build a
#                 Release one (bench/README.md)
# RUNS            each program runs this many times, alternately; the fastest run counts
#                 (default 3)
#
# A frame is a line of the log that is not blank and not a comment ('#'): one CAN frame of a
# PLAIN log (a FAST line, a whole message, counts as one too). Prints the figures and
#   ratio: analyzer / seawire-decode = R x
# Needs bash and awk only.

set -euo pipefail

if [[ $# -lt 2 || $# -gt 4 ]]; then
  sed -n '3,21p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
fi
analyzer=$1
log=$2
here=$(cd "$(dirname "$0")/.." && pwd)
decode=${3:-}
runs=${4:-3}
if [[ -z $decode ]]; then
  if [[ -x $here/build/rel/tools/seawire-decode ]]; then
    decode=$here/build/rel/tools/seawire-decode
  else
    decode=$(command -v seawire-decode || true)
  fi
fi
for p in "$analyzer" "$decode"; do
  if [[ -z $p || ! -x $p ]]; then
    echo "n2k_vs_analyzer.sh: no program at '$p'" >&2
    exit 2
  fi
done
if [[ ! -r $log ]]; then
  echo "n2k_vs_analyzer.sh: cannot read $log" >&2
  exit 2
fi

frames=$(awk '!/^[ \t]*(#|$)/ { n++ } END { print n + 0 }' "$log")
if [[ $frames -eq 0 ]]; then
  echo "n2k_vs_analyzer.sh: $log has no frame" >&2
  exit 2
fi

# The CPU seconds (user + system) of one run of "$@" < log > /dev/null.
cpu_seconds() {
  local TIMEFORMAT='%U %S' t
  t=$({ time "$@" < "$log" > /dev/null 2> /dev/null; } 2>&1) || true
  awk -v t="$t" 'BEGIN { split(t, a, " "); printf "%.3f\n", a[1] + a[2] }'
}

best_analyzer=""
best_decode=""
for ((i = 0; i < runs; i++)); do
  a=$(cpu_seconds "$analyzer" -json -si -camel -empty)
  d=$(cpu_seconds "$decode" --quiet)
  best_analyzer=$(awk -v a="$a" -v b="$best_analyzer" 'BEGIN { print (b == "" || a < b) ? a : b }')
  best_decode=$(awk -v a="$d" -v b="$best_decode" 'BEGIN { print (b == "" || a < b) ? a : b }')
done

awk -v f="$frames" -v a="$best_analyzer" -v d="$best_decode" -v runs="$runs" -v file="$log" 'BEGIN {
  printf "log: %s, %d frames (lines); CPU time, fastest of %d runs each\n", file, f, runs
  printf "analyzer -json:  %8.3f s  %8.1f ns/frame\n", a, a * 1e9 / f
  printf "seawire-decode:  %8.3f s  %8.1f ns/frame\n", d, d * 1e9 / f
  if (d > 0) printf "ratio: analyzer / seawire-decode = %.2f x\n", a / d
  else print "ratio: seawire-decode took no measurable time (use a larger log)"
}'
