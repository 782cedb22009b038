#!/usr/bin/env python3
"""The gate's own test, without valgrind noise: `measure.py check` on baselines derived from one real
measurement. For each workload, a baseline with its count 5 % lower (the tree looks 5 % regressed)
must fail naming that workload and no other; the unchanged baseline and one 5 % higher (an
improvement) must pass; a workload missing on either side must fail naming it.

  gate_selftest.py MEASURE_PY MEASUREMENT.json WORK_DIR
Exit 0 when every case behaves, 1 naming the first that does not, 77 when there is no measurement.
"""
import copy
import json
import os
import subprocess
import sys

SKIP = 77


def run_check(measure_py, baseline, current, work_dir, tag):
    """Writes `baseline`, runs check against `current`: (exit code, output)."""
    path = os.path.join(work_dir, f"baseline-{tag}.json")
    with open(path, "w") as f:
        json.dump(baseline, f)
    proc = subprocess.run([sys.executable, measure_py, "check", "--baseline", path, "--tolerance", "0.02",
                           "--current", current], capture_output=True, text=True)
    return proc.returncode, proc.stdout + proc.stderr


def scaled(doc, name, factor):
    """A copy of `doc` with `name`'s instructions times `factor`."""
    out = copy.deepcopy(doc)
    for r in out["benchmarks"]:
        if r["name"] == name:
            r["instructions"] = int(r["instructions"] * factor)
    return out


def without(doc, name):
    out = copy.deepcopy(doc)
    out["benchmarks"] = [r for r in out["benchmarks"] if r["name"] != name]
    return out


def failing_lines(output):
    """Names on the table's failing rows."""
    return {line.split()[0] for line in output.splitlines() if "REGRESSION" in line or "MISSING" in line}


def cases(doc, current, work_dir):
    """(tag, baseline, measurement file, expected exit, expected failing names)."""
    names = [r["name"] for r in doc["benchmarks"]]
    yield "unchanged", doc, current, 0, set()
    for n in names:
        yield f"regressed-{n[5:]}", scaled(doc, n, 0.95), current, 1, {n}
        yield f"improved-{n[5:]}", scaled(doc, n, 1.05), current, 0, set()
    yield "missing-in-baseline", without(doc, names[0]), current, 1, {names[0]}
    # a workload the baseline has and the measurement lacks: the measurement without it
    lacking = os.path.join(work_dir, "measurement-lacking.json")
    with open(lacking, "w") as f:
        json.dump(without(doc, names[-1]), f)
    yield "missing-now", doc, lacking, 1, {names[-1]}


def main(measure_py, current, work_dir):
    if not os.path.isfile(current):
        print(f"SKIPPED: {current}: no measurement (perf.measure skipped: valgrind missing?)")
        return SKIP
    with open(current) as f:
        doc = json.load(f)
    os.makedirs(work_dir, exist_ok=True)
    count = 0
    for tag, baseline, measured, want_rc, want_failing in cases(doc, current, work_dir):
        rc, output = run_check(measure_py, baseline, measured, work_dir, tag)
        if rc != want_rc or failing_lines(output) != want_failing:
            print(f"FAILED case {tag}: exit {rc} (want {want_rc}), failing rows {sorted(failing_lines(output))} "
                  f"(want {sorted(want_failing)}); check said:\n{output}")
            return 1
        count += 1
    print(f"ok: {count} cases; a 5 % rise of any one workload fails naming it, equal and lower counts pass, "
          "a missing workload fails")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 4:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(*sys.argv[1:]))
