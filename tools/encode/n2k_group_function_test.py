# SPDX-License-Identifier: BSL-1.0
"""126208 Group Function (a layout per function code) through both programs.

    n2k_group_function_test.py <seawire-decode> <seawire-encode> <tests/data/n2k> <case>

encode   a request, a command and an acknowledgement written from JSON, their bytes checked here
         by hand (the acknowledgement's 4-bit codes two to a byte); a function code seawire has
         no layout of sent from "data"; an object naming no layout, another layout's fields, bad
         parameter bytes: each refused naming the field, the good lines still written.
vectors  the real captures (vectors 73 and 74) decoded, encoded back, decoded again: the same
         messages, in every log format.
csv      a table per layout (PGN126208_request.csv ...); on stdout (--type PGN126208) the first
         layout's table, the others' messages counted on stderr; --stats names the PGN once.
"""

import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import harness
from harness import check

DECODE, ENCODE, DATA, CASE = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
FORMATS = ["candump_log", "candump", "canboat", "yd_raw", "actisense_n2k_ascii"]
VECTORS = ["73_group_function_126208", "74_group_function_frames_126208"]


def objects(p):
    return [json.loads(l) for l in p.stdout.decode().splitlines()]


def payloads(canboat_fast):
    """The payloads of canboat FAST lines (one line a message)."""
    out = []
    for line in canboat_fast.decode().splitlines():
        if line.startswith("#") or not line.strip():
            continue
        parts = line.split(",")
        out.append(bytes(int(x, 16) for x in parts[6:]))
    return out


def case_encode():
    lines = [
        # 1: a request for 127251 every 200 ms, no offset, no pairs
        '{"type":"PGN126208","dst":52,"function_code":"request","pgn":127251,'
        '"transmission_interval_s":0.2,"transmission_interval_offset_s":null,'
        '"number_of_parameters":0}',
        # 2: a command for 127501: field 3 set to 1 (on), priority left as it is
        '{"type":"PGN126208","dst":72,"function_code":"command","pgn":127501,'
        '"priority":"leave_unchanged","number_of_parameters":1,"parameters":"0301"}',
        # 3: an acknowledgement with three codes: two to a byte, the last byte's rest ones
        '{"type":"PGN126208","dst":1,"function_code":"acknowledge","pgn":130824,'
        '"pgn_error_code":"access_denied","transmission_interval_priority_error_code":'
        '"acknowledge","number_of_parameters":3,"parameters":[{"parameter":"acknowledge"},'
        '{"parameter":"temporary_error"},{"parameter":"not_supported"}]}',
        # 4: Read Fields (3), which seawire has no layout of: its payload as given
        '{"type":"PGN126208","dst":28,"data":"0300000A000E00FF"}',
        # 5: no layout named
        '{"type":"PGN126208","pgn":127501,"number_of_parameters":0}',
        # 6: a layout seawire does not describe, without "data"
        '{"type":"PGN126208","function_code":"read_fields","pgn":127501}',
        # 7: a request with a command's field
        '{"type":"PGN126208","function_code":"request","pgn":127501,"priority":"priority_3"}',
        # 8: pairs that are not hex bytes
        '{"type":"PGN126208","function_code":"command","pgn":127501,"number_of_parameters":1,'
        '"parameters":"03 01"}',
        # 9: more pair bytes than a command holds (217)
        '{"type":"PGN126208","function_code":"command","pgn":127501,"parameters":"%s"}' % ("00" * 218),
    ]
    out = harness.run([ENCODE, "--output", "canboat"], ("\n".join(lines) + "\n").encode())
    check(out.returncode == 1, f"exit {out.returncode}: {out.stderr[:300]!r}")
    got = payloads(out.stdout)
    want = [bytes.fromhex("0013f101c8000000ffff00"),
            bytes.fromhex("010df201f8010301"),
            bytes.fromhex("0208ff01030320f5"),
            bytes.fromhex("0300000A000E00FF")]
    check(got == want, f"payloads {[g.hex() for g in got]}, expected {[w.hex() for w in want]}")
    err = out.stderr.decode()
    for line, words in [(5, ["function_code", '"request"', '"command"', '"acknowledge"', "data"]),
                        (6, ["function_code", "data"]),
                        (7, ["priority"]),
                        (8, ["parameters", "bad_text"]),
                        (9, ["parameters", "text_too_long"])]:
        found = [l for l in err.splitlines() if l.startswith(f"seawire-encode: line {line}:")]
        check(len(found) == 1 and all(w in found[0] for w in words),
              f"line {line} refused naming {words}: {found}")
    back = objects(harness.run([DECODE], out.stdout, 0))
    check([o.get("function_code", "data" if "data" in o else None) for o in back] ==
          ["request", "command", "acknowledge", "data"], f"decoded back: {back}")
    if len(back) == 4:
        check(back[0]["transmission_interval_s"] == 0.2 and back[0]["parameters"] == "",
              f"{back[0]}")
        check(back[1]["parameters"] == "0301" and back[1]["priority"] == "leave_unchanged",
              f"{back[1]}")
        check([p["parameter"] for p in back[2]["parameters"]] ==
              ["acknowledge", "temporary_error", "not_supported"], f"{back[2]}")
        check(back[3]["data"] == "0300000A000E00FF", f"{back[3]}")


