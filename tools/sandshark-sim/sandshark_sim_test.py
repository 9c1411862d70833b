#!/usr/bin/env python3
# SPDX-License-Identifier: BSL-1.0
"""seawire-sandshark-sim over loopback: a payload written here against the simulated BAM.

    sandshark_sim_test.py SIM CASE      CASE: session, shutdown, usage

Every step is checked from both sides: what the payload receives and what the simulator logs.
"""

import os
import re
import signal
import socket
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from harness import Server, check, checksum_ok, refusals, run_case, seal

SIM, CASE = sys.argv[1], sys.argv[2]
BACKSEAT = sys.argv[3] if len(sys.argv) > 3 else None  # the backseat example, for its case


def stamp():
    t = time.gmtime()
    return time.strftime("%H%M%S.00", t)


def seconds_of_day(hhmmss):
    """'231300.125' -> seconds since midnight."""
    return int(hhmmss[0:2]) * 3600 + int(hhmmss[2:4]) * 60 + float(hhmmss[4:])


def day_offset(a, b):
    """a - b in seconds for two times of day, the nearest way round midnight."""
    return (a - b + 43200) % 86400 - 43200


def wall_seconds_of_day():
    return time.time() % 86400


class Payload:
    def __init__(self, port):
        self.sock = socket.create_connection(("127.0.0.1", port), timeout=10)
        self.sock.settimeout(0.05)
        self.buf = b""
        self.lines = []  # (arrival, line)
        self.closed = False

    def pump(self, seconds):
        end = time.monotonic() + seconds
        while time.monotonic() < end and not self.closed:
            try:
                data = self.sock.recv(65536)
            except socket.timeout:
                continue
            except ConnectionError:
                self.closed = True
                break
            if not data:
                self.closed = True
                break
            self.buf += data
            *done, self.buf = self.buf.split(b"\r\n")
            now = time.monotonic()
            self.lines += [(now, l.decode()) for l in done]

    def wait_for(self, pattern, timeout=10, start=None):
        """The first line matching `pattern` (a regex), from now on or from line `start`."""
        start = len(self.lines) if start is None else start
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            for at, l in self.lines[start:]:
                if re.search(pattern, l):
                    return l
            start = len(self.lines)
            self.pump(0.05)
            if self.closed:
                break
        return None

    def send(self, body):
        self.sock.sendall(seal(body).encode())

    def of(self, address):
        return [l.split("*")[0].split(",") for _, l in self.lines if l[1:6] == address]

    def close(self):
        self.sock.close()


TIMELINE = """# a short mission
0    mission Waiting
0.5  mission Ready dive1.xml
1.0  mission Running dive1.xml
1.5  control on
60   mission Completed dive1.xml
"""


