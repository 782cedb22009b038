// libFuzzer target: GarmentCode JSON through parse_garmentcode. InputError is the expected answer
// to bad input; any other exception, crash or sanitizer report is a finding. The reference body
// is GarmentCode's mean_female.obj from the data root (CLOTHBENCH_DATA), read once.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "clothbench/io/data_root.hpp"
#include "clothbench/io/errors.hpp"
#include "clothbench/io/garmentcode.hpp"

namespace {

clothbench::Box3 g_reference_body;  // libFuzzer's entry points share no other state

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // the body GarmentCode placed its garments for; without it the run cannot start
  try {
    g_reference_body = clothbench::obj_bounding_box(clothbench::data_path("garments/garmentcode/mean_female.obj"));
  } catch (const clothbench::InputError& e) {
    std::fprintf(stderr, "garmentcode_fuzz: %s (set CLOTHBENCH_DATA)\n", e.what());
    std::exit(2);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // the input as GarmentCode JSON
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    clothbench::parse_garmentcode(text, "fuzz.json", g_reference_body);
  } catch (const clothbench::InputError&) {
  }
  return 0;
}
