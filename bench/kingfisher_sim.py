#!/usr/bin/env python3
# SPDX-License-Identifier: BSL-1.0
"""Figures for seawire-kingfisher-sim, on loopback (build it in Release for these):

    python3 bench/kingfisher_sim.py build/<dir>/tools/seawire-kingfisher-sim

1. Throughput: sentences per second one simulator delivers to 50 clients, each client reading
   everything (the simulator at --nav-rate 1000, so it sends 4,000+ sentences a second to each
   client); counted at the clients over 5 s.
2. Command latency: the time from a PYDIR leaving the payload to the first CPNVR showing its
   effect (yaw rate of the commanded sign), at --nav-rate 10 (the default: bounded by one tick,
   100 ms) and at --nav-rate 1000 (one tick is 1 ms: what is left is the command's way in, its
   application and the way out). 50 samples each; median and 95th percentile.
"""

import os
import re
import select
import socket
import statistics
import subprocess
import sys
import time

SIM = sys.argv[1]


def start(*args):
    p = subprocess.Popen([SIM, "--listen", "127.0.0.1:0", *args], stderr=subprocess.PIPE)
    first = p.stderr.readline().decode()
    port = int(re.fullmatch(r"listening on 127\.0\.0\.1:(\d+)\n", first).group(1))
    return p, port


def cpu_seconds(pid):
    with open("/proc/%d/stat" % pid) as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def throughput(clients=50, seconds=5.0):
    p, port = start("--nav-rate", "1000", "--status-rate", "10", "--max-queue", "100000")
    socks = [socket.create_connection(("127.0.0.1", port)) for _ in range(clients)]
    for s in socks:
        s.setblocking(False)
    counts = [0] * clients
    end = time.monotonic() + 1.0  # warm up
    while time.monotonic() < end:
        for s in select.select(socks, [], [], 0.05)[0]:
            s.recv(1 << 20)
    t0 = time.monotonic()
    cpu0 = cpu_seconds(p.pid)
    end = t0 + seconds
    while time.monotonic() < end:
        for s in select.select(socks, [], [], 0.05)[0]:
            counts[socks.index(s)] += s.recv(1 << 20).count(b"\n")
    elapsed = time.monotonic() - t0
    cpu = cpu_seconds(p.pid) - cpu0
    for s in socks:
        s.close()
    p.terminate()
    p.wait()
    total = sum(counts)
    print("throughput: %d clients, %.0f sentences/s in all (%.0f per client, min %.0f), "
          "simulator at %.0f%% of one core"
          % (clients, total / elapsed, total / elapsed / clients, min(counts) / elapsed,
             100 * cpu / elapsed))


def yaws(lines):
    return [float(l.split(b"*")[0].split(b",")[7]) for l in lines if l.startswith(b"$CPNVR")]


def latency(rate, samples=50):
    """Yaw rate has no noise in the model: before a command it moves steadily toward the old
    demand, so the first CPNVR whose yaw rate moves the other way shows the new command."""
    p, port = start("--nav-rate", str(rate), "--watchdog", "10")
    s = socket.create_connection(("127.0.0.1", port))
    s.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    s.settimeout(10)
    buf = b""
    last = None
    results = []
    sign = 1

    def read_lines():
        nonlocal buf
        buf += s.recv(65536)
        *lines, buf = buf.split(b"\r\n")
        return lines

    s.sendall(b"$PYDIR,-100,100\r\n")
    for _ in range(samples):
        end = time.monotonic() + 0.5  # let the yaw rate head for the old demand
        while time.monotonic() < end:
            for y in yaws(read_lines()):
                last = y
        t0 = time.perf_counter()
        s.sendall(b"$PYDIR,%d,%d\r\n" % (100 * sign, -100 * sign))
        found = False
        while not found:
            for y in yaws(read_lines()):
                if not found and (y - last) * sign > 0:
                    results.append(time.perf_counter() - t0)
                    found = True
                last = y
        sign = -sign
    s.close()
    p.terminate()
    p.wait()
    results.sort()
    print("latency at --nav-rate %d: median %.2f ms, p95 %.2f ms, max %.2f ms (%d samples)"
          % (rate, statistics.median(results) * 1e3, results[int(len(results) * 0.95)] * 1e3,
             results[-1] * 1e3, len(results)))


throughput()
latency(10)
latency(1000)
