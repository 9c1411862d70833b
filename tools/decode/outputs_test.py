# SPDX-License-Identifier: BSL-1.0
"""seawire-decode's outputs for people and their tools, checked with independent readers.

    outputs_test.py <seawire-decode> <examples/data> <case> [rsvg-convert]

csv       Python's csv module reads every table back to the values of the JSON output.
geojson   the FeatureCollection keeps RFC 7946's rules and the wire's exact coordinates.
svg       rsvg-convert renders the picture; the track's pixels are where its coordinates say.
progress  the progress line shows on a terminal only, and is erased at the end.
"""

import csv
import io
import json
import math
import os
import pty
import re
import select
import struct
import subprocess
import sys
import tempfile
import zlib

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import harness
from harness import check, run_case, seal

DECODE, DATA, CASE = sys.argv[1], sys.argv[2], sys.argv[3]
RSVG = sys.argv[4] if len(sys.argv) > 4 else None
FAMILIES = ["kingfisher", "sandshark", "robotx", "anello", "anello_mixed", "standard"]
# NMEA 2000 CAN logs (candump, plain/fast, YD raw), beside the tests that use them.
N2K = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "data", "n2k")
N2K_LOGS = sorted(f for f in os.listdir(N2K) if f.endswith(".in"))


def run(args, data, want_rc=None):
    return harness.run([DECODE, *args], data, want_rc)


def read(name):
    with open(os.path.join(DATA, name + ".nmea"), "rb") as f:
        return f.read()


def exact(text):
    """JSON with every number kept as its text, so values compare digit for digit."""
    return json.loads(text, parse_float=str, parse_int=str)


def json_messages(data):
    """The messages seawire-decode's JSON output holds (errors and unknown sentences left out)."""
    out = run([], data).stdout.decode()
    objs = [exact(line) for line in out.splitlines()]
    return [o for o in objs if "type" in o and "fields" not in o]


def cell(v):
    """A JSON value as a CSV cell holds it."""
    if v is None:
        return ""
    if v is True:
        return "true"
    if v is False:
        return "false"
    return v


# The NMEA 2000 string fields of the vectors (their values are JSON strings).
STRINGS = {"model_id", "software_version_code", "model_version", "model_serial_code",
           "installation_description_1", "installation_description_2",
           "manufacturer_information", "callsign", "name", "destination", "vendor_id"}


def text_cell(v):
    """A string as its CSV cell: printable ASCII as it is, any other character escaped."""
    short = {"\n": "\\n", "\r": "\\r", "\t": "\\t"}

    def escaped(c):
        o = ord(c)
        if o > 0xFFFF:  # UTF-16's surrogate pair
            o -= 0x10000
            return f"\\u{0xD800 + (o >> 10):04X}\\u{0xDC00 + (o & 0x3FF):04X}"
        return short.get(c, f"\\u{o:04X}")
    return "".join(c if " " <= c <= "~" else escaped(c) for c in v)


# The NMEA 2000 repeating groups of the vectors (their values are JSON arrays of objects).
GROUPS = {"pgns", "satellites", "stations", "parameters"}  # a request's parameters: hex text


def group_cell(v):
    """A repeating group as its CSV cell."""
    return ";".join("|".join(";".join(x) or "none" if isinstance(x, list) else cell(x)
                             for x in item.values()) for item in v)


# ---------------------------------------------------------------------------------------------

