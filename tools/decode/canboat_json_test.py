# SPDX-License-Identifier: BSL-1.0
"""seawire-decode --format canboat against canboat's analyzer, object for object.

    canboat_json_test.py <seawire-decode> <tests/data/n2k> <case>

vectors      every CAN log of tests/data/n2k (NN_*.in, and the NN_*.log of canboat's sample
             logs, a random log of every PGN seawire describes and the catch-all ranges, and
             messages cut short at every length) through --format canboat, each line compared
             with NN_*.canboat.json, what `analyzer -json` (default options) wrote for the same
             log, its first ("version") line deleted; candump -L logs went through
             candump2analyzer first, as canboat reads them. Same keys, same values, numbers equal
             as numbers, in the same order; the only differences let through are those
             tools/decode/README.md names (DIFFERENCES), each checked for what it must be.
differences  those differences shown on lines written here: a date past 2038-01-19, an undescribed
             proprietary PGN's manufacturer, a Yacht Devices time's date.
by_hand      values worked out here from the bit layouts and canboat's rules, not from its output:
             units, decimals, sentinels, reserved bits, short payloads, catch-alls.
usage        sentence input refused (a usage error), an empty input, rejected lines on stderr.
"""

import datetime
import glob
import json
import os
import re
import sys
from decimal import Decimal

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import harness
from harness import check

DECODE, DATA, CASE = sys.argv[1], sys.argv[2], sys.argv[3]
DATE = re.compile(r"^\d{4}\.\d\d\.\d\d$")
compared = 0  # objects compared, reported at the end


def exact(text):
    """JSON with every fractional number as a Decimal, so 1.50 and 1.5 are equal, 1.51 is not."""
    return json.loads(text, parse_float=Decimal)


def canboat(args, data, want_rc=0):
    p = harness.run([DECODE, "--format", "canboat", *args], data, want_rc)
    return [exact(line) for line in p.stdout.decode().splitlines()], p


def wrapped_date(ours):
    """What canboat's analyzer shows for the date `ours` ("YYYY.MM.DD"): its days times 86400 in a
    32-bit int, which wraps after 2038-01-19."""
    day = datetime.date(*map(int, ours.split(".")))
    seconds = (day - datetime.date(1970, 1, 1)).days * 86400
    seconds = (seconds + 2**31) % 2**32 - 2**31
    when = datetime.datetime(1970, 1, 1) + datetime.timedelta(seconds=seconds)
    return when.strftime("%Y.%m.%d")


def iso(ts):
    return datetime.datetime.strptime(ts, "%Y-%m-%dT%H:%M:%S.%fZ")


def log_offsets(text):
    """The UTC offsets of the log's timestamps ("-07:00"), as timedeltas."""
    out = set()
    for sign, h, m in re.findall(r"T[\d:.]+([+-])(\d\d):?(\d\d),", text):
        d = datetime.timedelta(hours=int(h), minutes=int(m))
        out.add(d if sign == "+" else -d)
    return out


def same_timestamp(ours, theirs, text, where):
    if ours == theirs:
        return True
    # A Yacht Devices line has no date: analyzer gives it today's (local), as seawire-decode does.
    if re.search(r"^\d\d:\d\d:\d\d\.\d+ [RT] ", text, re.M) and ours[10:] == theirs[10:]:
        return check(ours[:10] == datetime.date.today().isoformat(),
                     f"{where}: a Yacht Devices time dated {ours[:10]}, not today")
    # A time with a UTC offset: analyzer writes its digits with a Z (the wrong instant), seawire
    # the instant in UTC.
    if re.match(r"^\d{4}-", ours) and re.match(r"^\d{4}-", theirs):
        return check(iso(ours) - iso(theirs) in {-o for o in log_offsets(text)},
                     f"{where}: timestamp {ours} != {theirs}")
    return check(False, f"{where}: timestamp {ours} != {theirs}")


