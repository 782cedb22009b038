#!/usr/bin/env python3
"""The `browser` ctest: results/index.html in headless Chromium (Debian's `chromium`).

Builds a small fixture with the real programs (not a full reproduce): `clothbench reproduce --quick --only
walking-f8` (a table, a chart, a picture), `clothbench run` of a short walking clip with `--gltf` (the
animated file) and of a small dressing with `--gltf` (end state with strain and distance), then
report/make_report.py. Fails on
- a page asset that is not there, or any http(s) asset (the page must work offline),
- any error in the page: console.error, an uncaught exception or rejection, a resource that failed to
  load (the page's first script records them into <html data-errors>),
- a viewer whose model did not load, or a blank 3-D canvas (less than 2 % of its pixels differ from the
  viewer's background in the screenshot),
- a walking animation that does not advance: while the page plays, its clock must run (data-played), and
  the animated canvas must differ between screenshots at two times of the clip (#time=0.05, #time=0.35; with
  #viewer-first, which moves the viewer, the page's last section, under the header),
- a page that does not open with the answers (then the claims, the viewer last), an answer that names a row
  missing a limit (answers_test.py's checks), anything wider than the 1,300 px window (the page, or a table
  scrolling in its box), or a chart with two series of one colour; on the fixture and, where the source tree
  has results/, on the page of those results (copied into WORK/).
Screenshots are left in WORK/. Exit 77 (ctest: skipped) without chromium.
"""
import argparse
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import time
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from answers_test import check_page  # noqa: E402

BACKGROUND = (242, 242, 242)  # viewer.js's clear colour 0xf2f2f2


