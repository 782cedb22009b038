#!/usr/bin/env python3
"""Figures typed into the prose of the generated pages (python3 standard library only).

A page's prose either computes its figures from the run or does not print them. This finds every figure with
a unit (ms, s, mm, cm, %, m/s, frames/s, x, ...) inside a string literal of experiments/src/*.cpp, and fails
(exit 1) on any that experiments/prose_figures.txt does not list for that file with its reason: a setting the
page describes (an input of the runs, not a result), an accuracy limit, a published figure of the papers, or a
target the page weighs results against. A listed figure that no longer occurs fails as well, so the list stays
the reviewed set. A figure printed from a variable (num(...)) is never a literal and never listed.

Usage: tools/prose_figures.py [ROOT]   (ctest: prose_figures)
"""
import os
import re
import sys

# a C++ string literal on one line (escapes kept); raw strings are not used in experiments/src
LITERAL = re.compile(r'"((?:[^"\\\n]|\\.)*)"')
# a number and its unit, not part of a key (garment.vertices=336), a name (walk_07_01) or a longer number
FIGURE = re.compile(r"(?<![\w.=/-])(\d+(?:[.,]\d+)?)\s?(ms|µs|µm|mm|cm|%|m/s|frames/s|fps|x\b|×|s\b)")


def figures(path):
    """(figure, line number) for every figure with a unit in a string literal of a C++ file."""
    out = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            code = line.split("//", 1)[0] if line.lstrip().startswith("//") else line
            for literal in LITERAL.finditer(code):
                for m in FIGURE.finditer(literal.group(1)):
                    out.append((m.group(1) + " " + m.group(2), number))
    return out


def allowed(path):
    """{(file, figure): reason} from the list: lines 'file | figure | reason', # comments."""
    out = {}
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            parts = [p.strip() for p in line.split("|")]
            if len(parts) != 3 or not all(parts):
                sys.exit(f"{path}:{number}: expected 'file | figure | reason', got: {line}")
            out[(parts[0], parts[1])] = parts[2]
    return out


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    src = os.path.join(root, "experiments", "src")
    listed = allowed(os.path.join(root, "experiments", "prose_figures.txt"))
    found = {}
    for name in sorted(os.listdir(src)):
        if name.endswith(".cpp"):
            for figure, line in figures(os.path.join(src, name)):
                found.setdefault((name, figure), line)
    unlisted = [(k, line) for k, line in found.items() if k not in listed]
    stale = [k for k in listed if k not in found]
    for (name, figure), line in unlisted:
        print(f"experiments/src/{name}:{line}: '{figure}' typed into a page's prose: print it from the run, or list "
              "it in experiments/prose_figures.txt with why it may be typed (setting, limit, paper, target)")
    for name, figure in stale:
        print(f"experiments/prose_figures.txt: '{name} | {figure}' no longer occurs: remove it")
    print(f"{len(found)} typed figures, all listed with a reason" if not unlisted and not stale else "FAILED")
    return 1 if unlisted or stale else 0


if __name__ == "__main__":
    sys.exit(main())
