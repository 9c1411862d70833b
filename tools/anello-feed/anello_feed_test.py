#!/usr/bin/env python3
# SPDX-License-Identifier: BSL-1.0
"""seawire-anello-feed through a socat pseudo-terminal pair, over UDP on loopback, and from a file.

    anello_feed_test.py FEED DECODE CASE
    CASE: pty, udp, input, usage, signal, stuck, stream, pipe, rmc
"""

import fcntl
import json
import os
import pty
import signal
import select
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time
import tty

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from harness import check, fill_pty, refusals, run_case

FEED, DECODE, CASE = sys.argv[1], sys.argv[2], sys.argv[3]


def decode(data):
    r = subprocess.run([DECODE, "--format", "json"], input=data, capture_output=True, timeout=60)
    return [json.loads(l) for l in r.stdout.decode().splitlines()]


def in_order(objs):
    frames = [o for o in objs if o["type"] == "AB00"]
    times = [o["gps_time"] for o in frames]
    return frames, all(a < b for a, b in zip(times, times[1:]))


def case_pty():
    socat = shutil.which("socat")
    if not socat:
        raise SystemExit("socat is needed (apt-get install socat)")
    d = tempfile.mkdtemp()
    ins, feed = os.path.join(d, "ins"), os.path.join(d, "feed")
    s = subprocess.Popen([socat, "PTY,raw,echo=0,link=" + ins, "PTY,raw,echo=0,link=" + feed],
                         stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 10
        while not (os.path.exists(ins) and os.path.exists(feed)) and time.monotonic() < deadline:
            time.sleep(0.05)
        fd = os.open(ins, os.O_RDWR | os.O_NOCTTY)
        tty.setraw(fd)
        p = subprocess.Popen([FEED, "--device", feed, "--baud", "115200", "--rate", "10",
                              "--seconds", "3", "--read-rmc"],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        got = b""
        sent_rmc = False
        end = time.monotonic() + 10
        while p.poll() is None and time.monotonic() < end:
            r, _, _ = select.select([fd], [], [], 0.05)
            if r:
                got += os.read(fd, 65536)
            if not sent_rmc and len(got) > 200:
                # The INS answers: an RMC, a GGA (not RMC: counted, not printed), a bad checksum.
                os.write(fd, b"$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214"
                             b",,,A*70\r\n$GPGGA,164959.00,4221.71114,N,07105.44878,W,1,06,2.80,"
                             b"46.6,M,-33.2,M,,*5C\r\n$GPRMC,164959.00,A,4221.71114,N*00\r\n")
                sent_rmc = True
        while True:
            r, _, _ = select.select([fd], [], [], 0.3)
            if not r:
                break
            got += os.read(fd, 65536)
        out, err = p.communicate(timeout=10)
        os.close(fd)
    finally:
        s.terminate()
        s.wait(timeout=10)
    check(p.returncode == 0, "exit 0: %r" % err)
    objs = decode(got)
    frames, ordered = in_order(objs)
    vbw = [o for o in objs if o["type"] == "VWVBW"]
    check(len(frames) == 30 and len(vbw) == 3, "30 frames and 3 VBW in 3 s at 10 Hz: %d, %d"
          % (len(frames), len(vbw)))
    check(ordered, "frames in order")
    check(all("error" not in o for o in objs), "everything decodes: %r" % [o for o in objs if "error" in o][:2])
    check(objs and objs[0]["type"] == "VWVBW", "a VBW leads each second")
    check(out == b"$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A*70\n",
          "--read-rmc prints the INS's RMC and nothing else: %r" % out)
    check(b"30 frames, 3 sentences sent" in err and b"1 RMC read, 2 other lines" in err,
          "summary: %r" % err)


def case_udp():
    u = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    u.bind(("127.0.0.1", 0))
    u.settimeout(3)
    p = subprocess.Popen([FEED, "--udp", "127.0.0.1:%d" % u.getsockname()[1], "--rate", "10",
                          "--seconds", "1"], stderr=subprocess.PIPE)
    grams = []
    try:
        while len(grams) < 11:
            grams.append(u.recv(65536))
    except socket.timeout:
        pass
    p.wait(timeout=10)
    check(p.returncode == 0, "exit 0")
    frames = [g for g in grams if g[:2] == b"\xab\x00"]
    sentences = [g for g in grams if g[:1] == b"$"]
    check(len(frames) == 10 and all(len(g) == 56 for g in frames), "one frame per datagram")
    check(len(sentences) == 1 and sentences[0].endswith(b"\r\n") and
          sentences[0].count(b"\r\n") == 1, "one sentence per datagram: %r" % sentences)
    objs = decode(b"".join(grams))
    check(len([o for o in objs if o["type"] == "AB00"]) == 10 and all("error" not in o for o in objs),
          "the datagrams decode")


def case_input():
    # A recorded stream (here: what the feed itself writes to stdout) is sent back unchanged,
    # paced: 20 frames at 10 Hz take about two seconds.
    rec = subprocess.run([FEED, "--rate", "10", "--seconds", "2", "-q"], capture_output=True,
                         timeout=30).stdout
    with tempfile.NamedTemporaryFile(delete=False) as f:
        f.write(b"noise before\r\n" + rec)
        path = f.name
    t = time.monotonic()
    r = subprocess.run([FEED, "--input", path, "--rate", "10"], capture_output=True, timeout=30)
    elapsed = time.monotonic() - t
    os.remove(path)
    check(r.returncode == 0 and r.stdout == rec, "the recorded stream comes out unchanged")
    check(1.6 < elapsed < 4, "paced at the frame rate: %.2f s" % elapsed)
    check(b"bytes outside frames and sentences skipped" in r.stderr, "noise reported: %r" % r.stderr)
    check(b"20 frames, 2 sentences sent" in r.stderr, "summary: %r" % r.stderr)


def case_signal():
    # SIGINT ends a run without --seconds cleanly: summary, exit 0.
    p = subprocess.Popen([FEED, "--rate", "10"], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    time.sleep(1.0)
    p.send_signal(2)
    out, err = p.communicate(timeout=10)
    check(p.returncode == 0 and b"frames," in err, "SIGINT: exit 0 with the summary: %r %r"
          % (p.returncode, err))
    frames = [o for o in decode(out) if o["type"] == "AB00"]
    check(8 <= len(frames) <= 12, "about a second of frames: %d" % len(frames))


def case_usage():
    refusals(FEED, b"--device",
             ((["--baud", "12345"], b"not a serial speed"),
              (["--device", "/nonexistent/tty"], b"No such file", 1),
              (["--device", "/dev/null"], b"not a terminal", 1),
              (["--device", "x", "--udp", "127.0.0.1:9"], b"excludes"),
              (["--read-rmc"], b"requires"),
              (["--udp", "127.0.0.1"], b"expected HOST:PORT", 1),
              (["--input", "/nonexistent"], b"cannot be read", 2),
              (["--input", "/"], b"--input /: cannot be read: Is a directory", 2)),
             extra=["--seconds", "0.1"])
    r = subprocess.run([FEED, "--input", "/", "--seconds", "0.1"], capture_output=True,
                       timeout=20)
    check(r.stderr.count(b"\n") == 1, "a directory: one line: %r" % r.stderr)


def stops_within(p, sig, seconds):
    """Sends `sig` and whether `p` then exits within `seconds` (killed if not)."""
    t = time.monotonic()
    p.send_signal(sig)
    try:
        p.wait(timeout=seconds)
    except subprocess.TimeoutExpired:
        p.kill()
        p.wait()
        return False
    return time.monotonic() - t < seconds


def case_stuck():
    # A pty nobody reads fills up; the feed must still hear SIGTERM, SIGINT and --seconds.
    for sig, args in ((signal.SIGTERM, []), (signal.SIGINT, []), (None, ["--seconds", "2"])):
        master, slave = pty.openpty()
        path = os.ttyname(slave)
        p = subprocess.Popen([FEED, "--device", path, "--rate", "10", *args],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        time.sleep(0.5)
        fill_pty(slave)  # the master is never read
        time.sleep(0.3)
        if sig is None:
            try:
                p.wait(timeout=6)
                ok = True
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()
                ok = False
            check(ok, "--seconds 2 ends a run on a full pty")
        else:
            check(stops_within(p, sig, 2.5), "signal %d ends a run on a full pty within 2.5 s"
                  % sig)
        err = p.stderr.read()
        check(p.returncode == 0 and b"frames," in err, "exit 0 with the summary: %d %r"
              % (p.returncode, err))
        os.close(slave)
        os.close(master)


def case_rmc():
    # --read-rmc with a stdout nobody reads: the RMC lines the INS sends fill the pipe; the
    # feed still hears SIGTERM.
    master, slave = pty.openpty()
    tty.setraw(master)
    rd, wr = os.pipe()
    p = subprocess.Popen([FEED, "--device", os.ttyname(slave), "--read-rmc", "--rate", "10"],
                         stdout=wr, stderr=subprocess.PIPE)
    os.close(wr)
    time.sleep(0.5)
    rmc = (b"$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A*70\r\n")
    fcntl.fcntl(master, fcntl.F_SETFL, fcntl.fcntl(master, fcntl.F_GETFL) | os.O_NONBLOCK)
    sent = 0
    end = time.monotonic() + 3
    while sent < 200000 and time.monotonic() < end:
        try:
            sent += os.write(master, rmc * 50)
        except BlockingIOError:
            time.sleep(0.01)
    check(sent > 70000, "more RMC sent than a pipe holds: %d bytes" % sent)
    check(stops_within(p, signal.SIGTERM, 2.5), "SIGTERM ends a run whose stdout is full")
    err = p.stderr.read()
    check(p.returncode == 0 and b"RMC read" in err, "exit 0 with the summary: %d %r"
          % (p.returncode, err))
    os.close(rd)
    os.close(slave)
    os.close(master)


def case_stream():
    # --input - is read as it comes: frames go out while stdin is still open (all but the last,
    # whose period the sentences after it may still join).
    rec = subprocess.run([FEED, "--rate", "10", "--seconds", "1", "-q"], capture_output=True,
                         timeout=30).stdout
    check(len(rec) > 56 * 10 and rec[-56:-54] == b"\xab\x00",
          "the recording ends with a frame: %r" % rec[-56:])
    p = subprocess.Popen([FEED, "--input", "-", "--rate", "10", "-q"], stdin=subprocess.PIPE,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    p.stdin.write(rec)
    p.stdin.flush()
    got = b""
    end = time.monotonic() + 5
    while len(got) < len(rec) - 56 and time.monotonic() < end:
        r, _, _ = select.select([p.stdout], [], [], 0.1)
        if r:
            got += os.read(p.stdout.fileno(), 65536)
    check(got == rec[:-56], "the stream sent while stdin is open: %d of %d bytes"
          % (len(got), len(rec) - 56))
    p.stdin.close()
    got += p.stdout.read()
    p.wait(timeout=10)
    check(p.returncode == 0 and got == rec, "all sent, exit 0 at the input's end: %d %d of %d"
          % (p.returncode, len(got), len(rec)))
    # Endless input without a frame (/dev/zero): memory bounded, --seconds and signals heard.
    with open("/dev/zero", "rb") as zero:
        t = time.monotonic()
        p = subprocess.Popen([FEED, "--input", "-", "--seconds", "2"], stdin=zero,
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        killer = threading.Timer(10, p.kill)
        killer.start()
        _, status, usage = os.wait4(p.pid, 0)
        elapsed = time.monotonic() - t
        killer.cancel()
    p.returncode = os.waitstatus_to_exitcode(status)
    err = p.stderr.read()
    check(p.returncode == 0 and elapsed < 5, "--seconds 2 on /dev/zero: %d after %.1f s %r"
          % (p.returncode, elapsed, err))
    check(b"0 frames, 0 sentences sent" in err and b"bytes outside frames" in err,
          "nothing sent, the zeros counted: %r" % err)
    check(usage.ru_maxrss < 200 * 1024, "memory bounded: %d KiB" % usage.ru_maxrss)
    with open("/dev/zero", "rb") as zero:
        p = subprocess.Popen([FEED, "--input", "-"], stdin=zero, stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL)
        time.sleep(1)
        check(stops_within(p, signal.SIGTERM, 2.5) and p.returncode == 0,
              "SIGTERM heard while reading /dev/zero")


def case_pipe():
    # The reader of stdout goes away: EPIPE told (SIGPIPE ignored), exit 1.
    rd, wr = os.pipe()
    p = subprocess.Popen([FEED, "--rate", "10"], stdout=wr, stderr=subprocess.PIPE)
    os.close(wr)
    os.read(rd, 10)
    os.close(rd)
    try:
        _, err = p.communicate(timeout=10)
    except subprocess.TimeoutExpired:
        p.kill()
        _, err = p.communicate()
    check(p.returncode == 1 and b"seawire-anello-feed: writing stdout: Broken pipe\n" in err,
          "EPIPE told: %d %r" % (p.returncode, err))
    with open("/dev/full", "wb") as full:
        r = subprocess.run([FEED, "--rate", "10", "--seconds", "1"], stdout=full,
                           capture_output=False, stderr=subprocess.PIPE, timeout=20)
    check(r.returncode == 1 and b"writing stdout: No space left on device\n" in r.stderr,
          "ENOSPC told: %d %r" % (r.returncode, r.stderr))


run_case(globals(), CASE)
