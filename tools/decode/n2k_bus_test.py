# SPDX-License-Identifier: BSL-1.0
"""seawire-decode on a whole NMEA 2000 bus, beyond the PGNs seawire describes.

    n2k_bus_test.py <seawire-decode> <tests/data/n2k> <case>

unknown_fast  a fast-packet PGN seawire does not describe comes out once, with its whole payload
              (frames of a real capture, in candump -L and canboat PLAIN lines, interleaved with
              other PGNs' frames), a single-frame one frame by frame; the vectors 70-79 hold the
              same captures, compared with canboat's analyzer by n2k_test.py.
pseudo_pgns   canboat's pseudo-PGNs (a gateway's own messages) skipped without an error and
              counted, in --stats and at the end of the run; one past canboat's range refused.
stats         --stats on a CAN log: messages per PGN, in numeric order, named when described,
              equal to the messages written; at most 4096 PGNs one by one.
"""

import collections
import json
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import harness
from harness import check

DECODE, DATA, CASE = sys.argv[1], sys.argv[2], sys.argv[3]


def run(args, data, want_rc=None):
    return harness.run([DECODE, *args], data, want_rc)


def decoded(p):
    return [json.loads(line) for line in p.stdout.decode().splitlines()]


def by_pgn(stderr):
    """The "by PGN:" rows of --stats: {pgn: (name, count)}, in the order printed; the
    "(other PGNs)" count."""
    rows, other, inside = {}, None, False
    for line in stderr.splitlines():
        if line == "  by PGN:":
            inside = True
            continue
        if not inside:
            continue
        m = re.fullmatch(r"    (\d+)\s+(\S+(?: \S+)?)\s+(\d+)", line)
        if m:
            rows[int(m.group(1))] = (m.group(2), int(m.group(3)))
            continue
        m = re.fullmatch(r"    \(other PGNs\)\s+(\d+)", line)
        if m:
            other = int(m.group(1))
            continue
        inside = False
    return rows, other


# A Raymarine autopilot's proprietary 126720 (9 bytes in two frames), from a capture of a real
# bus (canboat's candumpSample3.txt), with its proprietary single-frame 65359 between the two.
CANDUMP_126720 = [
    "(1502984867.025933) slcan0 1DEFFFCC#00093B9FF081AE02",
    "(1502984867.031501) slcan0 1CFF4FCC#3B9FFFFFFF765AFF",
    "(1502984867.025937) slcan0 1DEFFFCC#01000CA5FFFFFFFF",
]
# A Furuno autopilot in canboat PLAIN lines (canboat's furuno-fap7011c-autopilot-maneuvers.raw):
# a standard fast-packet PGN, 127237 Heading/Track control (21 bytes in four frames, a 127250
# among them), and its proprietary 130821 (12 bytes in two frames). seawire describes 127237 now:
# the same four frames sent as 127233 (a standard fast-packet PGN seawire does not describe) are
# assembled whole too.
PLAIN_FURUNO = [
    "2021-08-06-11:45:30.505,2,127237,5,255,8,80,15,00,40,1f,ff,7f,ff",
    "2021-08-06-11:45:30.506,2,127237,5,255,8,81,ff,ff,ff,ff,ff,ff,ff",
    "2021-08-06-11:45:30.507,2,127237,5,255,8,82,ff,7f,ff,7f,ff,7f,d5",
    "2021-08-06-11:45:30.507,6,127250,36,255,8,ae,d5,5e,00,00,ba,02,fd",
    "2021-08-06-11:45:30.508,2,127237,5,255,8,83,5e,ff,ff,ff,ff,ff,ff",
    "2021-08-06-11:45:35.071,7,130821,1,255,8,20,0c,3f,9f,04,00,1c,45",
    "2021-08-06-11:45:35.071,7,130821,1,255,8,21,e2,e7,00,af,78,c0,ff",
    "2021-08-06-11:45:36.505,2,127233,5,255,8,80,15,00,40,1f,ff,7f,ff",
    "2021-08-06-11:45:36.506,2,127233,5,255,8,81,ff,ff,ff,ff,ff,ff,ff",
    "2021-08-06-11:45:36.507,2,127233,5,255,8,82,ff,7f,ff,7f,ff,7f,d5",
    "2021-08-06-11:45:36.508,2,127233,5,255,8,83,5e,ff,ff,ff,ff,ff,ff",
]


