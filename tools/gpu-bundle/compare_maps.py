#!/usr/bin/env python3
"""Compare the map pictures of `clothbench maps --renderer egl` with `--renderer cpu` (run-on-gpu.sh).

MAPS_DIR holds folders POSE-SIZE-RENDERER (e.g. walk-1024-egl), each with the *_depth.png, *_normal.png (and
*_velocity.png) that `maps --png` writes (front view left, back view right; white is no body). Prints JSON: per pose, size
and picture, the pixels covered by one renderer only (coverage: not white), and among the pixels both cover,
how many differ and by how much (8-bit colour steps of the picture, not metres: a screening, not the
bit-for-bit check of tests/collide_is/egl_test.cpp). Needs numpy and Pillow.
"""
import json
import sys
from pathlib import Path

import numpy as np
from PIL import Image


def load(folder: Path, kind: str) -> np.ndarray:
    (path,) = sorted(folder.glob(f"*_{kind}.png"))
    return np.asarray(Image.open(path).convert("RGB"), dtype=np.int16)


def main() -> None:
    root = Path(sys.argv[1])
    rows = []
    for egl in sorted(root.glob("*-egl")):
        pose, size, _ = egl.name.rsplit("-", 2)
        cpu = egl.with_name(f"{pose}-{size}-cpu")
        if not cpu.is_dir():
            continue
        for kind in ("depth", "normal", "velocity"):
            if not list(egl.glob(f"*_{kind}.png")):
                continue  # velocity: moving poses only
            a, b = load(egl, kind), load(cpu, kind)
            if a.shape != b.shape:
                rows.append({"pose": pose, "size": int(size), "picture": kind, "error": f"shapes {a.shape} {b.shape}"})
                continue
            cover_a, cover_b = (a != 255).any(-1), (b != 255).any(-1)
            both = cover_a & cover_b
            diff = np.abs(a - b).max(-1)
            differ = both & (diff > 0)
            rows.append({
                "pose": pose, "size": int(size), "picture": kind,
                "pixels": int(a.shape[0] * a.shape[1]),
                "covered_egl": int(cover_a.sum()), "covered_cpu": int(cover_b.sum()),
                "covered_egl_only": int((cover_a & ~cover_b).sum()), "covered_cpu_only": int((cover_b & ~cover_a).sum()),
                "both_covered_differ": int(differ.sum()),
                "both_covered_differ_by_more_than_1": int((both & (diff > 1)).sum()),
                "max_channel_difference": int(diff[both].max()) if both.any() else 0,
                "identical": bool((a == b).all()),
            })
    json.dump({"maps_dir": str(root), "comparisons": rows}, sys.stdout, indent=1)
    print()


if __name__ == "__main__":
    main()
