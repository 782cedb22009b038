#!/usr/bin/env python3
"""Draws one chart from a JSON spec written by clothbench (bench/src/experiment.cpp).

spec: {"out": PNG, "title", "xlabel", "ylabel", "logx", "logy", "xticklabels": [...] (at x = 0, 1, ...),
       "series": [{"label", "x": [...], "y": [...], "style": "o-" | "--" | ...}]}
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(path):
    with open(path) as f:
        spec = json.load(f)
    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=100)
    for s in spec["series"]:
        ax.plot(s["x"], s["y"], s.get("style", "o-"), label=s["label"], markersize=4, linewidth=1.2)
    ax.set_title(spec.get("title", ""))
    ax.set_xlabel(spec.get("xlabel", ""))
    ax.set_ylabel(spec.get("ylabel", ""))
    if spec.get("logx"):
        ax.set_xscale("log")
    if spec.get("logy"):
        ax.set_yscale("log")
    if spec.get("xticklabels"):
        labels = spec["xticklabels"]
        ax.set_xticks(range(len(labels)))
        ax.set_xticklabels(labels, rotation=45, ha="right", fontsize=7)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(spec["out"])


if __name__ == "__main__":
    main(sys.argv[1])
