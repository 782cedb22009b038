#!/usr/bin/env python3
"""The `report.answers` ctest: the answers section at the top of results/index.html (report/answers.py).

On a made-up RESULTS_DIR (rows written here, not by the experiments) where the fastest row of each group misses
a limit, one category has no row within every limit, one configuration has repetitions and a GPU folder holds
walking runs only, report/make_report.py must write a page that
- opens with the answers section, then the claims, then the experiments' tables, charts and the 3-D viewer last;
- names as fastest only rows that meet every limit (meets_limits 1, no limit_misses), the fastest of them;
- says so where no row meets every limit, and where there is no GPU data (here: the static body);
- gives a measured spread where the row has repetitions and "one run" where it has none.
Then the same checks that need no made-up answer on RESULTS_DIR given with --results (the committed results/):
every row the answers name meets every limit in the file it names, and each of static and walking has a CPU and a
GPU answer or says why not. Needs python3 only (and Debian's libjs-three / libjs-chart.js, as make_report.py).
"""
import argparse
import html
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def answer_rows(page):
    """[(attributes, cells text)] of the answers table's rows."""
    start = page.index('<section id="answers"')
    section = page[start:page.index("</section>", start)]
    out = []
    for attrs, inner in re.findall(r'<tr class="answer"([^>]*)>(.*?)</tr>', section, re.S):
        a = {k: html.unescape(v) for k, v in re.findall(r'data-([\w-]+)="([^"]*)"', attrs)}
        text = html.unescape(re.sub(r"\s+", " ", re.sub(r"<[^>]+>", " ", inner))).strip()
        out.append((a, text))
    return out


def rows_named(results, source, name):
    doc = json.load(open(os.path.join(results, source), encoding="utf-8"))
    return [r for r in doc.get("benchmarks", []) if r.get("run_type") != "aggregate"
            and (r.get("run_name") == name or r.get("name") == name
                 or source.startswith("gpu") and name.endswith(source.split("/")[-1]))]


def check_page(results, page):
    """Failures that hold for any RESULTS_DIR: order of the sections, the named rows meet every limit, each of
    static/walking x CPU/GPU answered or said why not."""
    failures = []
    ids = re.findall(r'<section id="([^"]+)"', page)
    if not ids or ids[0] != "answers":
        failures.append("the page does not open with the answers section: %s" % ids[:3])
    if "claims" in ids and ids.index("claims") != 1:
        failures.append("the claims do not follow the answers: %s" % ids[:3])
    if "viewer" in ids and ids[-1] != "viewer":
        failures.append("the 3-D viewer is not the last section: %s" % ids[-3:])
    rows = answer_rows(page) if "answers" in ids else []
    for category in ("static", "walking"):
        for machine in ("CPU", "GPU"):
            if not any(a.get("category") == category and a.get("machine", "").startswith(machine) for a, _ in rows):
                failures.append("no %s answer on the %s, nor a line saying why" % (category, machine))
    for a, text in rows:
        if a.get("meets") == "1":
            named = rows_named(results, a["source"], a["row"])
            if not named:
                failures.append("answer names %s in %s, not there" % (a["row"], a["source"]))
            for r in named:
                if r.get("meets_limits") != 1 or r.get("limit_misses"):
                    failures.append("answer names %s of %s, which misses a limit (%s)"
                                    % (a["row"], a["source"], r.get("limit_misses")))
            if not re.search(r"one run|median of \d+ runs", text):
                failures.append("answer %s without its spread or 'one run': %s" % (a["row"], text))
        elif a.get("meets") == "0":
            if "no row meets every limit" not in text:
                failures.append("an answer without a row that does not say no row meets every limit: " + text)
        elif a.get("meets") == "none":
            if not re.search(r"no GPU data|no rows", text):
                failures.append("a line without data that does not say so: " + text)
        else:
            failures.append("answer row without data-meets: " + text)
    return failures, rows


