#!/usr/bin/env python3
# SPDX-License-Identifier: BSL-1.0
"""seawire-sandshark-sim over loopback: a payload written here against the simulated BAM.

    sandshark_sim_test.py SIM CASE      CASE: session, backseat, usage, flood, refusals

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


def mission_file(text):
    """A mission timeline file holding `text` (bytes or str); the caller removes it."""
    fd, path = tempfile.mkstemp(suffix=".mission")
    os.write(fd, text.encode() if isinstance(text, str) else text)
    os.close(fd)
    return path


def case_session():
    mission = mission_file(TIMELINE.encode())
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
    mission = mission_file(b"0 mission Running dive1.xml\n0.5 control on\n")
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


def invalid_counts(log, what):
    """The invalid-command lines logged and the sum of the suppressed counts noted."""
    logged = len(re.findall(r"^client \d+: invalid ", log, re.M))
    noted = sum(int(n) for n in re.findall(r"^\.\.\. (\d+) more %s suppressed$" % what, log,
                                           re.M))
    return logged, noted


def case_flood():
    # A payload sending nothing but bad commands as fast as it can: the log keeps to its rate
    # (20 lines a second per kind), and says how many lines it left out, to the line.
    sim = Server(SIM, "--nav-rate", "10", "--shutdown-wait", "0")
    p = Payload(sim.port)
    lines = (seal("BPXYZ,%s,1" % stamp()) * 1000).encode()
    sent = 0
    start = time.monotonic()
    size0 = len(sim.log())
    p.sock.settimeout(30)
    while time.monotonic() - start < 2:
        p.sock.sendall(lines)
        sent += 1000
    p.sock.shutdown(socket.SHUT_WR)
    check(sim.wait_log(r"client 1 \S+ disconnected: end of stream; .* %d sentences in, %d rejected"
                       % (sent, sent), timeout=60),
          "every line read and rejected: %d sent" % sent)
    elapsed = time.monotonic() - start
    # The count of a window that was over shows without another line (the flood stopped).
    check(sim.wait_log(r"more invalid commands suppressed", timeout=5), "the count is logged")
    check(sim.stop(timeout=20) == 0, "exit 0")
    log = sim.log()
    rate = (len(log) - size0) / elapsed
    logged, noted = invalid_counts(log, "invalid commands")
    print("flood: %d lines in %.1f s; %d logged, %d noted suppressed; %.0f bytes/s of log"
          % (sent, elapsed, logged, noted, rate), file=sys.stderr)
    check(logged + noted == sent, "every invalid line logged or counted: %d + %d != %d"
          % (logged, noted, sent))
    check(logged <= 20 * (elapsed + 2), "at most 20 lines a second: %d in %.1f s" % (logged, elapsed))
    check(rate < 20000, "the log grows by less than 20 kB/s under a flood: %.0f B/s" % rate)


def ack_of(p, code, mark):
    """The fields of the first BFACK for `code` after line `mark`, or None."""
    line = p.wait_for(r"^\$BFACK,[^,]*,%s," % code, start=mark)
    return line.split("*")[0].split(",") if line else None


def case_refusals():
    # Commands that decode but ask what the vehicle cannot do are acknowledged invalid (0) and
    # not acted on; a payload subscribing to BFCTL is told at once whether it has control.
    mission = mission_file(b"0 mission Running dive1.xml\n1.0 control on\n")
    sim = Server(SIM, "--mission", mission, "--nav-rate", "10", "--shutdown-wait", "0")
    p = Payload(sim.port)
    p.wait_for(r"^\$BFVER,")
    p.send("BPLOG,ACK,ON")
    mark = len(p.lines)
    p.send("BPLOG,ALL,ON")
    first = p.wait_for(r"^\$BFCTL,", start=mark)
    check(first is not None and first.split("*")[0].endswith(",0"),
          "subscribing before the hand-over: told BFCTL 0 at once: %r" % first)
    check(p.wait_for(r"^\$BFCTL,[^,]*,1\*", timeout=5) is not None, "then BFCTL 1")
    # A payload connecting after the hand-over learns it has control when it subscribes.
    q = Payload(sim.port)
    q.wait_for(r"^\$BFVER,")
    q.pump(0.3)
    check(q.of("BFCTL") == [], "no BFCTL before it asks")
    q.send("BPLOG,CTL,ON")
    told = q.wait_for(r"^\$BFCTL,", timeout=3)
    check(told is not None and told.split("*")[0].endswith(",1"),
          "a payload subscribing during the hand-over: told BFCTL 1: %r" % told)
    q.close()
    # Out of the vehicle's range: invalid, the command's timestamp echoed, the reason logged.
    for body, field, reason in (
            ("%s,90.0,99999999999,0,1.0,1,0", "depth", r"depth 99999999999 m outside 0 to 200 m"),
            ("%s,90.0,-99999,0,1.0,1,0", "depth", r"depth -99999 m outside 0 to 200 m"),
            ("%s,90.0,200.1,,1.0,1,0", "depth", r"depth 200.1 m outside"),
            ("%s,90.0,250,1,1.0,1,0", "depth", r"altitude 250 m outside"),
            ("%s,90.0,95,2,1.0,1,0", "depth", r"pitch 95 deg outside -90 to 90 deg"),
            ("%s,360.0,5,0,1.0,1,0", "heading", r"heading 360 deg outside 0 to 360 \(excluded\)"),
            ("%s,-100,5,0,1.0,1,1", "heading", r"rudder -100 deg outside -90 to 90 deg"),
            ("%s,90.0,5,0,30,1,0", "speed", r"speed 30 m/s outside 0 to 2 m/s"),
            ("%s,90.0,5,0,-1,1,0", "speed", r"speed -1 m/s outside"),
            ("%s,90.0,5,0,5000,0,0", "speed", r"thruster 5000 RPM outside 0 to 2000 RPM")):
        t = stamp()
        mark = len(p.lines)
        p.send("BPRMB," + body % t)
        a = ack_of(p, "RMB", mark)
        check(a is not None and a[5] == "0" and a[3] == t and field in a[7],
              "BPRMB %s refused invalid: %r" % (body % t, a))
        check(sim.wait_log(r"invalid BPRMB: .*: " + reason), "logged: %s\n%s" % (reason, sim.log()[-800:]))
    p.pump(1)
    check("BPRMB request started" not in sim.log(), "no refused request steers the vehicle")
    depths = [float(f[8]) for f in p.of("BFNVG")]
    check(depths and max(depths) < 5, "the vehicle stays near its mission depth: %r" % depths[-3:])
    # Within range: ok, and it steers (altitude 45 m in 50 m of water is 5 m deep).
    for body in ("%s,90.0,200,0,2.0,1,0", "%s,90.0,45,1,2000,0,0", "%s,-90,-90,3,0,1,1"):
        mark = len(p.lines)
        p.send("BPRMB," + body % stamp())
        a = ack_of(p, "RMB", mark)
        check(a is not None and a[5] == "2", "BPRMB %s acknowledged ok: %r" % (body, a))
    check(sim.wait_log("BPRMB request started"), "the request in range steers")
    # BPLOG: a code of no status message is invalid and turns nothing on; the real ones are ok.
    for code, status in (("XYZ", "0"), ("SHT", "0"), ("NVG", "2"), ("MIS", "2"), ("ALL", "2")):
        mark = len(p.lines)
        p.send("BPLOG,%s,ON" % code)
        a = ack_of(p, "LOG", mark)
        check(a is not None and a[5] == status, "BPLOG,%s,ON acknowledged %s: %r" % (code, status, a))
    check(sim.wait_log(r"invalid BPLOG: .*\(field 1\): no status message XYZ"), "the code logged")
    p.close()
    check(sim.stop(timeout=20) == 0, "exit 0")
    os.remove(mission)


def case_usage():
    bad = mission_file(b"0 mission Waiting\n2 launch now\n")
    # Mission steps a BFMIS cannot carry are refused at start with their line, not published
    # blank: a reserved character, a text over 256 characters, a line over the session's 512.
    unsendable = [mission_file(b"0 mission Waiting\n" + step + b"\n") for step in (
        b"1 mission Run*ning", b"1 mission Running dive,1.xml", b"1 mission Running " + b"d" * 257,
        b"1 mission " + b"R" * 250 + b" " + b"d" * 250)]
    refusals(SIM, b"--mission",
             ((["--listen", "x"], b"expected ADDR:PORT"),
              (["--client", "backseat=nowhere"], b"not an IP address"),
              (["--mission", bad], b":2: expected"),
              (["--mission", "/nonexistent"], b"cannot be read"),
              (["--pending", "ABT,XYZ"], b"XYZ is none of"),
              (["--version-text", "1,0"], b"at most 32 printable"))
             # (--duration: a simulator that took the file ends, and the case fails.)
             + tuple((["--mission", path, "--duration", "1"], b":2: BFMIS cannot carry")
                     for path in unsendable), rc=2)
    os.remove(bad)
    for path in unsendable:
        os.remove(path)


run_case(globals(), CASE)
