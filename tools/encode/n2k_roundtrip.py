# SPDX-License-Identifier: BSL-1.0
"""NMEA 2000 through both programs: seawire-decode | seawire-encode | seawire-decode.

    n2k_roundtrip.py <seawire-decode> <seawire-encode> <tests/data/n2k>

For every vector and every log format seawire-encode writes, the second decode gives the same
messages as the first: the same values, and the same time to what the format keeps (yd_raw and
Actisense keep
milliseconds of the day). Then seawire-encode's refusals: each names the line, the field and why,
and the good lines around them are still written. Then whatever decodes encodes: a short 127489
(its flag words not sent), and random messages of every PGN of every length, times of 24 h and
later among them, come back the same through every format.
"""

import glob
import json
import os
import random
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import harness
from harness import check

DECODE, ENCODE, DATA = sys.argv[1], sys.argv[2], sys.argv[3]
FORMATS = ["candump_log", "candump", "canboat", "yd_raw", "actisense_n2k_ascii"]


def run(prog, args, data):
    return harness.run([prog, *args], data)


def comparable(obj, fmt):
    o = dict(obj)
    # Where the log keeps them: the interface (candump formats, "can0" when none was given) and
    # the direction (yd_raw, "R" when none was given).
    o.pop("interface", None)
    o.pop("direction", None)
    t = o.pop("time_s", None)
    if t is not None and fmt in ("yd_raw", "actisense_n2k_ascii"):
        t = int(round(t * 1e6)) // 1000 % 86400000 / 1000  # milliseconds of the day, cut
    return o, t


# Each vector decoded on its own (a log's format is the stream's); then all of them, one after the
# other, through each format at once (two programs a format, not two a vector and format), cut back
# into the vectors by their message counts.
first_out = {}  # vector -> (seawire-decode's output, its messages)
for path in sorted(glob.glob(os.path.join(DATA, "*.in"))):
    name = os.path.basename(path)
    first = run(DECODE, [], open(path, "rb").read())
    check(first.returncode == 0, f"{name}: decode exit {first.returncode}: {first.stderr[:300]}")
    msgs = [json.loads(l) for l in first.stdout.decode().splitlines()]
    check(len(msgs) > 0, f"{name}: no messages")
    first_out[name] = (first.stdout, msgs)


def owners(names):
    """(vector, message number) of each message of `names`' outputs one after the other."""
    return [(name, i + 1) for name in names for i in range(len(first_out[name][1]))]


every = b"".join(out for out, _ in first_out.values())
firsts = [m for _, msgs in first_out.values() for m in msgs]
where = owners(first_out)
for fmt in FORMATS:
    enc = run(ENCODE, ["--output", fmt], every)
    check(enc.returncode == 0, f"vectors -> {fmt}: encode exit {enc.returncode}: {enc.stderr[:300]}")
    second = run(DECODE, [], enc.stdout)
    check(second.returncode == 0, f"vectors -> {fmt}: decode again exit {second.returncode}")
    again = [json.loads(l) for l in second.stdout.decode().splitlines()]
    if not check(len(again) == len(firsts),
                 f"vectors -> {fmt}: {len(again)} messages, not {len(firsts)}"):
        continue  # the messages no longer line up: comparing them would blame the wrong vectors
    for (name, i), a, b in zip(where, firsts, again):
        (va, ta), (vb, tb) = comparable(a, fmt), comparable(b, "")
        check(va == vb, f"{name} -> {fmt} message {i}: {va} != {vb}")
        if ta is not None:
            check(tb is not None and abs(ta - tb) < 5e-4,
                  f"{name} -> {fmt} message {i}: time {ta} != {tb}")

# Same format in and out: every message, interface and time included, is identical (the vectors
# of one format at once).
same = {"01": "canboat", "02": "candump_log", "03": "candump_log", "04": "yd_raw",
        "08": "canboat", "09": "candump_log", "10": "yd_raw", "40": "actisense_n2k_ascii",
        **{str(n): "canboat" for n in range(41, 48)}}  # strings