def case_csv():
    with tempfile.TemporaryDirectory() as tmp:
        for family in FAMILIES:
            data = read(family)
            msgs = json_messages(data)
            d = os.path.join(tmp, family)
            run(["--format", "csv", "--output-dir", d], data, 0)
            by_type = {}
            for m in msgs:
                by_type.setdefault(m["type"], []).append(m)
            check(sorted(f[:-4] for f in os.listdir(d)) == sorted(by_type),
                  f"{family}: one table per type: {sorted(os.listdir(d))} vs {sorted(by_type)}")
            for t, rows in by_type.items():
                with open(os.path.join(d, t + ".csv"), newline="") as f:
                    table = list(csv.reader(f))
                keys = [k for k in rows[0] if k != "type"]
                check(table[0] == keys, f"{family} {t}: header {table[0]} vs {keys}")
                check(len(table) == len(rows) + 1, f"{family} {t}: {len(table) - 1} rows")
                for row, m in zip(table[1:], rows):
                    want = [cell(m[k]) for k in keys]
                    check(row == want, f"{family} {t}: row {row} vs JSON {want}")
                # One type to stdout gives the same table as its file.
                one = run(["--format", "csv", "--type", t], data, 0).stdout
                with open(os.path.join(d, t + ".csv"), "rb") as f:
                    check(one == f.read(), f"{family} {t}: --type table differs from its file")

        # NMEA 2000 logs: a table per PGN with the frame's time, priority, source and
        # destination before the fields (the log's interface and direction are not columns).
        for log in N2K_LOGS:
            with open(os.path.join(N2K, log), "rb") as f:
                data = f.read()
            d = os.path.join(tmp, log)
            p = run(["--format", "csv", "--output-dir", d], data, 0)
            by_type = {}
            for m in json_messages(data):
                if "data" in m and m["type"][3:].isdigit():
                    # A PGN (or layout) seawire does not describe has no table: said on stderr.
                    check(re.search(rf"\b\d+ {m['type']} messages? left out",
                                    p.stderr.decode()),
                          f"{log}: {m['type']} not said to be left out")
                    continue
                # 126208: a table per layout (its function code)
                layout = "_" + m["function_code"] if m["type"] == "PGN126208" else ""
                by_type.setdefault(m["type"] + layout, []).append(m)
            check(by_type != {} and sorted(f[:-4] for f in os.listdir(d)) == sorted(by_type),
                  f"{log}: one table per PGN: {sorted(os.listdir(d))} vs {sorted(by_type)}")
            for t, rows in by_type.items():
                with open(os.path.join(d, t + ".csv"), newline="") as f:
                    table = list(csv.reader(f))
                keys = ["time_s", "prio", "src", "dst"] + [
                    k for k in rows[0]
                    if k not in ("type", "time_s", "interface", "direction", "prio", "src", "dst")]
                check(table[0] == keys, f"{log} {t}: header {table[0]} vs {keys}")
                check(len(table) == len(rows) + 1, f"{log} {t}: {len(table) - 1} rows")
                for row, m in zip(table[1:], rows):
                    # a flag set: its names joined by ';', "none" when it was sent with no flag
                    # set (an empty cell, like any field not available, when it was not sent)
                    # a string: its text, a character outside printable ASCII escaped as in
                    # JSON (\n, \u00E9)
                    # a repeating group: its repetitions joined by ';', a repetition's fields
                    # by '|', each as its own cell
                    want = [group_cell(m[k]) if k in GROUPS and isinstance(m[k], list)
                            else (";".join(m[k]) or "none") if isinstance(m.get(k), list)
                            else text_cell(m[k]) if isinstance(m.get(k), str) and k in STRINGS
                            else cell(m.get(k)) for k in keys]
                    check(row == want, f"{log} {t}: row {row} vs JSON {want}")

        # A table that cannot be created is reported, the others still written, exit status 1.
        d = os.path.join(tmp, "blocked")
        os.makedirs(os.path.join(d, "CPNVG.csv"))
        p = run(["--format", "csv", "--output-dir", d], read("kingfisher"), 1)
        check(b"cannot create" in p.stderr and b"CPNVG.csv" in p.stderr,
              f"blocked table: {p.stderr[:300]!r}")
        check(os.path.getsize(os.path.join(d, "GPRMC.csv")) > 0, "other tables still written")

    # Text with a quote is quoted with the quote doubled; the csv module reads it back.
    data = seal('BFMIS,231121.30,dive1.xml,Aborted,said "too deep" twice').encode()
    p = run(["--format", "csv", "--type", "BFMIS"], data, 0)
    rows = list(csv.reader(io.StringIO(p.stdout.decode(), newline="")))
    check(rows == [["timestamp", "dive_file", "status", "details"],
                   ["23:11:21.30", "dive1.xml", "Aborted", 'said "too deep" twice']],
          f"quoted text: {rows}")
    check(b'"said ""too deep"" twice"' in p.stdout, f"quotes doubled: {p.stdout!r}")
    # A table on stdout has its header even with no rows (pandas reads an empty table).
    p = run(["--format", "csv", "--type", "GNRMC"], b"", 0)
    check(p.stdout == b"time,status,latitude,longitude,speed_knots,course_true,date,"
          b"magnetic_variation,mode,navigational_status\n", f"empty table: {p.stdout!r}")
    p = run(["--format", "csv", "--type", "AB00"], b"", 0)
    check(p.stdout.startswith(b"heading_deg,latitude,longitude,"), f"empty AB00: {p.stdout!r}")
    run(["--format", "csv", "--type", "CPNVX"], b"", 2)
    run(["--format", "csv", "--output-dir", ""], b"", 2)
    # --line-buffered: each row comes out as it is decoded, before the input ends.
    proc = subprocess.Popen([DECODE, "--format", "csv", "--type", "CPNVG", "--line-buffered"],
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE)
    nvg = [l for l in read("kingfisher").splitlines(keepends=True) if l.startswith(b"$CPNVG")]
    proc.stdin.write(nvg[0])
    proc.stdin.flush()
    got = b""
    while got.count(b"\n") < 2 and select.select([proc.stdout], [], [], 10)[0]:
        chunk = os.read(proc.stdout.fileno(), 4096)
        if not chunk:
            break
        got += chunk
    check(got.count(b"\n") == 2 and got.startswith(b"timestamp,"),
          f"--line-buffered row while the input is open: {got!r}")
    proc.stdin.close()
    proc.wait(timeout=30)

    # Usage: csv to stdout needs exactly one type; --output-dir is for csv only.
    run(["--format", "csv"], b"", 2)
    run(["--format", "csv", "--type", "CPNVG", "--type", "GPRMC"], b"", 2)
    run(["--format", "json", "--output-dir", "x"], b"", 2)
    # Rejected input is reported on stderr, the tables keep the good rows.
    bad = read("bad")
    p = run(["--format", "csv", "--type", "GPRMC"], bad, 1)
    check(b"line 5: minute_out_of_range" in p.stderr, f"csv errors on stderr: {p.stderr[:200]!r}")
    check(len(p.stdout.splitlines()) == 1 + sum(1 for m in json_messages(bad)
                                                if m["type"] == "GPRMC"), "csv rows of bad.nmea")
    # Sentences no message describes are counted, not silently lost.
    with tempfile.TemporaryDirectory() as tmp:
        p = run(["--format", "csv", "--output-dir", tmp], seal("GPGSV,1,1,01,01,40,083,46").encode(), 0)
        check(b"1 GPGSV message left out" in p.stderr, f"unknown types: {p.stderr!r}")
        check(os.listdir(tmp) == [], f"no table for unknown types: {os.listdir(tmp)}")
    run(["--format", "csv", "--type", "GPGSV"], b"", 2)
    # --type filters the other formats too.
    p = run(["--type", "CPNVG"], read("kingfisher"), 0)
    types = {exact(l)["type"] for l in p.stdout.decode().splitlines()}
    check(types == {"CPNVG"}, f"--type CPNVG gives {types}")


