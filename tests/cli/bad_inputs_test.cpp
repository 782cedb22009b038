// The malformed-input corpus (tests/data/bad/): every file makes clothbench exit 2 with a message
// naming the file, nothing crashes, and no output file is left behind (complete or half-written).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "clothbench/config.h"

namespace {

namespace fs = std::filesystem;

const fs::path kBad = fs::path(CLOTHBENCH_SOURCE_DIR) / "tests" / "data" / "bad";

// the command that reads a corpus file, chosen by its name
std::string command_for(const fs::path& file, const fs::path& out) {
  const std::string name = file.filename().string();
  if (name.rfind("scene_", 0) == 0)
    return "run --quiet '" + file.string() + "' --json '" + (out / "r.json").string() + "' --png '" +
           (out / "r.png").string() + "'";
  if (name.rfind("pattern_", 0) == 0 || name.rfind("garmentcode_", 0) == 0)
    return "garment '" + file.string() + "' --png '" + (out / "g.png").string() + "'";
  return "body '" + file.string() + "'";
}

TEST(BadInputs, EveryCorpusFileExitsTwoNamingTheFile) {
  const char* bin = std::getenv("CLOTHBENCH_BIN");
  if (!bin || !fs::exists(bin)) GTEST_SKIP() << "CLOTHBENCH_BIN not set";
  const fs::path out = fs::temp_directory_path() / ("clothbench_bad_" + std::to_string(::getpid()));
  fs::create_directories(out);
  int files = 0;
  for (const auto& entry : fs::directory_iterator(kBad)) {
    ++files;
    const fs::path log = out / "log";
    const std::string line = std::string(bin) + " " + command_for(entry.path(), out) + " > '" + log.string() + "' 2>&1";
    const int rc = std::system(line.c_str());
    ASSERT_TRUE(WIFEXITED(rc)) << entry.path() << ": killed by a signal";
    std::ifstream in(log);
    const std::string message((std::istreambuf_iterator<char>(in)), {});
    EXPECT_EQ(WEXITSTATUS(rc), 2) << entry.path() << "\n" << message;
    EXPECT_NE(message.find(entry.path().filename().string()), std::string::npos)
        << entry.path() << ": the message does not name the file:\n" << message;
    EXPECT_NE(message.find("error"), std::string::npos) << message;
    for (const char* left : {"r.json", "r.json.tmp", "r.png", "r.png.tmp", "g.png", "g.png.tmp"})
      EXPECT_FALSE(fs::exists(out / left)) << entry.path() << " left " << left;
  }
  fs::remove_all(out);
  EXPECT_GE(files, 40);
}

}  // namespace
