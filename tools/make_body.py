#!/usr/bin/env python3
"""Make a MakeHuman body shape as an OBJ like scenes/data/body/mh_female_walk_rest.obj (same vertices, same
triangles, meters, +Y up, soles at y = 0) from the CC0 sources in shared/data/body/src: the hm08 base mesh's body
group (its first 13,380 vertices) plus macro targets at given weights, in decimetres, scaled to metres.

The walking body's rest OBJ is this with the three `*-female-young` targets at 1/3 each, the
`universal-female-young-averagemuscle-averageweight` target at 1 and the `...-maxheight` target at 0.083
(scenes/data/body/README.md); `--check` rebuilds it and compares.

usage: make_body.py SRC_DIR OUT.obj [TARGET=WEIGHT ...]     (default: the walking body's weights)
       make_body.py SRC_DIR --check REST.obj
"""
import sys

BODY_VERTICES = 13380  # hm08: the body group's vertices come first, the helpers after them
WALKING = {
    "african-female-young": 1 / 3,
    "asian-female-young": 1 / 3,
    "caucasian-female-young": 1 / 3,
    "universal-female-young-averagemuscle-averageweight": 1.0,
    "female-young-averagemuscle-averageweight-maxheight": 0.083,
}


def vertices(path):
    with open(path) as f:
        return [[float(x) for x in line.split()[1:4]] for line in f if line.startswith("v ")]


def shape(src, weights):
    v = [p[:] for p in vertices(src + "/base.obj")[:BODY_VERTICES]]
    for name, w in weights.items():
        with open(f"{src}/targets/{name}.target") as f:
            for line in f:
                if line.startswith("#") or not line.strip():
                    continue
                i, *d = line.split()
                i = int(i)
                if i < BODY_VERTICES:
                    for k in range(3):
                        v[i][k] += w * float(d[k])
    floor = min(p[1] for p in v)
    return [[0.1 * p[0], 0.1 * (p[1] - floor), 0.1 * p[2]] for p in v]


def faces(rest):
    with open(rest) as f:
        return [line for line in f if line.startswith("f ")]


def main(argv):
    if len(argv) == 4 and argv[2] == "--check":
        made, rest = shape(argv[1], WALKING), vertices(argv[3])
        err = max(abs(a - b) for p, q in zip(made, rest) for a, b in zip(p, q))
        print(f"largest difference from {argv[3]}: {err:.2e} m")
        return 0 if len(made) == len(rest) and err < 1e-5 else 1
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    src, out = argv[1], argv[2]
    weights = dict(WALKING)
    for arg in argv[3:]:
        name, _, w = arg.partition("=")
        weights[name] = float(w)
    v = shape(src, weights)
    rest = src + "/../mh_female_walk_rest.obj"  # the same triangles
    with open(out, "w") as f:
        f.write("# MakeHuman hm08 body (CC0), adult female macro targets: "
                + ", ".join(f"{n} {w:.3f}" for n, w in weights.items()) + "; meters, Y-up\n")
        for p in v:
            f.write(f"v {p[0]:.6f} {p[1]:.6f} {p[2]:.6f}\n")
        f.writelines(faces(rest))
    print(f"{out}: {len(v)} vertices, stature {max(p[1] for p in v):.3f} m")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