# ---------------------------------------------------------------------------------------------

def position(p):
    ok = isinstance(p, list) and len(p) in (2, 3) and all(
        isinstance(v, (int, float)) and not isinstance(v, bool) for v in p)
    return ok and -180 <= p[0] <= 180 and -90 <= p[1] <= 90


def rfc7946(doc, what):
    """The rules of RFC 7946 that a FeatureCollection of Points and LineStrings must keep."""
    check(doc.get("type") == "FeatureCollection", f"{what}: not a FeatureCollection")
    check("crs" not in doc, f"{what}: RFC 7946 has no crs member")
    check(isinstance(doc.get("features"), list), f"{what}: features is not an array")
    for f in doc.get("features", []):
        check(f.get("type") == "Feature", f"{what}: member of type {f.get('type')}")
        check("properties" in f and (f["properties"] is None or isinstance(f["properties"], dict)),
              f"{what}: a Feature needs properties (object or null)")
        g = f.get("geometry")
        check(isinstance(g, dict) and g.get("type") in ("Point", "LineString"),
              f"{what}: geometry {g if not isinstance(g, dict) else g.get('type')}")
        if g.get("type") == "Point":
            check(position(g.get("coordinates")), f"{what}: Point {g.get('coordinates')}")
        else:
            c = g.get("coordinates")
            check(isinstance(c, list) and len(c) >= 2 and all(position(p) for p in c),
                  f"{what}: a LineString needs two or more positions")


