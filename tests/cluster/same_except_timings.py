#!/usr/bin/env python3
"""Two merged sweep results are equal but for timings: the same rows by name, every other field equal,
no failed points. usage: same_except_timings.py A.json B.json"""
import json
import sys

TIMINGS = {"real_time", "cpu_time", "time_unit", "total_s", "setup_ms", "cdr_ms", "cs_ms", "limit_ms", "cloth_ms",
           "oracle_depth_ms", "oracle_crossings_ms", "fps", "skinning_ms_per_frame", "collider_update_ms_per_frame"}


def rows(path):
    with open(path) as f:
        doc = json.load(f)
    if doc.get("failed"):
        sys.exit(f"{path}: {len(doc['failed'])} failed point(s): {doc['failed']}")
    return {r["name"]: {k: v for k, v in r.items() if k not in TIMINGS} for r in doc["benchmarks"]}


a, b = rows(sys.argv[1]), rows(sys.argv[2])
if a.keys() != b.keys():
    sys.exit(f"different rows: only in A {sorted(a.keys() - b.keys())}, only in B {sorted(b.keys() - a.keys())}")
bad = [(n, k, a[n].get(k), b[n].get(k)) for n in a for k in a[n].keys() | b[n].keys() if a[n].get(k) != b[n].get(k)]
if bad:
    sys.exit("fields differ: " + "; ".join(f"{n} {k}: {x} vs {y}" for n, k, x, y in bad[:10]))
print(f"{len(a)} rows equal but for timings")