def same_value(key, ours, theirs, where):
    if ours == theirs and type(ours) is type(theirs):
        return True
    if isinstance(ours, str) and DATE.match(ours) and isinstance(theirs, str):
        # canboat's dates wrap after 2038-01-19 (a 32-bit time); seawire's do not.
        return check(ours > "2038.01.19" and theirs == wrapped_date(ours),
                     f"{where}: {key} {ours!r} != {theirs!r}")
    if key == "Manufacturer Code" and isinstance(ours, int) and isinstance(theirs, str):
        return True  # canboat's names of manufacturers are not seawire's: the number
    return check(False, f"{where}: {key} {ours!r} != {theirs!r}")


HEX_BYTES = re.compile(r"^[0-9A-F]{2}( [0-9A-F]{2})*$")


def proprietary(pgn):
    return 65280 <= pgn <= 65535 or 126720 <= pgn <= 126975 or 130816 <= pgn <= 131071


def same_pairs(ours, theirs, where, pgn):
    """A group function's parameter pairs: pair for pair the same up to the first value of a
    field seawire has no description of (a PGN it does not describe, past a proprietary PGN's
    manufacturer and industry codes), which ours gives as bytes with the rest of the payload and
    stops, where analyzer knows the field and reads on (README: DIFFERENCES)."""
    if not check(isinstance(ours, list) and isinstance(theirs, list), f"{where}: list {ours!r}"):
        return
    for i, o in enumerate(ours):
        t = theirs[i] if i < len(theirs) else None
        if o == t:
            continue
        # a proprietary PGN's manufacturer, reserved bits and industry (fields 1-3) are known
        known = proprietary(pgn) and isinstance(o.get("Parameter"), int) and o["Parameter"] <= 3
        check(i == len(ours) - 1 and t is not None and o.get("Parameter") == t.get("Parameter")
              and HEX_BYTES.match(str(o.get("Value", ""))) is not None and not known,
              f"{where}: pair {i + 1} {o!r} != {t!r}")
        return
    check(len(ours) == len(theirs), f"{where}: {len(ours)} pairs, analyzer {len(theirs)}")


def same_message(ours, theirs, text, where):
    check(list(ours) == list(theirs), f"{where}: keys {list(ours)} != {list(theirs)}")
    for key in ("prio", "src", "dst", "pgn", "description"):
        check(ours.get(key) == theirs.get(key), f"{where}: {key} {ours.get(key)!r} != "
              f"{theirs.get(key)!r}")
    same_timestamp(ours.get("timestamp"), theirs.get("timestamp"), text, where)
    a, b = ours.get("fields", {}), theirs.get("fields", {})
    check(list(a) == list(b), f"{where}: fields {list(a)} != {list(b)}")
    pairs = ours.get("pgn") == 126208 and a.get("Function Code") in ("Request", "Command")
    for key in b:
        if key in a and key == "list" and pairs:
            same_pairs(a[key], b[key], where, a.get("PGN", -1))
        elif key in a:
            same_value(key, a[key], b[key], where)


def logs():
    names = sorted(glob.glob(os.path.join(DATA, "[0-9][0-9]_*.in")) +
                   glob.glob(os.path.join(DATA, "[0-9][0-9]_*.log")))
    names = [n for n in names if os.path.exists(os.path.splitext(n)[0] + ".canboat.json")]
    check(len(names) >= 46, f"only {len(names)} logs with analyzer's output in {DATA}")
    return names