def case_geojson():
    for family in FAMILIES:
        data = read(family)
        p = run(["--format", "geojson"], data, 0)
        doc = json.loads(p.stdout)
        rfc7946(doc, family)
        # Strict JSON (RFC 8259, which RFC 7946 requires): no NaN or Infinity, no duplicate keys.
        def refuse(name):
            raise ValueError(f"{name} is not JSON")

        def unique(pairs):
            keys = [k for k, _ in pairs]
            check(len(keys) == len(set(keys)), f"{family}: duplicate keys {keys}")
            return dict(pairs)

        json.loads(p.stdout, parse_constant=refuse, object_pairs_hook=unique)
        # Each source's track is its messages' positions, digit for digit, in order, and its
        # per-vertex properties are their values.
        ex = exact(p.stdout.decode())
        tracks = {}
        for m in json_messages(data):
            if m.get("latitude") is None or m.get("longitude") is None:
                continue
            source = m["type"] + (" " + m["team_id"] if m.get("team_id") else "")
            tracks.setdefault(source, []).append(m)
        lines = [f for f in ex["features"] if "event" not in f["properties"]]
        check(sorted(f["properties"]["source"] for f in lines) == sorted(tracks),
              f"{family}: sources {[f['properties']['source'] for f in lines]} vs {list(tracks)}")
        for f in lines:
            msgs = tracks.get(f["properties"]["source"], [])
            coords = f["geometry"]["coordinates"]
            if f["geometry"]["type"] == "Point":
                coords = [coords]
            check(coords == [[m["longitude"], m["latitude"]] for m in msgs],
                  f"{family} {f['properties']['source']}: coordinates differ from the wire's")
            check(f["properties"]["points"] == str(len(msgs)), f"{family}: point count")
            for k in msgs[0] if msgs else []:
                if k in ("type", "latitude", "longitude"):
                    continue
                got = f["properties"].get(k)
                want = [m[k] for m in msgs] if len(msgs) > 1 else msgs[0][k]
                check(got == want, f"{family} {f['properties']['source']}: property {k}")
    # NMEA 2000 logs: none of these PGNs carries a position, so the collection is empty and
    # still valid, whatever the log's format.
    for log in N2K_LOGS:
        with open(os.path.join(N2K, log), "rb") as f:
            p = run(["--format", "geojson"], f.read(), 0)
        doc = json.loads(p.stdout)
        rfc7946(doc, log)
        check(doc == {"type": "FeatureCollection", "features": []}, f"{log}: {p.stdout[:200]!r}")
    # Events: a RobotX heartbeat whose mode changes is a Point where it changed.
    hb = [seal(f"RXHRB,101218,1612{s:02d},21.31{s:03d},N,157.88972,W,AUVSI,{mode},1").encode()
          for s, mode in ((29, 2), (30, 2), (31, 1), (32, 1))]
    p = run(["--format", "geojson"], b"".join(hb), 0)
    doc = exact(p.stdout.decode())
    events = [f for f in doc["features"] if "event" in f["properties"]]
    check(len(events) == 1, f"one mode change, {len(events)} events")
    if events:
        e = events[0]
        check(e["geometry"]["coordinates"] == ["-157.88972", "21.31031"], f"event at {e}")
        check(e["properties"]["changed"] == ["system_mode"] and
              e["properties"]["previous"] == {"system_mode": "2"} and
              e["properties"]["system_mode"] == "1", f"event properties {e['properties']}")
    # No positions: an empty collection, still valid.
    p = run(["--format", "geojson"], seal("BPLOG,ALL,ON").encode(), 0)
    check(json.loads(p.stdout) == {"type": "FeatureCollection", "features": []},
          f"no positions: {p.stdout!r}")


# ---------------------------------------------------------------------------------------------

def png_pixels(path):
    """(width, height, rows of RGBA tuples) of an 8-bit RGBA or RGB PNG (what rsvg-convert
    writes)."""
    with open(path, "rb") as f:
        data = f.read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat = 8, b""
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour in (2, 6) and interlace == 0, "unexpected PNG form"
            bpp = 4 if colour == 6 else 3
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    stride = w * bpp
    rows, prev = [], bytearray(stride)
    for y in range(h):
        ft = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if ft == 1:
                line[i] = (line[i] + a) & 255
            elif ft == 2:
                line[i] = (line[i] + b) & 255
            elif ft == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif ft == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + pred) & 255
        rows.append([tuple(line[x * bpp:x * bpp + 3]) for x in range(w)])
        prev = line
    return w, h, rows