def case_session():
    fd, mission = tempfile.mkstemp(suffix=".mission")
    os.write(fd, TIMELINE.encode())
    os.close(fd)
    sim = Server(SIM, "--mission", mission, "--nav-rate", "10", "--client", "backseat=127.0.0.1",
              "--shutdown-wait", "1")
    p = Payload(sim.port)
    # Handshake: BFVER at once; nothing else before BPLOG.
    ver = p.wait_for(r"^\$BFVER,")
    check(ver is not None and ver.split(",")[2].startswith("1.0"), "BFVER on connect: %r" % ver)
    p.send("BPVER,%s,1.0" % stamp())
    p.pump(1.2)
    check([l for _, l in p.lines if not l.startswith("$BFVER")] == [],
          "no status messages before BPLOG: %r" % [l for _, l in p.lines][:5])
    check(sim.wait_log(r"client 1 \(backseat\): BPVER 1.0"), "BPVER logged with the client's name")
    check("client 1: named backseat (127.0.0.1)" in sim.log(), "the named client recognised")
    # Subscriptions: ACK must be asked for explicitly; ALL then brings the status messages.
    p.send("BPLOG,ALL,ON")
    p.pump(0.5)
    check(p.of("BFACK") == [], "no BFACK before BPLOG,ACK,ON")
    check(p.of("BFNVG") != [], "BPLOG,ALL,ON: BFNVG flows")
    p.send("BPLOG,ACK,ON")
    ack = p.wait_for(r"^\$BFACK,[^,]*,LOG,")
    check(ack is not None and ack.split(",")[5] == "2", "BPLOG,ACK,ON acknowledged ok: %r" % ack)
    check(all(checksum_ok(l) for _, l in p.lines), "every line has a good checksum")
    # The mission runs and hands control over.
    ctl = p.wait_for(r"^\$BFCTL,[^,]*,1\*", start=0)
    check(ctl is not None, "BFCTL 1 once the mission runs")
    check(any(f[3].startswith("Running") for f in p.of("BFMIS")) or
          sim.wait_log("BFMIS Running dive1.xml"), "BFMIS Running")
    # Dynamic requests, kept alive every second: heading 90, 5 m, 1.5 m/s.
    for _ in range(8):
        p.send("BPRMB,%s,90.0,5.0,0,1.5,1,0" % stamp())
        p.pump(1.0)
    acks = [f for f in p.of("BFACK") if f[2] == "RMB"]
    check(len(acks) == 8 and all(f[5] == "2" for f in acks), "each BPRMB acked ok: %r" % acks)
    check(re.search(r"client 1 \(backseat\): BPRMB request started", sim.log()), "the request logged")
    heading = float(p.of("BFNVG")[-1][9])
    check(abs(heading - 90) < 20, "the vehicle turns to the requested heading: %.1f" % heading)
    depth = float(p.of("BFNVG")[-1][8])
    check(depth > 1.0, "and dives toward 5 m: %.2f" % depth)
    check(not any(f[2] == "0" for f in p.of("BFCTL")[1:]), "control kept while BPRMB comes")
    # The keep-alive lapses: control goes back to the vehicle after 5 s.
    lapse_start = time.monotonic()
    back = p.wait_for(r"^\$BFCTL,[^,]*,0\*", timeout=10)
    elapsed = time.monotonic() - lapse_start
    check(back is not None and 3.5 < elapsed < 7, "BFCTL 0 about 5 s after the last BPRMB: %.2f s" % elapsed)
    check(sim.wait_log(r"no BPRMB for 5 s: the vehicle takes control back"), "the lapse logged")
    p.send("BPRMB,%s,180.0,,,,,0" % stamp())
    late = p.wait_for(r"^\$BFACK,[^,]*,RMB,")
    check(late is not None and late.split(",")[5] == "1", "a BPRMB without control fails: %r" % late)
    # Abort: pending first, the final ack within 2 s, the mission shows it.
    p.send("BPABT,%s,test abort,1" % stamp())
    mark = len(p.lines)
    first = p.wait_for(r"^\$BFACK,[^,]*,ABT,")
    t_first = time.monotonic()
    final = p.wait_for(r"^\$BFACK,[^,]*,ABT,[^,]*,[^,]*,[^3]", start=mark)
    check(first is not None and first.split(",")[5] == "3", "BPABT: pending ack first: %r" % first)
    check(final is not None and final.split(",")[5] == "2" and time.monotonic() - t_first < 2.0,
          "BPABT: final ack within 2 s: %r" % final)
    aborted = p.wait_for(r"^\$BFMIS,[^,]*,[^,]*,Aborted", timeout=5, start=mark)
    statuses = [f[3] for f in p.of("BFMIS")]
    check("Aborting" in statuses and aborted is not None, "BFMIS Aborting then Aborted: %r" % statuses)
    # Nothing left to abort: acknowledged, but no second Aborted.
    p.send("BPABT,%s,again,1" % stamp())
    p.pump(3)
    check([f[3] for f in p.of("BFMIS")].count("Aborted") == 1, "one Aborted only")
    check(sim.wait_log("abort requested with no mission to abort"), "the second abort logged")
    # Reconnect: a new session, BFVER again, no subscriptions kept.
    p.close()
    check(sim.wait_log(r"client 1 127\.0\.0\.1:\d+ disconnected"), "disconnect logged")
    q = Payload(sim.port)
    check(q.wait_for(r"^\$BFVER,") is not None, "BFVER again after reconnecting")
    q.pump(0.6)
    check([l for _, l in q.lines if not l.startswith("$BFVER")] == [], "subscriptions start empty")
    # Shutdown: BFSHT at once, the connection kept for --shutdown-wait, then closed.
    q.send("BPLOG,ALL,ON")
    q.pump(0.3)
    sim.proc.send_signal(signal.SIGTERM)
    sht = q.wait_for(r"^\$BFSHT,")
    t_sht = time.monotonic()
    check(sht is not None, "BFSHT on SIGTERM")
    q.pump(5)
    check(q.closed and time.monotonic() - t_sht >= 0.8, "closed after the shutdown wait")
    check(sim.proc.wait(timeout=10) == 0, "exit 0")
    log = sim.log()
    check("BFSHT sent to 1 client(s), closing in 1 s" in log, "shutdown logged:\n" + log)
    os.remove(mission)


