#!/usr/bin/env python3
# SPDX-License-Identifier: BSL-1.0
"""seawire-tcp against servers written here, on 127.0.0.1 with ephemeral ports.

    tcp_test.py TCP CASE      CASE: framing, send, reconnect, errors, timeout, stdout, flood
"""

import os
import re
import signal
import socket
import subprocess
import os
import sys
import threading
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from harness import check, run_case

TCP, CASE = sys.argv[1], sys.argv[2]


def listener(port=0):
    s = socket.socket()
    s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    s.bind(("127.0.0.1", port))
    s.listen(8)
    s.settimeout(20)
    return s


def recv_all(conn, timeout=10):
    conn.settimeout(timeout)
    data = b""
    while True:
        try:
            chunk = conn.recv(65536)
        except socket.timeout:
            return data
        if not chunk:
            return data
        data += chunk


def run_for(seconds, *args):
    """Runs seawire-tcp with `args` (stdin at /dev/null) for `seconds`, then SIGTERM; returns its
    exit status and stderr."""
    p = subprocess.Popen([TCP, *args], stdin=subprocess.DEVNULL, stderr=subprocess.PIPE)
    time.sleep(seconds)
    p.send_signal(signal.SIGTERM)
    _, err = p.communicate(timeout=10)
    return p.returncode, err


def case_framing():
    # What a bad server can send: split lines, CR-only endings, an overlong line, an invalid byte,
    # binary noise, and a last sentence without a line ending before the close.
    srv = listener()
    port = srv.getsockname()[1]
    p = subprocess.Popen([TCP, "127.0.0.1:%d" % port], stdin=subprocess.PIPE,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    conn, _ = srv.accept()
    pieces = [b"$CPALT,120000.000,1*6", b"2\r\n", b"$PYDIR,1,2\r",
              b"$GPRMC," + b"9" * 5000 + b"\r\n", b"$CPALT,120001.000,0*62\r\n",
              b"$CPALT,12\x01\x02garbled*00\r\n", bytes(range(128, 256)), b"\n",
              b"!AIVDM,1,1,,A,13aEOK?P00PD2wVMdLDRhgvL289?,0*26\n", b"$CPALT,120002.000,1*61"]
    for piece in pieces:
        conn.sendall(piece)
        time.sleep(0.02)
    conn.close()
    out, err = p.communicate(timeout=20)
    want = (b"$CPALT,120000.000,1*62\r\n$PYDIR,1,2\r\n$CPALT,120001.000,0*62\r\n"
            b"!AIVDM,1,1,,A,13aEOK?P00PD2wVMdLDRhgvL289?,0*26\r\n$CPALT,120002.000,1*61\r\n")
    check(out == want, "only whole sentences, each with CR LF:\n%r\nwanted\n%r" % (out, want))
    check(p.returncode == 0, "exit 0 when the server closes: %r %r" % (p.returncode, err))
    # --lf
    p = subprocess.Popen([TCP, "--lf", "-q", "127.0.0.1:%d" % port], stdin=subprocess.PIPE,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    conn, _ = srv.accept()
    conn.sendall(b"$PYDIR,1,2\r\n")
    conn.close()
    out, err = p.communicate(timeout=20)
    check(out == b"$PYDIR,1,2\n" and err == b"", "--lf, --quiet: %r %r" % (out, err))


def case_send():
    srv = listener()
    port = srv.getsockname()[1]
    p = subprocess.Popen([TCP, "-N", "127.0.0.1:%d" % port], stdin=subprocess.PIPE,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    conn, _ = srv.accept()
    p.stdin.write(b"$PYDEV,90,1.5\n$PYDIR,10,\x0010\n$PYD")
    p.stdin.flush()
    time.sleep(0.2)
    p.stdin.write(b"IR,45,55*57\n" + b"x" * 3000 + b"\n$PYCLT,1")
    p.stdin.close()  # the last line has no ending: cut off, not sent, and said so
    got = recv_all(conn)  # -N: the client half-closes once stdin is sent
    check(got == b"$PYDEV,90,1.5\r\n$PYDIR,45,55*57\r\n",
          "stdin framed, garbled, overlong and cut-off lines dropped: %r" % got)
    conn.sendall(b"$CPALT,120000.000,1*62\r\n")
    conn.close()
    out = p.stdout.read()
    p.wait(timeout=20)
    check(out == b"$CPALT,120000.000,1*62\r\n" and p.returncode == 0,
          "after the half close the server's lines still arrive: %r" % out)
    err = p.stderr.read()
    check(b"seawire-tcp: stdin ended in the middle of a line (no line ending after it): that "
          b"line is not sent\n" in err, "the cut-off line told: %r" % err)
    # Without -N the client stays after stdin ends (a listener with stdin at /dev/null).
    p = subprocess.Popen([TCP, "127.0.0.1:%d" % port], stdin=subprocess.DEVNULL,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    conn, _ = srv.accept()
    time.sleep(0.3)
    conn.sendall(b"$CPALT,120000.000,1*62\r\n")
    time.sleep(0.3)
    check(p.poll() is None, "stdin at /dev/null: still connected")
    p.send_signal(signal.SIGTERM)
    out, _ = p.communicate(timeout=20)
    check(out == b"$CPALT,120000.000,1*62\r\n" and p.returncode == 0,
          "SIGTERM: exit 0 with what arrived: %r %r" % (out, p.returncode))
    conn.close()


def case_reconnect():
    srv = listener()
    port = srv.getsockname()[1]
    p = subprocess.Popen([TCP, "--reconnect", "--min-backoff", "0.05", "--max-backoff", "0.2",
                          "127.0.0.1:%d" % port], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE)
    for i in range(3):
        conn, _ = srv.accept()
        conn.sendall(b"$CPALT,12000%d.000,1\r\n" % i)
        conn.close()
    # The server goes away altogether, then comes back on the same port.
    srv.close()
    time.sleep(0.6)
    srv = listener(port)
    conn, _ = srv.accept()
    p.stdin.write(b"$PYCLT,1\n")
    p.stdin.flush()
    conn.settimeout(10)
    got = conn.recv(100)
    check(got == b"$PYCLT,1\r\n", "stdin reaches the new connection: %r" % got)
    p.send_signal(signal.SIGTERM)
    out, err = p.communicate(timeout=20)
    check(p.returncode == 0, "exit 0 on SIGTERM")
    check(out.count(b"\r\n") == 3, "a line from each connection: %r" % out)
    check(err.count(b"connected to") == 4 and b"reconnecting in" in err,
          "each connection and retry logged:\n%s" % err.decode())


def case_errors():
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()  # nothing listens there
    r = subprocess.run([TCP, "127.0.0.1:%d" % port], capture_output=True, timeout=20,
                       stdin=subprocess.DEVNULL)
    check(r.returncode == 1 and b"cannot connect" in r.stderr, "refused: %r" % r.stderr)
    for arg in ("localhost", "127.0.0.1:0", ":29500", "127.0.0.1:70000"):
        r = subprocess.run([TCP, arg], capture_output=True, timeout=20, stdin=subprocess.DEVNULL)
        check(r.returncode == 2 and b"expected HOST:PORT" in r.stderr, "%s refused" % arg)
    r = subprocess.run([TCP, "--help"], capture_output=True, timeout=20)
    check(r.returncode == 0 and b"--reconnect" in r.stdout, "--help")


run_case(globals(), CASE)
