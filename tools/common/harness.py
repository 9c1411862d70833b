# SPDX-License-Identifier: BSL-1.0
"""What the program tests here share: checks that are counted, NMEA checksums, a program that
listens on an ephemeral port, a program's refusals of bad arguments, and the end of a run.

A test script beside a program imports it from tools/common:

    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
    from harness import check, finish
    ...
    finish()   # the failures counted, exit 1 if any, else "ok"
"""

import fcntl
import functools
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

failures = []
LOGS = []  # the stderr files of the programs started, named when a case fails


def check(ok, what):
    """Counts a failure when `ok` is false and says what failed; returns `ok`."""
    if not ok:
        failures.append(what)
        print("FAIL:", what, file=sys.stderr, flush=True)
    return ok


def finish():
    """Ends the run: exit 1 with the count (and the programs' logs, kept) when anything failed."""
    if failures:
        logs = "; the programs' logs: " + " ".join(LOGS) if LOGS else ""
        print(f"{len(failures)} failure(s){logs}", file=sys.stderr)
        sys.exit(1)
    for path in LOGS:
        os.remove(path)
    print("ok")


def case_of(scope, name):
    """The function case_<name> of `scope` (a test script's globals()): a script's cases are its
    case_ functions, and CMake makes one test of each (tools/CMakeLists.txt)."""
    fn = scope.get("case_" + name)
    if not callable(fn):
        cases = sorted(k[5:] for k, v in scope.items() if k.startswith("case_") and callable(v))
        print(f"no case {name!r}; the cases: {' '.join(cases)}", file=sys.stderr)
        sys.exit(2)
    return fn


def children():
    """The processes this one started that are still running (not yet exited): from /proc, where
    each process's stat gives its state and its parent."""
    me = os.getpid()
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % entry, encoding="ascii", errors="replace") as f:
                stat = f.read()
        except OSError:
            continue  # gone meanwhile
        # pid (comm) state ppid ...: comm may hold spaces and parentheses, so split after the last.
        state, ppid = stat[stat.rindex(")") + 2:].split()[:2]
        if int(ppid) == me and state not in ("Z", "X"):
            found.append(int(entry))
    return found


def kill_children():
    """Kills what this run started and left running; returns their pids."""
    left = children()
    for pid in left:
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    return left


def run_case(scope, name):
    """Runs the case `name` (the function case_<name> of `scope`), then finish(). Whatever the
    case started and left running is killed, however it ended, so that a case that fails
    half-way (an exception, a program that never started) leaves no server or client behind;
    a case that ends normally and leaves one fails."""
    try:
        case_of(scope, name)()
    finally:
        left = kill_children()
    check(not left, "the case left %d program(s) running (killed)" % len(left))
    finish()


def run(argv, data, want_rc=None, timeout=60):
    """Runs argv with `data` on stdin; with want_rc, checks the exit status."""
    p = subprocess.run(argv, input=data, capture_output=True, timeout=timeout)
    if want_rc is not None:
        check(p.returncode == want_rc,
              f"{argv[1:]}: exit status {p.returncode}, expected {want_rc}: {p.stderr[:300]!r}")
    return p


def xor(body):
    """The NMEA 0183 checksum of the text between '$' and '*'."""
    return functools.reduce(lambda a, c: a ^ ord(c), body, 0)


def seal(body, lower=False, ending="\r\n"):
    """The sentence $body*hh with its checksum (lower-case hex digits if `lower`) and `ending`."""
    return ("$%s*%02" + ("x" if lower else "X") + "%s") % (body, xor(body), ending)


def checksum_ok(line):
    """Whether `line` (no ending) is $...*HH with the right checksum in upper-case hex."""
    m = re.fullmatch(r"\$([^*]*)\*([0-9A-F]{2})", line)
    return bool(m) and xor(m.group(1)) == int(m.group(2), 16)


def refusals(program, help_word, cases, rc=None, extra=()):
    """--help exits 0 and names `help_word` (or each of a tuple of them); each (args, why) or (args, why, rc) of `cases`, run
    with `extra` after args, is refused: exit status rc (any but 0 when None) and `why` in what
    the program says on stderr."""
    r = subprocess.run([program, "--help"], capture_output=True, timeout=20)
    words = help_word if isinstance(help_word, tuple) else (help_word,)
    check(r.returncode == 0 and all(w in r.stdout for w in words), "--help")
    for args, why, *own_rc in cases:
        rc_wanted = own_rc[0] if own_rc else rc
        r = subprocess.run([program, *args, *extra], capture_output=True, timeout=20)
        check(r.returncode != 0 and (rc_wanted is None or r.returncode == rc_wanted)
              and why in r.stderr,
              "%r refused: %d %r" % (args, r.returncode, r.stderr[-200:]))


class Server:
    """A program started with --listen (127.0.0.1:0 unless told), its stderr in a log file, whose
    first line says the port it listens on: "listening on 127.0.0.1:PORT"."""

    def __init__(self, program, *args, listen="127.0.0.1:0", stdout=subprocess.DEVNULL, env=None):
        # The program appends to its log file (O_APPEND): reading it from here never moves the
        # offset the program writes at.
        fd, self.log_path = tempfile.mkstemp(prefix="seawire-", suffix=".log")
        os.close(fd)
        LOGS.append(self.log_path)
        with open(self.log_path, "ab") as err:
            self.proc = subprocess.Popen([program, "--listen", listen, *args], stdout=stdout,
                                         stderr=err, env=env)
        deadline = time.monotonic() + 20
        self.port = None
        while time.monotonic() < deadline and self.port is None:
            first = self.log().split("\n")[0] + "\n"
            m = re.fullmatch(r"listening on 127\.0\.0\.1:(\d+)\n", first)
            if m:
                self.port = int(m.group(1))
            elif self.proc.poll() is not None:
                break
            else:
                time.sleep(0.02)
        if self.port is None:
            raise SystemExit("%s did not say where it listens: %r" % (program, self.log()))

    def log(self):
        with open(self.log_path, encoding="ascii", errors="replace") as f:
            return f.read()

    def wait_log(self, pattern, timeout=10):
        """Whether `pattern` (a regex) shows in the log within `timeout` seconds."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if re.search(pattern, self.log()):
                return True
            time.sleep(0.05)
        return False

    def stop(self, sig=signal.SIGTERM, timeout=20):
        """Sends `sig` and returns the exit status; a program still running after `timeout`
        seconds is killed, counted as a failure, and None returned."""
        if self.proc.poll() is None:
            self.proc.send_signal(sig)
        try:
            return self.proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
            check(False, "the program did not exit within %ds of signal %d" % (timeout, sig))
            return None


def fill_pty(fd, rounds=50, pause=0.1):
    """Fills the pty whose slave side is `fd` (its master never read) until a pause frees no
    room: the kernel moves what was written on to the master side a moment later, which frees
    room, so it is written again until nothing more fits. Leaves `fd` non-blocking."""
    fcntl.fcntl(fd, fcntl.F_SETFL, fcntl.fcntl(fd, fcntl.F_GETFL) | os.O_NONBLOCK)
    for _ in range(rounds):
        wrote = 0
        for size in (4096, 64, 1):
            try:
                while True:
                    wrote += os.write(fd, b"x" * size)
            except BlockingIOError:
                pass
        if wrote == 0:
            return
        time.sleep(pause)
