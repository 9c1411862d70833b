# SPDX-License-Identifier: BSL-1.0
"""seawire-encode's bounds: a line longer than 64 KiB is refused (its line number, its length) and
not kept, the lines after it are read; a refused value is quoted by a prefix, not whole; a flood
of bad lines is told in part with the count of the rest; a write error is reported with its
errno's text; a PGN seawire does not describe is sent from its "data" only when that is whole
bytes in hex, at most 223 of them.

    encode_limits_test.py ENCODE CASE      CASE: line, quote, flood, full, data
"""

import os
import re
import subprocess
import sys
import tempfile
import threading

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from harness import check, run_case

ENCODE, CASE = sys.argv[1], sys.argv[2]
GOOD = b'{"type":"PYDIR","thrust_left":45,"thrust_right":55}\n'
SENT = b"$PYDIR,45,55*57\r\n"


def feed(chunks, timeout=120):
    """Runs seawire-encode with the byte strings of `chunks` written to its stdin as they come;
    returns (status, stdout, stderr, peak resident set in KiB)."""
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        p = subprocess.Popen([ENCODE], stdin=subprocess.PIPE, stdout=out, stderr=err)
        timer = threading.Timer(timeout, p.kill)
        timer.start()
        try:
            for c in chunks:
                p.stdin.write(c)
            p.stdin.close()
        except BrokenPipeError:
            pass
        _, status, usage = os.wait4(p.pid, 0)
        p.returncode = os.waitstatus_to_exitcode(status)
        timer.cancel()
        out.seek(0)
        err.seek(0)
        return p.returncode, out.read(), err.read(), usage.ru_maxrss


def case_line():
    # 64 KiB exactly is a line; a byte more is not, nor 300 MB without a newline, which must
    # not be kept: the peak memory stays far below it.
    at_bound = b'{"type":"PYDIR",' + b" " * (65536 - len(GOOD) + 1) + GOOD[16:]
    assert len(at_bound) == 65537
    big = [b"x" * (1 << 20)] * 300
    rc, out, err, peak_kib = feed([GOOD, b"y" * 65537 + b"\n", GOOD, *big, b"\n", at_bound, GOOD,
                                   b"z" * 100000])
    lines = err.decode().splitlines()
    check(rc == 1, "exit 1: %d" % rc)
    check(out == SENT * 4, "the lines around the long ones sent, and the line of 64 KiB: %r"
          % out[:200])
    check("seawire-encode: line 2: 65537 bytes, more than the 65536 a line may have: not read"
          in lines, "line 2 refused: %r" % lines)
    check("seawire-encode: line 4: 314572800 bytes, more than the 65536 a line may have: "
          "not read" in lines, "line 4 refused: %r" % lines)
    check("seawire-encode: line 7: 100000 bytes, more than the 65536 a line may have: not read"
          in lines, "the last line, without a newline, refused: %r" % lines)
    check(len(lines) == 3, "three lines on stderr: %r" % lines)
    check(peak_kib < 150 * 1024, "peak memory %d KiB (300 MB fed)" % peak_kib)


def case_quote():
    huge = b"q" * 60000
    rc, out, err, _ = feed([b'{"type":"PYDIR","thrust_left":"' + huge + b'","thrust_right":55}\n',
                            b'{"type":"' + huge + b'","fields":[]}\n',
                            b'{"type":"PYDIR","' + huge + b'":1}\n',
                            b'{"type":"PYDIR","thrust_left":"' + huge + b'\n',
                            b'{"type":"PYDIR","thrust_left":4' + b"5" * 60000 + b',"thrust_right":55}\n',
                            GOOD])
    lines = err.decode().splitlines()
    check(rc == 1 and out == SENT, "exit 1 and the good line sent: %d %r" % (rc, out[:100]))
    check(len(lines) == 5, "one line per bad line: %r" % [l[:100] for l in lines])
    for i, line in enumerate(lines):
        check(len(line) < 600, "line %d quoted in part: %d bytes" % (i + 1, len(line)))
        runs = [len(m) for m in re.findall(r"q+|5+", line)]
        check(re.search(r"[q5]{60,64}\.\.\.", line) and max(runs) <= 64,
              "line %d quotes a prefix of at most 64 bytes, then ...: %r" % (i + 1, line[:300]))
        check(line.startswith("seawire-encode: line %d: " % (i + 1)), "numbered: %r" % line[:80])


def case_data():
    # 65280 is proprietary single-frame: up to 8 bytes go out as one CAN frame; 130816 is a
    # proprietary fast packet, which takes up to 223 bytes.
    good = b'{"type":"PGN65280","src":3,"data":"0102fF"}\n'
    bad = [b'"0g"', b'"012"', b"5", b'"' + b"ab" * 224 + b'"', b'"01 02"', b"null"]
    lines = [good] + [b'{"type":"PGN130816","src":3,"data":%s}\n' % d for d in bad] + \
        [b'{"type":"PGN130816","src":3,"data":"' + b"cd" * 223 + b'"}\n', good]
    p = subprocess.run([ENCODE, "--output", "canboat"], input=b"".join(lines),
                       capture_output=True, timeout=60)
    err = p.stderr.decode().splitlines()
    out = p.stdout.decode().splitlines()
    check(out[:1] == ["# format=FAST"], "canboat's header: %r" % out[:1])
    out = out[1:]
    check(p.returncode == 1, "exit 1: %d" % p.returncode)
    check(len(err) == len(bad), "one refusal a bad line: %r" % err)
    for i, line in enumerate(err):
        check(line.startswith("seawire-encode: line %d: PGN130816: \"data\" must be the payload's "
                              "bytes in hex, at most 223 bytes" % (i + 2)), "refusal: %r" % line)
    check(len(out) == 3, "the good lines sent: %r" % [l[:80] for l in out])
    check(out[0].endswith(",65280,3,255,3,01,02,ff") and out[2] == out[0],
          "the bytes as given, either case: %r" % out[0])
    check(out[1].endswith(",130816,3,255,223," + ",".join(["cd"] * 223)),
          "223 bytes in one line: %r" % out[1][:80])


def case_flood():
    n = 200000
    rc, out, err, _ = feed([b"not json\n" * n, GOOD])
    lines = err.decode().splitlines()
    told = [l for l in lines if re.fullmatch(r"seawire-encode: line \d+: invalid JSON: .*", l)]
    notes = [int(m.group(1)) for l in lines
             if (m := re.fullmatch(r"seawire-encode: \.\.\. (\d+) more rejected lines suppressed",
                                   l))]
    check(rc == 1 and out == SENT, "exit 1, the good line sent: %d %r" % (rc, out[:100]))
    check(len(lines) == len(told) + len(notes), "only refusals and notes: %r" % lines[:5])
    check(0 < len(told) <= 20 * 10, "a few refusals told: %d" % len(told))
    check(notes and len(told) + sum(notes) == n,
          "the rest counted: %d told + %r suppressed != %d" % (len(told), notes[-3:], n))
    check(len(err) < 64 * 1024, "stderr bounded: %d bytes" % len(err))


def case_full():
    with open("/dev/full", "wb") as full:
        r = subprocess.run([ENCODE], input=GOOD * 100000, stdout=full, stderr=subprocess.PIPE,
                           timeout=60)
    check(r.returncode == 1, "exit 1: %d" % r.returncode)
    check(r.stderr == b"seawire-encode: writing stdout: No space left on device\n",
          "the errno told: %r" % r.stderr)


run_case(globals(), CASE)