def row(name, value, meets, misses=None, unit="ms", iterations=100, fps=None, **kw):
    r = {"name": name, "run_type": "iteration", "real_time": value, "cpu_time": value, "time_unit": unit,
         "iterations": iterations, "meets_limits": 1 if meets else 0, "collider": name.split("/")[2]}
    if fps is not None:
        r["fps"] = fps
    if misses is not None:
        r["limit_misses"] = misses
    r.update(kw)
    return r


def write(path, doc):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        json.dump(doc, f)


def fixture(results):
    context = {"cpu_model": "Test CPU", "num_cpus": 2}
    # static: the shirt's fastest row misses a limit (never the answer); the dress's fastest meeting row has
    # three repetitions (a spread); the trousers meet no limit at all
    reps = []
    for i, t in enumerate((2.0, 2.2, 2.6)):
        reps.append(row("dressing-t1/dress/embree", t, True, run_name="dressing-t1/dress/embree", repetitions=3,
                        repetition_index=i))
    reps.append(dict(reps[1], run_type="aggregate", name="dressing-t1/dress/embree_median", aggregate_name="median"))
    write(os.path.join(results, "dressing-t1.json"), {"context": context, "benchmarks": [
        row("dressing-t1/shirt/bbtree", 1.0, False),
        row("dressing-t1/shirt/is-cpu", 3.0, True),
        row("dressing-t1/shirt/embree", 5.0, True),
        row("dressing-t1/shirt/fcl", 2.0, True, misses=["strain 12 % > 11 %"]),  # meets_limits 1 but a miss named
        row("dressing-t1/dress/bbtree", 1.0, False),
        row("dressing-t1/dress/is-cpu", 3.0, True)] + reps + [
        row("dressing-t1/trousers/is-cpu", 1.0, False),
        row("dressing-t1/trousers/embree", 2.0, False)]})
    # walking: higher frames/s is faster; the fastest misses a limit
    write(os.path.join(results, "walking-t2.json"), {"context": context, "benchmarks": [
        row("walking-t2/skirt/bbtree", 1.0, False, fps=90.0),
        row("walking-t2/skirt/is-cpu", 1.0, True, fps=20.0),
        row("walking-t2/skirt/embree", 1.0, True, fps=30.0),
        row("walking-t2/skirt/is-gl", 1.0, True, fps=10.0)]})
    # a GPU folder with two runs of walking only: the newer one's answer, the older one listed beside it
    for run, date, rows in (("old", "2026-01-01T00:00:00Z", [("is-egl", 50.0, []), ("is-cpu", 40.0, [])]),
                            ("new", "2026-01-02T00:00:00Z", [("is-egl", 35.0, ["strain 20 % > 11 %"]),
                                                              ("is-cpu", 25.0, []), ("embree", 28.0, [])])):
        folder = os.path.join(results, "gpu-test", run)
        os.makedirs(folder, exist_ok=True)
        with open(os.path.join(folder, "environment.txt"), "w") as f:
            f.write("--- nvidia-smi -L\nGPU 0: NVIDIA Test GPU (UUID: x)\n")
        for collider, fps, misses in rows:
            r = row("walking-skirt/%s/x" % collider, 1.0, not misses, misses=misses, fps=fps,
                    device="NVIDIA Test GPU" if collider == "is-egl" else "our CPU rasteriser")
            r["name"] = "walking-skirt/" + collider
            write(os.path.join(folder, "walking-skirt-%s.json" % collider), {
                "context": dict(context, scene="/x/scenes/walking/skirt.toml", date=date, overrides=[]),
                "benchmarks": [r]})
    with open(os.path.join(results, "claims.md"), "w") as f:
        f.write("# claims: The papers' claims\n\n| claim | verdict |\n|---|---|\n| a | holds |\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--source", default=os.path.dirname(os.path.dirname(HERE)), help="the source tree (report/)")
    ap.add_argument("--results", help="a RESULTS_DIR to check as well (copied first; the committed results/)")
    a = ap.parse_args()
    make_report = os.path.join(a.source, "report/make_report.py")
    sys.path.insert(0, os.path.join(a.source, "report"))
    import make_report as mr
    missing = [src for src, _ in mr.LIBS + mr.LICENCES if not os.path.exists(src)]
    if missing:
        print("SKIP: %s missing (apt-get install libjs-three libjs-chart.js)" % missing[0])
        return 77
    failures = []
    work = tempfile.mkdtemp(prefix="answers-test-")
    try:
        results = os.path.join(work, "made-up")
        fixture(results)
        subprocess.run([sys.executable, make_report, results], check=True, stdout=subprocess.DEVNULL)
        page = open(os.path.join(results, "index.html"), encoding="utf-8").read()
        f, rows = check_page(results, page)
        failures += f
        picked = {(a.get("category"), a.get("machine"), text.split(" ")[0]): a for a, text in rows}
        expect = {
            ("static", "shirt"): "dressing-t1/shirt/is-cpu",       # bbtree misses, fcl names a miss
            ("static", "dress"): "dressing-t1/dress/embree",      # 2.2 ms median x 100 < is-cpu's 3.0 ms x 100
            ("walking", "skirt"): "walking-t2/skirt/embree",      # 30 frames/s; bbtree's 90 misses a limit
        }
        for (category, garment), name in expect.items():
            got = [x for (c, m, g), x in picked.items() if c == category and m.startswith("CPU") and g == garment]
            if not got or got[0].get("row") != name:
                failures.append("%s %s: expected %s, the page names %s" % (category, garment, name,
                                                                          got[0].get("row") if got else None))
        texts = {"/".join((text.split(" ")[0], a.get("category", ""), a.get("machine", ""))): text
                 for a, text in rows}
        trousers = texts.get("trousers/static/CPU: Test CPU, 2 cores", "")
        if "no row meets every limit" not in trousers:
            failures.append("trousers (no row within the limits): " + trousers)
        if "0.100 s, misses" not in trousers:
            failures.append("trousers: the fastest of all rows and what it misses not given: " + trousers)
        dress = texts.get("dress/static/CPU: Test CPU, 2 cores", "")
        if "median of 3 runs" not in dress or "0.200-0.260 s" not in dress or "0.220 s" not in dress:
            failures.append("dress: the spread of its three repetitions not given: " + dress)
        if "one run" not in texts.get("shirt/static/CPU: Test CPU, 2 cores", ""):
            failures.append("shirt: 'one run' not said")
        gpu = [(x, t) for x, t in rows if x.get("machine", "").startswith("GPU")]
        static_gpu = [t for x, t in gpu if x.get("category") == "static"]
        if not static_gpu or "no GPU data" not in static_gpu[0]:
            failures.append("static body on the GPU: 'no GPU data' not said: %s" % static_gpu)
        walking_gpu = [x for x, t in gpu if x.get("category") == "walking"]
        if not walking_gpu or walking_gpu[0].get("row") != "gpu-test/new/walking-skirt-embree.json":
            failures.append("walking on the GPU: expected the newest run's embree (28 frames/s within the limits; "
                            "is-egl's 35 misses strain), got %s" % (walking_gpu[0] if walking_gpu else None))
        wtext = [t for x, t in gpu if x.get("category") == "walking"][0] if walking_gpu else ""
        if "run old/" not in wtext or "is-egl" not in wtext or "50.0 frames/s" not in wtext:
            failures.append("walking on the GPU: the older run's winner not listed: " + wtext)
        print("made-up RESULTS_DIR: %d answer rows checked" % len(rows))

        if a.results and os.path.isdir(a.results):
            copy = os.path.join(work, "results")
            shutil.copytree(a.results, copy, ignore=shutil.ignore_patterns("web", "index.html", "*.png"))
            subprocess.run([sys.executable, make_report, copy], check=True, stdout=subprocess.DEVNULL)
            page = open(os.path.join(copy, "index.html"), encoding="utf-8").read()
            f, rows = check_page(copy, page)
            failures += ["%s: %s" % (a.results, x) for x in f]
            for x, text in rows:
                print("  %s %s: %s" % (x.get("category"), x.get("machine"), text[:160]))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    for f in failures:
        print("FAIL: " + f)
    print("answers test: %d failures" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
