"""The answers at the top of results/index.html: which method is fastest at equal accuracy (every accuracy limit
met), on the static body and on the walking one, on this machine's CPU and on a GPU, each with its row and the
spread of its runs.

Read only from RESULTS_DIR, as the rest of the page:
- CPU, static body: dressing-t1.json (every collider, both solver regimes), time to dress = iterations x time per
  iteration (CD&R + CS, the JSON's real_time).
- CPU, walking body: walking-t2.json, frames/s of the walk (the JSON's fps).
- GPU: every run document (`clothbench run --json`: rows with meets_limits) under gpu-*/ folders, one machine kind
  per folder; of each kind the newest run (the context's date) that holds the garment, since timings compare only
  within one run (each run folder is another VM, often another commit). The winner of every other run is listed
  beside it.
A row meets the limits when its meets_limits is 1 and it names no limit_misses (every repetition, where it has
repetitions). A row that misses any limit is never called fastest; where none meets them the answer says so, with
the fastest row and what it misses. Labels come from the experiment's markdown table (the same rows in the same
order) where it lines up with the JSON, else from the JSON's row names.
"""
import html
import json
import os
import re

UNIT_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}
# (category, experiment ID, what the time is)
CPU_SOURCES = [("static", "dressing-t1"), ("walking", "walking-t2")]
LABEL_STOP = {"vertices", "frames", "iterations at dt"}


def num(x, digits=3):
    """x with `digits` significant digits, without exponent for the magnitudes of this page."""
    if x is None:
        return "-"
    if x == 0:
        return "0"
    from math import floor, log10
    decimals = max(0, digits - 1 - int(floor(log10(abs(x)))))
    return "%.*f" % (decimals, x)


def limit_misses(row):
    """The row's limit_misses as the run wrote them (bench/report's row_limit_misses: strings of an array)."""
    m = row.get("limit_misses")
    return [s for s in m if isinstance(s, str)] if isinstance(m, list) else []


def row_meets(row):
    return row.get("meets_limits") == 1 and not limit_misses(row) and not row.get("diverged")


def md_table(path, count):
    """(head, rows) of the first markdown table in `path` with `count` rows, else None."""
    if not os.path.exists(path):
        return None
    lines = open(path, encoding="utf-8").read().splitlines()
    i = 0
    while i < len(lines):
        if lines[i].lstrip().startswith("|") and i + 1 < len(lines) and re.match(r"\s*\|?\s*:?-{3,}", lines[i + 1]):
            j = i + 2
            while j < len(lines) and lines[j].lstrip().startswith("|"):
                j += 1
            split = lambda l: [c.strip() for c in re.split(r"(?<!\\)\|", l.strip().strip("|"))]
            head, rows = split(lines[i]), [split(l) for l in lines[i + 2:j]]
            if len(rows) == count and all(len(r) == len(head) for r in rows):
                return head, rows
            i = j
        else:
            i += 1
    return None


def configurations(doc):
    """One entry per configuration of a result document: its iteration rows (several with repetitions)."""
    groups, order = {}, []
    for row in doc.get("benchmarks", []):
        if row.get("run_type") == "aggregate":
            continue
        key = row.get("run_name", row.get("name")) if row.get("repetitions", 1) > 1 else (row.get("name"), len(order))
        if key not in groups:
            groups[key] = []
            order.append(key)
        groups[key].append(row)
    return [groups[k] for k in order]