for fmt in sorted(set(same.values())):
    names = [name for name in first_out if same.get(name[:2]) == fmt]
    msgs = [m for name in names for m in first_out[name][1]]
    enc = run(ENCODE, ["--output", fmt], b"".join(first_out[name][0] for name in names))
    second = run(DECODE, [], enc.stdout)
    again = [json.loads(l) for l in second.stdout.decode().splitlines()]
    differ = [w for w, a, b in zip(owners(names), msgs, again) if a != b]
    check(len(again) == len(msgs) and not differ,
          f"the {fmt} vectors -> {fmt} -> decode: not identical ({len(again)} messages of "
          f"{len(msgs)}" + (f"; first {differ[0][0]} message {differ[0][1]})" if differ else ")"))

# Strings (vectors 41-47): the bytes. decode -> encode -> decode -> encode writes the same bytes
# as the first encode (a text encodes one way), and those are the sender's own bytes where it
# padded as the standard says (0xFF after a product's texts, '@' after an AIS text, counted
# strings as they are); a sender that padded with spaces or NULs gets the same texts back.
def payloads(text):
    return [(l.split(",")[2], bytes(int(b, 16) for b in l.split(",")[6:]))
            for l in text.splitlines() if l and not l.startswith("#")]


for path in sorted(glob.glob(os.path.join(DATA, "4[1-7]_*.in"))):
    name = os.path.basename(path)
    first = run(DECODE, [], open(path, "rb").read())
    once = run(ENCODE, ["--output", "canboat"], first.stdout).stdout
    twice = run(ENCODE, ["--output", "canboat"], run(DECODE, [], once).stdout).stdout
    check(len(payloads(once.decode())) > 0, f"{name}: nothing encoded")
    check(payloads(once.decode()) == payloads(twice.decode()),
          f"{name}: decode -> encode -> decode -> encode changed the bytes")
sent = {  # (vector, line): the sender padded as the standard says
    ("41_product_information_126996.in", 1), ("42_configuration_information_126998.in", 1),
    ("42_configuration_information_126998.in", 2), ("42_configuration_information_126998.in", 3)}
for name, index in sorted(sent):
    original = open(os.path.join(DATA, name)).read().splitlines()[index]
    want = bytes(int(b, 16) for b in original.split(",")[6:])
    line = ("# format=FAST\n" + original + "\n").encode()  # a whole message, of 6 bytes too
    enc = run(ENCODE, ["--output", "canboat"], run(DECODE, [], line).stdout)
    got = payloads(enc.stdout.decode())
    check(len(got) == 1 and got[0][1] == want,
          f"{name} line {index + 1}: {got[0][1].hex() if got else None} != {want.hex()}")

# A fast packet becomes its frames, with a sequence counter per PGN and source.
speed = b'{"type":"PGN130578","src":35,"longitudinal_water_mps":2.5,"transverse_water_mps":-0.12}\n'
out = run(ENCODE, [], speed + speed)
lines = out.stdout.decode().splitlines()
check(len(lines) == 4, f"two 130578 messages are 4 frames: {lines}")
check([l.split("#")[1][:2] for l in lines] == ["00", "01", "20", "21"],
      f"frame and sequence counters: {lines}")
# No time given: 0; priority 2, 130578's default; n/a fields as 0x7FFF.
check(lines[0] == "(0.000000) can0 09FE1223#000CC40988FFFF7F", f"first frame: {lines[0]}")

# Refusals: each names the line and the field, and the rest is still written.
bad = (b'{"type":"PGN128259","speed_water_mps":700}\n'
       b'{"type":"PGN128259","speed_water_mps":1.5,"speed_type":"sonar"}\n'
       b'{"type":"PGN128259","speed_water_mps":1.5,"spede":1}\n'
       b'{"type":"PGN128259","speed_water_mps":1.5,"prio":9}\n'
       b'{"type":"PGN60928","data":"12345"}\n'
       b'{"type":"PGN128259","speed_water_mps":1.5}\n'
       b'{"type":"PGN127489","discrete_status_1":[],"discrete_status_2":["warning_level_1","bit_9"]}\n'
       b'{"type":"PGN127489","discrete_status_1":["low_oil_levels"]}\n'
       b'{"type":"PGN127489","discrete_status_2":["warning_level_1"]}\n')