def project(points):
    """The documented projection: equirectangular around the mean latitude, fitted alike both
    ways into the plot area (40,40)-(760,520), centred, north up."""
    r, rad = 6371008.8, math.pi / 180
    lat0 = sum(p[1] for p in points) / len(points)
    xy = [(r * rad * lon * math.cos(lat0 * rad), r * rad * lat) for lon, lat in points]
    x0, x1 = min(p[0] for p in xy), max(p[0] for p in xy)
    y0, y1 = min(p[1] for p in xy), max(p[1] for p in xy)
    sx = 720 / (x1 - x0) if x1 > x0 else math.inf
    sy = 480 / (y1 - y0) if y1 > y0 else math.inf
    s = min(sx, sy) if min(sx, sy) != math.inf else 1
    mx, my = (x0 + x1) / 2, (y0 + y1) / 2
    return [(400 + (x - mx) * s, 280 - (y - my) * s) for x, y in xy]


def near(rows, x, y, colour, radius=2):
    for dy in range(-radius, radius + 1):
        for dx in range(-radius, radius + 1):
            px, py = int(round(x)) + dx, int(round(y)) + dy
            if 0 <= py < len(rows) and 0 <= px < len(rows[0]):
                if all(abs(a - b) <= 40 for a, b in zip(rows[py][px], colour)):
                    return True
    return False


