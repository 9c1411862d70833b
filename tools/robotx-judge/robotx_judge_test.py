#!/usr/bin/env python3
# SPDX-License-Identifier: BSL-1.0
"""seawire-robotx-judge over loopback: teams written here connect and report.

    robotx_judge_test.py JUDGE CASE      CASE: live, text, usage, heartbeat, reasons, dropped,
                                        flood, summaries
"""

import json
import re
import signal
import socket
import subprocess
import os
import sys
import threading
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from harness import Server, check, refusals, run_case, seal

JUDGE, CASE = sys.argv[1], sys.argv[2]
HEARTBEAT = sys.argv[3] if len(sys.argv) > 3 else None  # the heartbeat example, for its case


def hst_now():
    t = time.gmtime(time.time() - 10 * 3600)
    return time.strftime("%d%m%y", t), time.strftime("%H%M%S", t)


def hrb(team="AUVSI"):
    d, t = hst_now()
    return seal("RXHRB,%s,%s,21.31198,N,157.88972,W,%s,2,1" % (d, t, team))


class Judge(Server):
    def __init__(self, *args, listen="127.0.0.1:0"):
        super().__init__(JUDGE, *args, listen=listen, stdout=subprocess.PIPE)
        self.out = []  # (arrival time, line)
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        for line in self.proc.stdout:
            self.out.append((time.monotonic(), line.decode().rstrip("\n")))

    def stop(self, sig=signal.SIGTERM):
        rc = super().stop(sig)
        time.sleep(0.2)
        return rc

    def findings(self):
        objs = [json.loads(l) for _, l in self.out]
        return [o for o in objs if o["type"] == "finding"]


def team_socket(port):
    s = socket.create_connection(("127.0.0.1", port), timeout=10)
    return s


def case_live():
    j = Judge("--team", "AUVSI", "--report", "json", "--gap-limit", "1.5")
    a = team_socket(j.port)
    a.sendall(hrb().encode())
    time.sleep(1.0)
    a.sendall(hrb().encode())
    d, t = hst_now()
    cod = seal("RXCOD,%s,%s,AUVSI,RGB" % (d, t))
    a.sendall(cod.encode())
    a.settimeout(10)
    echo = a.recv(200).decode()
    check(echo == cod, "RXCOD echoed back as sent: %r, sent %r" % (echo, cod))
    gat = seal("RXGAT,%s,%s,AUVSI,1,2,Y,RGB" % (d, t))
    # A lower-case checksum shows only with a hex letter in it: pick an RXDOK that has one.
    dok = next(x for x in (seal("RXDOK,%s,%s,AUVSI,%s,%s" % (d, t, c, shape), lower=True,
                                    ending="\n")
                           for c in "RGB" for shape in ("CRUCI", "TRIAN", "CIRCL"))
               if re.search(r"[a-f]", x[-3:-1]))
    a.sendall((gat + gat + dok).encode())  # the same report twice within a second
    time.sleep(1.0)
    a.sendall(hrb("ROBOT").encode())  # another team's id on this link
    a.sendall(b"$RXHRB,garbage*00\r\n" + bytes(range(128, 256)) + b"\r\n")
    sent_last = time.monotonic()
    time.sleep(2.6)  # no heartbeat: the gap is reported while it is open
    gap = [(at, l) for at, l in j.out if '"rule":"heartbeat_gap"' in l]
    check(gap and gap[0][0] - sent_last < 2.4,
          "heartbeat gap reported live: %r" % [l for _, l in j.out][-5:])
    b = team_socket(j.port)
    b.sendall(hrb("ROBOT").encode() + b"$RXHRB,1112")  # ... and gone mid-sentence
    b.close()
    time.sleep(0.3)
    a.close()
    time.sleep(0.3)
    check(j.stop() == 0, "exit 0 on SIGTERM")
    rules = [f["rule"] for f in j.findings()]
    print("findings:", rules)
    for rule in ("rate", "checksum_lowercase", "line_ending", "team_mismatch", "heartbeat_gap",
                 "checksum"):
        check(rule in rules, "finding %s reported: %r" % (rule, rules))
    mismatch = [f for f in j.findings() if f["rule"] == "team_mismatch"][0]
    check(mismatch["address"] == "RXHRB" and mismatch["field_name"] == "team_id" and
          mismatch["input"].startswith("$RXHRB"), "the finding names field and line: %r" % mismatch)
    summary = json.loads(j.out[-1][1])
    check(summary["type"] == "summary", "a summary last")
    teams = {t["team"]: t for t in summary["teams"]}
    check(set(teams) == {"AUVSI", "ROBOT"}, "a summary per team: %r" % list(teams))
    auvsi = teams.get("AUVSI", {})
    check(auvsi.get("reports", {}).get("RXHRB") == 3 and auvsi.get("reports", {}).get("RXCOD") == 1,
          "AUVSI's accepted reports counted: %r" % auvsi)
    check(auvsi.get("findings", {}).get("rate", 0) >= 1, "AUVSI's rate finding summed")
    log = j.log()
    check(log.count(" connected (") == 2 and log.count("disconnected:") == 2,
          "connection events logged:\n" + log)


