#!/usr/bin/env python3
"""results/index.html: every experiment's tables, charts and claims in one static page, with a 3-D viewer.

Answers first (answers.py: the fastest configuration within every accuracy limit, static and walking, on the CPU
and on a GPU, with its row and spread), then the claims with their verdicts, then every experiment's tables and
charts, the interactive Pareto charts and the 3-D viewer.

Run by `clothbench reproduce` after the experiments (also on its own: make_report.py RESULTS_DIR). It reads
only what the experiments wrote into RESULTS_DIR (README.md, ID.md, ID.json, the charts, pictures/*.glb, the run
documents under gpu-*/) and
writes RESULTS_DIR/index.html plus RESULTS_DIR/web/: the page's script and style (from report/ in the source
tree), three.js r111 and Chart.js 3 copied from Debian's libjs-three and libjs-chart.js with their copyright
files, and each glb as a script (web/models/NAME.js, base64) so that the page works from file:// (browsers
refuse fetch() there). Nothing is typed in: a number on the page is a number in RESULTS_DIR.
"""
import base64
import html
import json
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import answers  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
# Debian's files: (source, name under web/)
THREE = "/usr/share/javascript/three"
LIBS = [
    (THREE + "/three.min.js", "three.min.js"),
    (THREE + "/examples/js/loaders/GLTFLoader.js", "GLTFLoader.js"),
    (THREE + "/examples/js/controls/OrbitControls.js", "OrbitControls.js"),
    ("/usr/share/javascript/chart.js/chart.min.js", "chart.min.js"),
]
LICENCES = [("/usr/share/doc/libjs-three/copyright", "LICENSE-three.txt"),
            ("/usr/share/doc/libjs-chart.js/copyright", "LICENSE-chart.js.txt")]
OWN = ["report.js", "report.css", "viewer.js"]


def inline(text):
    """Markdown inline markup of the experiments' files: images, links, code, bold."""
    out, pos = [], 0
    pattern = re.compile(r"!\[([^\]]*)\]\(([^)\s]+)\)|\[([^\]]+)\]\(([^)\s]+)\)|`([^`]+)`|\*\*([^*]+)\*\*")
    for m in pattern.finditer(text):
        out.append(html.escape(text[pos:m.start()], quote=False))
        if m.group(2):
            out.append('<img src="%s" alt="%s" loading="lazy">' % (html.escape(m.group(2)), html.escape(m.group(1))))
        elif m.group(4):
            href = m.group(4)
            # a link to another experiment's markdown goes to its section of this page
            target = re.fullmatch(r"([\w.-]+)\.md", href)
            if target and target.group(1) != "README":
                href = "#" + target.group(1)
            out.append('<a href="%s">%s</a>' % (html.escape(href), inline(m.group(3))))
        elif m.group(5):
            out.append("<code>%s</code>" % html.escape(m.group(5), quote=False))
        else:
            out.append("<strong>%s</strong>" % inline(m.group(6)))
        pos = m.end()
    out.append(html.escape(text[pos:], quote=False))
    return "".join(out)


def cells(line):
    line = line.strip()
    if line.startswith("|"):
        line = line[1:]
    if line.endswith("|"):
        line = line[:-1]
    return [c.strip() for c in re.split(r"(?<!\\)\|", line)]


def verdict_class(text):
    t = text.lower()
    if t.startswith("holds (") or t == "holds" or t.startswith("holds:") or t.startswith("holds for every"):
        return "holds"
    if t.startswith("fails") or t.startswith("no"):
        return "fails"
    if t.startswith("untestable"):
        return "untestable"
    if t.startswith("holds") or t.startswith("partly"):
        return "partly"
    return ""


def table(lines):
    head = cells(lines[0])
    verdict_col = [i for i, h in enumerate(head) if h in ("verdict", "meets the limits", "meets the limits (every frame)")]
    rows = [cells(l) for l in lines[2:]]
    # a table of many columns in a smaller font, so that it fits 1,300 px without scrolling
    out = ['<div class="table"><table class="sortable%s"><thead><tr>' % (" many" if len(head) >= 16 else "")]
    out += ['<th title="sort">%s</th>' % inline(h) for h in head]
    out.append("</tr></thead><tbody>")
    for r in rows:
        out.append("<tr>")
        for i, c in enumerate(r):
            cls = verdict_class(c) if i in verdict_col else ""
            out.append('<td%s>%s</td>' % (' class="%s"' % cls if cls else "", inline(c)))
        out.append("</tr>")
    out.append("</tbody></table></div>")
    return "".join(out)


