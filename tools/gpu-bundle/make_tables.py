#!/usr/bin/env python3
"""Tables of a run-on-gpu.sh run, from its files (nothing typed in): puts them between the lines
<!-- tables --> and <!-- /tables --> of DIR/README.md (where it has them) and prints them.

  python3 tools/gpu-bundle/make_tables.py results/gpu-h100

Reads DIR/raw/: map-render.json (collide_is_bench), walking-*.json and .txt (clothbench run, three variants, every
collider the run had; the worst frame of --every-frame from the JSON, or from the text where an older JSON lacks
it), gl-timer.jsonl with gl-timer-*.json (the runs with gl_timer.c preloaded; columns left empty without them),
collide_is_tests.txt and maps-compare.json.
Standard library only.
"""
import json
import re
import sys
from pathlib import Path


def bench_rows(path):
    return json.loads(path.read_text())["benchmarks"]


def median_row(rows, name):
    found = [r for r in rows if r["name"] == name + "_median"]
    return found[0] if found else None


def median_ms(rows, name):
    row = median_row(rows, name)
    return row["real_time"] if row else float("nan")


COLLIDERS = ("is-egl", "is-cpu", "is-gl", "embree", "fcl", "bbtree", "vdb")


def main():
    d = Path(sys.argv[1])
    raw = d / "raw"
    out = []
    timer_log = raw / "gl-timer.jsonl"
    timer = ({j["label"]: j for j in map(json.loads, timer_log.read_text().splitlines())}
             if timer_log.exists() else {})

    rows = bench_rows(raw / "map-render.json")
    egl_device = next(r["label"] for r in rows if r["name"].startswith("render/egl/") and "label" in r)
    out += ["## Map rendering: one frame's maps (collide_is_bench `render/`)", "",
            "The walking body at 2 s of walk_07_01 (26,756 triangles), 2 views x 1 layer, depth + normal + velocity "
            "and the side layer, as `update_body` makes them (is-gl and is-cpu: drawn, read back, the side layer added on "
            "the CPU; is-egl as its commit does: the same before its maps stayed on the device, after that drawn, turned "
            "into maps and the side layer grown there, nothing read back). Median of the repetitions [ms/frame]; - where the run had none. "
            "glReadPixels: the same benchmark run once more with gl_timer.c preloaded (its own frame time in brackets; "
            "empty where the run did not time it); its time is the wait for the GPU's drawing plus the copy to the CPU.", "",
            f"is-egl device: {egl_device}", "",
            "| size | encoding | is-egl [ms] | is-cpu [ms] | is-cpu / is-egl | read back [MB/frame] "
            "| glReadPixels [ms/frame] (timed run's frame) | glReadPixels share | read-back rate [GB/s] |",
            "|---|---|---|---|---|---|---|---|---|"]
    for enc in ("float", "8bit"):
        for size in (320, 512, 1024):
            egl = median_ms(rows, f"render/egl/{enc}/{size}")
            cpu = median_ms(rows, f"render/cpu/{enc}/{size}")
            t = timer.get(f"render/egl/{enc}/{size}")
            if not t:
                f = lambda x: "-" if x != x else f"{x:.2f}"  # NaN: not run
                out.append(f"| {size}^2 | {enc} | {f(egl)} | {f(cpu)} | {f(cpu / egl)} | | | | |")
                continue
            (timed,) = bench_rows(raw / f"gl-timer-render-egl-{enc}-{size}.json")
            rp = t["glReadPixels"]["ms_per_frame"]
            mb = t["read_bytes_per_frame"] / 1e6
            out.append(f"| {size}^2 | {enc} | {egl:.2f} | {cpu:.2f} | {cpu / egl:.2f} | {mb:.1f} | {rp:.2f} "
                       f"({timed['real_time']:.2f}) | {100 * rp / timed['real_time']:.0f} % | {mb / rp:.1f} |")

    # the walking dress's maps under a frame's load, and query batches (benchmarks the bundle may lack)
    dress = [(f"render/{r}/float/320/6views5layers{load}", r, what) for r in ("egl", "cpu")
             for load, what in (("", "alone, back to back"), ("/200batches", "after 200 query batches of 2,300 points"),
                                ("/idle50ms", "after 50 ms idle"))]
    dress = [(n, r, w, median_row(rows, n)) for n, r, w in dress if median_row(rows, n)]
    if dress:
        out += ["", "## The walking dress's maps (6 views x 5 layers, 320^2, float) and query batches", "",
                "collide_is_bench, median of the repetitions: `update_body` per frame [ms] as it follows what a "
                "walking frame does between two updates; query batches of N points within 3 cm of the surface, "
                "[us per batch] (is-egl: the points' upload, the compute shader and the answers' read-back).", "",
                "| renderer | maps | maps [ms/frame] | query batch [ms] |", "|---|---|---|---|"]
        for n, r, w, row in dress:
            q = row.get("query_batch_ms")
            out.append(f"| {r} | {w} | {row['update_ms']:.2f} | {'' if q is None else f'{q:.3f}'} |")
        out += ["", "| renderer | points | views x layers | batch [us] | per point [ns] |", "|---|---|---|---|---|"]
        for r in ("egl", "cpu"):
            for count in (2300, 10000):
                for suffix, vl in (("", "2 x 1"), ("/6views5layers", "6 x 5")):
                    row = median_row(rows, f"query/{r}/float/tangent_plane/{count}pts{suffix}")
                    if row:
                        out.append(f"| {r} | {count} | {vl} | {row['real_time']:.1f} "
                                   f"| {1e3 * row['real_time'] / count:.1f} |")

    out += ["", "## Walking (`make bench-gpu`): `clothbench run scenes/walking/G.toml --every-frame`", "",
            "60 frames (1 - 3 s of walk_07_01). Variants: *stable* = the scene as it is (our stable regime); "
            "*ahead* = `--set body.prepare_ahead=true` (the next frame skinned and its maps drawn on a second thread "
            "while the cloth steps; skinning and maps ms/frame are then that thread's); *papers, ahead* = `--set "
            "solver.regime=papers --set solver.limit=velocity --set solver.limit_passes=16 --set "
            "body.prepare_ahead=true` (walking-t2's speed row). s/frame = wall time of the animate phase per frame "
            "(1 / frames/s). Cloth ms/frame = (CD&R + CS) per iteration x steps/frame, the per-iteration means being "
            "over the whole run (sew and drape included: the JSON has no animate-only cloth time), so an estimate. "
            "Maps = the collider's `update_body` per frame (6 views x 5 layers, as the scenes set). Worst frame: of "
            "the 60 measured frames (the JSON's worst_frame_* fields, or the text output where the JSON has none). glReadPixels / glTexImage2D: "
            "the stable is-egl run once more with gl_timer.c preloaded (without --every-frame; its own maps time in "
            "brackets).", "",
            "| garment | variant | collider | steps/frame at dt | s/frame | frames/s | skinning [ms/frame] "
            "| maps [ms/frame] | cloth [ms/frame] (est.) | worst frame: inside | depth max | crossings | strain max "
            "| glReadPixels [ms/frame] (timed run's maps) | glTexImage2D [ms/frame] | read back [MB/frame] |",
            "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    worst_re = re.compile(r"worst frame: ([\d.]+) % inside, depth max ([\d.]+) mm, crossings ([\d.]+) %; "
                          r"strain max ([\d.]+) %")
    variants = (("", "stable"), ("-ahead", "ahead"), ("-ahead-proxy", "ahead, 6,000-triangle colliders' body"),
                ("-papers-ahead", "papers, ahead"))
    for g in ("skirt", "dress_sleeves"):
        for suffix, variant in variants:
            for c in COLLIDERS:
                path = raw / f"walking-{g}-{c}{suffix}.json"
                if not path.exists():
                    continue
                (b,) = bench_rows(path)
                w = worst_re.search((raw / f"walking-{g}-{c}{suffix}.txt").read_text())
                extra = "| | |"
                if c == "is-egl" and not suffix and f"walking-{g}-is-egl" in timer:
                    t = timer[f"walking-{g}-is-egl"]
                    (tb,) = bench_rows(raw / f"gl-timer-walking-{g}-is-egl.json")
                    extra = (f"| {t['glReadPixels']['ms_per_frame']:.1f} ({tb['collider_update_ms_per_frame']:.1f}) "
                             f"| {t['glTexImage2D']['ms_per_frame']:.1f} | {t['read_bytes_per_frame'] / 1e6:.1f} |")
                if b.get("diverged"):
                    worst = f"diverged ({b.get('diverged_phase', '?')}: {b.get('diverged_reason', '?')}) | | |"
                elif "worst_frame_inside_pct" in b:
                    worst = (f"{b['worst_frame_inside_pct']:.2f} % | {b['worst_frame_depth_max_mm']:.2f} mm "
                             f"| {b['worst_frame_crossings_pct']:.2f} % | {100 * b['worst_frame_strain_max']:.1f} %")
                elif w:
                    worst = f"{w[1]} % | {w[2]} mm | {w[3]} % | {w[4]} %"
                else:
                    worst = "? | | |"
                fps = b.get("fps", 0.0)
                cloth = (b["cdr_ms"] + b["cs_ms"]) * b["steps_per_frame"]
                out.append(f"| {g} ({b['vertices']} v) | {variant} | {c} | {b['steps_per_frame']:.0f} at "
                           f"{b['dt_ms']:.3f} ms | {1 / fps if fps else float('nan'):.4f} | {fps:.2f} "
                           f"| {b['skinning_ms_per_frame']:.2f} | {b['collider_update_ms_per_frame']:.2f} "
                           f"| {cloth:.1f} | {worst} {extra}")

    # a later run of the maps' phases on the device (timestamp queries): profile-<commit>/
    for prof in sorted(d.glob("profile-*")):
        commit = re.search(r"git_commit: (\w+)", (prof / "environment.txt").read_text())[1]
        phases = ("upload", "draw", "depth_copy", "resolve", "side_layer")
        out += ["", f"## The device's time per phase at {commit[:7]} (`{prof.name}/`)", "",
                "collide_is_bench, one repetition: `update_body` per frame as the CPU sees it, and the GPU's own time "
                "of each phase of the same frame's maps (GL_TIMESTAMP queries, mean over the frames) [ms].", "",
                "| benchmark | update [ms] | " + " | ".join(phases) + " | GPU sum |",
                "|---|---|" + "---|" * (len(phases) + 1)]
        for r in bench_rows(prof / "map-render.json"):
            if not r["name"].startswith("render/egl/") or r.get("run_type") == "aggregate":
                continue
            g = [r.get(f"gpu_{p}_ms", float("nan")) for p in phases]
            out.append(f"| {r['name']} | {r['update_ms']:.3f} | " + " | ".join(f"{x:.3f}" for x in g) +
                       f" | {sum(g):.3f} |")
        for w in sorted(prof.glob("walking-*.txt")):
            lines = [x.strip() for x in w.read_text().splitlines() if "frames/s" in x or "collider queries" in x]
            out += ["", f"`{w.name}`: " + "; ".join(lines)]

    # a later, smaller run (walking only) of a newer commit: check-<commit>/
    for check in sorted(d.glob("check-*")):
        commit = re.search(r"git_commit: (\w+)", (check / "environment.txt").read_text())[1]
        out += ["", f"## Check at {commit[:7]}: walking only (`{check.name}/`)", "",
                "The same machine kind, another VM (compare within this table only): stable and ahead as above; "
                "*ahead, 6,000-triangle colliders' body* adds `--set body.collision_triangles=6000` (the oracle "
                "keeps the exact body); *papers, ahead* is run-on-gpu.sh's at the check's commit (walking-t2's "
                "speed row). Frames/s, the collider's maps ms/frame, the worst frame's strain and the accuracy "
                "verdict (every limit at every frame, strain included).", "",
                "| garment | variant | collider | frames/s | skinning [ms/frame] | maps [ms/frame] | strain, worst frame [%] "
                "| meets the limits |", "|---|---|---|---|---|---|---|---|"]
        for g in ("skirt", "dress_sleeves"):
            for suffix, variant in variants:
                for c in COLLIDERS:
                    path = check / f"walking-{g}-{c}{suffix}.json"
                    if path.exists():
                        (b,) = bench_rows(path)
                        verdict = "yes" if b.get("meets_limits") else "no: " + "; ".join(b.get("limit_misses", []))
                        out.append(f"| {g} ({b['vertices']} v) | {variant} | {c} | {b.get('fps', 0.0):.2f} "
                                   f"| {b['skinning_ms_per_frame']:.2f} | {b['collider_update_ms_per_frame']:.2f} "
                                   f"| {100 * b.get('worst_frame_strain_max', 0.0):.1f} | {verdict} |")

    out += ["", "## is-egl's maps against is-cpu's", "",
            "Float maps (tests/collide_is/egl_test.cpp, EglMaps.SameAsCpuAsIsGlIs; the walking body at rest and a "
            "sphere, 320^2): pixels covered in both, pixels covered by one renderer only, depth equal to the bit, "
            "largest depth difference.", "",
            "| body | views x layers | covered | coverage mismatches | depth bit-identical | max depth difference |",
            "|---|---|---|---|---|---|"]
    maps_re = re.compile(r"\[ maps \] (\S+) \(egl\) (\d+) views, (\d+) layers \d+\^2: covered (\d+), coverage "
                         r"mismatches (\d+), depth bit-identical on ([\d.]+) %, max ([\d.]+) um")
    for m in maps_re.finditer((raw / "collide_is_tests.txt").read_text()):
        out.append(f"| {Path(m[1]).name} | {m[2]} x {m[3]} | {m[4]} | {m[5]} | {float(m[6]):.2f} % "
                   f"| {float(m[7]) / 1000:.3f} mm |")
    out += ["", "Pictures of `clothbench maps --renderer egl|cpu` (8-bit colour pictures, tools/gpu-bundle/"
            "compare_maps.py): pixels covered by one renderer only, and covered pixels whose colour differs.", "",
            "| pose | size | picture | covered | egl only | cpu only | colour differs | by > 1 step | max step |",
            "|---|---|---|---|---|---|---|---|---|"]
    for r in json.loads((raw / "maps-compare.json").read_text())["comparisons"]:
        out.append(f"| {r['pose']} | {r['size']}^2 | {r['picture']} | {r['covered_egl']} | {r['covered_egl_only']} "
                   f"| {r['covered_cpu_only']} | {r['both_covered_differ']} | {r['both_covered_differ_by_more_than_1']} "
                   f"| {r['max_channel_difference']} |")
    text = "<!-- generated by tools/gpu-bundle/make_tables.py from raw/; do not edit -->\n" + "\n".join(out) + "\n"
    readme = d / "README.md"
    if readme.exists():
        r = readme.read_text()
        a, b = r.find("<!-- tables -->\n"), r.find("<!-- /tables -->")
        if 0 <= a < b:
            readme.write_text(r[: a + len("<!-- tables -->\n")] + text + r[b:])
    print(text, end="")


if __name__ == "__main__":
    main()