def case_unknown_fast():
    p = run([], ("\n".join(CANDUMP_126720) + "\n").encode(), 0)
    got = decoded(p)
    check([m["type"] for m in got] == ["PGN65359", "PGN126720"], f"candump: {got}")
    if len(got) == 2:
        check(got[1]["data"] == "3B9FF081AE02000CA5" and got[1]["src"] == 204 and
              got[1]["dst"] == 255 and got[1]["prio"] == 7 and
              got[1]["time_s"] == 1502984867.025937,
              f"candump: 126720 not whole, or not as its last frame says: {got[1]}")
        check(got[0]["data"] == "3B9FFFFFFF765AFF", f"candump: 65359 {got[0]}")

    p = run([], ("\n".join(PLAIN_FURUNO) + "\n").encode(), 0)
    got = decoded(p)
    check([(m["type"], m.get("data")) for m in got] ==
          [("PGN127250", None), ("PGN127237", None),
           ("PGN130821", "3F9F04001C45" "E2E700AF78C0"),
           ("PGN127233", "00401FFF7FFF" "FFFFFFFFFFFFFF" "FF7FFF7FFF7FD5" "5E")],
          f"canboat PLAIN: 127237, 130821 and 127233 not one message each, whole: {got}")
    if len(got) == 4:  # 127237's last field, in its last frame: 0x5ED5 = 2.4277 rad
        check(got[1].get("vessel_heading_rad") == 2.4277, f"127237 not whole: {got[1]}")

    # Every 126720 of the real capture: once each, as many as canboat's analyzer decoded.
    path = os.path.join(DATA, "70_candump_proprietary_fast.in")
    with open(path, "rb") as f:
        p = run(["--type", "PGN126720"], f.read(), 0)
    ours = decoded(p)
    with open(path[:-3] + ".out.json") as f:
        theirs = [next(iter(json.loads(l).values())) for l in f if l.strip()]
    theirs = [t for t in theirs if t["pgn"] == 126720]
    check(len(ours) == len(theirs) and len(ours) > 10,
          f"70: {len(ours)} messages of PGN 126720, canboat {len(theirs)}")
    for o, t in zip(ours, theirs):
        check((o["src"], o["dst"]) == (t["src"], t["dst"]), f"70: {o} vs canboat {t}")
    check(any(len(o["data"]) > 16 for o in ours), "70: no 126720 longer than a frame")


GATEWAY = ("2016-02-28T19:57:02.480Z,0,262386,0,0,33,01,0e,00,d7,e2,01,00,00,00,00,00,02,20,"
           "04,00,00,01,00,01,00,00,00,4e,62,02,13,00,01,01,1c,01,0a,0e")