def markdown(text, skip_title=True):
    """The subset of markdown the experiments write: headings, tables, lists, paragraphs."""
    lines = text.splitlines()
    out, i = [], 0
    while i < len(lines):
        line = lines[i]
        if not line.strip():
            i += 1
            continue
        m = re.match(r"(#+)\s+(.*)", line)
        if m:
            if not (skip_title and len(m.group(1)) == 1):
                level = min(6, len(m.group(1)) + 2)
                out.append("<h%d>%s</h%d>" % (level, inline(m.group(2)), level))
            i += 1
            continue
        if line.lstrip().startswith("|") and i + 1 < len(lines) and re.match(r"\s*\|?\s*:?-{3,}", lines[i + 1]):
            j = i
            while j < len(lines) and lines[j].lstrip().startswith("|"):
                j += 1
            out.append(table(lines[i:j]))
            i = j
            continue
        if re.match(r"\s*[-*] ", line):
            items = []
            while i < len(lines) and re.match(r"\s*[-*] ", lines[i]):
                items.append("<li>%s</li>" % inline(re.sub(r"^\s*[-*] ", "", lines[i])))
                i += 1
            out.append("<ul>%s</ul>" % "".join(items))
            continue
        para = []
        while i < len(lines) and lines[i].strip() and not lines[i].lstrip().startswith(("|", "#")) \
                and not re.match(r"\s*[-*] ", lines[i]):
            para.append(lines[i])
            i += 1
        out.append("<p>%s</p>" % inline(" ".join(para)))
    return "\n".join(out)


def index_entries(results):
    """(id, title) of README.md's index, else of the ID.md files present."""
    entries, machine = [], ""
    readme = os.path.join(results, "README.md")
    if os.path.exists(readme):
        for line in open(readme, encoding="utf-8"):
            if line.startswith("Machine:"):
                machine = line.strip()
            m = re.match(r"\|\s*([\w-]+)\s*\|\s*([^|]+)\|\s*\[", line)
            if m and os.path.exists(os.path.join(results, m.group(1) + ".md")):
                entries.append((m.group(1), m.group(2).strip()))
    known = {e[0] for e in entries}
    for name in sorted(os.listdir(results)):
        stem = name[:-3]
        if name.endswith(".md") and name != "README.md" and stem not in known:
            title = open(os.path.join(results, name), encoding="utf-8").readline().strip("# \n")
            entries.append((stem, title.split(": ", 1)[-1]))
    return entries, machine


def pareto_data(results):
    """Pareto's rows for the interactive chart: time per iteration [ms] against crossings and inside [%]."""
    path = os.path.join(results, "pareto.json")
    if not os.path.exists(path):
        return None
    unit = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}
    points = []
    for row in json.load(open(path, encoding="utf-8")).get("benchmarks", []):
        if row.get("run_type") == "aggregate" or "real_time" not in row:
            continue
        parts = row["name"].split("/")
        if len(parts) < 4:
            continue
        points.append({"name": row["name"], "garment": parts[1], "method": parts[2],
                       "ms": row["real_time"] * unit.get(row.get("time_unit", "ms"), 1.0),
                       "crossings": row.get("crossings_pct", 0), "inside": row.get("inside_pct", 0),
                       "vertices": row.get("vertices", 0), "meets": row.get("meets_limits", 0)})
    return points


