#!/usr/bin/env python3
"""Instruction counts of clothbench's perf workloads under callgrind: the CI performance gate.

  measure.py measure --out F.json                       count every workload, write Google Benchmark JSON
  measure.py check --baseline B.json [--tolerance 0.02] [--current F.json]
                                                        compare with a baseline; exit 1 on a rise beyond the
                                                        tolerance or a workload missing on either side
  measure.py accept [--baseline B.json] [--current F.json]
                                                        rewrite the baseline from a fresh measurement

Each workload runs once in `clothbench_perf_workloads --workload NAME` under
`valgrind --tool=callgrind --collect-atstart=no --instr-atstart=no`; only the region the program
wraps in callgrind client requests is counted (the `totals:` line of its callgrind output, event Ir).
Exit codes: 0 ok, 1 regression or missing workload, 2 bad input or a failed run, 77 skipped (no
valgrind, or a build that cannot be compared with the baseline). Standard library only.
"""
import argparse
import datetime
import json
import os
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_BASELINE = os.path.join(ROOT, "results", "ci-baseline.json")
DEFAULT_WORKLOADS = os.path.join(ROOT, "build", "bin", "clothbench_perf_workloads")
SKIP = 77
# the libraries whose code the workloads count: libc (libm), libstdc++, Embree and the TBB it builds with
LIBRARY_PACKAGES = ("libc6", "libstdc++6", "libembree3-3", "libtbb12")
METRIC = ("instructions: callgrind's Ir (instructions executed) of the measured region of each workload, "
          "the calling thread only; every workload runs on one thread")
TIMES = ("real_time / cpu_time: wall and process CPU time of the measured region while running under "
         "callgrind (tens of times slower than native, not a native timing); valgrind_wall_s: the whole "
         "valgrind process, set-up included. The gate reads instructions only")
TOOLCHAIN = ("counts depend on the toolchain (compiler, flags, Debian's libraries, valgrind) and on the CPU "
             "features valgrind reports (library code dispatched at run time): compare only with a "
             "baseline made by the same toolchain; `make perf-baseline` rewrites it")


class Failure(Exception):
    """Bad input or a failed run: exit 2 with the message."""


class Skipped(Exception):
    """Nothing to judge here: exit 77 (ctest SKIP_RETURN_CODE) with the message."""


def run_text(cmd):
    """stdout of a short helper command; Failure naming it when it fails."""
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        raise Failure(f"{' '.join(cmd)} exited {proc.returncode}: {proc.stderr.strip()}")
    return proc.stdout


def find_valgrind(given):
    """The valgrind to run: the path given (CMake's find_program) or the one on PATH."""
    for candidate in (given, shutil.which("valgrind")):
        if candidate and os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return candidate
    raise Skipped("valgrind is not installed (Debian: apt-get install valgrind; `make test` installs it): "
                  "the instruction counts cannot be measured")


def list_workloads(binary):
    """(name, description, uncounted function pattern) of every workload the binary knows."""
    if not os.path.isfile(binary):
        raise Failure(f"{binary}: not found (build it: cmake --build build --target clothbench_perf_workloads)")
    rows = [line.split("\t") for line in run_text([binary, "--list"]).splitlines() if line]
    return [(r[0], r[1], r[2] if len(r) > 2 else "") for r in rows]


def toolchain(binary, valgrind):
    """compiler, build type and flags the binary was built with, and valgrind's version."""
    info = dict(line.split("\t", 1) for line in run_text([binary, "--toolchain"]).splitlines() if "\t" in line)
    info["valgrind"] = run_text([valgrind, "--version"]).strip()
    info["packages"] = package_versions()
    return info


def package_versions():
    """Debian versions of the libraries the counted code runs in ("" where dpkg-query cannot tell)."""
    versions = {}
    for pkg in LIBRARY_PACKAGES:
        try:
            proc = subprocess.run(["dpkg-query", "-W", "-f=${Version}", pkg], capture_output=True, text=True)
            versions[pkg] = proc.stdout.strip() if proc.returncode == 0 else ""
        except OSError:
            versions[pkg] = ""
    return versions


def read_ir(path):
    """Total Ir of a callgrind output file (its `totals:` line, else `summary:`)."""
    events, totals = None, None
    with open(path) as f:
        for line in f:
            if line.startswith("events:"):
                events = line.split()[1:]
            elif line.startswith("totals:") or (line.startswith("summary:") and totals is None):
                totals = [int(x) for x in line.split()[1:]]
    if events is None or totals is None or "Ir" not in events:
        raise Failure(f"{path}: no events/totals line with Ir (not a callgrind output file?)")
    return totals[events.index("Ir")]


