// write_html_report: report/make_report.py, run as ExperimentContext::chart runs plot.py (run_python_script)
#include "clothbench/experiments/html_report.hpp"

#include <iostream>

#include "clothbench/bench/report.hpp"

namespace clothbench {

bool write_html_report(const std::string& out, bool screenshots) {
  if (run_python_script("report/make_report.py", (screenshots ? "--screenshots '" : "'") + out + "'") != 0) {
    std::cerr << "  warning: " << out << "/index.html not written (python3 and Debian's libjs-three and libjs-chart.js "
              << "are needed: apt-get install libjs-three libjs-chart.js)\n";
    return false;
  }
  return true;
}

}  // namespace clothbench