def case_svg():
    if RSVG is None or RSVG.endswith("NOTFOUND"):
        check(False, "svg: no rsvg-convert to render with (apt-get install librsvg2-bin)")
        return
    first_colour = (0x1F, 0x77, 0xB4)
    with tempfile.TemporaryDirectory() as tmp:
        for family, t in (("kingfisher", "CPNVG"), ("sandshark", "BFNVG"),
                          ("anello_mixed", "AB00"), ("standard", "GPGGA"),
                          ("robotx", "RXHRB")):
            data = read(family)
            svg = run(["--format", "svg", "--type", t], data, 0).stdout
            svg_path, png_path = os.path.join(tmp, t + ".svg"), os.path.join(tmp, t + ".png")
            with open(svg_path, "wb") as f:
                f.write(svg)
            subprocess.run([RSVG, "-o", png_path, svg_path], check=True, timeout=60)
            check(os.path.getsize(png_path) > 0, f"{t}: empty PNG")
            w, h, rows = png_pixels(png_path)
            check((w, h) == (800, 600), f"{t}: {w}x{h}")
            msgs = [m for m in json_messages(data) if m["type"] == t and m.get("latitude")]
            # The first source of the file (RobotX: the first team) is drawn in the first
            # colour. Points of other sources drawn over it (a second team's heartbeat) hide it
            # within their markers: vertices there are not sampled.
            first = msgs[0].get("team_id")
            projected = project([(float(m["longitude"]), float(m["latitude"])) for m in msgs])
            xy = [p for p, m in zip(projected, msgs) if m.get("team_id") == first]
            others = [p for p, m in zip(projected, msgs) if m.get("team_id") != first]

            def hidden(x, y):
                return any(math.hypot(x - ox, y - oy) < 10 for ox, oy in others)

            for i in range(0, len(xy), max(1, len(xy) // 12)):
                check(hidden(*xy[i]) or near(rows, *xy[i], first_colour),
                      f"{t}: vertex {i} at {xy[i]} not drawn")
            # Start: a filled circle (radius 6) around the first vertex; end: a 10 px square.
            sx, sy = xy[0]
            ex, ey = xy[-1]
            for dx, dy in ((4, 0), (-4, 0), (0, 4), (0, -4)):
                check(hidden(sx, sy) or near(rows, sx + dx, sy + dy, first_colour, 0),
                      f"{t}: start marker at {(sx + dx, sy + dy)}")
            for dx, dy in ((3, 3), (-3, 3), (3, -3), (-3, -3)):
                check(hidden(ex, ey) or near(rows, ex + dx, ey + dy, first_colour, 0),
                      f"{t}: end marker at {(ex + dx, ey + dy)}")
            check(len(xy) > 1 and not all(hidden(x, y) for x, y in xy), f"{t}: nothing sampled")
            # Away from the track, legend and labels the picture is white: the top-left of the
            # plot area is blank unless the track passes there.
            if all(x > 120 or y > 120 for x, y in xy):
                check(rows[100][60] == (255, 255, 255), f"{t}: background {rows[100][60]}")
        # Text from the input is escaped for XML: a team id with '&' and '<' renders.
        data = seal("RXHRB,101218,161229,21.31198,N,157.88972,W,A&<B>,2,1").encode()
        svg = run(["--format", "svg"], data, 0).stdout
        check(b"A&amp;&lt;B&gt;" in svg, f"XML escapes: {svg[:200]!r}")
        p = os.path.join(tmp, "esc.svg")
        with open(p, "wb") as f:
            f.write(svg)
        r = subprocess.run([RSVG, "-o", p + ".png", p], capture_output=True, timeout=60)
        check(r.returncode == 0, f"escaped SVG renders: {r.stderr[:200]!r}")


# ---------------------------------------------------------------------------------------------

def read_all(fd, proc):
    out = b""
    while True:
        r, _, _ = select.select([fd], [], [], 10)
        if not r:
            break
        try:
            chunk = os.read(fd, 65536)
        except OSError:
            break
        if not chunk:
            break
        out += chunk
    proc.wait(timeout=30)
    return out


def case_progress():
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "log.nmea")
        with open(path, "wb") as f:
            f.write(read("kingfisher") * 50)
        size = os.path.getsize(path)
        # stderr a terminal, stdin a file: the line shows and is erased at the end.
        for extra, shown in (([], True), (["--quiet"], False)):
            master, slave = pty.openpty()
            with open(path, "rb") as stdin:
                proc = subprocess.Popen([DECODE, "--format", "none"] + extra, stdin=stdin,
                                        stdout=subprocess.DEVNULL, stderr=slave)
            os.close(slave)
            err = read_all(master, proc)
            os.close(master)
            check(proc.returncode == 0, f"progress {extra}: exit status {proc.returncode}")
            if shown:
                total = f"of {size / 1e6:.1f} MB".encode()
                check(b"seawire-decode: " in err and total in err and b"messages/s" in err,
                      f"progress line: {err[:300]!r}")
                check(err.endswith(b"\r\x1b[K"), f"progress line erased: {err[-40:]!r}")
            else:
                check(err == b"", f"--quiet: {err[:200]!r}")
        # A rejected line: the progress line is erased before the report, which starts a line.
        bad_path = os.path.join(tmp, "bad.nmea")
        with open(bad_path, "wb") as f:
            f.write(read("kingfisher") * 50 + seal("CPNVG,164959.034,4261.81092,N").encode() +
                    read("kingfisher") * 50)
        master, slave = pty.openpty()
        with open(bad_path, "rb") as stdin:
            proc = subprocess.Popen([DECODE, "--format", "none"], stdin=stdin,
                                    stdout=subprocess.DEVNULL, stderr=slave)
        os.close(slave)
        err = read_all(master, proc)
        os.close(master)
        check(proc.returncode == 1, f"progress with a reject: exit status {proc.returncode}")
        report = err.find(b"seawire-decode: line ")
        check(report > 0 and err[:report].endswith(b"\r\x1b[K"),
              f"report after an erased progress line: {err[:400]!r}")
        # stdout a terminal too (output there would run into the line): no progress line.
        master, slave = pty.openpty()
        with open(path, "rb") as stdin:
            proc = subprocess.Popen([DECODE, "--format", "none"], stdin=stdin, stdout=slave,
                                    stderr=slave)
        os.close(slave)
        err = read_all(master, proc)
        os.close(master)
        check(err == b"", f"stdout a terminal: {err[:200]!r}")
        # stderr not a terminal: nothing.
        with open(path, "rb") as stdin:
            p = subprocess.run([DECODE, "--format", "none"], stdin=stdin, capture_output=True,
                               timeout=60)
        check(p.returncode == 0 and p.stderr == b"", f"stderr a pipe: {p.stderr[:200]!r}")
        # stdin a pipe (size unknown), stderr a terminal: nothing either.
        master, slave = pty.openpty()
        proc = subprocess.Popen([DECODE, "--format", "none"], stdin=subprocess.PIPE,
                                stdout=subprocess.DEVNULL, stderr=slave)
        os.close(slave)
        proc.stdin.write(read("kingfisher"))
        proc.stdin.close()
        err = read_all(master, proc)
        os.close(master)
        check(err == b"", f"stdin a pipe: {err[:200]!r}")


run_case(globals(), CASE)