def region_times(stdout):
    """(wall, cpu) of the measured region [ms] as the workload printed them."""
    m = re.search(r"measured region: wall ([0-9.]+) ms, cpu ([0-9.]+) ms", stdout)
    return (float(m.group(1)), float(m.group(2))) if m else (0.0, 0.0)


def run_workload(binary, valgrind, name, uncounted, out_dir):
    """One workload under callgrind: (instructions, region wall ms, region cpu ms, valgrind wall s)."""
    cmd = [valgrind, "--tool=callgrind", "--collect-atstart=no", "--instr-atstart=no",
           f"--callgrind-out-file={out_dir}/callgrind.{name}.%p.out"]
    if uncounted:
        cmd.append(f"--toggle-collect={uncounted}")
    start = time.monotonic()
    proc = subprocess.Popen(cmd + [binary, "--workload", name], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)
    stdout, stderr = proc.communicate()
    wall_s = time.monotonic() - start
    if proc.returncode != 0:
        raise Failure(f"workload {name} failed under valgrind (exit {proc.returncode}):\n{stderr[-3000:]}")
    # valgrind runs the program in its own process: the file of that pid (a child it forks writes its own)
    ir = read_ir(os.path.join(out_dir, f"callgrind.{name}.{proc.pid}.out"))
    if ir == 0:
        raise Failure(f"workload {name}: callgrind counted nothing (clothbench_perf_workloads built without "
                      "valgrind/callgrind.h?)")
    return ir, *region_times(stdout), wall_s


def row(index, name, what, ir, wall_ms, cpu_ms, valgrind_s):
    """One Google Benchmark iteration row."""
    return {"name": f"perf/{name}", "family_index": index, "per_family_instance_index": 0,
            "run_name": f"perf/{name}", "run_type": "iteration", "repetitions": 1, "repetition_index": 0,
            "threads": 1, "iterations": 1, "real_time": wall_ms, "cpu_time": cpu_ms, "time_unit": "ms",
            "instructions": ir, "valgrind_wall_s": round(valgrind_s, 3), "label": what}


def measure(args):
    """Every workload once under callgrind, as a Google Benchmark JSON document."""
    valgrind = find_valgrind(args.valgrind)
    binary = os.path.abspath(args.workloads)
    workloads = list_workloads(binary)
    context = {"date": datetime.datetime.now().astimezone().isoformat(timespec="seconds"),
               "host_name": socket.gethostname(), "executable": binary, "num_cpus": os.cpu_count(),
               **toolchain(binary, valgrind), "metric": METRIC, "times": TIMES, "toolchain_note": TOOLCHAIN}
    context["library_build_type"] = context.get("build_type", "unknown").lower()
    rows = []
    with tempfile.TemporaryDirectory(prefix="clothbench-perf-") as tmp:
        out_dir = args.profiles or tmp
        os.makedirs(out_dir, exist_ok=True)
        for i, (name, what, uncounted) in enumerate(workloads):
            ir, wall_ms, cpu_ms, valgrind_s = run_workload(binary, valgrind, name, uncounted, out_dir)
            print(f"  perf/{name}: {ir:,} instructions ({valgrind_s:.1f} s under valgrind)", file=sys.stderr)
            rows.append(row(i, name, what, ir, wall_ms, cpu_ms, valgrind_s))
    return {"context": context, "benchmarks": rows}


def load(path, what):
    try:
        with open(path) as f:
            doc = json.load(f)
    except OSError as e:
        raise Failure(f"{path}: cannot read the {what}: {e.strerror}")
    except json.JSONDecodeError as e:
        raise Failure(f"{path}: the {what} is not JSON: {e}")
    if not isinstance(doc.get("benchmarks"), list):
        raise Failure(f"{path}: the {what} has no \"benchmarks\" array (expected Google Benchmark's layout)")
    return doc


def write(doc, path):
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w") as f:
        json.dump(doc, f, indent=2)
        f.write("\n")


def counts(doc, path):
    """instructions by row name (iteration rows)."""
    out = {}
    for r in doc["benchmarks"]:
        if r.get("run_type", "iteration") != "iteration":
            continue
        if not isinstance(r.get("instructions"), (int, float)) or "name" not in r:
            raise Failure(f"{path}: a row lacks a name or a numeric instructions counter")
        out[r["name"]] = r["instructions"]
    return out