def case_pseudo_pgns():
    # A PLAIN_OR_FAST log (its first line a frame): the gateway's status does not make it FAST,
    # the 130842 frames after it are assembled.
    log = "\n".join([
        "2016-02-28T19:57:02.364Z,2,127250,7,255,8,ff,10,3b,ff,7f,ce,f5,fc",
        GATEWAY,
        "2016-02-28T19:57:02.500Z,7,130842,12,255,8,40,0a,3b,9f,01,02,03,04",
        "2016-02-28T19:57:02.501Z,7,130842,12,255,8,41,05,06,07,08,ff,ff,ff",
        "A000057.086 00002 40100 0102",
        # canboat's Actisense reader, in a real log (susteranna-actisense-serial.raw)
        "2016-04-09T16:41:09.092Z,0,16057090,255,1,0",
    ]) + "\n"
    p = run([], log.encode(), 0)
    got = decoded(p)
    check([m.get("type") for m in got] == ["PGN127250", "PGN130842"], f"messages: {got}")
    if len(got) == 2:
        check(got[1]["data"] == "3B9F0102030405060708", f"130842 after the gateway's: {got[1]}")
    err = p.stderr.decode()
    check(err == "seawire-decode: 3 lines of gateway pseudo-PGNs (262144 and up) skipped\n",
          f"the end of the run: {err!r}")
    p = run(["--stats", "--format", "none"], log.encode(), 0)
    err = p.stderr.decode()
    check(err.startswith("seawire-decode: 2 messages decoded, 0 rejected, 3 lines of gateway "
                         "pseudo-PGNs (262144 and up) skipped\n"), f"--stats: {err!r}")
    check(err.count("pseudo-PGNs") == 1, f"--stats says it once: {err!r}")
    # A PLAIN log: the gateway's long line is no bad frame.
    p = run([], ("# format=PLAIN\n" + GATEWAY + "\n").encode(), 0)
    check(p.stdout == b"", f"PLAIN: {p.stdout!r}")

    # The real log: as many skipped as canboat decoded of them, the rest compared by n2k_test.
    path = os.path.join(DATA, "72_pseudo_pgns_fast.in")
    with open(path, "rb") as f:
        data = f.read()
    with open(path[:-3] + ".out.json") as f:
        theirs = [next(iter(json.loads(l).values())) for l in f if l.strip()]
    n = sum(1 for t in theirs if t["pgn"] >= 262144)
    check(n > 0, "72: no pseudo-PGN in canboat's decode")
    p = run(["--stats", "--format", "none"], data, 0)
    check(f"{len(theirs) - n} messages decoded, 0 rejected, {n} lines of gateway pseudo-PGNs"
          in p.stderr.decode(), f"72: {p.stderr[:300]!r}")
    # No pseudo-PGN without a line on stderr, and none from a log without them.
    p = run([], "2016-02-28T19:57:02.364Z,2,127250,7,255,8,ff,10,3b,ff,7f,ce,f5,fc\n".encode(), 0)
    check(p.stderr == b"", f"no pseudo-PGNs: {p.stderr!r}")

    # Past 32 bits in a canboat line, past canboat's range in an Actisense line: no PGN of anyone,
    # an error with its token.
    p = run(["--input", "n2k"],
            b"2016-02-28T19:57:02.480Z,0,4294967296,0,0,1,01\nA000057.086 00002 40300 0102\n", 1)
    errors = decoded(p)
    check([(e.get("line"), e.get("error"), e.get("field")) for e in errors] ==
          [(1, "bad_can_id", 3), (2, "bad_can_id", 3)], f"past the range: {errors}")


def case_stats():
    path = os.path.join(DATA, "70_candump_proprietary_fast.in")
    with open(path, "rb") as f:
        data = f.read()
    written = collections.Counter(int(m["type"][3:]) for m in decoded(run([], data, 0)))
    p = run(["--stats", "--format", "none"], data, 0)
    err = p.stderr.decode()
    rows, other = by_pgn(err)
    check({k: v[1] for k, v in rows.items()} == dict(written),
          f"--stats by PGN {rows} vs the messages written {dict(written)}")
    check(list(rows) == sorted(rows), f"not in numeric order: {list(rows)}")
    check(other is None, f"(other PGNs) {other}")
    check(rows.get(127250, ("",))[0] == "vessel_heading" and
          rows.get(126720, ("",))[0] == "(no description)" and
          rows.get(65359, ("",))[0] == "(no description)", f"names: {rows}")
    check(f"seawire-decode: {sum(written.values())} messages decoded, 0 rejected\n" in err,
          f"total: {err[:200]!r}")
    check("by type:" not in err, "a CAN log's --stats counts by PGN, not by type")
    # Each fast packet counts once: the frames are in the CAN log line.
    check(re.search(r"fast packets: \d+ frames, \d+ assembled into \d+ messages", err),
          f"fast packets: {err!r}")

    # At most 4096 PGNs one by one: 4100 distinct single-frame PGNs, every broadcast PGN of
    # data page 0 (61440-65535) and four of data page 1 below the first fast one.
    pgns = [*range(0xF000, 0x10000), 126976, 126977, 126978, 126979]
    check(len(pgns) == 4100, f"{len(pgns)} PGNs")
    log = "".join(f"2024-01-01T00:00:00.000Z,6,{p},1,255,1,00\n" for p in pgns)
    p = run(["--stats", "--format", "none"], log.encode(), 0)
    rows, other = by_pgn(p.stderr.decode())
    check(len(rows) == 4096 and other == 4, f"{len(rows)} PGNs counted, other {other}")


harness.run_case(globals(), CASE)