out = run(ENCODE, [], bad)
err = out.stderr.decode()
check(out.returncode == 1, f"refusals: exit {out.returncode}")
for line, words in [(1, ["speed_water_mps", "out_of_range"]), (2, ["speed_type", "bad_enum"]),
                    (3, ['"spede"']), (4, ["prio", "out_of_range"]), (5, ['"data"']),
                    (8, ["discrete_status_1", "bad_flag"]),
                    (9, ["discrete_status_1", "missing_field", "not available"])]:
    found = [l for l in err.splitlines() if l.startswith(f"seawire-encode: line {line}:")]
    check(len(found) == 1 and all(w in found[0] for w in words),
          f"line {line} refused naming {words}: {found}")
good = run(DECODE, [], out.stdout)
got = [json.loads(l) for l in good.stdout.decode().splitlines()]
check([g["type"] for g in got] == ["PGN128259", "PGN127489"], f"good lines written: {got}")
if len(got) == 2:
    check(got[0]["speed_water_mps"] == 1.5, f"1.5 m/s: {got[0]}")
    check(got[1]["discrete_status_2"] == ["warning_level_1", "bit_9"], f"flags: {got[1]}")
    check(got[1]["discrete_status_1"] == [], f"no flag set: {got[1]}")

# A PGN seawire does not describe and the standard does not list as a fast packet is one frame:
# longer than 8 bytes it is refused where a line is a frame, written whole where a line is a
# message, and read back the same.
long_single = b'{"type":"PGN65280","src":7,"data":"00112233445566778899"}\n'
out = run(ENCODE, ["--output", "candump_log"], long_single)
check(out.returncode == 1 and out.stdout == b"" and b"single-frame PGN" in out.stderr
      and b"ISO transport" in out.stderr, f"10 bytes of PGN 65280 as frames: {out.stderr!r}")
for fmt in ("canboat", "actisense_n2k_ascii"):
    out = run(ENCODE, ["--output", fmt], long_single)
    back = run(DECODE, [], out.stdout)
    got = [json.loads(l) for l in back.stdout.decode().splitlines()]
    check(out.returncode == 0 and len(got) == 1 and got[0].get("data") == "00112233445566778899",
          f"10 bytes of PGN 65280 through {fmt}: {got}")

# A 127489 without its discrete status words (a short message): not available, null, and written
# back short, so it reads back the same.
short = b"2016-04-09T16:41:39.628Z,2,127489,16,255,20,00,2f,06,ff,ff,e3,73,65,05,ff,7f,72,10,00,00,ff,ff,ff,ff,ff\n"
first = run(DECODE, [], short)
m = json.loads(first.stdout)
check(m.get("discrete_status_1", "absent") is None and m.get("discrete_status_2", "absent") is None,
      f"127489 without status words: {m}")
for fmt in FORMATS:
    again = run(DECODE, [], run(ENCODE, ["--output", fmt], first.stdout).stdout)
    check(again.returncode == 0 and comparable(json.loads(again.stdout), "")[0] ==
          comparable(m, "")[0], f"short 127489 -> {fmt}: {again.stdout[:300]!r}")

