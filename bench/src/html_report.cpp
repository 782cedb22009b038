// write_html_report: report/make_report.py, run the way ExperimentContext::chart runs plot.py
#include "html_report.hpp"

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "clothbench/config.h"

namespace clothbench {

bool write_html_report(const std::string& out, bool screenshots) {
  const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string cmd = python + " '" + std::string(CLOTHBENCH_SOURCE_DIR) + "/report/make_report.py' " +
                          (screenshots ? "--screenshots " : "") + "'" + out + "'";
  if (std::system(cmd.c_str()) != 0) {
    std::cerr << "  warning: " << out << "/index.html not written (python3 and Debian's libjs-three and libjs-chart.js "
              << "are needed: apt-get install libjs-three libjs-chart.js)\n";
    return false;
  }
  return true;
}

}  // namespace clothbench
