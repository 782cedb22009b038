#pragma once
/// results/index.html: the experiments' tables, charts, claims and a 3-D viewer in one static page.
#include <string>

namespace clothbench {

/// Runs report/make_report.py on OUT (reads only what the experiments wrote there; writes OUT/index.html
/// and OUT/web/); with `screenshots`, where Chromium is installed, also OUT/report-page.png and
/// OUT/report-viewer.png. Returns false (and says why on stderr) when python3 or Debian's libjs-three /
/// libjs-chart.js are missing; the experiments' results stand either way.
bool write_html_report(const std::string& out, bool screenshots);

}  // namespace clothbench
