#!/usr/bin/env python3
"""The include graph of the tree, by top-level module folder (python3 standard library only).

Prints the lines of C++ (*.cpp, *.hpp, *.h) per top-level folder with their share of the total, and the
module-to-module include edges (with how many #include lines make each). Fails (exit 1) when
- a lower module includes a higher one (sim < osmesa < collide_is, collide_os, io, render < bench <
  experiments < cli; tests/, perf/ and fuzz/ sit on top and may include any module), or modules of one
  level include each other both ways;
- a module runs its own executable: /proc/self/exe anywhere but cli/src/cmd_sweep.cpp (the sweep writes a
  Slurm script that runs the executable on other nodes: that is what `sweep --slurm` is for);
- a module folder holds more than --max-share of the lines (default 35 %).

Usage: tools/include_graph.py [ROOT] [--max-share PCT]   (ctest: include_graph)
"""
import os
import re
import sys
from collections import Counter, defaultdict

# level of each module folder; an include may only go to the same level or lower
LEVELS = {
    "sim": 0,
    "osmesa": 1,
    "collide_is": 2, "collide_os": 2, "io": 2, "render": 2,
    "bench": 3,
    "experiments": 4,
    "cli": 5,
    "tests": 6, "perf": 6, "fuzz": 6,
}
# the module a public header path names: clothbench/<name>/...
HEADER_MODULE = {"collide_os": "collide_os", "collide_is": "collide_is", "sim": "sim", "io": "io",
                 "render": "render", "bench": "bench", "experiments": "experiments", "osmesa": "osmesa"}
SELF_EXEC_ALLOWED = {"cli/src/cmd_sweep.cpp"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
SKIP_DIRS = {".git", "build", "results", "scenes", "report", "tools", ".ci", "cmake"}


def sources(root):
    for top in sorted(os.listdir(root)):
        path = os.path.join(root, top)
        if top in SKIP_DIRS or top.startswith("build") or not os.path.isdir(path):
            continue
        for d, dirs, files in os.walk(path):
            dirs[:] = sorted(x for x in dirs if not x.startswith("."))
            for f in sorted(files):
                if f.endswith((".cpp", ".hpp", ".h")):
                    yield top, os.path.join(d, f)


def included_module(include, including_top):
    parts = include.split("/")
    if len(parts) >= 3 and parts[0] == "clothbench":
        return HEADER_MODULE.get(parts[1])
    if include == "clothbench/config.h":
        return None  # generated: which backends the build has
    return including_top  # a private header beside the file


def main():
    args = sys.argv[1:]
    max_share = 35.0
    if "--max-share" in args:
        i = args.index("--max-share")
        max_share = float(args[i + 1])
        del args[i:i + 2]
    root = os.path.abspath(args[0] if args else os.path.join(os.path.dirname(__file__), ".."))
    lines = Counter()
    edges = Counter()
    problems = []
    for top, path in sources(root):
        rel = os.path.relpath(path, root)
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
        lines[top] += text.count("\n")
        if top not in LEVELS:
            problems.append("%s: folder %s has no level in tools/include_graph.py" % (rel, top))
            continue
        if "/proc/self/exe" in text and rel not in SELF_EXEC_ALLOWED:
            problems.append("%s: runs its own executable (/proc/self/exe)" % rel)
        for line in text.splitlines():
            m = INCLUDE.match(line)
            if not m:
                continue
            target = included_module(m.group(1), top)
            if target and target != top:
                edges[(top, target)] += 1
    total = sum(lines.values())
    print("lines per folder (C++ sources and headers):")
    for top, n in sorted(lines.items(), key=lambda kv: -kv[1]):
        share = 100.0 * n / total
        print("  %-12s %7d  %5.1f %%" % (top, n, share))
        if share > max_share:
            problems.append("%s holds %.1f %% of the lines (more than %.0f %%)" % (top, share, max_share))
    print("  %-12s %7d" % ("total", total))
    print("include edges (module -> module: #include lines):")
    for (a, b), n in sorted(edges.items(), key=lambda kv: (LEVELS.get(kv[0][0], 9), kv[0][0], kv[0][1])):
        print("  %-12s -> %-12s %4d" % (a, b, n))
        la, lb = LEVELS.get(a), LEVELS.get(b)
        if la is not None and lb is not None and la < lb:
            problems.append("%s (level %d) includes %s (level %d): a lower module includes a higher one" % (a, la, b, lb))
        if la is not None and la == lb and (b, a) in edges and a < b:
            problems.append("%s and %s include each other" % (a, b))
    if problems:
        print("FAILED:")
        for p in problems:
            print("  " + p)
        return 1
    print("ok: no lower module includes a higher one, no module runs its own executable")
    return 0


if __name__ == "__main__":
    sys.exit(main())