def models(results, web):
    """Every glb under pictures/ as web/models/NAME.js; (name, is_animated, frames) per model."""
    found = []
    pictures = os.path.join(results, "pictures")
    os.makedirs(os.path.join(web, "models"), exist_ok=True)
    for name in sorted(os.listdir(pictures)) if os.path.isdir(pictures) else []:
        if not name.endswith(".glb"):
            continue
        data = open(os.path.join(pictures, name), "rb").read()
        n = int.from_bytes(data[12:16], "little")
        doc = json.loads(data[20:20 + n])
        stem = name[:-4]
        animated = bool(doc.get("animations"))
        fields = any("_STRAIN" in p["attributes"] for m in doc.get("meshes", []) for p in m["primitives"])
        with open(os.path.join(web, "models", stem + ".js"), "w") as f:
            f.write("clothbenchModel(%s, \"%s\");\n" % (json.dumps(stem), base64.b64encode(data).decode()))
        found.append({"name": stem, "glb": "pictures/" + name, "animated": animated, "fields": fields,
                      "frames": doc.get("extras", {}).get("frames", 0), "kib": len(data) // 1024})
    return found


def screenshots(results):
    """report-viewer.png (the 3-D viewers, moved to the top by the page's #viewer-first) and report-page.png (the
    top of the page as it opens: the answers, then the claims), by headless Chromium where it is installed; a clip
    still plays at the time it is taken."""
    binary = shutil.which("chromium") or shutil.which("chromium-browser")
    if not binary:
        print("make_report.py: no chromium, no screenshots (apt-get install chromium)")
        return
    url = "file://" + os.path.abspath(os.path.join(results, "index.html"))
    profile = os.path.join(results, ".chromium-profile")
    for name, height, hash_ in (("report-viewer.png", 900, "#viewer-first"), ("report-page.png", 2400, "")):
        cmd = [binary, "--headless=new", "--no-sandbox", "--disable-gpu", "--enable-unsafe-swiftshader",
               "--use-angle=swiftshader", "--hide-scrollbars", "--force-device-scale-factor=1",
               "--window-size=1300,%d" % height, "--user-data-dir=" + profile, "--virtual-time-budget=6000",
               "--screenshot=" + os.path.join(results, name), url + hash_]
        try:
            subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=120, check=True)
        except (subprocess.SubprocessError, OSError) as e:
            print("make_report.py: screenshot %s failed: %s" % (name, e))
    shutil.rmtree(profile, ignore_errors=True)


def main():
    args = [a for a in sys.argv[1:] if a != "--screenshots"]
    if len(args) != 1:
        sys.exit("usage: make_report.py [--screenshots] RESULTS_DIR")
    results = args[0]
    web = os.path.join(results, "web")
    os.makedirs(web, exist_ok=True)
    for src, dst in LIBS + LICENCES:
        if not os.path.exists(src):
            sys.exit("make_report.py: %s missing (apt-get install libjs-three libjs-chart.js)" % src)
        shutil.copyfile(src, os.path.join(web, dst))
    for name in OWN:
        shutil.copyfile(os.path.join(HERE, name), os.path.join(web, name))
    entries, machine = index_entries(results)
    found = models(results, web)
    # stale model scripts of glbs no longer there
    for name in os.listdir(os.path.join(web, "models")):
        if name[:-3] not in {m["name"] for m in found}:
            os.remove(os.path.join(web, "models", name))
    pareto = pareto_data(results)

    body = []
    # answers first, then the claims with their verdicts, then every experiment's tables, the interactive charts
    # and the 3-D viewer
    claims = [e for e in entries if e[0] == "claims"]
    ordered = claims + [e for e in entries if e[0] != "claims"]
    nav = ['<a href="#answers">answers</a>'] + ['<a href="#claims">claims</a>' for _ in claims]
    nav += ['<a href="#index">experiments</a>'] + ['<a href="#%s">%s</a>' % (i, i) for i, _ in entries if i != "claims"]
    nav += (['<a href="#pareto-interactive">Pareto (interactive)</a>'] if pareto else []) + ['<a href="#viewer">3-D viewer</a>']
    body.append('<nav>%s</nav>' % " ".join(nav))
    body.append(answers.section(results))

    def experiment_section(i, title):
        text = open(os.path.join(results, i + ".md"), encoding="utf-8").read()
        links = '<a href="%s.md">%s.md</a>' % (i, i)
        if os.path.exists(os.path.join(results, i + ".json")):
            links += ', <a href="%s.json">%s.json</a>' % (i, i)
        return ('<section id="%s"><h2>%s: %s</h2><p class="files">%s</p>%s</section>'
                % (i, i, html.escape(title), links, markdown(text)))

    for i, title in claims:
        body.append(experiment_section(i, title))

    body.append('<section id="index"><h2>Experiments</h2><div class="table"><table class="sortable"><thead><tr>'
                '<th>ID</th><th>what</th><th>markdown</th><th>data</th></tr></thead><tbody>')
    for i, title in ordered:
        data = '<a href="%s.json">%s.json</a>' % (i, i) if os.path.exists(os.path.join(results, i + ".json")) else "-"
        body.append('<tr><td><a href="#%s">%s</a></td><td>%s</td><td><a href="%s.md">%s.md</a></td><td>%s</td></tr>'
                    % (i, i, html.escape(title), i, i, data))
    body.append("</tbody></table></div></section>")

    for i, title in entries:
        if i != "claims":
            body.append(experiment_section(i, title))

    if pareto:
        body.append('<section id="pareto-interactive"><h2>Speed against accuracy (pareto.json, interactive)</h2>'
                    '<p>Every configuration of <a href="#pareto">pareto</a>: time per iteration against the share of '
                    'structural springs crossing the body; hover a point for its configuration. Filled points meet the '
                    'limits; each series its own colour and marker.</p><div class="charts" id="pareto-charts"></div>'
                    '<script>var CLOTHBENCH_PARETO = %s;</script></section>' % json.dumps(pareto))

    body.append('<section id="viewer"><h2>3-D viewer</h2>')
    if not found:
        body.append("<p>No glTF files under <code>pictures/</code>.</p>")
    else:
        body.append('<p>Drag to orbit, wheel to zoom, right-drag to pan. Cloth colours: per panel, by strain (largest '
                    'structural strain at the vertex, white 0 to red 20 %, blue compressed) or by signed distance to '
                    'the body from the oracle (red inside, white at the surface to blue 2 cm out). Animated files play '
                    'on one clock: every walking viewer shows the same time of the clip.</p>')
        body.append('<div class="controls"><label>cloth colour <select id="colour-mode"><option value="panels">panels'
                    '</option><option value="strain">strain</option><option value="distance">distance to the body'
                    '</option></select></label>')
        if any(m["animated"] for m in found):
            body.append(' <button id="play">pause</button> <input id="time" type="range" min="0" max="1000" value="0">'
                        ' <span id="time-label">0.00 s</span>')
        body.append('</div><div class="viewers">')
        for m in found:
            what = ("animated, %d frames" % m["frames"]) if m["animated"] else "end state"
            body.append('<figure class="viewer" data-model="%s" data-animated="%d" data-fields="%d"><div class="canvas">'
                        '</div><figcaption><a href="%s">%s</a> (%s, %d KiB)</figcaption></figure>'
                        % (html.escape(m["name"]), m["animated"], m["fields"], html.escape(m["glb"]),
                           html.escape(m["glb"]), what, m["kib"]))
        body.append("</div>")
    body.append("</section>")

    scripts = ["web/three.min.js", "web/GLTFLoader.js", "web/OrbitControls.js", "web/chart.min.js", "web/viewer.js",
               "web/report.js"] + ["web/models/%s.js" % m["name"] for m in found]
    page = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>clothbench results</title>
<meta name="viewport" content="width=device-width, initial-scale=1">
<link rel="stylesheet" href="web/report.css">
<script>/* every error (console.error, uncaught, a resource that failed to load) into <html data-errors>: the browser test reads it */
(function () {
  var errors = [], root = document.documentElement, error = console.error;
  function note(text) { errors.push(String(text)); root.setAttribute("data-errors", JSON.stringify(errors)); }
  root.setAttribute("data-errors", "[]");
  console.error = function () { note(Array.prototype.join.call(arguments, " ")); error.apply(console, arguments); };
  window.addEventListener("error", function (e) {
    var t = e.target;
    note(t && t !== window && (t.src || t.href) ? "failed to load " + (t.src || t.href) : e.message);
  }, true);
  window.addEventListener("unhandledrejection", function (e) { note("unhandled rejection: " + e.reason); });
})();</script></head>
<body><header><h1>clothbench results</h1><p>Written by <code>clothbench reproduce</code> from the files of this
folder; never edited by hand. %s</p><p class="files">three.js r111 and Chart.js 3 from Debian
(<a href="web/LICENSE-three.txt">three.js licence</a>, <a href="web/LICENSE-chart.js.txt">Chart.js licence</a>).</p>
</header>
%s
%s
</body></html>
""" % (inline(machine), "\n".join(body), "\n".join('<script src="%s"></script>' % s for s in scripts))
    tmp = os.path.join(results, "index.html.tmp")
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(page)
    os.replace(tmp, os.path.join(results, "index.html"))
    total = os.path.getsize(os.path.join(results, "index.html"))
    for root, _, files in os.walk(web):
        total += sum(os.path.getsize(os.path.join(root, f)) for f in files)
    if "--screenshots" in sys.argv:
        screenshots(results)
    print("index.html: %d experiments, %d 3-D models, page and web/ %.1f MB" % (len(entries), len(found), total / 1e6))


if __name__ == "__main__":
    main()
