#pragma once
/// Errors the CLI reports with exit code 2: bad input, named file (and line), what is wrong.
#include <stdexcept>
#include <string>

namespace clothbench {

/// Bad user input (scene, pattern, mesh, option). `what()` already names the file and line.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// "FILE:LINE: message" (line omitted when 0).
inline std::string located(const std::string& file, int line, const std::string& message) {
  return line > 0 ? file + ":" + std::to_string(line) + ": " + message : file + ": " + message;
}

}  // namespace clothbench