def comparable(base_ctx, now_ctx):
    """Skipped when the build types differ; a list of warnings for other toolchain differences."""
    if base_ctx.get("build_type") != now_ctx.get("build_type"):
        raise Skipped(f"the baseline was measured on a {base_ctx.get('build_type')} build, this is a "
                      f"{now_ctx.get('build_type')} build: instruction counts are not comparable")
    base = {**base_ctx, **base_ctx.get("packages", {})}
    now = {**now_ctx, **now_ctx.get("packages", {})}
    keys = ("compiler", "cxx_flags", "valgrind") + LIBRARY_PACKAGES
    return [f"{k} differs: baseline `{base.get(k)}`, now `{now.get(k)}`" for k in keys if base.get(k) != now.get(k)]


def verdict(base, now, tolerance):
    """(text, failed) for one workload."""
    if base is None:
        return "MISSING in the baseline (new workload: make perf-baseline)", True
    if now is None:
        return "MISSING now (workload gone or not built: make perf-baseline if on purpose)", True
    ratio = now / base
    if ratio > 1 + tolerance:
        return f"REGRESSION (+{100 * (ratio - 1):.1f} %)", True
    if ratio < 1 - tolerance:
        return f"improved ({100 * (ratio - 1):.1f} %): refresh the baseline with make perf-baseline", False
    return "ok", False


def fmt(n):
    return "-" if n is None else f"{n:,}"


def compare(base, now, tolerance):
    """Prints the table; returns the names of the failing workloads."""
    failed = []
    print(f"{'workload':<22} {'baseline':>16} {'now':>16} {'ratio':>7}  verdict")
    for name in sorted(set(base) | set(now)):
        b, n = base.get(name), now.get(name)
        text, bad = verdict(b, n, tolerance)
        ratio = f"{n / b:.4f}" if b and n is not None else "-"
        print(f"{name:<22} {fmt(b):>16} {fmt(n):>16} {ratio:>7}  {text}")
        if bad:
            failed.append(name)
    return failed


def current(args):
    """The measurement to judge: --current FILE, or a fresh one (also written to --out)."""
    if args.current:
        if not os.path.isfile(args.current):
            raise Skipped(f"{args.current}: no measurement (perf.measure skipped or failed: valgrind missing?)")
        return load(args.current, "measurement")
    doc = measure(args)
    if args.out:
        write(doc, args.out)
    return doc


def check(args):
    base_doc = load(args.baseline, "baseline")
    now_doc = current(args)
    warnings = comparable(base_doc.get("context", {}), now_doc.get("context", {}))
    for w in warnings:
        print(f"warning: toolchain: {w}")
    if warnings:
        print(f"note: {TOOLCHAIN}")
    failed = compare(counts(base_doc, args.baseline), counts(now_doc, args.current or "measurement"), args.tolerance)
    if failed:
        print(f"FAILED: {', '.join(failed)} (tolerance {100 * args.tolerance:g} % on instructions; baseline "
              f"{args.baseline}). A deliberate change: make perf-baseline and commit the baseline."
              + (" The toolchain differs from the baseline's (warnings above)." if warnings else ""))
        return 1
    print(f"ok: every workload within {100 * args.tolerance:g} % of the baseline's instructions")
    return 0


def accept(args):
    doc = current(args)
    if os.path.isfile(args.baseline):
        compare(counts(load(args.baseline, "baseline"), args.baseline), counts(doc, "measurement"), args.tolerance)
    write(doc, args.baseline)
    print(f"wrote {args.baseline}: commit it with the change that moved the counts")
    return 0


def parse(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--workloads", default=DEFAULT_WORKLOADS, help="clothbench_perf_workloads binary")
    p.add_argument("--valgrind", default=None, help="valgrind binary (default: the one on PATH)")
    p.add_argument("--profiles", default=None, help="keep the callgrind output files in this folder")
    sub = p.add_subparsers(dest="mode", required=True)
    m = sub.add_parser("measure", help="count every workload")
    m.add_argument("--out", required=True, help="Google Benchmark JSON to write")
    for name in ("check", "accept"):
        s = sub.add_parser(name, help="compare with the baseline" if name == "check" else "rewrite the baseline")
        s.add_argument("--baseline", default=DEFAULT_BASELINE)
        s.add_argument("--tolerance", type=float, default=0.02, help="allowed rise, a fraction (0.02 = 2 %%)")
        s.add_argument("--current", default=None, help="judge this measurement instead of measuring now")
        s.add_argument("--out", default=None, help="also write the fresh measurement here")
    return p.parse_args(argv)


def main(argv):
    args = parse(argv)
    try:
        if args.mode == "measure":
            if os.path.exists(args.out):
                os.remove(args.out)  # never leave a stale measurement for the checks
            write(measure(args), args.out)
            return 0
        return check(args) if args.mode == "check" else accept(args)
    except Skipped as e:
        print(f"SKIPPED: {e}")
        return SKIP
    except Failure as e:
        print(f"measure.py: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
