# SPDX-License-Identifier: BSL-1.0
"""NMEA 2000 repeating groups and 64-bit fields through both programs.

    n2k_groups_test.py <seawire-decode> <seawire-encode> <tests/data/n2k> <case>

bytes     the group vectors (50-55) decoded, encoded back as canboat FAST lines: each payload the
          capture's bytes (reserved bits as ones), and decoded again to the same messages.
random    random 126464, 129540 and 129029 payloads (counts up to the capacity or a sentinel,
          cut at any length, 64-bit extremes) through decode | encode | decode in every format.
refusals  a count past the capacity, more repetitions than the count, an array past the
          capacity, an element that is no object, a bad member: each line refused naming the
          field, the good lines around it still written.
csv       --format csv: a group is one cell, repetitions by ';', fields by '|'.
"""

import json
import os
import random
import struct
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import harness
from harness import check

DECODE, ENCODE, DATA, CASE = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
FORMATS = ["candump_log", "candump", "canboat", "yd_raw", "actisense_n2k_ascii"]
# The reserved bits of each PGN's fixed part (byte, mask): sent as ones whatever was received.
RESERVED = {126464: [], 129540: [(1, 0xFC)], 129029: [(32, 0xFC)]}
ITEM = {126464: (1, 3), 129540: (3, 12), 129029: (43, 4)}  # fixed bytes, bytes a repetition


def run(prog, args, data):
    return harness.run([prog, *args], data)


def decode(data, args=()):
    p = run(DECODE, list(args), data)
    check(p.returncode == 0, f"decode exit {p.returncode}: {p.stderr[:300]!r}")
    return p


def objects(p):
    return [json.loads(l) for l in p.stdout.decode().splitlines()]


def fast_lines(text):
    """canboat FAST lines as (pgn, payload bytes)."""
    out = []
    for line in text.splitlines():
        if line.startswith("#") or not line.strip():
            continue
        parts = line.split(",")
        out.append((int(parts[2]), bytes(int(x, 16) for x in parts[6:])))
    return out