def case_vectors():
    global compared
    for path in logs():
        name = os.path.basename(path)
        with open(path, "rb") as f:
            data = f.read()
        with open(os.path.splitext(path)[0] + ".canboat.json") as f:
            theirs = [exact(line) for line in f if line.strip()]
        ours, p = canboat(["--input", "n2k"], data, None)
        check(p.returncode in (0, 1), f"{name}: exit status {p.returncode}")
        # The PGNs seawire describes, and those canboat does not (its catch-alls): a PGN canboat
        # describes and seawire does not cannot be shown alike (README: DIFFERENCES).
        catch_all = lambda o: o.get("description", "").startswith("0x")
        kept = {o["pgn"] for o in ours if not catch_all(o)} | \
               {o["pgn"] for o in theirs if catch_all(o)}
        ours = [o for o in ours if o["pgn"] in kept]
        theirs = [o for o in theirs if o["pgn"] in kept]
        check(len(ours) == len(theirs),
              f"{name}: {len(ours)} objects, analyzer {len(theirs)}: {p.stderr[:300]!r}")
        text = data.decode(errors="replace")
        for i, (a, b) in enumerate(zip(ours, theirs)):
            if catch_all(a) and not catch_all(b):
                # A proprietary PGN: canboat describes some manufacturers' messages of it
                # (by their codes), seawire none. The header still agrees.
                check(a["pgn"] == b["pgn"] and a["src"] == b["src"],
                      f"{name} object {i + 1}: {a['pgn']}/{a['src']} != {b['pgn']}/{b['src']}")
                continue
            same_message(a, b, text, f"{name} object {i + 1}")
            compared += 1
    check(compared > 2500, f"only {compared} objects compared")


def fields_of(line, *args):
    out, _ = canboat(list(args), line.encode())
    check(len(out) == 1, f"{line}: {len(out)} objects")
    return out[0].get("fields") if out else None


def case_differences():
    # The date: 24855 days is 2038-01-19, the last analyzer gets right.
    days = lambda d: f"{d & 0xff:02x},{d >> 8:02x}"
    f = fields_of(f"2024-07-03T15:42:58.000Z,3,129033,35,255,8,{days(24855)},00,00,00,00,00,00")
    check(f == {"Date": "2038.01.19", "Time": "00:00:00.0000", "Local Offset": "00:00:00"}, f"{f}")
    f = fields_of(f"2024-07-03T15:42:58.000Z,3,129033,35,255,8,{days(24856)},00,00,00,00,ff,7f")
    check(f == {"Date": "2038.01.20", "Time": "00:00:00.0000"}, f"{f}")
    check(wrapped_date("2038.01.20") == "1901.12.14", wrapped_date("2038.01.20"))
    # A proprietary PGN seawire does not describe: the manufacturer as a number.
    f = fields_of("2024-07-03T15:42:58.000Z,6,65300,16,255,8,13,99,01,02,03,04,05,06")
    check(f == {"Manufacturer Code": 275, "Industry Code": "Marine Industry",
                "Data": "01 02 03 04 05 06"}, f"{f}")
    # A Yacht Devices line: today's date.
    out, _ = canboat([], b"21:55:35.425 R 15FD0723 FF C0 D9 6F FF 7F FF FF\n")
    check(len(out) == 1 and out[0]["timestamp"] ==
          datetime.date.today().isoformat() + "T21:55:35.425Z", f"{out}")


