// write_text_file: PATH.tmp, then renamed.
#include "clothbench/io/text_file.hpp"

#include <filesystem>
#include <fstream>

#include "clothbench/io/errors.hpp"

namespace clothbench {

void write_text_file(const std::string& path, const std::string& text) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(path).parent_path();
  std::error_code ec;
  if (!dir.empty()) fs::create_directories(dir, ec);
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError(path + ": cannot write (is the directory writable?)");
    out << text;
    if (!out.flush()) {
      fs::remove(tmp, ec);
      throw InputError(path + ": write failed");
    }
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw InputError(path + ": cannot rename the temporary file: " + ec.message());
  }
}

}  // namespace clothbench
