#!/usr/bin/env python3
# SPDX-License-Identifier: BSL-1.0
"""Turns seawire_bench's JSON output into the tables of bench/README.md.

    seawire_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \\
                  --benchmark_out=bench.json --benchmark_out_format=json
    python3 bench/report.py bench.json

Every figure is the median over the repetitions (or the single run without repetitions), in CPU
time per message, so that time the process spent descheduled on a busy machine is not counted.
Ratios divide by the baseline over the same corpus, measured in the same run.
"""

import json
import sys


# The order of the tables: the headline first, then each family and role.
FAMILIES = ["rmc_gga", "anello_inputs", "kingfisher_from_vehicle", "kingfisher_to_vehicle",
            "sandshark_from_vehicle", "sandshark_to_vehicle", "robotx_reports"]


def load(path):
    with open(path, encoding="utf-8") as f:
        data = json.load(f)
    runs = {}
    cvs = {}
    for b in data["benchmarks"]:
        aggregate = b.get("aggregate_name")
        name = b.get("run_name", b["name"])
        if aggregate == "cv":
            cvs[name] = b.get("time_per_msg", 0.0)
            continue
        if aggregate not in (None, "median"):
            continue
        if aggregate is None and name in runs:
            continue  # repetitions without aggregates: keep the first
        runs[name] = b
    return data.get("context", {}), runs, cvs


def ns_per_msg(b):
    return b["time_per_msg"] * 1e9


def mb_per_s(b):
    return b.get("bytes_per_second", 0.0) / 1e6


def allocs(b):
    return b.get("allocs_per_msg", 0.0)


def fmt_ns(v):
    return f"{v:,.1f}" if v < 100 else f"{v:,.0f}"


def ratio(a, b):
    return f"{a / b:.2f}x" if b > 0 else "-"


def corpora(runs, kind, order=None):
    prefix = kind + "/"
    names = [n[len(prefix):] for n in runs if n.startswith(prefix)]
    if order is None:
        return sorted(names)
    return [n for n in order if n in names] + sorted(n for n in names if n not in order)


def spread(cvs, name):
    cv = cvs.get(name)
    return f"{cv * 100:.0f}%" if cv is not None else "-"


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    context, runs, cvs = load(sys.argv[1])
    print(f"Machine: {context.get('num_cpus', '?')} CPUs at {context.get('mhz_per_cpu', '?')} MHz,"
          f" load average {', '.join(f'{x:.2f}' for x in context.get('load_avg', []))} at the start;"
          f" {context.get('date', '')}")
    print()

    print("Sentence corpora (1,000 sentences each): ns per sentence, ratio to the baseline, MB/s"
          " of decode, heap allocations per sentence, coefficient of variation of decode over"
          " the repetitions")
    print()
    print("| corpus | baseline | decode | ratio | decode (visit) | ratio | encode | ratio |"
          " decode MB/s | allocs | decode cv |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for c in corpora(runs, "decode", FAMILIES):
        base = runs.get("baseline/" + c)
        dec = runs["decode/" + c]
        vis = runs.get("decode_visit/" + c)
        enc = runs.get("encode/" + c)
        b = ns_per_msg(base) if base else 0
        cells = [c, fmt_ns(b) if base else "-", fmt_ns(ns_per_msg(dec)), ratio(ns_per_msg(dec), b)]
        cells += [fmt_ns(ns_per_msg(vis)), ratio(ns_per_msg(vis), b)] if vis else ["-", "-"]
        cells += [fmt_ns(ns_per_msg(enc)), ratio(ns_per_msg(enc), b)] if enc else ["-", "-"]
        worst = max(allocs(x) for x in (dec, vis, enc) if x)
        cells += [f"{mb_per_s(dec):,.0f}", f"{worst:g}", spread(cvs, "decode/" + c)]
        print("| " + " | ".join(cells) + " |")
    for n, b in runs.items():
        if n.startswith("decode_all_sets/"):
            base = runs.get("baseline/" + n.split("/", 1)[1])
            r = ratio(ns_per_msg(b), ns_per_msg(base)) if base else "-"
            print(f"\n`{n}` (every family's messages in one set): {fmt_ns(ns_per_msg(b))} ns,"
                  f" {r} the baseline")
    # The hand-written one-pass decoder and writer: the floor for decode and encode.
    for kind, ours in (("decode", "decode"), ("encode", "encode")):
        for n, b in runs.items():
            if not n.startswith(f"reference_{kind}/"):
                continue
            corpus = n.split("/", 1)[1]
            base = runs.get("baseline/" + corpus)
            mine = runs.get(f"{ours}/" + corpus)
            r = ratio(ns_per_msg(b), ns_per_msg(base)) if base else "-"
            m = ratio(ns_per_msg(mine), ns_per_msg(b)) if mine else "-"
            print(f"\n`{n}` (the hand-written one-pass {kind}r): {fmt_ns(ns_per_msg(b))} ns,"
                  f" {r} the baseline; seawire's {ours}/{corpus} is {m} it")
    print()

    print("Each message type (1,000 sentences of the type): ns per sentence")
    print()
    print("| type | baseline | decode | ratio | encode | ratio | bytes/sentence | allocs |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for t in corpora(runs, "decode_typed"):
        base = runs.get("baseline/" + t)
        dec = runs["decode_typed/" + t]
        enc = runs.get("encode/" + t)
        b = ns_per_msg(base) if base else 0
        size = base["bytes_per_second"] / base["items_per_second"] if base else 0
        cells = [t, fmt_ns(b), fmt_ns(ns_per_msg(dec)), ratio(ns_per_msg(dec), b)]
        cells += [fmt_ns(ns_per_msg(enc)), ratio(ns_per_msg(enc), b)] if enc else ["-", "-"]
        cells += [f"{size:.0f}", f"{max(allocs(dec), allocs(enc) if enc else 0):g}"]
        print("| " + " | ".join(cells) + " |")
    print()

    print("Streams and checks: ns per item (sentence, frame or block), MB/s")
    print()
    print("| benchmark | ns/item | MB/s | allocs |")
    print("|---|---:|---:|---:|")
    kinds = ["framer", "framer+decode", "checksum", "crc32", "frame"]
    streams = sorted((n for n in runs if n.split("/")[0] in kinds),
                     key=lambda n: (kinds.index(n.split("/")[0]), n))
    for n in streams:
        b = runs[n]
        print(f"| {n} | {fmt_ns(ns_per_msg(b))} | {mb_per_s(b):,.0f} | {allocs(b):g} |")


if __name__ == "__main__":
    main()