def case_text():
    j = Judge("--duration", "1.5")
    a = team_socket(j.port)
    a.sendall(hrb().encode() + seal("RXHRB,111221,161229,21.31198,N,157.88972,W,AUVSI,7,1").encode())
    # A report ended by a lone CR is judged as it arrives, not when the next bytes come.
    a.sendall(hrb().encode().replace(b"\r\n", b"\r"))
    time.sleep(0.5)
    check(any("line_ending" in l for _, l in j.out), "a CR-ended report judged at once: %r"
          % [l for _, l in j.out])
    rc = j.proc.wait(timeout=20)
    time.sleep(0.2)
    a.close()
    text = [l for _, l in j.out]
    check(rc == 0, "--duration ends the run with 0")
    check(any(re.search(r"client 1 127\.0\.0\.1:\d+ team AUVSI: field RXHRB field 8 \(system_mode\)", l)
              for l in text), "text finding names the field:\n" + "\n".join(text))
    check(text[-2].startswith("summary: 1 team(s)") and text[-1].startswith("  AUVSI: 1 connection(s), 3 lines, 2 accepted (RXHRB 2)"),
          "text summary:\n" + "\n".join(text))


def case_heartbeat():
    # The heartbeat example reports at 1 Hz, and reconnects when the judge goes away and back.
    j1 = Judge("--team", "AUVSI", "--report", "json")
    hb = subprocess.Popen([HEARTBEAT, "--connect", "127.0.0.1:%d" % j1.port, "5"],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    time.sleep(2.5)
    check(j1.stop() == 0, "first judge: exit 0")
    time.sleep(0.7)
    j2 = Judge("--team", "AUVSI", "--report", "json", listen="127.0.0.1:%d" % j1.port)
    out, err = hb.communicate(timeout=30)
    time.sleep(0.3)
    check(j2.stop() == 0, "second judge: exit 0")
    check(hb.returncode == 0, "the example ends after 5 heartbeats: %r" % err)
    check(err.decode().count("connected to") == 2, "it reconnected:\n" + err.decode())
    for n, j in (("first", j1), ("second", j2)):
        summary = json.loads(j.out[-1][1])
        hrb_count = summary["teams"][0]["reports"].get("RXHRB", 0) if summary["teams"] else 0
        check(hrb_count >= 1, "%s judge got heartbeats: %r" % (n, summary))
        bad = [f for f in j.findings() if f["rule"] not in ("heartbeat_gap",)]
        check(not bad, "%s judge: the heartbeats are clean: %r" % (n, bad))


def case_reasons():
    # A refused field is named for what it is, with what is wrong with its text.
    j = Judge("--duration", "1.5")
    a = team_socket(j.port)
    a.sendall(seal("RXHRB,111221,161229,21.31198,,-157.88972,W,AUVSI,2,1").encode())
    j.proc.wait(timeout=20)
    a.close()
    text = "\n".join(l for _, l in j.out)
    check("RXHRB field 4 (latitude's hemisphere letter): hemisphere letter is missing (blank)"
          in text, "the blank letter named and told:\n" + text)
    check("RXHRB field 5 (longitude): a sign is not allowed: the hemisphere letter carries it"
          in text, "the sign told:\n" + text)
    j = Judge("--duration", "1.5", "--report", "json")
    a = team_socket(j.port)
    a.sendall(seal("RXHRB,111221,161229,21.31198,,-157.88972,W,AUVSI,2,1").encode())
    j.proc.wait(timeout=20)
    a.close()
    fields = {f.get("field"): f for f in j.findings()}
    letter, number = fields.get(4, {}), fields.get(5, {})
    check(letter.get("field_name") == "latitude" and letter.get("field_part") == "hemisphere letter"
          and letter.get("error") == "hemisphere letter is missing (blank)",
          "JSON: the blank letter: %r" % letter)
    check(number.get("field_name") == "longitude" and "field_part" not in number and
          number.get("error") == "a sign is not allowed: the hemisphere letter carries it",
          "JSON: the sign: %r" % number)


def case_dropped():
    # Reports the stream reader drops are judged too: each is a framing finding, with why and
    # what was sent, and counted in the summary.
    bad = [
        (hrb().replace(",AUVSI,", ",AUV\tI,").encode(), "bad_character", "0x09"),
        (hrb().encode().replace(b"AUVSI", b"AUV\xc3\xa9"), "bad_character", "0xC3"),
        (hrb().encode().replace(b"AUVSI", b"AUV\x00I"), "bad_character", "0x00"),
        (seal("RXHRB," + "1" * 600).encode(), "too_long", "longer than 512 bytes"),
        (hrb().encode()[1:], "missing_start", "no '$' first"),
    ]
    for report in ("json", "text"):
        j = Judge("--team", "AUVSI", "--report", report, "--duration", "2", "--gap-limit", "10")
        a = team_socket(j.port)
        a.sendall(hrb().encode() + b"".join(b for b, _, _ in bad) + b"\r\n\n")
        j.proc.wait(timeout=20)
        time.sleep(0.3)
        a.close()
        if report == "json":
            found = [f for f in j.findings() if f["rule"] == "framing"]
            if not check(len(found) == len(bad), "one framing finding per dropped report: %r" % found):
                continue
            for f, (_, ec, why) in zip(found, bad):
                check(why in f.get("error", "") and f.get("field") == 0 and f.get("input"),
                      "%s: %r" % (why, f))
            check(found[0].get("address") == "RXHRB", "the address when it shows: %r" % found[0])
            check("\\x00" in found[2]["input"], "a NUL shown escaped: %r" % found[2]["input"])
            check(found[3]["input"].endswith("..."), "a long report shown cut: %r" % found[3])
            summary = json.loads(j.out[-1][1])
            team = summary["teams"][0]
            check(team["findings"].get("framing") == len(bad) and team["lines"] == 1 + len(bad),
                  "the summary counts them: %r" % team)
        else:
            text = [l for _, l in j.out]
            check(sum(re.search(r"team AUVSI: framing\b", l) is not None for l in text) == len(bad),
                  "text: %r" % text)
            check(text[-1].endswith("findings: framing %d" % len(bad)),
                  "not 'findings: none': %r" % text[-1])


def case_flood():
    # Heartbeats as fast as the network carries them: every one after the first in a second
    # breaks the rate rule, and the findings printed keep to 20 a second, the rest counted.
    j = Judge("--team", "AUVSI", "--report", "json")
    a = team_socket(j.port)
    block = hrb().encode() * 2000
    start = time.monotonic()
    sent = 0
    while time.monotonic() - start < 2:
        a.sendall(block)
        sent += 2000
    a.close()
    check(j.wait_log("disconnected: end of stream", timeout=60), "every heartbeat read")
    elapsed = time.monotonic() - start
    check(j.stop() == 0, "exit 0")
    objs = [json.loads(l) for _, l in j.out]
    out_bytes = sum(len(l) + 1 for _, l in j.out)
    printed = sum(1 for o in objs if o["type"] == "finding" and o["rule"] == "rate")
    noted = sum(o["count"] for o in objs if o["type"] == "suppressed" and o["what"] == "rate findings")
    summary = objs[-1]
    total = summary["teams"][0]["findings"].get("rate", 0)
    print("flood: %d heartbeats in %.1f s; %d rate findings printed, %d suppressed; %.0f bytes/s"
          % (sent, elapsed, printed, noted, out_bytes / elapsed), file=sys.stderr)
    check(total == sent - 1, "each heartbeat but the first is too soon: %r" % summary)
    check(printed + noted == total, "printed %d + suppressed %d == %d" % (printed, noted, total))
    check(printed <= 20 * (elapsed + 2), "at most 20 a second: %d in %.1f s" % (printed, elapsed))


def case_summaries():
    # The summary is bounded: 100 teams by name, the rest together, each team's last 10 peers.
    j = Judge("--report", "json")
    for _ in range(12):
        s = team_socket(j.port)
        s.sendall(hrb("AUVSI").encode())
        s.close()
    for n in range(115):
        s = team_socket(j.port)
        s.sendall(hrb("T%04d" % n).encode())
        s.close()
    check(j.wait_log(r"client 127 \S+ disconnected", timeout=30), "127 connections closed")
    time.sleep(0.3)
    check(j.stop() == 0, "exit 0")
    teams = {t["team"]: t for t in json.loads(j.out[-1][1])["teams"]}
    check(len(teams) == 101, "100 teams and the rest: %d" % len(teams))
    check(teams.get("(other teams)", {}).get("connections") == 16,
          "the 16 teams after the first 100 summed: %r" % teams.get("(other teams)"))
    auvsi = teams.get("AUVSI", {})
    check(auvsi.get("connections") == 12 and len(auvsi.get("peers", [])) == 10,
          "12 connections, the last 10 peers: %r" % auvsi)
    check(sum(t["connections"] for t in teams.values()) == 127, "every connection counted")


def case_usage():
    refusals(JUDGE, b"--team",
             ((["--listen", "nowhere"], b"expected ADDR:PORT"),
              (["--team", "AB", "--listen", "127.0.0.1:0"], b"5 characters"),
              (["--report", "xml", "--listen", "127.0.0.1:0"], b"report")))


run_case(globals(), CASE)
