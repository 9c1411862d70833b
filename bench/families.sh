#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# seawire-decode's speed per protocol family, as ratios taken in one run. For each family's
# sample log (examples/data), repeated to about `lines` lines (default 500,000; not committed),
# times in turn, interleaved round by round so that machine load falls on all three alike:
#   seawire-xor-baseline           (split lines, check the XOR checksum, nothing else)
#   seawire-decode --format none   (frame, parse, decode every field of every message)
#   seawire-decode --format json
# and prints the medians with none/xor and json/none. anello_mixed carries 0xAB00 binary
# frames between its sentences: the baseline counts those as bad lines and does not check
# their CRC-32, so its floor there is lower than the work that stream asks for.
#   bench/families.sh [lines] [runs]     SEAWIRE_JOBS=N for the build (default 1)
set -euo pipefail
root=$(cd -- "$(dirname -- "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
lines=${1:-500000}
runs=${2:-11}
build=build/bench-programs

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF -DSEAWIRE_BUILD_EXAMPLES=ON \
  >/dev/null
cmake --build "$build" -j "${SEAWIRE_JOBS:-1}" --target seawire-decode seawire-xor-baseline

python3 - "$build" "$lines" "$runs" <<'PY'
import os, statistics, subprocess, sys, time

build, lines, runs = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
tools = os.path.join(build, "examples", "tools")
xor = os.path.join(tools, "seawire-xor-baseline")
decode = os.path.join(tools, "seawire-decode")
families = ["kingfisher", "sandshark", "robotx", "anello", "anello_mixed", "standard"]
commands = {
    "xor": [xor],
    "none": [decode, "--format", "none", "--quiet"],
    "json": [decode, "--format", "json", "--quiet"],
}


def corpus(family):
    with open(os.path.join("examples", "data", family + ".nmea"), "rb") as f:
        log = f.read()
    rounds = max(1, -(-lines // log.count(b"\n")))
    path = os.path.join(build, "family-" + family + ".nmea")
    if not os.path.exists(path) or os.path.getsize(path) != rounds * len(log):
        with open(path, "wb") as f:
            f.write(log * rounds)
    return path, rounds * log.count(b"\n")


def run(cmd, path, may_fail):
    with open(path, "rb") as stdin:
        start = time.perf_counter()
        status = subprocess.run(cmd, stdin=stdin, stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL).returncode
        elapsed = time.perf_counter() - start
    if status != 0 and not may_fail:
        sys.exit(f"{' '.join(cmd)} < {path} failed ({status})")
    return elapsed


print(f"{'family':<14}{'lines':>10}{'xor ms':>10}{'none ms':>10}{'json ms':>10}"
      f"{'none/xor':>10}{'json/none':>11}")
for family in families:
    path, count = corpus(family)
    times = {name: [] for name in commands}
    for name, cmd in commands.items():  # warm-up: the file in the page cache, the programs loaded
        run(cmd, path, name == "xor")
    for _ in range(runs):
        for name, cmd in commands.items():
            times[name].append(run(cmd, path, name == "xor"))
    m = {name: statistics.median(t) * 1000 for name, t in times.items()}
    print(f"{family:<14}{count:>10,}{m['xor']:>10.1f}{m['none']:>10.1f}{m['json']:>10.1f}"
          f"{m['none'] / m['xor']:>10.2f}{m['json'] / m['none']:>11.2f}")
PY