def median(values):
    v = sorted(values)
    return v[len(v) // 2] if len(v) % 2 else 0.5 * (v[len(v) // 2 - 1] + v[len(v) // 2])


def measure(runs):
    """(value, unit, higher is better, spread text) of a configuration's runs: frames/s of a walk, else the time
    to the end state (iterations x real_time) [s]."""
    if all("fps" in r for r in runs):
        values, unit, higher = [r["fps"] for r in runs], "frames/s", True
    else:
        values = [r["iterations"] * r["real_time"] * UNIT_MS.get(r.get("time_unit", "ms"), 1.0) / 1e3 for r in runs]
        unit, higher = "s", False
    value = median(values)
    if len(values) < 2:
        spread = "one run"
    else:
        mean = sum(values) / len(values)
        sd = (sum((v - mean) ** 2 for v in values) / (len(values) - 1)) ** 0.5
        spread = "median of %d runs; range %s-%s %s, CV %s %%" % (len(values), num(min(values)), num(max(values)), unit,
                                                                  num(100 * sd / mean, 2))
    return value, unit, higher, spread


def candidates(results, experiment):
    """Every configuration of RESULTS_DIR/experiment.json with its label, group (garment, clip), figure and
    verdict."""
    path = os.path.join(results, experiment + ".json")
    if not os.path.exists(path):
        return None, None
    doc = json.load(open(path, encoding="utf-8"))
    configs = configurations(doc)
    table = md_table(os.path.join(results, experiment + ".md"), len(configs))
    out = []
    for n, runs in enumerate(configs):
        first = runs[0]
        name = first.get("run_name", first.get("name", ""))
        parts = name.split("/")
        label, group, verdict_text = None, None, None
        if table:
            head, cells = table[0], table[1][n]
            stop = next((k for k, h in enumerate(head) if h in LABEL_STOP), 3)
            label = ", ".join(c for c in cells[:stop] if c)
            group = " ".join(cells[k] for k, h in enumerate(head) if h in ("garment", "clip"))
            v = [k for k, h in enumerate(head) if h.startswith("meets the limits")]
            verdict_text = cells[v[0]] if v else None
            # the markdown row must be this configuration's: its collider column is the JSON's collider
            col = [k for k, h in enumerate(head) if h == "collider"]
            if col and first.get("collider") and not cells[col[0]].startswith(first["collider"]):
                label, group, verdict_text = None, None, None
        if label is None:
            label = "/".join(parts[1:]) or name
            group = parts[1] if len(parts) > 1 else name
        value, unit, higher, spread = measure(runs)
        meets = all(row_meets(r) for r in runs)
        misses = sorted({m for r in runs for m in limit_misses(r)})
        if not meets and not misses:
            if verdict_text and verdict_text.lower().startswith("no"):
                misses = [re.sub(r"^no:?\s*", "", verdict_text)]
            elif any(r.get("diverged") for r in runs):
                misses = ["diverged"]
            else:
                misses = ["meets_limits 0"]
        out.append({"name": name, "label": label, "group": group, "value": value, "unit": unit, "higher": higher,
                    "spread": spread, "meets": meets, "misses": misses, "source": experiment + ".json",
                    "anchor": "#" + experiment, "settled": first.get("converged"), "device": first.get("device", ""),
                    "collider": first.get("collider", ""), "runs": len(runs)})
    return doc.get("context", {}), out


def pick(rows):
    """(fastest row meeting every limit or None, fastest row of all, rows meeting, rows)."""
    if not rows:
        return None, None, 0, 0
    key = (lambda r: -r["value"]) if rows[0]["higher"] else (lambda r: r["value"])
    ordered = sorted(rows, key=key)
    good = [r for r in ordered if r["meets"]]
    return (good[0] if good else None), ordered[0], len(good), len(rows)


def gpu_runs(results):
    """{kind folder: {run folder: (context date, GPU name, [candidate rows])}} of every run document under
    RESULTS_DIR/gpu-*/."""
    kinds = {}
    for kind in sorted(os.listdir(results)):
        top = os.path.join(results, kind)
        if not (kind.startswith("gpu") and os.path.isdir(top)):
            continue
        for run in sorted(os.listdir(top)):
            folder = os.path.join(top, run)
            if not os.path.isdir(folder):
                continue
            gpu = ""
            env = os.path.join(folder, "environment.txt")
            if os.path.exists(env):
                m = re.search(r"^GPU \d+: ([^(\n]+)", open(env, encoding="utf-8", errors="replace").read(), re.M)
                gpu = m.group(1).strip() if m else ""
            rows, date = [], ""
            for name in sorted(os.listdir(folder)):
                if not name.endswith(".json"):
                    continue
                try:
                    doc = json.load(open(os.path.join(folder, name), encoding="utf-8"))
                except (ValueError, OSError):
                    continue
                if not isinstance(doc, dict) or not isinstance(doc.get("benchmarks"), list):
                    continue
                context = doc.get("context", {})
                for runs in configurations(doc):
                    first = runs[0]
                    if "meets_limits" not in first:
                        continue  # not a simulation run (a micro-benchmark)
                    scene = context.get("scene", "")
                    walking = "/walking/" in scene or first.get("name", "").startswith("walking")
                    garment = os.path.splitext(os.path.basename(scene))[0] or first["name"].split("/")[0]
                    value, unit, higher, spread = measure(runs)
                    misses = sorted({m for r in runs for m in limit_misses(r)})
                    meets = all(row_meets(r) for r in runs)
                    if not meets and not misses:
                        misses = ["diverged"] if any(r.get("diverged") for r in runs) else ["meets_limits 0"]
                    overrides = context.get("overrides", [])
                    device = first.get("device", "")
                    on_gpu = bool(re.search(r"NVIDIA|AMD Radeon|Intel.*Graphics|GeForce|Tesla", device))
                    label = "%s, %s" % (first.get("collider", "?"), "on the GPU" if on_gpu else "on the host's CPU")
                    shown = [o for o in overrides if not o.startswith("garment.vertices=")]
                    label += "; " + (", ".join(shown) if shown else "the scene as it is")
                    date = max(date, context.get("date", ""))
                    rows.append({"name": "%s/%s/%s" % (kind, run, name), "label": label, "group": garment,
                                 "walking": walking, "value": value, "unit": unit, "higher": higher, "spread": spread,
                                 "meets": meets, "misses": misses, "source": "%s/%s/%s" % (kind, run, name),
                                 "anchor": "%s/%s/%s" % (kind, run, name), "on_gpu": on_gpu,
                                 "collider": first.get("collider", ""), "settled": None, "runs": len(runs)})
            if rows:
                kinds.setdefault(kind, {})[run] = (date, gpu, rows)
    return kinds


def cell_row(r, with_settled):
    text = '<a href="%s">%s</a> <code>%s</code>' % (html.escape(r["anchor"]), html.escape(r["label"]),
                                                    html.escape(r["name"]))
    if with_settled and r.get("settled") is not None:
        text += " (settled: %s)" % ("yes" if r["settled"] else "no")
    return text


def figure(r):
    return "%s %s" % (num(r["value"]), r["unit"])


COLUMNS = 7


def answer_row(category, machine, group, rows, note=""):
    """One <tr> of the answers table; data-* name the picked row for tests."""
    best, fastest, good, total = pick(rows)
    static = category == "static"
    if best:
        answer, value = cell_row(best, static), "<strong>%s</strong>" % figure(best)
        spread = html.escape(best["spread"])
        data = ' data-source="%s" data-row="%s" data-meets="1"' % (html.escape(best["source"]),
                                                                   html.escape(best["name"]))
        cls = "holds"
    else:
        answer, value, spread = "<strong>no row meets every limit</strong>", "-", "-"
        data = ' data-source="%s" data-row="" data-meets="0"' % html.escape(rows[0]["source"]) if rows else ""
        cls = "fails"
    other = "-"
    if fastest and fastest is not best:
        other = "%s: %s, misses %s" % (cell_row(fastest, static), figure(fastest),
                                       html.escape("; ".join(fastest["misses"])))
    return ('<tr class="answer" data-category="%s" data-machine="%s"%s><td>%s</td><td class="%s">%s</td>'
            '<td class="figure">%s</td><td>%s</td><td>%d of %d</td><td>%s</td><td>%s</td></tr>'
            % (category, html.escape(machine), data, html.escape(group), cls, answer, value, spread, good, total, other,
               note))


def group_row(category, machine, what):
    body = "Static body (dressing)" if category == "static" else "Walking body"
    return '<tr class="group"><th colspan="%d">%s, %s%s</th></tr>' % (COLUMNS, body, html.escape(machine),
                                                                     (": " + what) if what else "")


def no_data_row(category, machine, text):
    return ('<tr class="answer" data-category="%s" data-machine="%s" data-meets="none"><td>-</td>'
            '<td class="untestable" colspan="%d">%s</td></tr>' % (category, html.escape(machine), COLUMNS - 1, text))


def section(results):
    """The answers section's HTML."""
    out = ['<section id="answers"><h2>Answers: the fastest method at equal accuracy</h2>',
           '<p>Per garment (and walking clip), the fastest configuration that meets <strong>every</strong> accuracy '
           'limit (its verdict column: inside, depth, crossings, seam gap, strain; at every frame of a walk), with '
           'the spread of its runs; beside it the fastest of all rows where that one misses a limit. Static body: '
           'time to dress = iterations x time per iteration (CD&amp;R + CS, <code>real_time</code> of the JSON; '
           'lower is better). Walking body: frames/s of the walk (<code>fps</code>; higher is better). Every figure '
           'is read from the file the row names.</p>']
    head = ('<div class="table"><table class="answers"><thead><tr><th>garment</th><th>fastest within every limit '
            '(its row)</th><th>time</th><th>spread</th><th>rows within every limit</th><th>fastest of all rows, '
            'if it misses a limit</th><th>notes</th></tr></thead><tbody>')
    body = []
    for category, experiment in CPU_SOURCES:
        context, rows = candidates(results, experiment)
        if not rows:
            body.append(group_row(category, "on the CPU", ""))
            why = "holds none" if rows is not None else "is not here"
            body.append(no_data_row(category, "CPU", "no rows: %s.json %s" % (html.escape(experiment), why)))
            continue
        machine = "CPU: %s, %s cores" % (context.get("cpu_model", "?"), context.get("num_cpus", "?"))
        gl = any(r["device"] and "llvmpipe" in r["device"] for r in rows)
        body.append(group_row(category, "on the " + machine, '<a href="#%s">%s</a>.json%s' % (
            experiment, experiment, "; its OpenGL colliders on Mesa's llvmpipe (no GPU)" if gl else "")))
        groups = []
        for r in rows:
            if r["group"] not in groups:
                groups.append(r["group"])
        for g in groups:
            body.append(answer_row(category, machine, g, [r for r in rows if r["group"] == g], "-"))
    kinds = gpu_runs(results)
    if not kinds:
        for category in ("static", "walking"):
            body.append(group_row(category, "on a GPU", ""))
            body.append(no_data_row(category, "GPU", "no GPU data: no run document under gpu-*/ in this folder"))
    for kind, runs in sorted(kinds.items()):
        gpu = next((g for _, g, _ in runs.values() if g), kind)
        for category in ("static", "walking"):
            rows_of = {run: [r for r in rows if r["walking"] == (category == "walking")]
                       for run, (_, _, rows) in runs.items()}
            garments = []
            for run in sorted(runs, key=lambda k: runs[k][0]):
                for r in rows_of[run]:
                    if r["group"] not in garments:
                        garments.append(r["group"])
            body.append(group_row(category, "on a GPU machine: " + gpu, "the run documents under %s/"
                                  % html.escape(kind)))
            if not garments:
                body.append(no_data_row(category, "GPU: " + gpu, "no GPU data for the %s body under %s/"
                                        % ("static" if category == "static" else "walking", html.escape(kind))))
                continue
            for g in garments:
                held = [run for run in runs if any(r["group"] == g for r in rows_of[run])]
                newest = max(held, key=lambda k: (runs[k][0], k))
                mine = [r for r in rows_of[newest] if r["group"] == g]
                notes = ["newest run %s/%s/ (%s); timings compare within one run only"
                         % (html.escape(kind), html.escape(newest), html.escape(runs[newest][0]))]
                best = pick(mine)[0]
                if best and not best["on_gpu"]:
                    gpu_best = pick([r for r in mine if r["on_gpu"]])[0]
                    if gpu_best:
                        notes.append("the fastest within every limit that uses the GPU: %s, %s"
                                     % (cell_row(gpu_best, False), figure(gpu_best)))
                for run in sorted(held, key=lambda k: runs[k][0], reverse=True):
                    if run == newest:
                        continue
                    b, f, n_good, n = pick([r for r in rows_of[run] if r["group"] == g])
                    notes.append("run %s/: %s" % (html.escape(run), "%s, %s (%d of %d within every limit)"
                                                  % (html.escape(b["label"]), figure(b), n_good, n) if b else
                                                  "no row within every limit (fastest %s, %s)"
                                                  % (html.escape(f["label"]), figure(f))))
                body.append(answer_row(category, "GPU: " + gpu, g, mine, "<br>".join(notes)))
    out.append(head + "".join(body) + "</tbody></table></div></section>")
    return "\n".join(out)