def case_by_hand():
    line = "2024-07-03T15:42:58.123Z,{},{},35,255,{}"

    def one(pgn, data, prio=2):
        hexes = data.split()
        return fields_of(line.format(prio, pgn, len(hexes)) + "".join("," + h for h in hexes))

    # Angles in degrees at one decimal (0.0001 rad x 180/pi); a cut field read from its bytes:
    # deviation 0x04 alone is 0.0004 rad.
    check(one(127250, "01 02 03 04") ==
          {"SID": 1, "Heading": Decimal("4.4"), "Deviation": Decimal("0.0")}, "127250 cut")
    check(one(127250, "01 10 27 ff 7f ff 7f fe") == {"SID": 1, "Heading": Decimal("57.3"),
                                                     "Reference": "Error"},
          "127250: 1 rad, reference raw 2 is canboat's \"Error\", 3 left out")
    check(one(127250, "ff ff ff ff 7f ff 7f ff") is None, "127250 all not available: no fields")
    check(one(127250, "ff ff ff ff ff ff ff ff") == {"Deviation": Decimal("-0.0"),
                                                     "Variation": Decimal("-0.0")},
          "127250: signed 0xFFFF is -1, -0.0057 degrees")
    # Temperatures in C (K - 273.15, the resolution's decimals), pressures in bar (3 decimals).
    check(one(130312, "01 02 00 83 72 ff ff ff") ==
          {"SID": 1, "Instance": 2, "Source": "Sea Temperature", "Actual Temperature":
           Decimal("20.00")}, "130312")
    check(one(130314, "01 02 00 28 75 0f 00 ff") ==
          {"SID": 1, "Instance": 2, "Source": "Atmospheric", "Pressure": Decimal("1.013")},
          "130314: 101300.0 Pa")
    # Rate of turn in deg/s, six decimals (3.125e-8 rad/s x 180/pi ~ 1.79e-6).
    rate = f"{65536 * (3.125e-8 * (360.0 / 2 / 3.141592653589793)):.6f}"
    check(rate == "0.117342" and one(127251, "00 00 00 01 00 ff ff ff") ==
          {"SID": 0, "Rate": Decimal(rate)}, "127251: 65536 steps")
    # Durations as text; an unnamed lookup value as a number; an engine instance's title.
    f = one(127489, "01 ff ff ff ff ff ff ff 7f ff 7f 10 0e 00 00 ff ff ff ff ff 00 00 00 01 7f 7f")
    check(f == {"Instance": "Dual Engine Starboard", "Total Engine hours": "01:00:00",
                "Discrete Status 2": [256]}, f"127489: no flag set, a flag without a title: {f}")
    check(one(128259, "01 10 27 ff ff 07 ff ff") ==
          {"SID": 1, "Speed Water Referenced": Decimal("100.00"),
           "Speed Water Referenced Type": 7}, "128259: unnamed speed type 7")
    # Reserved bits shown only when not all ones, at their place in the byte.
    check(one(129026, "01 f0 00 00 00 00 ff ff") ==
          {"SID": 1, "COG Reference": "True", "Reserved": "F0", "COG": Decimal("0.0"),
           "SOG": Decimal("0.00")}, "129026: reserved bits 2-7 with two clear")
    # A date of one byte: analyzer writes nothing of the message; said on stderr.
    out, p = canboat([], (line.format(3, 126992, 3) + ",01,f0,00\n").encode())
    check(out == [] and b"126992" in p.stderr, f"126992 of 3 bytes: {out} {p.stderr!r}")
    # A group function's parameter pairs: each value read from as many whole bytes as the named
    # field needs (127250's SID 1 byte, its 2-bit reference a byte, its heading 2), written as
    # that field is; a value the payload ends in read from the byte there is (0x39 = 57 x
    # 0.0001 rad, 0.3 degrees); a counted string (126998's #2); a proprietary PGN's manufacturer
    # (11 bits in 2 bytes) and industry (3 bits in a byte); a field seawire does not describe:
    # the rest as bytes, and no more pairs.
    gf = "01 12 f1 01 f8 03 01 07 05 01 02 39 30"
    check(one(126208, gf, 3) == {
        "Function Code": "Command", "PGN": 127250, "Priority": "Leave unchanged",
        "Number of Parameters": 3, "list": [{"Parameter": 1, "Value": 7},
                                            {"Parameter": 5, "Value": "Magnetic"},
                                            {"Parameter": 2, "Value": Decimal("70.7")}]},
          "126208 command for 127250")
    check(one(126208, "01 12 f1 01 f8 04 01 07 02 39", 3)["list"] ==
          [{"Parameter": 1, "Value": 7}, {"Parameter": 2, "Value": Decimal("0.3")}],
          "126208: a value cut short")
    check(one(126208, "01 16 f0 01 f8 01 02 06 01 41 42 43 44", 3)["list"] ==
          [{"Parameter": 2, "Value": "ABCD"}], "126208 command for 126998's text")
    check(one(126208, "01 10 ff 01 f8 03 01 89 00 03 04 07 aa bb", 3)["list"] ==
          [{"Parameter": 1, "Value": "Maretron"}, {"Parameter": 3, "Value": "Marine Industry"},
           {"Parameter": 7, "Value": "AA BB"}], "126208 command for proprietary 130832")
    check(one(126208, "01 0d f2 01 f8 02 03 01 04 00", 3)["list"] ==
          [{"Parameter": 3, "Value": "01 04 00"}], "126208 command for 127501, which seawire lacks")
    # A number that is no field of the PGN named: analyzer writes nothing of the message.
    out, p = canboat([], (line.format(3, 126208, 9) + ",01,12,f1,01,f8,01,09,aa,bb\n").encode())
    check(out == [] and b"126208" in p.stderr, f"126208 field 9 of 127250: {out} {p.stderr!r}")
    # Undescribed PGNs: the catch-all of their range, the data after it as bytes.
    check(one(60000, "01 02 03 04 05 06 07 08 09") == {"Data": "01 02 03 04 05 06 07 08"},
          "60000 of 9 bytes: 64 bits of data")
    check(one(126999, "01 02 03") == {"Data": "01 02 03"}, "126999")
    out, _ = canboat([], (line.format(6, 126999, 3) + ",01,02,03\n").encode())
    check(out and out[0]["description"] ==
          "0x1F000-0x1FEFF: Standardized mixed single/fast packet non-addressed", f"{out}")
    # The header: the time to the millisecond, the addresses.
    out, _ = canboat([], b"(1720021378.123456) can0 09F11223#011027FF7FFF7FFD\n")
    check(len(out) == 1 and list(out[0])[:6] == ["timestamp", "prio", "src", "dst", "pgn",
                                                 "description"]
          and out[0]["timestamp"] == "2024-07-03T15:42:58.123Z" and out[0]["src"] == 35,
          f"{out}")
    # Strings from their bytes: a UTF-16 counted string as UTF-8, padding (' ', '@') trimmed, an
    # empty one left out; the rows after a counted string start where it ended.
    check(one(126998, "06 00 e9 00 ac 20 05 01 61 20 40 02 01", 6) ==
          {"Installation Description #1": "\u00e9\u20ac", "Installation Description #2": "a"},
          "126998 UTF-16 and ASCII")
    # An encoding byte analyzer does not know (2): nothing of the message is written.
    out, _ = canboat([], (line.format(6, 126998, 4) + ",04,02,41,42").encode())
    check(out == [], f"126998 encoding byte 2: {out}")
    # An identifier (an MMSI) as 9-digit text, leading zeros kept; not available left out
    # (analyzer's output for these two lines).
    name = " ".join(["41"] * 4 + ["40"] * 16)
    head = {"Message ID": "Static data report", "Repeat Indicator": "Initial"}
    tail = {"Name": "AAAA", "AIS Transceiver information": "Channel A VDL reception"}
    check(one(129809, f"18 10 43 25 00 {name} e0 ff", 6) ==
          head | {"User ID": "002442000"} | tail, "129809: MMSI 2442000")
    check(one(129809, f"18 ff ff ff ff {name} e0 ff", 6) == head | tail,
          "129809: MMSI not available")


