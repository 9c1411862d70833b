# SPDX-License-Identifier: BSL-1.0
"""seawire-decode stays bounded and stoppable, as a real process fed what a bad link sends.

    decode_limits_test.py <seawire-decode> <examples/data> <case>

noise    megabytes of zeros or random bytes without a line ending, then sentences: decided on,
         read in linear time and bounded memory, the sentences after the noise all decoded.
signals  SIGTERM or SIGINT while reading a terminal or a pipe that stays open: what was read is
         decoded and written, --stats printed, exit status 128 + the signal's number; output
         line by line when stdin is a terminal, in blocks to a pipe.
tables   --format csv --output-dir with more types than files may be open (RLIMIT_NOFILE 12, and
         more than the 32 kept open): every table whole, its header once, rows in input order.
logs     a flood of bad lines (and of sentences no table has): stderr shows at most 100 lines a
         second, and says how many it held back; the two add up to every line.
"""

import math
import os
import pty
import random
import re
import resource
import select
import signal
import subprocess
import sys
import tempfile
import threading
import time
import tty

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from harness import check, run_case, seal

DECODE, DATA, CASE = sys.argv[1], sys.argv[2], sys.argv[3]
MB = 1024 * 1024


def sentences(family="kingfisher"):
    with open(os.path.join(DATA, family + ".nmea"), "rb") as f:
        return f.read()


def measured(args, chunks, tmp):
    """Runs seawire-decode with args, the chunks written to its stdin one after the other; returns
    (exit status, seconds, peak RSS in KiB of this run alone, stdout, stderr)."""
    out_path, err_path = os.path.join(tmp, "out"), os.path.join(tmp, "err")
    with open(out_path, "wb") as out, open(err_path, "wb") as err:
        start = time.monotonic()
        # Under AddressSanitizer, freed memory is held back (up to 256 MiB) to catch late uses:
        # a little is enough here, so the peak shows what the program keeps.
        env = dict(os.environ)
        env["ASAN_OPTIONS"] = env.get("ASAN_OPTIONS", "") + ":quarantine_size_mb=4"
        p = subprocess.Popen([DECODE, "--quiet", *args], stdin=subprocess.PIPE, stdout=out,
                             stderr=err, env=env)

        def write():
            try:
                for c in chunks:
                    p.stdin.write(c)
            except BrokenPipeError:
                pass
            p.stdin.close()

        writer = threading.Thread(target=write)
        writer.start()
        # The peak RSS of the program itself: VmHWM of its own memory, read while it runs
        # (rusage would count this script's memory too, which the child had before its exec).
        deadline = start + 120
        peak = 0
        while True:
            try:
                with open(f"/proc/{p.pid}/status") as f:
                    for line in f:
                        if line.startswith("VmHWM:"):
                            peak = max(peak, int(line.split()[1]))
            except (OSError, ValueError):
                pass
            pid, status = os.waitpid(p.pid, os.WNOHANG)
            if pid != 0:
                break
            if time.monotonic() > deadline:
                p.kill()
                pid, status = os.waitpid(p.pid, 0)
                check(False, f"{args}: still running after 120 s")
                break
            time.sleep(0.005)
        p.returncode = os.waitstatus_to_exitcode(status)
        seconds = time.monotonic() - start
        writer.join()
    with open(out_path, "rb") as f:
        stdout = f.read()
    with open(err_path, "rb") as f:
        stderr = f.read()
    return p.returncode, seconds, peak, stdout, stderr


def case_noise():
    good = sentences()
    want_nmea = subprocess.run([DECODE, "--quiet", "--format", "nmea"], input=good,
                               capture_output=True, timeout=60).stdout
    want_json = subprocess.run([DECODE, "--quiet"], input=good, capture_output=True,
                               timeout=60).stdout
    check(len(want_nmea) > 1000 and len(want_json) > 1000, "the sample decodes")
    zeros = bytes(MB)
    rng = random.Random(20)
    noise = rng.randbytes(32 * MB)
    with tempfile.TemporaryDirectory() as tmp:
        _, _, small_rss, _, _ = measured([], [good], tmp)
        # 64 MiB of zeros, no line ending in them: input auto must decide within a bounded prefix
        # (a CAN log or sentences), not keep the noise and scan it again as more comes.
        for fmt, want in (("json", want_json), ("nmea", want_nmea)):
            rc, seconds, rss, out, err = measured(["--format", fmt], [zeros] * 64 + [good], tmp)
            print(f"64 MiB of zeros then the sample, --format {fmt}: {seconds:.2f} s, "
                  f"peak RSS {rss // 1024} MiB (the sample alone: {small_rss // 1024} MiB)")
            check(rc == 1, f"zeros --format {fmt}: exit status {rc} (noise is rejected input)")
            check(seconds < 20, f"zeros --format {fmt}: {seconds:.1f} s")
            check(rss - small_rss < 32 * 1024,
                  f"zeros --format {fmt}: peak RSS {rss} KiB vs {small_rss} KiB for the sample")
            check(out.endswith(want), f"zeros --format {fmt}: the sentences after the noise")
            if fmt == "json":
                # The noise itself is reported: one missing_start of every byte of it.
                first = out.split(b"\n")[0]
                check(b'"error":"missing_start"' in first and b"67108864 bytes" in first,
                      f"zeros reported: {first[:160]!r}")
        # 32 MiB of random bytes (some '\n', '$' and 0xAB among them) then the sentences.
        rc, seconds, rss, out, err = measured(["--format", "nmea"], [noise, b"\r\n", good], tmp)
        print(f"32 MiB of random bytes then the sample: {seconds:.2f} s, peak RSS {rss // 1024} "
              f"MiB, {len(err)} bytes on stderr")
        check(rc == 1, f"random: exit status {rc}")
        check(seconds < 20, f"random: {seconds:.1f} s")
        check(rss - small_rss < 32 * 1024, f"random: peak RSS {rss} KiB vs {small_rss} KiB")
        check(out.endswith(want_nmea), "random: the sentences after the noise")


