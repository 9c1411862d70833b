# SPDX-License-Identifier: BSL-1.0
"""The command line of every program: each usage error exits 2 with one line on stderr that names
the option refused; --help (and seawire-decode's and seawire-encode's --version) exit 0. Every floating-point option refuses nan, inf and
a number out of its range (0 where it must be positive, a negative where it must not be).

    usage_test.py DECODE ENCODE KINGFISHER SANDSHARK JUDGE TCP FEED
"""

import subprocess
import sys

from harness import check, finish

DECODE, ENCODE, KINGFISHER, SANDSHARK, JUDGE, TCP, FEED = sys.argv[1:8]

# Arguments the program needs besides the one refused (none of them is read before the refusal).
NEEDS = {TCP: ["127.0.0.1:9"]}


def real_option(option, positive=True, zero_ok=False, upper=None):
    """The refusals of a floating-point option: nan, inf, -inf, 1e999, a negative number, 0 when
    it must be positive, a value above `upper`, text, and the value missing."""
    bad = ["nan", "NaN", "inf", "-inf", "infinity", "1e999", "-1", "abc", "1.5x"]
    if not zero_ok:
        bad.append("0")
    if upper is not None:
        bad.append(str(upper * 10))
    return [[option, v] for v in bad] + [[option]]


# LAT,LON options: read by the program itself, refused the same way.
START = [["--start", v] for v in ("nan,nan", "0,inf", "1e999,0", "95,0", "0", "x")]

TABLE = {
    DECODE: [["--no-such-option"], ["--format", "xml"], ["--format"], ["--checksum", "sometimes"],
             ["--log-format", "nope"]],
    ENCODE: [["--no-such-option"], ["--output", "nope"], ["--output"]],
    KINGFISHER: [["--no-such-option"], ["--max-clients", "0"], ["--max-queue", "0"],
                 ["--pydep-units", "grad"]] + START
    + real_option("--nav-rate", upper=1000) + real_option("--status-rate", upper=1000)
    + real_option("--watchdog") + real_option("--max-speed") + real_option("--max-yaw-rate")
    + real_option("--duration", zero_ok=True),
    SANDSHARK: [["--no-such-option"]] + START + real_option("--nav-rate", upper=100)
    + real_option("--abort-time", zero_ok=True) + real_option("--shutdown-wait", zero_ok=True)
    + real_option("--duration", zero_ok=True),
    JUDGE: [["--no-such-option"], ["--max-clients", "0"], ["--report", "xml"]]
    + real_option("--gap-limit") + real_option("--jitter", zero_ok=True, upper=0.5)
    + real_option("--clock-tolerance", zero_ok=True) + real_option("--duration", zero_ok=True),
    TCP: [["--no-such-option"]] + real_option("--min-backoff") + real_option("--max-backoff")
    + real_option("--connect-timeout"),
    FEED: [["--no-such-option"], ["--baud", "12345"]] + START + real_option("--rate", upper=10)
    + real_option("--seconds", zero_ok=True),
}

for program, cases in TABLE.items():
    name = program.rsplit("/", 1)[-1]
    for what in ("--help", "--version") if program in (DECODE, ENCODE) else ("--help",):
        r = subprocess.run([program, what], capture_output=True, timeout=20)
        check(r.returncode == 0 and r.stdout, f"{name} {what}: exit {r.returncode}")
    for args in cases:
        # The refused option goes last when its value is missing, so nothing follows it.
        argv = [program, *NEEDS.get(program, []), *args]
        try:
            r = subprocess.run(argv, stdin=subprocess.DEVNULL, capture_output=True, timeout=20)
        except subprocess.TimeoutExpired:
            check(False, f"{name} {args}: still running after 20 s")
            continue
        lines = r.stderr.decode(errors="replace").splitlines()
        option = args[0]
        check(r.returncode == 2, f"{name} {args}: exit {r.returncode}, expected 2: {lines}")
        check(len(lines) == 1, f"{name} {args}: {len(lines)} lines on stderr, expected 1: {lines}")
        check(bool(lines) and option in lines[0] and lines[0].startswith(name + ": "),
              f"{name} {args}: the line does not name {option}: {lines}")

finish()
