# SPDX-License-Identifier: BSL-1.0
"""The expected rounding of doubles to wire numbers, computed by Python's decimal module.

    rounding_table.py <tests/data/rounding_table.txt>          check the table (a ctest test)
    rounding_table.py --write <tests/data/rounding_table.txt>  write it

seawire's rule: a double is its shortest decimal (Python's repr, the same digits as
std::to_chars), rounded half away from zero (decimal.ROUND_HALF_UP) to the places or step the
wire needs. rounding_test.cpp reads the table and checks every path from a double against it;
this program recomputes it from a fixed seed, so the table is Python's and not the library's.

Lines: <double as hex> <repr> <kind> <parameter> <expected>
  dec <places>      decimal::from_double: the signed mantissa at those places, or ! (too large)
  n2k <resolution>  nmea2000 signed_number<32, resolution>::from: the raw value, or ! (out of
                    range); resolutions by their pgns.hpp names, "unit" for 1
  lon <places>      longitude::from_degrees: signed minutes x 10^places in all (degrees x 60),
                    or ! (beyond 180 degrees)
"""

import random
import sys
from decimal import ROUND_HALF_UP, Context, Decimal, localcontext

RESOLUTIONS = {
    "unit": Decimal("1"),
    "quarter": Decimal("0.25"),
    "hundred": Decimal("100"),
    "thousand": Decimal("1000"),
    "tenth": Decimal("0.1"),
    "hundredth": Decimal("0.01"),
    "thousandth": Decimal("0.001"),
    "humidity": Decimal("0.004"),
}
MAX_MANTISSA = 10**19 - 1
INT32_MIN, INT32_MAX_VALID = -(2**31), 2**31 - 1 - 3  # the top three raw values are sentinels

# The cases every path must get right, then random ones.
FIXED = [1.005, 2.675, 0.125, 1.115, -1.005, -2.675, -0.125, 1.0000000000000002, 1e-7, -1e-7,
         -0.001, 0.0, -0.0, 0.5, -0.5, 1.5, 2.5, 0.49999999999999994, 0.045, 1.45, 8.345,
         4503599627370497.0, 9007199254740993.0, 1e19, 9.999999999999998e18, 1.2345678901234567e18,
         123456789012345678.0, 0.30000000000000004, 5e-324, 2.2250738585072014e-308,
         1.7976931348623157e308, 1e-20, 5e-20, 1e-19, 179.999999999, 89.99999999999999,
         180.00000000000003, 21.31198, -157.88972, 363.15, 0.035, 1.0005, 10.9999999999]


def shortest(x):
    return Decimal(repr(x))


def rounded(d, places):
    with localcontext(Context(prec=1000)):
        return d.quantize(Decimal(10) ** -places, rounding=ROUND_HALF_UP)


def signed(value, negative):
    return ("-" if negative and value != 0 else "") + str(value)


def dec_row(x, places):
    q = rounded(shortest(x), places)
    with localcontext(Context(prec=1000)):
        m = int(abs(q).scaleb(places))
    return "!" if m > MAX_MANTISSA else signed(m, x < 0)


def n2k_row(x, name):
    with localcontext(Context(prec=1000)):
        raw = (shortest(x) / RESOLUTIONS[name]).quantize(Decimal(1), rounding=ROUND_HALF_UP)
    raw = int(raw)
    return "!" if raw < INT32_MIN or raw > INT32_MAX_VALID else str(raw)


def lon_row(x, places):
    with localcontext(Context(prec=1000)):
        total = int(abs(rounded(shortest(x) * 60, places)).scaleb(places))
    return "!" if total > 180 * 60 * 10**places else signed(total, x < 0)


def halfway(rng, places, integer_digits):
    """A decimal with places + 1 fraction digits, the last a 5: a tie at `places`."""
    whole = rng.randrange(10**integer_digits)
    frac = "".join(rng.choice("0123456789") for _ in range(places)) + "5"
    sign = rng.choice(["", "-"])
    return float(f"{sign}{whole}.{frac}")


def table():
    rng = random.Random(20261127)
    rows = []

    def add(x, kind, param, expected):
        rows.append(f"{x.hex()} {x!r} {kind} {param} {expected}")

    values = list(FIXED)
    for _ in range(150):  # ties at some places, from 1 to 15 significant digits
        values.append(halfway(rng, rng.randrange(0, 8), rng.randrange(0, 7)))
    for _ in range(150):  # any digits, magnitudes 1e-21 .. 1e20
        values.append(rng.choice([-1, 1]) * rng.random() * 10.0 ** rng.randrange(-21, 21))
    for _ in range(50):  # any double at all
        x = float.fromhex("0x1.%013xp%+d" % (rng.getrandbits(52), rng.randrange(-1074, 1024)))
        values.append(rng.choice([-1, 1]) * x)

    for x in values:
        for places in sorted({0, 1, 2, 3, rng.randrange(0, 20)}):
            add(x, "dec", places, dec_row(x, places))
        for name in RESOLUTIONS:
            add(x, "n2k", name, n2k_row(x, name))
    # Positions: degrees with places + 2 fraction digits are ties at `places` minute digits (x 60
    # leaves places + 1 digits) once in ten.
    for _ in range(400):
        places = rng.randrange(1, 13)
        digits = places + 2
        whole = rng.randrange(0, 181)
        frac = rng.randrange(10**digits)
        x = float(f"{rng.choice(['', '-'])}{whole}.{frac:0{digits}d}")
        add(x, "lon", places, lon_row(x, places))
    for x in FIXED:
        for places in (1, 2, 4, 12):
            add(x, "lon", places, lon_row(x, places))
    return "\n".join(rows) + "\n"


def main():
    args = sys.argv[1:]
    write = args[:1] == ["--write"]
    path = args[-1]
    text = table()
    if write:
        with open(path, "w") as f:
            f.write(text)
        return 0
    with open(path) as f:
        have = f.read()
    if have != text:
        old, new = have.splitlines(), text.splitlines()
        for i, (a, b) in enumerate(zip(old, new)):
            if a != b:
                print(f"line {i + 1}: table has\n  {a}\nPython computes\n  {b}", file=sys.stderr)
                break
        else:
            print(f"table has {len(old)} lines, Python computes {len(new)}", file=sys.stderr)
        print("regenerate with: rounding_table.py --write " + path, file=sys.stderr)
        return 1
    print(f"{len(text.splitlines())} rows agree with Python's decimal module")
    return 0


if __name__ == "__main__":
    sys.exit(main())