def read_for(fd, seconds, until=None):
    """What `fd` gives within `seconds` (sooner once `until` is in it)."""
    got = b""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline and (until is None or until not in got):
        r, _, _ = select.select([fd], [], [], max(0, deadline - time.monotonic()))
        if not r:
            break
        piece = os.read(fd, 65536)
        if not piece:
            break
        got += piece
    return got


def caught(pid, sig, seconds=20):
    """Waits until process `pid` catches signal `sig` (its handler installed: it started)."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith("SigCgt:") and int(line.split()[1], 16) >> (sig - 1) & 1:
                    return True
        time.sleep(0.01)
    return False


def stopped(p, sig, what):
    """Sends `sig` to `p` and returns its (stdout, stderr) once it exits (killed after 20 s)."""
    p.send_signal(sig)
    try:
        return p.communicate(timeout=20)
    except subprocess.TimeoutExpired:
        p.kill()
        check(False, f"{what}: still running 20 s after signal {sig}")
        return p.communicate()


def case_signals():
    lines = sentences().splitlines(keepends=True)[:6]
    check(all(line.endswith(b"\r\n") for line in lines), "the sample's lines end in CR LF")
    want = subprocess.run([DECODE, "--quiet"], input=b"".join(lines), capture_output=True,
                          timeout=60).stdout.splitlines(keepends=True)
    check(len(want) == 6, "six messages")

    # stdin a terminal (a pty in raw mode, as a serial port is): each message goes out as its
    # line comes; SIGTERM then decodes the sentence still without its line ending.
    master, slave = pty.openpty()
    tty.setraw(slave)
    p = subprocess.Popen([DECODE, "--quiet", "--stats"], stdin=slave, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE)
    os.close(slave)
    os.write(master, b"".join(lines[:5]))
    os.write(master, lines[5].rstrip(b"\r\n"))
    early = read_for(p.stdout.fileno(), 20, until=want[4])
    check(early == b"".join(want[:5]), f"pty: five messages before the signal: {early[-200:]!r}")
    out, err = stopped(p, signal.SIGTERM, "pty")
    os.close(master)
    check(p.returncode == 143, f"pty: SIGTERM: exit status {p.returncode}, expected 143")
    check(out == want[5], f"pty: the sixth message after the signal: {out[:200]!r}")
    check(b"6 messages decoded, 0 rejected" in err, f"pty: --stats: {err[:300]!r}")

    # stdin a pipe that stays open, stdout a pipe: nothing is written until the buffer fills or
    # the input ends; SIGINT ends it, and everything decoded is written, the stats after it.
    p = subprocess.Popen([DECODE, "--quiet", "--stats"], stdin=subprocess.PIPE,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    p.stdin.write(b"".join(lines) + b"$GPRMC,1*")  # a last sentence cut short
    p.stdin.flush()
    caught(p.pid, signal.SIGINT)
    early = read_for(p.stdout.fileno(), 1)
    check(early == b"", f"pipe: block-buffered, nothing written yet: {early[:200]!r}")
    time.sleep(0.5)  # the chunk read before the signal comes
    out, err = stopped(p, signal.SIGINT, "pipe")
    check(p.returncode == 130, f"pipe: SIGINT: exit status {p.returncode}, expected 130")
    out_lines = out.splitlines(keepends=True)
    check(out_lines[:6] == want, f"pipe: every message after the signal: {out[:300]!r}")
    check(len(out_lines) == 7 and out_lines[6].startswith(b'{"line":7,"error":'),
          f"pipe: the cut sentence reported: {out_lines[6:]!r}")
    check(b"6 messages decoded, 1 rejected" in err, f"pipe: --stats: {err[:300]!r}")


def case_tables():
    # 48 tables: RMC and GGA from 24 talkers, round after round, so that files are closed and
    # opened again many times.
    talkers = [a + b for a in "ABCDEFGHIJKL" for b in "PQ"]
    rounds = 6
    lines = []
    for r in range(rounds):
        for t in talkers:
            lines.append(seal(f"{t}RMC,16495{r}.00,A,4221.71114,N,07105.44878,W,0.145,156.78,"
                              "311214,,,A"))
            lines.append(seal(f"{t}GGA,16495{r}.00,4221.71114,N,07105.44878,W,1,06,2.80,46.6,"
                              "M,-33.2,M,,"))
    data = "".join(lines).encode()

    def low_limit():
        resource.setrlimit(resource.RLIMIT_NOFILE, (12, 12))

    with tempfile.TemporaryDirectory() as tmp:
        for what, limit in (("the default limit", None), ("RLIMIT_NOFILE 12", low_limit)):
            d = os.path.join(tmp, "limited" if limit else "default")
            p = subprocess.run([DECODE, "--quiet", "--format", "csv", "--output-dir", d],
                               input=data, capture_output=True, timeout=60, preexec_fn=limit)
            check(p.returncode == 0, f"{what}: exit status {p.returncode}: {p.stderr[:300]!r}")
            files = sorted(os.listdir(d)) if os.path.isdir(d) else []
            want_files = sorted(f"{t}{k}.csv" for t in talkers for k in ("RMC", "GGA"))
            check(files == want_files, f"{what}: {len(files)} tables of {len(want_files)}")
            for name in files:
                with open(os.path.join(d, name), encoding="ascii") as f:
                    rows = f.read().splitlines()
                check(len(rows) == rounds + 1, f"{what}: {name}: {len(rows)} rows")
                check(rows[0].startswith("time,") and
                      sum(1 for row in rows if row.startswith("time,")) == 1,
                      f"{what}: {name}: one header row: {rows[:3]}")
                times = [row.split(",")[0] for row in rows[1:]]
                check(times == [f"16:49:5{r}.00" for r in range(rounds)],
                      f"{what}: {name}: rows in input order: {times}")


def said(err):
    """(lines shown, lines held back as the program says) of seawire-decode's stderr."""
    shown = held = 0
    for line in err.decode().splitlines():
        m = re.fullmatch(r"seawire-decode: \.\.\. (\d+) more lines? like these not shown \(at most "
                         r"100 a second are; --stats counts every rejected line by error\)", line)
        if m:
            held += int(m.group(1))
        elif line.startswith("seawire-decode: ") and " decoded, " not in line:
            shown += 1
    return shown, held


