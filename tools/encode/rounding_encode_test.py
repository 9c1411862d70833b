# SPDX-License-Identifier: BSL-1.0
"""seawire-encode rounds JSON numbers by the library's one rule, from the number's own text.

    rounding_encode_test.py <seawire-decode> <seawire-encode>

A JSON number such as 1.005 is taken as written (never through a double, whose value is
1.00499999...), then rounded half away from zero to the field's step: NMEA 2000 resolutions
(0.01, 0.001, 0.25, 0.004), the ANELLO frame's (0.1, 1e-6, 1) and a DDMM.m position's minute
digits. Each result is decoded back with seawire-decode and compared with what Python's decimal
module computes from the same text (ROUND_HALF_UP); values past a field's range are refused.
"""

import json
import os
import sys
from decimal import ROUND_HALF_UP, Decimal

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import harness
from harness import check

DECODE, ENCODE = sys.argv[1], sys.argv[2]


def run(exe, data, args=()):
    return harness.run([exe, *args], data)


def step_round(text, step):
    """The value of `text` at `step`, halves away from zero."""
    return (Decimal(text) / Decimal(step)).quantize(Decimal(1), rounding=ROUND_HALF_UP) * Decimal(step)


# (JSON line template, the decoded object's key, the field's step, values written as text)
CASES = [
    ('{"type":"PGN128259","speed_water_mps":%s}', "speed_water_mps", "0.01",
     ["1.005", "2.675", "0.125", "1.115", "655.324", "1.005e0", "100.5e-2", "0.0049"]),
    ('{"type":"PGN130578","longitudinal_water_mps":%s}', "longitudinal_water_mps", "0.001",
     ["-2.6745", "2.6745", "1.0005", "-1.0005", "-32.768", "-0.0004", "32.7635"]),
    ('{"type":"PGN127488","speed_rpm":%s}', "speed_rpm", "0.25", ["798.625", "0.125", "0.124"]),
    ('{"type":"PGN130311","humidity_pct":%s}', "humidity_pct", "0.004",
     ["60.118", "-0.002", "0.002", "0.0019"]),
    ('{"type":"AB00","sog_mps":%s}', "sog_mps", "0.1", ["1.05", "0.15", "6553.3"]),
    ('{"type":"AB00","latitude":%s}', "latitude", "0.000001",
     ["42.0000005", "-42.0000005", "89.9999995", "-0.0000005"]),
    ('{"type":"AB00","alt_msl_m":%s}', "alt_msl_m", "0.1", ["-2.675", "-2.65", "1.005"]),
    ('{"type":"AB00","motor_pct":%s}', "motor_pct", "1", ["12.5", "-12.5", "99.5", "-100.4"]),
]

for template, key, step, values in CASES:
    lines = "".join(template % v + "\n" for v in values).encode()
    enc = run(ENCODE, lines)
    if not check(enc.returncode == 0, f"{key}: encode exit {enc.returncode}: {enc.stderr[:400]!r}"):
        continue
    dec = run(DECODE, enc.stdout)
    got = [json.loads(l, parse_float=Decimal) for l in dec.stdout.decode().splitlines()]
    if not check(len(got) == len(values), f"{key}: {len(values)} values, decoded {got}"):
        continue
    for text, obj in zip(values, got):
        want = step_round(text, step)
        have = obj.get(key)
        check(have is not None and Decimal(have) == want,
              f"{key} {text}: decoded {have}, expected {want} ({text} / {step} half away from zero)")

# Past the range once rounded: refused, naming the field (655.325 m/s is raw 65533 and 32.7645
# m/s raw 32765, sentinels;
# 90.0000005 degrees is beyond 90; 100.5 % is beyond 100).
for line, key in [('{"type":"PGN128259","speed_water_mps":655.325}', "speed_water_mps"),
                  ('{"type":"PGN130578","longitudinal_water_mps":-32.7685}',
                   "longitudinal_water_mps"),
                  ('{"type":"PGN130578","longitudinal_water_mps":32.7645}',
                   "longitudinal_water_mps"),
                  ('{"type":"AB00","latitude":90.0000005}', "latitude"),
                  ('{"type":"AB00","motor_pct":100.5}', "motor_pct")]:
    enc = run(ENCODE, (line + "\n").encode())
    err = enc.stderr.decode()
    check(enc.returncode == 1 and key in err and "line 1" in err,
          f"{line}: refused naming {key}: exit {enc.returncode}, {err!r}")

# A DDMM.m position at the minute digits asked for: 42.000175 degrees is 42 deg 0.0105', a tie
# at three places (0.011'); the written text of the position shows it.
for deg, places in [("42.000175", 3), ("-42.000175", 3), ("0.000125", 3), ("10.9999999999", 3)]:
    line = ('{"type":"CPNVG","timestamp":"08:10:25.987","latitude":%s,"longitude":-71.25,'
            '"position_quality":true,"precision":{"latitude":%d}}\n' % (deg, places))
    enc = run(ENCODE, line.encode())
    if not check(enc.returncode == 0, f"CPNVG {deg}: encode exit {enc.returncode}: {enc.stderr!r}"):
        continue
    total = (abs(Decimal(deg)) * 60).quantize(Decimal(1).scaleb(-places), rounding=ROUND_HALF_UP)
    whole, minutes = divmod(total, 60)
    want = "%02d%s,%s" % (whole, ("%0*.*f" % (places + 3, places, minutes)),
                          "S" if deg.startswith("-") and total != 0 else "N")
    sentence = enc.stdout.decode()
    check("," + want + "," in sentence, f"CPNVG latitude {deg} at {places}: {sentence!r}, want {want}")

harness.finish()
