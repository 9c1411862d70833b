#!/usr/bin/env python3
# SPDX-License-Identifier: BSL-1.0
"""The programs under the attacks of a hostile run, with the figures that show them bounded.

    python3 bench/hostile.py build/<dir>/tools        (a Release build: -DCMAKE_BUILD_TYPE=Release)

Each attack runs the real program (the servers on 127.0.0.1, port 0) and prints one line: what
was sent, how long it took, the program's peak memory (GNU time's maximum resident set) and how
much it wrote to its log. Needs GNU time (/usr/bin/time) and python3; takes about a minute.
Nothing here is a test: the tests that fail when a bound is lost are the programs' own
(tools/*/..._test.py); these are the figures.
"""

import os
import re
import signal
import socket
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools", "common"))
from harness import fill_pty, seal  # noqa: E402

TOOLS = sys.argv[1] if len(sys.argv) > 1 else "build/rel/tools"


def program(name):
    path = os.path.join(TOOLS, "seawire-" + name)
    if not os.access(path, os.X_OK):
        sys.exit(f"hostile.py: no {path}: build the programs first (see the top of this file)")
    return path


def timed(shell_input, argv):
    """Runs `shell_input | argv` under GNU time: (seconds, peak KiB, stderr bytes, exit)."""
    with tempfile.NamedTemporaryFile() as t, tempfile.NamedTemporaryFile() as err:
        cmd = f"{shell_input} | /usr/bin/time -f '%e %M' -o {t.name} " + " ".join(
            f"'{a}'" for a in argv) + f" > /dev/null 2> {err.name}"
        rc = subprocess.call(["sh", "-c", cmd])
        seconds, kib = open(t.name).read().split()[-2:]
        return float(seconds), int(kib), os.path.getsize(err.name), rc


def report(what, seconds, kib, log_bytes, rc):
    print(f"{what:<58} {seconds:7.2f} s {kib / 1024:8.1f} MiB  log {log_bytes:>9,} B  exit {rc}")


def noise_attacks():
    decode, encode = program("decode"), program("encode")
    report("decode: 64 MiB of zeros (no line ending)",
           *timed("head -c 64M /dev/zero", [decode]))
    report("decode: 256 MiB of zeros",
           *timed("head -c 256M /dev/zero", [decode]))
    report("decode: 32 MiB of random bytes",
           *timed("head -c 32M /dev/urandom", [decode]))
    report("decode --format none: 300,000 refused lines",
           *timed("yes '$GPXXX,1,2,3*00' | head -n 300000", [decode, "--format", "none"]))
    report("encode: 300 MiB without a line ending",
           *timed("head -c 300M /dev/zero | tr '\\\\0' x", [encode]))
    report("encode: a 64 MiB value",
           *timed("(printf '{\"type\":\"PYDIR\",\"thrust_left\":\"'; head -c 64M /dev/zero | "
                  "tr '\\\\0' 9; printf '\"}\\\\n')", [encode]))
    report("encode: 300,000 refused lines",
           *timed("yes '{\"type\":\"PYDIR\",\"thrust_left\":150}' | head -n 300000", [encode]))


def flood(name, line, log, extra=()):
    """One client sends `line` as fast as it can for 3 s: bytes a second of the server's log."""
    with tempfile.NamedTemporaryFile() as out, tempfile.NamedTemporaryFile() as err:
        p = subprocess.Popen([program(name), "--listen", "127.0.0.1:0", *extra], stdout=out,
                             stderr=err)
        try:
            deadline = time.monotonic() + 10
            while True:
                m = re.search(rb"listening on 127\.0\.0\.1:(\d+)", open(err.name, "rb").read())
                if m or time.monotonic() > deadline:
                    break
                time.sleep(0.05)
            if not m:
                print(f"{name}: did not say where it listens")
                return
            s = socket.create_connection(("127.0.0.1", int(m.group(1))))
            s.settimeout(30)
            block = (line * 1000).encode()
            path = out.name if log == "stdout" else err.name
            before, start, sent = os.path.getsize(path), time.monotonic(), 0
            while time.monotonic() - start < 3:
                s.sendall(block)
                sent += 1000
            took = time.monotonic() - start
            grew = os.path.getsize(path) - before
            s.close()
            print(f"{name}: {sent:,} bad lines in {took:.1f} s from one client: its {log} grew "
                  f"{grew / took:,.0f} B/s")
        finally:
            p.send_signal(signal.SIGINT)
            try:
                p.wait(timeout=30)
            except subprocess.TimeoutExpired:
                p.kill()


def stuck_feed():
    """seawire-anello-feed writing to a pty nobody reads: how long SIGTERM takes to end it."""
    master, slave = os.openpty()
    name = os.ttyname(slave)
    p = subprocess.Popen([program("anello-feed"), "--device", name, "--rate", "10"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(0.5)
    fill_pty(slave)  # the master is never read
    time.sleep(1)  # the feed's next writes find no room
    start = time.monotonic()
    p.send_signal(signal.SIGTERM)
    try:
        rc = p.wait(timeout=30)
        print(f"anello-feed: a full pty, then SIGTERM: ended in {time.monotonic() - start:.2f} s, "
              f"exit {rc}")
    except subprocess.TimeoutExpired:
        p.kill()
        print("anello-feed: a full pty, then SIGTERM: still running after 30 s (killed)")
    os.close(master)
    os.close(slave)


noise_attacks()
flood("sandshark-sim", seal("BPXYZ,120000.00,1"), "stderr", ["--shutdown-wait", "0"])
flood("kingfisher-sim", seal("PYDIR,150,0"), "stderr")
flood("robotx-judge", seal("RXHRB,261126,225321,21.31198,N,157.88972,W,AUVSI,2,1"), "stdout")
stuck_feed()