# Whatever decodes encodes: random payloads of every PGN, of every length from none to past the
# PGN's (bytes biased to the top of each range, where the sentinels are), as a canboat FAST log,
# through seawire-decode | seawire-encode | seawire-decode in every format.
LENGTHS = {127488: 8, 127489: 26, 128259: 8, 128275: 14, 130311: 8, 130578: 12, 127250: 8, 127251: 8, 127257: 8, 127258: 8, 128267: 8, 129025: 8, 129026: 8, 127245: 8, 130306: 8, 130312: 8, 130313: 8, 130314: 8, 130316: 8, 127508: 8, 127505: 8, 127506: 11, 129283: 8, 126992: 8, 129033: 8, 129539: 8, 129284: 34, 130577: 14, 59904: 3, 59392: 8}
# lookups whose names sit in the sentinel range or depend on another field
LENGTHS.update({60928: 8, 126993: 8, 127237: 21, 127252: 8, 127493: 8, 129038: 28, 129039: 27})
rng = random.Random(20261127)
lines = [b"# format=FAST"]
for pgn, length in LENGTHS.items():
    for i in range(400):
        n = length if i < 250 else rng.randrange(0, length + 9)
        data = [0xFF - rng.randrange(4) if rng.random() < 0.25 else rng.randrange(256)
                for _ in range(n)]
        if pgn == 128275 and n >= 6 and i % 3 == 0:  # times of 24 h and later
            t = rng.choice([864000000, 864010000, 900000000, 0xFFFFFFFC, rng.randrange(864000000, 0xFFFFFFFD)])
            data[2:6] = list(t.to_bytes(4, "little"))
        lines.append(("2024-07-03T15:42:58.%03dZ,2,%d,35,255,%d" % (i % 1000, pgn, n)
                      + "".join(",%02x" % b for b in data)).encode())
first = run(DECODE, [], b"\n".join(lines) + b"\n")
check(first.returncode == 0, f"random: decode exit {first.returncode}: {first.stderr[:300]}")
msgs = [json.loads(l) for l in first.stdout.decode().splitlines()]
check(len(msgs) == len(lines) - 1, f"random: {len(msgs)} messages of {len(lines) - 1}")
for fmt in FORMATS:
    enc = run(ENCODE, ["--output", fmt], first.stdout)
    check(enc.returncode == 0, f"random -> {fmt}: encode exit {enc.returncode}: {enc.stderr[:500]}")
    second = run(DECODE, [], enc.stdout)
    again = [json.loads(l) for l in second.stdout.decode().splitlines()]
    check(len(again) == len(msgs), f"random -> {fmt}: {len(again)} messages, not {len(msgs)}")
    bad = [(a, b) for a, b in zip(msgs, again) if comparable(a, fmt)[0] != comparable(b, "")[0]]
    check(not bad, f"random -> {fmt}: {len(bad)} messages changed, e.g. {bad[:1]}")


# Lookups: a device function is read by name for the device class given, wherever the class is
# among the members; a name of another class is refused naming the field; a named top value (127493
# reverse, raw 2) is sent as its value; a field with no "not available" (AIS's repeat indicator)
# cannot be left out.
claim = ('{"type":"PGN60928","device_function":"%s","unique_number":5,"manufacturer_code":"garmin",'
         '"device_instance_lower":7,"device_instance_upper":31,"device_class":"%s",'
         '"system_instance":0,"industry_group":"marine","arbitrary_address_capable":"yes"}\n')
lines = ((claim % ("pc_gateway", "safety")) + (claim % ("pc_gateway", "internetwork"))
         + '{"type":"PGN127493","transmission_gear":"reverse","discrete_status_1":[]}\n'
         + '{"type":"PGN129039","user_id":1}\n').encode()
enc = run(ENCODE, [], lines)
check(enc.returncode == 1, f"lookups: encode exit {enc.returncode}")
err = enc.stderr.decode()
check("line 1: PGN60928 field 5 (device_function)" in err and "bad_enum" in err,
      f"lookups: a function of another class: {err!r}")
check("line 4: PGN129039 field 2 (repeat_indicator)" in err and "missing_field" in err,
      f"lookups: repeat indicator left out: {err!r}")
back = [json.loads(l) for l in run(DECODE, [], enc.stdout).stdout.decode().splitlines()]
check(len(back) == 2 and back[0].get("device_function") == "pc_gateway"
      and back[0].get("device_class") == "internetwork"
      and back[0].get("device_instance_upper") == 31
      and back[1].get("transmission_gear") == "reverse", f"lookups: {back}")

harness.finish()