def case_bytes():
    for name in ("50_pgn_list_126464", "51_gnss_sats_in_view_129540", "52_gnss_position_129029",
                 "55_synthetic_group_edges"):
        data = open(os.path.join(DATA, name + ".in"), "rb").read()
        first = decode(data)
        enc = run(ENCODE, ["--output", "canboat"], first.stdout)
        check(enc.returncode == 0, f"{name}: encode exit {enc.returncode}: {enc.stderr[:300]!r}")
        sent = fast_lines(data.decode())
        back = fast_lines(enc.stdout.decode())
        check(len(back) == len(sent), f"{name}: {len(back)} lines, {len(sent)} sent")
        for i, ((pgn, was), (pgn2, now)) in enumerate(zip(sent, back)):
            where = f"{name} message {i + 1} (PGN {pgn})"
            check(pgn2 == pgn, f"{where}: PGN {pgn2}")
            fixed, size = ITEM[pgn]
            want = bytearray(was)
            for at, mask in RESERVED[pgn]:
                if at < len(want):
                    want[at] |= mask
            whole = len(was) >= fixed and (len(was) - fixed) % size == 0
            if whole:
                check(now == bytes(want), f"{where}: sent {now.hex()}, received {was.hex()}")
            else:
                # cut inside a repetition: the repetitions it started, whole, the bytes received
                # first and the fields cut short as "not available" (all ones)
                n = -(-(len(was) - fixed) // size)
                check(len(now) == fixed + n * size, f"{where}: {len(now)} bytes, {n} repetitions")
        again = objects(decode(enc.stdout))
        check(again == objects(first), f"{name}: decode -> encode -> decode changed a message")


def random_payload(rng, pgn):
    fixed, size = ITEM[pgn]
    cap = (223 - fixed) // size
    n = rng.choice([0, 1, cap, rng.randrange(cap + 1)])
    head = bytearray(rng.randrange(256) for _ in range(fixed))
    if pgn == 129540:
        head[2] = rng.choice([n, min(cap, n + rng.randrange(4)), 0xFF, 0xFE, 0xFD])
    if pgn == 129029:
        head[42] = rng.choice([n, min(cap, n + rng.randrange(4)), 0xFF, 0xFE, 0xFD])
        for at in (7, 15, 23):  # the 64-bit fields' extremes and sentinels
            v = rng.choice([-(1 << 63), (1 << 63) - 1, (1 << 63) - 2, (1 << 63) - 3, (1 << 63) - 4,
                            1 << 62, -1, 0, rng.randrange(-(1 << 63), 1 << 63)])
            head[at:at + 8] = struct.pack("<q", v)
    body = bytes(0xFF - rng.randrange(4) if rng.random() < 0.2 else rng.randrange(256)
                 for _ in range(n * size))
    data = bytes(head) + body
    if rng.random() < 0.3:
        data = data[:rng.randrange(len(data) + 1)]
    return data


def case_random():
    rng = random.Random(50)
    lines = [b"# format=FAST"]
    for pgn in (126464, 129540, 129029):
        for i in range(300):
            data = random_payload(rng, pgn)
            lines.append(("2024-07-03T15:42:58.%03dZ,6,%d,35,255,%d" % (i, pgn, len(data))
                          + "".join(",%02x" % b for b in data)).encode())
    first = decode(b"\n".join(lines) + b"\n")
    msgs = objects(first)
    check(len(msgs) == len(lines) - 1, f"{len(msgs)} messages of {len(lines) - 1}")
    for fmt in FORMATS:
        enc = run(ENCODE, ["--output", fmt], first.stdout)
        check(enc.returncode == 0, f"-> {fmt}: encode exit {enc.returncode}: {enc.stderr[:500]!r}")
        again = objects(decode(enc.stdout))
        check(len(again) == len(msgs), f"-> {fmt}: {len(again)} messages, not {len(msgs)}")
        strip = lambda o: {k: v for k, v in o.items() if k not in ("time_s", "interface", "direction")}
        bad = [(a, b) for a, b in zip(msgs, again) if strip(a) != strip(b)]
        check(not bad, f"-> {fmt}: {len(bad)} messages changed, e.g. {bad[:1]}")


def case_refusals():
    sat = '{"prn":7,"elevation_rad":0.5,"azimuth_rad":1,"snr_db":40,"range_residuals_m":0,"status":"used","gnss_system":"gps"}'
    good = '{"type":"PGN129540","sid":1,"sats_in_view":1,"satellites":[%s]}' % sat
    lines = [
        good,
        '{"type":"PGN129540","sats_in_view":19,"satellites":[]}',           # 2: past the capacity
        '{"type":"PGN129540","sats_in_view":1,"satellites":[%s,%s]}' % (sat, sat),  # 3: more than the count
        '{"type":"PGN126464","function_code":"transmit","pgns":[%s]}' % ",".join(['{"pgn":59904}'] * 75),  # 4
        '{"type":"PGN126464","function_code":"transmit","pgns":[59904]}',    # 5: no object
        '{"type":"PGN129540","sats_in_view":1,"satellites":[{"prn":7,"status":"lost"}]}',  # 6
        '{"type":"PGN129029","integrity":"none","reference_stations":1,"stations":[{"station_id":4093}]}',  # 7
        '{"type":"PGN129540","sats_in_view":1,"satellites":{"prn":7}}',     # 8: no array
        '{"type":"PGN129029","latitude_deg":922.3372036854775805,"integrity":"none"}',  # 9: a sentinel's value
        '{"type":"PGN129029","latitude_deg":-922.3372036854775808,"longitude_deg":1e-16,"integrity":"none","reference_stations":null,"stations":[{"station_type":"gps","station_id":12,"age_of_corrections_s":1.5}]}',
    ]
    out = run(ENCODE, ["--output", "canboat"], ("\n".join(lines) + "\n").encode())
    check(out.returncode == 1, f"exit {out.returncode}")
    err = out.stderr.decode()
    for line, words in [(2, ["sats_in_view", "out_of_range"]),
                        (3, ["satellites", "too_many_fields"]),
                        (4, ["pgns", "too_many_fields"]), (5, ["pgns", "bad_length"]),
                        (6, ["satellites", "bad_enum"]), (7, ["stations", "out_of_range"]),
                        (8, ["satellites", "bad_length"]), (9, ["latitude_deg", "out_of_range"])]:
        found = [l for l in err.splitlines() if l.startswith(f"seawire-encode: line {line}:")]
        check(len(found) == 1 and all(w in found[0] for w in words),
              f"line {line} refused naming {words}: {found}")
    got = objects(decode(out.stdout))
    check(len(got) == 2, f"the good lines written: {got}")
    if len(got) == 2:
        check(got[0]["satellites"] == [json.loads(sat.replace("0.5", "0.5000").replace(":1,", ":1.0000,"))
                                       | {"elevation_rad": 0.5, "azimuth_rad": 1.0, "snr_db": 40.0,
                                          "range_residuals_m": 0.0}],
              f"the satellite: {got[0]}")
        last = got[1]
        check(last["latitude_deg"] == -922.3372036854775808, f"latitude: {last}")
        check(out.stdout.decode().splitlines()[2].split(",")[13:21] ==
              ["00", "00", "00", "00", "00", "00", "00", "80"], "INT64_MIN on the wire")
        check(last["reference_stations"] is None and len(last["stations"]) == 1,
              f"a count of null says nothing: {last}")


def case_csv():
    data = open(os.path.join(DATA, "55_synthetic_group_edges.in"), "rb").read()
    p = decode(data, ["--format", "csv", "--type", "PGN129029"])
    rows = p.stdout.decode().splitlines()
    check(rows[0] == "time_s,prio,src,dst,sid,date,time,latitude_deg,longitude_deg,altitude_m,"
          "gnss_type,method,integrity,number_of_svs,hdop,pdop,geoidal_separation_m,"
          "reference_stations,stations", f"header {rows[0]}")
    check(rows[1].endswith(",1,glonass|4092|1.50"), f"one station: {rows[1]}")
    check(rows[2].endswith(",2,galileo|0|0.00;gps_glonass|230|655.32"), f"two: {rows[2]}")
    check(rows[3].endswith(",0,"), f"none: {rows[3]}")
    check(",-922.3372036854775808,922.3372036854775804,," in rows[1], f"64-bit: {rows[1]}")


harness.run_case(globals(), CASE)
