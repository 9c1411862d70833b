#!/usr/bin/env python3
# SPDX-License-Identifier: BSL-1.0
"""Writes the sample logs in examples/data/ (run from anywhere; deterministic).

One realistic log per protocol family, CR LF, canonical (uppercase checksums), built around the
verified vectors with generated lines around them (plausible motion, correct
checksums), plus bad.nmea, a few lines that must be rejected, with good lines between them.
The programs' tests (tools/decode/ and tools/encode/) know these files line by line: regenerate, then update
the expectations there.
"""

import math
import os
import random
import struct
import zlib
from functools import reduce

HERE = os.path.dirname(os.path.abspath(__file__))
rng = random.Random(20181210)


def seal(body):
    cs = reduce(lambda a, c: a ^ ord(c), body, 0)
    return "$%s*%02X" % (body, cs)


def write(name, lines):
    with open(os.path.join(HERE, name), "wb") as f:
        for line in lines:
            if isinstance(line, bytes):  # a binary frame: no line ending of its own
                f.write(line)
            else:
                f.write(line.encode("latin-1") + b"\r\n")


def hms(t, places):
    """Seconds of the day -> hhmmss.f with `places` fraction digits."""
    scale = 10**places
    ticks = int(round(t * scale))
    whole, frac = divmod(ticks, scale)
    s = "%02d%02d%02d" % (whole // 3600, whole // 60 % 60, whole % 60)
    return s + ("." + str(frac).zfill(places) if places else "")


def nmea_angle(deg, places, width, letters, pad):
    """An angle as the wire writes it: degrees (`width` digits when padded) and minutes with
    `places` fraction digits, then the hemisphere letter (letters[0] when positive)."""
    hemi = letters[0] if deg >= 0 else letters[1]
    deg = abs(deg)
    d = int(deg)
    minutes = ("%0" + str(3 + places) + "." + str(places) + "f")
    mtxt = minutes % ((deg - d) * 60)
    if mtxt.startswith("60"):  # rounded up to a whole degree
        d, mtxt = d + 1, minutes % 0
    return ("%0*d" % (width, d) if pad else "%d" % d) + mtxt, hemi


def nmea_lat(deg, places, pad=True):
    return nmea_angle(deg, places, 2, "NS", pad)


def nmea_lon(deg, places, pad=True):
    return nmea_angle(deg, places, 3, "EW", pad)


def f(x, places):
    s = ("%." + str(places) + "f") % x
    return "0" + s[2:] if s.startswith("-0") and float(s) == 0 else s


def move(lat, lon, heading_deg, dist_m):
    dn = dist_m * math.cos(math.radians(heading_deg))
    de = dist_m * math.sin(math.radians(heading_deg))
    return lat + dn / 111_320.0, lon + de / (111_320.0 * math.cos(math.radians(lat)))


# ------------------------------------------------------------------------------------------------
# Kingfisher: a 2014 capture's real lines, then the vehicle driving south-west at ~1.2 m/s under
# PYDIR/PYDEV commands from its payload; CPRBS in the vehicle's 5-field form, CPIMU with 7 fields,
# unpadded longitude degrees as the vehicle writes them.


def kingfisher():
    out = [
        "$CPIMU,164958.858,-0.061035,-0.000097,-0.061035,-0.026916,0.104533,-0.932172*57",
        "$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A*70",
        "$GPGGA,164959.00,4221.71114,N,07105.44878,W,1,06,2.80,46.6,M,-33.2,M,,*5C",
        "$CPNVG,164959.034,4221.711142,N,7105.44878,W,1,0,0,234.32964,-6.796959,-1.706798,"
        "164959.006*78",
        "$CPNVR,164959.063,0.02941,-0.068552,0,0.060938,0,-0.061132*59",
        "$CPRCM,164959.065,0,234.326694,-1.655603,-6.628557,164959.060*62",
        "$PYDIR,45,55*57",
        "$CPALT,164959.100,1*62",
    ]
    lat = 42 + 21.711142 / 60
    lon = -(71 + 5.44878 / 60)
    heading = 234.32964
    speed = 0.2
    for k in range(1, 11):
        t = 16 * 3600 + 49 * 60 + 59 + k
        speed = min(1.3, speed + 0.15)
        heading += rng.uniform(-0.8, 0.8)
        lat, lon = move(lat, lon, heading, speed)
        la, ns = nmea_lat(lat, 6)
        lo, ew = nmea_lon(lon, 5, pad=False)
        roll, pitch = rng.uniform(-7, -5), rng.uniform(-2, -1)
        out.append(seal("CPIMU,%s,%s,%s,%s,%s,%s,%s" % (
            hms(t - 0.176, 3), f(rng.uniform(-0.1, 0.1), 6), f(rng.uniform(-0.01, 0.01), 6),
            f(rng.uniform(-0.2, 0.2), 6), f(rng.uniform(-0.1, 0.1), 6),
            f(rng.uniform(0.05, 0.15), 6), f(rng.uniform(-0.95, -0.9), 6))))
        gla, gns = nmea_lat(lat, 5)
        glo, gew = nmea_lon(lon, 5)
        knots = speed * 3600 / 1852
        out.append(seal("GPRMC,%s,A,%s,%s,%s,%s,%s,%s,311214,,,A" % (
            hms(t, 2), gla, gns, glo, gew, f(knots, 3), f(heading % 360, 2))))
        out.append(seal("GPGGA,%s,%s,%s,%s,%s,1,%02d,%s,%s,M,-33.2,M,," % (
            hms(t, 2), gla, gns, glo, gew, 6 + k % 3, f(2.8 - 0.05 * k, 2),
            f(46.6 + rng.uniform(-0.3, 0.3), 1))))
        out.append(seal("CPNVG,%s,%s,%s,%s,%s,1,0,0,%s,%s,%s,%s" % (
            hms(t + 0.034, 3), la, ns, lo, ew, f(heading % 360, 5), f(roll, 6), f(pitch, 6),
            hms(t + 0.006, 3))))
        ve = speed * math.sin(math.radians(heading))
        vn = speed * math.cos(math.radians(heading))
        out.append(seal("CPNVR,%s,%s,%s,0,%s,0,%s" % (
            hms(t + 0.063, 3), f(ve, 5), f(vn, 6), f(rng.uniform(-0.1, 0.1), 6),
            f(rng.uniform(-0.2, 0.2), 6))))
        out.append(seal("CPRCM,%s,0,%s,%s,%s,%s" % (
            hms(t + 0.065, 3), f((heading + rng.uniform(-0.1, 0.1)) % 360, 6), f(pitch, 6),
            f(roll, 6), hms(t + 0.060, 3))))
        if k % 5 == 0:
            v = 15.121597 - 0.0021 * k
            out.append(seal("CPRBS,%s,%s,%s,%s,0" % (hms(t + 0.1, 3), f(v, 6), f(v - 0.004, 6),
                                                      f(v + 0.003, 6))))
        if k == 3:
            out.append("$PYDEV,90,1.5*7D")
        elif k == 6:
            out.append(seal("PYDEV,225.5,1.2"))
        elif k == 8:
            out.append("$PYDEP,-10,50*71")
        else:
            out.append(seal("PYDIR,%s,%s" % (f(40 + k, 1), f(55 - k / 2, 1))))
    out.append("$PYCLT,0*4E")
    out.append(seal("CPALT,165009.200,0"))
    out.append("$PYDIR,0,0*56")
    return out


# ------------------------------------------------------------------------------------------------
# Sandshark: a payload session on a training vehicle. Version exchange, acks on, all status on,
# the mission starting, the backseat getting control and steering with BPRMB (re-sent every 2-3 s)
# while the vehicle dives, then an abort and the vehicle taking control back.


def sandshark():
    out = []
    t = 23 * 3600 + 11 * 60 + 20.0

    def ts(dt=0.0, places=2):
        return hms(t + dt, places)

    out.append(seal("BPVER,%s,1.0" % ts()))
    out.append(seal("BFVER,%s,1.0" % ts(0.12)))
    t += 1
    out.append("$BPLOG,ACK,ON*1E")
    out.append(seal("BFACK,%s,LOG,,,2,0," % ts(0.05)))
    out.append("$BPLOG,ALL,ON*16")
    out.append(seal("BFACK,%s,LOG,,,2,0," % ts(0.09)))
    out.append(seal("BFMIS,%s,dive1.xml,Ready,Waiting for start" % ts(0.3)))
    lat, lon = 42.3, -71.1
    depth = 0.0
    heading = 45.0
    last_rmb = None
    for k in range(12):
        t = 23 * 3600 + 11 * 60 + 22 + k * 1.0 + 0.55 * (k > 8)
        if k == 1:
            out.append(seal("BFMIS,%s,dive1.xml,Running /var/log/mission_12," % ts(0.1)))
            out.append(seal("BFCTL,%s,1" % ts(0.2)))
        if k == 9:
            out.append(
                "$BFNVG,231131.55,4218.000000,N,07106.000000,W,0,10.0,1.0,45.0,0.0,0.0,231131.55*62")
        else:
            lat, lon = move(lat, lon, heading, 1.5)
            la, ns = nmea_lat(lat, 6)
            lo, ew = nmea_lon(lon, 6)
            out.append(seal("BFNVG,%s,%s,%s,%s,%s,0,%s,%s,%s,%s,%s,%s" % (
                ts(), la, ns, lo, ew, f(12.0 - depth, 1), f(depth, 1), f(heading, 1),
                f(rng.uniform(-1, 1), 1), f(-5.0 if depth < 2 else 0.0, 1), ts(-0.02))))
        out.append(seal("BFNVR,%s,%s,%s,%s,0.00,0.00,%s" % (
            ts(0.01), f(1.5 * math.sin(math.radians(heading)), 2),
            f(1.5 * math.cos(math.radians(heading)), 2), f(0.2 if depth < 2 else 0.0, 2),
            f(rng.uniform(-0.5, 0.5), 2))))
        depth = min(2.0, depth + 0.25)
        if k in (2, 5, 8):
            rmb_t = ts(0.3)
            out.append(seal("BPRMB,%s,%s,2.0,0,1.5,1,0" % (rmb_t, f(heading + 10, 1))))
            out.append(seal("BFACK,%s,RMB,%s,,2,0," % (ts(0.34, 3), rmb_t)))
            heading += 10
            last_rmb = rmb_t
        if k == 4:
            out.append("$BPSTS,231133.12,1,BWSI Autonomy OK*46")
        if k == 10:
            out.append(seal("BPSTS,%s,1,BWSI Autonomy OK" % ts(0.2)))
    assert last_rmb
    out.append("$BPRMB,231137.32,,,,750,0,1*7A")
    out.append(seal("BFACK,231137.360,RMB,231137.32,,2,0,"))
    out.append("$BPRMB,231204.72,-15,,,750,0,1*54")
    out.append(seal("BFACK,231204.760,RMB,231204.72,,3,0,processing"))
    out.append(seal("BFACK,231205.100,RMB,231204.72,,2,0"))
    out.append(seal("BPABT,231206.00,leak detected in the payload can,1"))
    out.append(seal("BFACK,231206.050,ABT,231206.00,,2,0,"))
    out.append(seal("BFCTL,231206.200,0"))
    out.append(seal("BFMIS,231206.300,dive1.xml,Aborted,Payload requested abort"))
    out.append(seal("BPLOG,NVR,OFF"))
    out.append(seal("BFACK,231207.010,LOG,,,2,0,"))
    out.append(seal("BFSHT,231300.00"))
    return out


# ------------------------------------------------------------------------------------------------
# RobotX 2018: the spec's five reports, then a team's heartbeat at 1 Hz while its vehicle crosses
# the course (positions moving east), the task reports once each, and a 2022-style heartbeat.


def robotx():
    out = [
        "$RXHRB,101218,161229,21.31198,N,157.88972,W,AUVSI,2,1*06",
        "$RXGAT,101218,161229,AUVSI,1,2,Y,RGB*25",
        "$RXCOD,101218,161229,AUVSI,RGB*49",
        "$RXDOK,101218,161229,AUVSI,R,TRIAN*28",
        "$RXDEL,101218,161229,AUVSI,R,CIRCL*32",
    ]
    lat, lon = 21.31198, -157.88972
    for k in range(1, 26):
        t = 16 * 3600 + 12 * 60 + 29 + k
        lat, lon = move(lat, lon, 80 + 10 * math.sin(k / 4), 1.8)
        auv = "1" if k < 15 else ("2" if k < 22 else "3")
        out.append(seal("RXHRB,101218,%s,%s,%s,%s,%s,AUVSI,2,%s" % (
            hms(t, 0), f(abs(lat), 5), "N" if lat >= 0 else "S", f(abs(lon), 5),
            "E" if lon >= 0 else "W", auv)))
        if k == 6:
            out.append(seal("RXGAT,101218,%s,AUVSI,2,3,N," % hms(t, 0)))
        if k == 11:
            out.append(seal("RXCOD,101218,%s,AUVSI,GBR" % hms(t, 0)))
        if k == 17:
            out.append(seal("RXDOK,101218,%s,AUVSI,B,CRUC" % hms(t, 0)))
        if k == 23:
            out.append(seal("RXDEL,101218,%s,AUVSI,G,CRUCI" % hms(t, 0)))
    out.append("$RXHRB,111221,161229,21.31198,N,157.88972,W,ROBOT,2,1*11")
    return out


# ------------------------------------------------------------------------------------------------
# ANELLO: what a USV computer sends the INS for speed aiding (VHW, VBW, RPM, RSA, VWR at ~2 Hz,
# PAPGPSCTRL at the start and when GPS is lost), and the RMC the INS sends back at 1 Hz.


def anello():
    out = ["$PAPGPSCTRL,1*11", "$VMVBW,0.0,0.0,A,0.0,0.0,A*58"]
    lat, lon = 32.828671, -117.229926
    heading = 89.0
    speed = 0.0
    for k in range(20):
        t = 15 * 3600 + 42 * 60 + 58 + k * 0.5
        speed = min(2.4, speed + 0.15)
        heading += rng.uniform(-1.0, 1.0)
        knots = speed * 3600 / 1852
        out.append(seal("VWVHW,%s,T,,M,%s,N,%s,K" % (f(heading % 360, 1), f(knots, 2),
                                                       f(speed * 3.6, 2))))
        out.append(seal("VWVBW,%s,%s,A,%s,%s,A" % (f(knots, 2), f(rng.uniform(-0.05, 0.05), 2),
                                                    f(knots * 1.02, 2),
                                                    f(rng.uniform(-0.1, 0.1), 2))))
        rpm = 300 + 700 * speed / 2.4
        out.append(seal("IIRPM,S,1,%s,%s,A" % (f(rpm, 1), f(60.0, 1))))
        out.append(seal("IIRPM,S,2,%s,%s,A" % (f(rpm + rng.uniform(-5, 5), 1), f(60.0, 1))))
        rudder = rng.uniform(-3, 3)
        out.append(seal("IIRSA,%s,A,,V" % f(rudder, 1)))
        if k % 2 == 0:
            out.append(seal("WIVWR,%s,%s,%s,N,%s,M,%s,K" % (
                f(35 + rng.uniform(-5, 5), 1), "R" if k % 4 else "L", f(11.7, 1), f(6.0, 1),
                f(21.6, 1))))
            lat, lon = move(lat, lon, heading, speed)
            la, ns = nmea_lat(lat, 5)
            lo, ew = nmea_lon(lon, 5)
            out.append(seal("GNRMC,%s,A,%s,%s,%s,%s,%s,%s,030724,,,A" % (
                hms(t, 2), la, ns, lo, ew, f(knots, 3), f(heading % 360, 2))))
        if k == 12:
            out.append("$PAPGPSCTRL,0*10")
        if k == 16:
            out.append(seal("PAPGPSCTRL,1"))
    return out


# ------------------------------------------------------------------------------------------------
# ANELLO, one RS-232 input carrying both: the NMEA speed aiding above and 0xAB00 binary sensor
# frames at 4 Hz (the spec's example frame first), back to back with no line breaks of their own.
# Some payloads hold 0x0A, 0x0D and '$' bytes, which are data inside a frame.

SEED_FRAME = bytes.fromhex(
    "AB0000308EF7F176005901F4ECFFF903369A0000FFFF00000190794363D0000001E07FFFFFFFFFFF000000000002"
    "006C0003005AFFFFFFFF")


def frame(heading, lat, lon, sog, cog, t_ms, alt, hdop, fix, motor, rudder, stw, wind):
    payload = struct.pack(
        ">HiiHHQiiBBbbHHHHHhH", heading, round(lat * 1e6), round(lon * 1e6), round(sog * 10), cog,
        t_ms, round(alt * 10), 0x7FFFFFFF, hdop, fix, motor, rudder, round(stw * 10),
        round(wind[0] * 10), wind[1], round(wind[2] * 10), wind[3], 0x7FFF, 0xFFFF)
    assert len(payload) == 48
    return struct.pack(">HHI", 0xAB00, 48, zlib.crc32(payload)) + payload


def anello_mixed():
    nmea = anello()
    out = [nmea[0], SEED_FRAME]
    lat, lon = 32.828671, -117.229926
    t_ms = 1720021378000
    speed = 0.0
    for k, line in enumerate(nmea[1:]):
        out.append(line)
        if k % 3 == 2:
            speed = min(2.4, speed + 0.1)
            lat, lon = move(lat, lon, 89, speed / 4)
            t_ms += 250
            out.append(frame(89 + k % 3, lat, lon, speed, 89, t_ms, 48.0 + k / 100, 9, 1,
                             10 + k % 40, (k % 7) - 3, speed * 0.97, (5.0, 108, 6.3, 90)))
    # A payload holding '$' (heading 36 = 00 24), CR (course 13 = 00 0D) and LF (speed through
    # water 1.0 m/s = 00 0A) bytes: the reader must keep them inside the frame.
    out.append(frame(36, 10.487844, -0.000013, 1.0, 13, t_ms + 250, 36.0, 13, 1, 36, 10, 1.0,
                     (1.0, 10, 1.0, 13)))
    out.append(seal("PAPGPSCTRL,1"))
    return out


# ------------------------------------------------------------------------------------------------
# Standard sentences from a boat's NMEA 0183 bus: a GPS receiver (RMC in the 2.2, 2.3 and 4.1
# forms, GGA, and GSA/GSV, which seawire does not decode), engine, rudder, log and wind sensors
# from several talkers, a gyrocompass (HDT, blank while it settles), and a receiver starting up
# without a fix.


def standard():
    out = [
        seal("GPRMC,,V,,,,,,,,,,N"),
        seal("GPGGA,,,,,,0,00,99.99,,M,,M,,"),
        seal("GPRMC,120000.00,V,,,,,,,010519,,,N"),
    ]
    lat, lon = 47.6062, -122.3321
    heading = 310.0
    for k in range(12):
        t = 12 * 3600 + 1 + k
        lat, lon = move(lat, lon, heading, 3.1)
        la, ns = nmea_lat(lat, 5)
        lo, ew = nmea_lon(lon, 5)
        knots = 3.1 * 3600 / 1852
        if k % 3 == 0:  # NMEA 2.2: 11 fields, magnetic variation
            out.append(seal("GPRMC,%s,A,%s,%s,%s,%s,%s,%s,010519,15.3,E" % (
                hms(t, 2), la, ns, lo, ew, f(knots, 1), f(heading, 1))))
        elif k % 3 == 1:  # NMEA 2.3: mode indicator
            out.append(seal("GPRMC,%s,A,%s,%s,%s,%s,%s,%s,010519,,,D" % (
                hms(t, 2), la, ns, lo, ew, f(knots, 3), f(heading, 2))))
        else:  # NMEA 4.1: navigational status, from a multi-constellation receiver
            out.append(seal("GNRMC,%s,A,%s,%s,%s,%s,%s,%s,010519,,,A,V" % (
                hms(t, 2), la, ns, lo, ew, f(knots, 3), f(heading, 2))))
        out.append(seal("GPGGA,%s,%s,%s,%s,%s,2,%02d,%s,%s,M,-19.4,M,%s,0131" % (
            hms(t, 2), la, ns, lo, ew, 9 + k % 2, f(0.9 + 0.01 * k, 2), f(12.3 + 0.1 * k, 1),
            f(2.0 + k % 5, 1))))
        if k % 4 == 0:
            out.append(seal("GPGSA,A,3,04,05,,09,12,,,24,,,,,2.5,1.3,2.1"))
            out.append(seal("GPGSV,2,1,08,01,40,083,46,02,17,308,41,12,07,344,39,14,22,228,45"))
        out.append(seal("IIVHW,%s,T,%s,M,%s,N,%s,K" % (f(heading, 1), f(heading - 15.3, 1),
                                                       f(knots - 0.2, 2), f(3.1 * 3.6 - 0.4, 2))))
        out.append(seal("VWVBW,%s,%s,A,%s,%s,A,%s,A,%s,A" % (
            f(knots - 0.2, 2), f(0.05, 2), f(knots, 2), f(-0.03, 2), f(0.01, 2), f(0.0, 2))))
        out.append(seal("ERRPM,E,0,%s,,A" % f(1850 + 10 * k, 0)))
        out.append(seal("AGRSA,%s,A,%s,A" % (f(-2.5 + 0.5 * k, 1), f(-2.4 + 0.5 * k, 1))))
        if k % 2 == 0:
            out.append(seal("WIVWR,%s,L,%s,N,%s,M,%s,K" % (
                f(42.0 + k, 1), f(14.2, 1), f(7.3, 1), f(26.3, 1))))
        elif k == 1:
            out.append(seal("HEHDT,,T"))
        else:
            out.append(seal("HEHDT,%s,T" % f(heading - 0.42 + 0.07 * k, 2)))
    return out


# ------------------------------------------------------------------------------------------------
# Bad on purpose. Each rejected line is commented in tools/decode/programs_test.sh.


def bad():
    good = seal("GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A")
    nvg_61 = seal("CPNVG,081025.987,4261.81092,N,07106.84603,W,1,0,0,203.1,-3.4,4.5,081025.980")
    return [
        good,                                                                           # 1
        "$BFNVG,081025.987,4221.81092,N,07106.84603,W,1,45.3,20.1,203.1,-3.4,4.5,081025.980*5B",
        "$BFNVG,081025.987,4221.81092,N,07106.84603,W,1,45.3,20.1,203.1,-3.4,4.5,081025.980*5b",
        "$RXHRB,29620,1384,0,N,0,E,USYD_ROWBOT,3,1*5e",                                # 4
        nvg_61,                                                                         # 5
        "$GPRMC,164959.00,A,4221.71114,N,07105.44",                                     # 6
        "### vehicle rebooted ###",                                                     # 7
        seal("PAPGPSCTRL,5"),                                                           # 8
        seal("PYDIR,120,0"),                                                            # 9
        "$CPNVR,164959.063,0.029\x01" + "41,-0.068552,0,0.060938,0,-0.061132*59",       # 10
        seal("RXHRB,101218,161230,21.31200,N,157.88970,W,USYD_ROWBOT,2,1"),             # 11
        "$CPRCM,164959.065,0,234.3$PYDIR,45,55*57",                                     # 12
        seal("BPLOG,ACK,MAYBE"),                                                        # 13
        good,                                                                           # 14
    ]


if __name__ == "__main__":
    write("kingfisher.nmea", kingfisher())
    write("sandshark.nmea", sandshark())
    write("robotx.nmea", robotx())
    write("anello.nmea", anello())
    write("anello_mixed.nmea", anello_mixed())
    write("standard.nmea", standard())
    write("bad.nmea", bad())