def case_usage():
    p = harness.run([DECODE, "--format", "canboat", "--input", "nmea"], b"", 2)
    check(b"--format canboat" in p.stderr and p.stdout == b"", f"--input nmea: {p.stderr!r}")
    p = harness.run([DECODE, "--format", "canboat"],
                    b"$GPHDT,123.4,T*31\r\n$GPHDT,123.5,T*30\r\n", 2)
    check(b"--format canboat" in p.stderr and p.stdout == b"", f"sentences: {p.stderr!r}")
    p = harness.run([DECODE, "--format", "canboat"], b"", 0)
    check(p.stdout == b"", f"empty input: {p.stdout!r}")
    # A bad line among good ones: the good ones written, the bad one on stderr, exit status 1.
    p = harness.run([DECODE, "--format", "canboat"],
                    b"2024-07-03T15:42:58.000Z,2,127250,35,255,8,01,10,27,ff,7f,ff,7f,fd\n"
                    b"2024-07-03T15:42:58.000Z,2,127250,35,255,8,01,zz\n", 1)
    lines = p.stdout.decode().splitlines()
    check(len(lines) == 1 and b"line 2" in p.stderr, f"{lines} {p.stderr!r}")


harness.case_of(globals(), CASE)()
if compared:
    print(f"{CASE}: {compared} objects compared")
harness.finish()