def case_backseat():
    # The backseat example takes control when the mission hands it over and keeps its request
    # alive; when it stops, the request lapses and the vehicle takes control back.
    fd, mission = tempfile.mkstemp(suffix=".mission")
    os.write(fd, b"0 mission Running dive1.xml\n0.5 control on\n")
    os.close(fd)
    sim = Server(SIM, "--mission", mission, "--nav-rate", "10", "--shutdown-wait", "0")
    watcher = Payload(sim.port)
    watcher.send("BPLOG,NVG,ON")
    started = wall_seconds_of_day()
    backseat = subprocess.run([BACKSEAT, "--connect", "127.0.0.1:%d" % sim.port, "12"],
                              capture_output=True, timeout=60)
    ended = wall_seconds_of_day()
    out = backseat.stdout.decode()
    watcher.pump(0.2)
    check(backseat.returncode == 0, "the example ran: %r" % backseat.stderr)
    check(out.count("send: $BPRMB") >= 2, "it kept its request alive:\n" + out[-1500:])
    heading = float(watcher.of("BFNVG")[-1][9])
    check(abs(heading - 90) < 5, "the vehicle follows the backseat to 90: %.1f" % heading)
    log = sim.log()
    check("BPRMB request started" in log, "the request started:\n" + log)
    check("takes control back" not in log, "no lapse while the backseat runs:\n" + log)
    check(sim.wait_log("no BPRMB for 5 s: the vehicle takes control back", timeout=10),
          "the lapse once it is gone")
    # Its timestamps are the UTC time of day, advancing with the run, whatever the machine's
    # uptime: as the simulator received them (BPVER, the BPSTS heartbeat) against the wall clock
    # and the simulator's own UTC at receipt ...
    received = re.findall(r"client \d+: (BP\w+) .*\[stamped (\d{6}\.\d{3}), vehicle (\d{6}\.\d{3})\]",
                          log)
    check(len(received) >= 10 and received[0][0] == "BPVER" and
          sum(1 for r in received if r[0] == "BPSTS") >= 10,
          "the simulator logged the backseat's BPVER and heartbeats:\n" + log[-1500:])
    for address, stamp, vehicle in received:
        t = seconds_of_day(stamp)
        check(-2 < day_offset(t, started) and day_offset(t, ended) < 2,
              "%s stamped %s within the run's wall clock (%.3f to %.3f s of the day)"
              % (address, stamp, started, ended))
        check(abs(day_offset(t, seconds_of_day(vehicle))) < 1,
              "%s stamped %s, the simulator's UTC %s" % (address, stamp, vehicle))
    sts = [seconds_of_day(r[1]) for r in received if r[0] == "BPSTS"]
    check(len(sts) >= 2 and day_offset(sts[-1], sts[0]) > 8,
          "the heartbeat's stamps advance over the 12 s run: %r" % sts)
    # ... and every stamp it sent, in order.
    sent = re.findall(r"^send: \$(BP\w+),(\d{6}\.\d{3}),", out, re.M)
    check(any(a == "BPRMB" for a, _ in sent), "BPRMB stamps sent:\n" + out[-1500:])
    for address, stamp in sent:
        t = seconds_of_day(stamp)
        check(-2 < day_offset(t, started) and day_offset(t, ended) < 2,
              "sent %s stamped %s within the run's wall clock (%.3f to %.3f)"
              % (address, stamp, started, ended))
    times = [seconds_of_day(st) for _, st in sent]
    check(all(day_offset(b, a) > 0 for a, b in zip(times, times[1:])),
          "the stamps sent increase: %r" % [st for _, st in sent][:20])
    watcher.close()
    check(sim.stop(timeout=10) == 0, "exit 0")
    os.remove(mission)


def case_usage():
    fd, bad = tempfile.mkstemp(suffix=".mission")
    os.write(fd, b"0 mission Waiting\n2 launch now\n")
    os.close(fd)
    refusals(SIM, b"--mission",
             ((["--listen", "x"], b"expected ADDR:PORT"),
              (["--client", "backseat=nowhere"], b"not an IP address"),
              (["--mission", bad], b":2: expected"),
              (["--mission", "/nonexistent"], b"cannot be read"),
              (["--pending", "ABT,XYZ"], b"XYZ is none of"),
              (["--version-text", "1,0"], b"at most 32 printable")), rc=2)
    os.remove(bad)


run_case(globals(), CASE)