def read_png(path):
    """(width, height, rows of (r, g, b)) of an 8-bit non-interlaced RGB(A) PNG (Chromium's screenshots)."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", chunk)
            assert depth == 8 and colour in (2, 6) and interlace == 0, "unsupported PNG " + path
            bpp = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += chunk
        pos += 12 + n
    raw, stride, rows, prev = zlib.decompress(idat), width * bpp, [], bytearray(width * bpp)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return width, height, [[tuple(r[x * bpp:x * bpp + 3]) for x in range(width)] for r in rows]


def region(image, rect):
    width, height, rows = image
    x0, y0 = max(0, int(rect["x"]) + 2), max(0, int(rect["y"]) + 2)
    x1, y1 = min(width, int(rect["x"] + rect["width"]) - 2), min(height, int(rect["y"] + rect["height"]) - 2)
    return [rows[y][x] for y in range(y0, y1) for x in range(x0, x1)]


def run(cmd, **kw):
    print("+ " + " ".join(cmd), flush=True)
    return subprocess.run(cmd, check=True, **kw)


def chromium_binary():
    for name in (os.environ.get("CHROMIUM"), "chromium", "chromium-browser", "google-chrome"):
        if name and shutil.which(name):
            return shutil.which(name)
    return None


def chromium(binary, url, budget_ms, extra):
    """Headless Chromium at `url` after `budget_ms` of virtual time; its stdout and stderr."""
    cmd = [binary, "--headless=new", "--no-sandbox", "--disable-gpu", "--enable-unsafe-swiftshader",
           "--use-angle=swiftshader", "--no-first-run", "--disable-extensions", "--hide-scrollbars",
           "--window-size=1300,900", "--force-device-scale-factor=1", "--enable-logging=stderr", "--v=0",
           "--user-data-dir=" + extra.pop("profile"), "--virtual-time-budget=%d" % budget_ms] + extra.pop("args") + [url]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=90)
    return r.stdout, r.stderr


def attribute(dom, name):
    m = re.search(r'\s%s="([^"]*)"' % re.escape(name), dom)
    if not m:
        return None
    return m.group(1).replace("&quot;", '"').replace("&amp;", "&").replace("&lt;", "<").replace("&gt;", ">")


def layout_failures(binary, url, profile, what):
    """The page at 1,300 px (report.js's data-page-overflow, data-wide-tables, data-chart-colours, data-errors)."""
    dom, _ = chromium(binary, url, 6000, {"profile": profile, "args": ["--dump-dom"]})
    out = []
    errors = json.loads(attribute(dom, "data-errors") or '["the page\'s error recorder did not run"]')
    out += ["%s: page error: %s" % (what, e) for e in errors]
    overflow = attribute(dom, "data-page-overflow")
    if overflow != "0":
        out.append("%s: wider than the 1,300 px window by %s px" % (what, overflow))
    wide = json.loads(attribute(dom, "data-wide-tables") or '["report.js did not measure the tables"]')
    out += ["%s: a table wider than its box at 1,300 px: %s" % (what, w) for w in wide]
    for colours in json.loads(attribute(dom, "data-chart-colours") or "[]"):
        if len(set(colours)) != len(colours):
            out.append("%s: a chart repeats a series colour: %s" % (what, colours))
    print("%s at 1,300 px: overflow %s px, %d tables scrolling, %d charts" % (what, overflow, len(wide),
          len(json.loads(attribute(dom, "data-chart-colours") or "[]"))))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--clothbench", required=True)
    ap.add_argument("--source", required=True, help="the source tree (scenes/, report/)")
    ap.add_argument("--work", required=True, help="scratch folder (emptied)")
    a = ap.parse_args()
    binary = chromium_binary()
    if not binary:
        print("SKIP: chromium not installed (apt-get install chromium; `make test` installs it)")
        return 77
    start = time.time()
    shutil.rmtree(a.work, ignore_errors=True)
    results = os.path.join(a.work, "results")
    os.makedirs(os.path.join(results, "pictures"))
    # the fixture, from the real programs
    run([a.clothbench, "reproduce", "--quick", "--only", "walking-f8", "--out", results], stdout=subprocess.DEVNULL)
    scenes = os.path.join(a.source, "scenes")
    run([a.clothbench, "run", os.path.join(scenes, "walking/skirt.toml"), "--quiet", "--set", "garment.vertices=150",
         "--set", "body.start_s=1.0", "--set", "body.end_s=1.5", "--set", "stop.sew_max_s=0.05",
         "--set", "stop.drape_max_s=0.05", "--gltf", os.path.join(results, "pictures/walking-skirt.glb")],
        stdout=subprocess.DEVNULL)
    run([a.clothbench, "run", os.path.join(scenes, "dressing/shirt.toml"), "--quiet", "--set", "garment.vertices=200",
         "--set", "stop.sew_max_s=0.1", "--set", "stop.drape_max_s=0.05",
         "--gltf", os.path.join(results, "pictures/dressing-shirt.glb")], stdout=subprocess.DEVNULL)
    run([sys.executable, os.path.join(a.source, "report/make_report.py"), results])
    fixture_s = time.time() - start
    index = os.path.join(results, "index.html")
    page = open(index, encoding="utf-8").read()
    failures = []

    # every asset the page names is there, and none is fetched from the network
    for ref in re.findall(r'(?:src|href)="([^"#]+)"', page):
        if re.match(r"[a-z]+:", ref):
            failures.append("asset from the network (the page must work offline): " + ref)
        elif not os.path.exists(os.path.join(results, ref)):
            failures.append("missing asset: " + ref)
    figures = len(re.findall(r'<figure class="viewer"', page))
    if figures < 2:
        failures.append("the page has %d 3-D viewers, expected the walking and the dressing model" % figures)

    url = "file://" + os.path.abspath(index)
    # answers first, claims next, the viewer last; no answer names a row that misses a limit
    failures += ["fixture page: " + f for f in check_page(results, page)[0]]
    # the page as it opens at 1,300 px: nothing wider than the window, charts' series in distinct colours
    failures += layout_failures(binary, url, os.path.join(a.work, "profile-layout"), "fixture page")
    source_results = os.path.join(a.source, "results")
    if os.path.exists(os.path.join(source_results, "README.md")):
        copy = os.path.join(a.work, "source-results")
        shutil.copytree(source_results, copy, ignore=shutil.ignore_patterns("web", "index.html", ".chromium-profile"))
        run([sys.executable, os.path.join(a.source, "report/make_report.py"), copy], stdout=subprocess.DEVNULL)
        copy_page = open(os.path.join(copy, "index.html"), encoding="utf-8").read()
        failures += ["results/ page: " + f for f in check_page(copy, copy_page)[0]]
        failures += layout_failures(binary, "file://" + os.path.abspath(os.path.join(copy, "index.html")),
                                    os.path.join(a.work, "profile-source"), "results/ page")
    # the viewers moved to the top (#viewer-first) for the screenshots below
    url += "#viewer-first"
    # the page playing: no errors, every model shown, the clock running
    dom, log = chromium(binary, url, 6000, {"profile": os.path.join(a.work, "profile"), "args": ["--dump-dom"]})
    open(os.path.join(a.work, "chromium.log"), "w").write(log)
    errors = json.loads(attribute(dom, "data-errors") or '["the page\'s error recorder did not run"]')
    failures += ["page error: " + e for e in errors]
    ready = int(attribute(dom, "data-viewers-ready") or 0)
    if ready != figures:
        failures.append("%d of %d viewers showed their model" % (ready, figures))
    played = float(attribute(dom, "data-played") or "nan")
    print("clip played for %.2f s of the page's virtual time" % played)
    if not played > 0.3:
        failures.append("the walking animation's clock does not advance (%s s played)" % played)
    # two screenshots, paused at two times of the clip (#time=...)
    shots = {}
    for n, t in enumerate((0.05, 0.35)):
        shot = os.path.join(a.work, "screenshot-t%.2f.png" % t)
        _, log = chromium(binary, url + "&time=%.2f" % t, 6000,
                          {"profile": os.path.join(a.work, "profile%d" % n), "args": ["--screenshot=" + shot]})
        if os.path.exists(shot):
            shots[t] = read_png(shot)
        else:
            failures.append("no screenshot at #time=%.2f" % t)
    canvases = json.loads(attribute(dom, "data-canvases") or "[]")
    if len(shots) == 2:
        for c in canvases:
            a_px, b_px = region(shots[0.05], c), region(shots[0.35], c)
            drawn = sum(1 for p in a_px if max(abs(p[k] - BACKGROUND[k]) for k in range(3)) > 8) / max(1, len(a_px))
            moved = sum(1 for p, q in zip(a_px, b_px) if p != q) / max(1, len(a_px))
            print("%s: %.1f %% of the canvas drawn, %.2f %% of its pixels differ between the clip's times 0.05 and "
                  "0.35 s" % (c["name"], 100 * drawn, 100 * moved))
            if drawn < 0.02:
                failures.append("blank 3-D canvas: %s (%.2f %% drawn)" % (c["name"], 100 * drawn))
            if c["animated"] and moved < 0.002:
                failures.append("the walking animation does not advance: %s looks the same at 0.05 and 0.35 s" % c["name"])
    if not any(c["animated"] for c in canvases):
        failures.append("no animated viewer on the page")
    print("browser test: fixture %.1f s, total %.1f s; screenshots in %s" % (fixture_s, time.time() - start, a.work))
    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