def case_vectors():
    for name in VECTORS:
        with open(os.path.join(DATA, name + ".in"), "rb") as f:
            data = f.read()
        first = harness.run([DECODE], data, 0)
        want = objects(first)
        check(len(want) > 5 and all(o["type"] == "PGN126208" for o in want), f"{name}: {want[:2]}")
        layouts = {o.get("function_code", "data") for o in want}
        check("request" in layouts, f"{name}: layouts {layouts}")
        for fmt in FORMATS:
            enc = harness.run([ENCODE, "--output", fmt], first.stdout, 0)
            again = objects(harness.run([DECODE], enc.stdout, 0))
            strip = lambda o: {k: v for k, v in o.items() if k not in ("time_s", "interface",
                                                                       "direction")}
            diff = [(a, b) for a, b in zip(again, want) if strip(a) != strip(b)]
            check(len(again) == len(want) and not diff,
                  f"{name} through {fmt}: {len(again)} messages of {len(want)}, "
                  f"first differing {diff[:1]}")


def case_csv():
    with open(os.path.join(DATA, VECTORS[0] + ".in"), "rb") as f:
        data = f.read()
    want = objects(harness.run([DECODE], data, 0))
    counts = {}
    for o in want:
        counts[o.get("function_code", "data")] = counts.get(o.get("function_code", "data"), 0) + 1
    with tempfile.TemporaryDirectory() as d:
        harness.run([DECODE, "--format", "csv", "--output-dir", d], data, 0)
        files = sorted(os.listdir(d))
        check(files == [f"PGN126208_{k}.csv" for k in sorted(k for k in counts if k != "data")],
              f"tables {files}, layouts {counts}")
        for layout in ("request", "command", "acknowledge"):
            path = os.path.join(d, f"PGN126208_{layout}.csv")
            if not os.path.exists(path):
                continue
            with open(path) as f:
                rows = f.read().splitlines()
            check(len(rows) == counts[layout] + 1, f"{layout}: {len(rows)} lines")
            check(rows and "function_code" in rows[0] and rows[1].count(layout) >= 1,
                  f"{layout}: {rows[:2]}")
        if os.path.exists(os.path.join(d, "PGN126208_command.csv")):
            with open(os.path.join(d, "PGN126208_command.csv")) as f:
                header = f.readline().strip().split(",")
            check("priority" in header and "parameters" in header and
                  "transmission_interval_s" not in header, f"command's columns: {header}")
    p = harness.run([DECODE, "--format", "csv", "--type", "PGN126208"], data, 0)
    rows = p.stdout.decode().splitlines()
    check(len(rows) == counts["request"] + 1 and "transmission_interval_s" in rows[0],
          f"stdout: the request's table, {len(rows)} lines: {rows[:2]}")
    err = p.stderr.decode()
    for layout in ("command", "acknowledge"):
        n = counts[layout]
        check(f"{n} PGN126208_{layout} message" in err and "PGN126208_request's" in err,
              f"stderr names the {n} {layout} messages left out: {err!r}")
    s = harness.run([DECODE, "--format", "none", "--stats"], data, 0).stderr.decode()
    lines = [l for l in s.splitlines() if l.strip().startswith("126208")]
    check(len(lines) == 1 and "group_function " in lines[0] and lines[0].split()[-1] ==
          str(len(want)), f"--stats: {lines}")


harness.run_case(globals(), CASE)