def case_logs():
    n = 300000
    bad = seal("GPRMC,16495x.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A").encode()
    good = sentences()
    data = bad * n + good
    start = time.monotonic()
    p = subprocess.run([DECODE, "--quiet", "--format", "nmea", "--stats"], input=data,
                       capture_output=True, timeout=120)
    seconds = time.monotonic() - start
    shown, held = said(p.stderr)
    print(f"{n} bad lines: {seconds:.2f} s, {shown} lines shown, {held} held back, "
          f"{len(p.stderr)} bytes on stderr")
    check(p.returncode == 1, f"bad lines: exit status {p.returncode}")
    check(shown + held == n, f"bad lines: {shown} shown + {held} held back != {n}")
    check(100 <= shown <= 100 * (math.ceil(seconds) + 1),
          f"bad lines: {shown} shown in {seconds:.1f} s")
    lines = p.stderr.decode().splitlines()
    check(lines[0].startswith("seawire-decode: line 1: bad_time: GPRMC field 1 (time)"),
          f"bad lines: the first shown: {lines[0]!r}")
    check(f"0 messages decoded, {n} rejected".encode() in p.stderr or
          b"messages decoded, %d rejected" % n in p.stderr, "bad lines: --stats counts them all")
    check(p.stdout == subprocess.run([DECODE, "--quiet", "--format", "nmea"], input=good,
                                     capture_output=True, timeout=60).stdout,
          "bad lines: the good sentences after them")

    # Sentences of 6000 addresses no message describes, to CSV tables: one line each on stderr,
    # the addresses past the 4096 counted one by one counted together.
    def address(i):
        return "PZ" + "".join("ABCDEFGHIJKLMNOPQRSTUVWXYZ"[i // 26 ** k % 26] for k in range(3))
    data = "".join(seal(f"{address(i)},1,2") for i in range(6000)).encode()
    with tempfile.TemporaryDirectory() as tmp:
        p = subprocess.run([DECODE, "--quiet", "--format", "csv", "--output-dir", tmp, "--stats"],
                           input=data, capture_output=True, timeout=120)
    shown, held = said(p.stderr)
    print(f"6000 unknown addresses: {shown} lines shown, {held} held back")
    check(p.returncode == 0, f"unknown addresses: exit status {p.returncode}")
    check(shown + held == 4097, f"unknown addresses: {shown} shown + {held} held back")
    check(shown <= 300, f"unknown addresses: {shown} shown")
    check(b"(other types)" in p.stderr and re.search(rb"\(other types\) +1904\n", p.stderr),
          f"unknown addresses: --stats: {p.stderr[-400:]!r}")


run_case(globals(), CASE)
