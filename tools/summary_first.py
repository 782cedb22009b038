#!/usr/bin/env python3
"""Every results page opens with its summary (python3 standard library only).

A page written by `clothbench reproduce` (DIR/*.md but README.md) has its title, then "**Summary.**" and three to
five lines: the paper's claim or figure, ours, the verdict. Exit 1 names each page that does not.

Usage: tools/summary_first.py DIR   (ctest: summary_first, on reproduce_quick's pages)
"""
import os
import sys


def summary_lines(path):
    """The summary's lines of a page, or None when the page does not open with one."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    if len(lines) < 5 or not lines[0].startswith("# ") or lines[2] != "**Summary.**":
        return None
    out = []
    for line in lines[4:]:
        if not line.startswith("- "):
            break
        out.append(line)
    return out


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else "results"
    pages = sorted(f for f in os.listdir(folder) if f.endswith(".md") and f != "README.md")
    bad = []
    for page in pages:
        lines = summary_lines(os.path.join(folder, page))
        if lines is None:
            bad.append(page + ": no summary under the title")
        elif not 3 <= len(lines) <= 5:
            bad.append(page + ": a summary of %d lines (3 to 5)" % len(lines))
    for b in bad:
        print(b)
    if not pages:
        print(folder + ": no pages")
        return 1
    print("%d pages, %d without a summary of 3 to 5 lines" % (len(pages), len(bad)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
