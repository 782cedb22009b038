// libFuzzer target: mesh files through load_body (assimp parses, our loader welds, drops open
// parts, checks and normalises). assimp 5.2.5 crashes, aborts or hangs on malformed files within
// seconds of fuzzing (fuzz/README.md lists what was found), so the fuzz bytes do not become the
// file itself: they become a mesh, written as well-formed OBJ, OFF, ASCII PLY or ASCII STL text,
// whose numbers and faces are anything the bytes say: NaN, tiny or enormous coordinates, repeated
// vertices, degenerate, duplicated, open or non-manifold faces, points and lines.
//
// Input: byte 0 picks the format (byte % 4) and, in bits 0-2 of byte / 4, turns off
// require_closed, drop_open_parts, normalise; byte 1 the vertex count (1 + byte % 32); byte 2 the
// scale (2^(byte % 64 - 32)); then 6 bytes per vertex (x, y, z as int16 * scale / 256; -32768 is
// NaN); then faces: a size byte (1 + byte % 4 corners; OFF, PLY and STL take 3 or 4) and one byte
// per corner (vertex byte % count). InputError is the expected answer to a bad mesh; any other
// exception, a crash, a hang, a sanitizer report, or an accepted body whose rest pose fails
// validate_body (garbage taken for a body) is a finding.
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "clothbench/io/body_loader.hpp"
#include "clothbench/io/errors.hpp"

namespace {

enum class Format { kObj, kOff, kPly, kStl };
constexpr std::array<const char*, 4> kExtensions = {".obj", ".off", ".ply", ".stl"};

std::string g_dir;  // this process's folder for the mesh file

// The mesh the fuzz bytes describe.
struct Mesh {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::vector<int>> faces;  // corner indices, 0-based
};

// Reads the vertices and faces that follow the 3 header bytes (see the top of this file).
Mesh decode(const std::uint8_t* data, std::size_t size, Format format) {
  Mesh m;
  const int count = 1 + data[1] % 32;
  const double scale = std::ldexp(1.0, data[2] % 64 - 32) / 256;
  std::size_t at = 3;
  // vertices: three little-endian int16 each
  for (int v = 0; v < count && at + 6 <= size; ++v, at += 6) {
    std::array<double, 3> p{};
    for (int k = 0; k < 3; ++k) {
      const auto raw = static_cast<std::int16_t>(data[at + 2 * k] | (data[at + 2 * k + 1] << 8));
      p[k] = raw == std::numeric_limits<std::int16_t>::min() ? std::nan("") : raw * scale;
    }
    m.vertices.push_back(p);
  }
  if (m.vertices.empty()) return m;
  // faces: a size byte, then one byte per corner
  const int n = static_cast<int>(m.vertices.size());
  while (at < size) {
    const int corners = format == Format::kObj ? 1 + data[at] % 4 : 3 + data[at] % 2;
    ++at;
    if (at + static_cast<std::size_t>(corners) > size) break;
    std::vector<int> face;
    for (int c = 0; c < corners; ++c) face.push_back(data[at++] % n);
    m.faces.push_back(face);
  }
  return m;
}

// The mesh as text of the format (numbers with 9 significant digits; NaN as "nan").
std::string write(const Mesh& m, Format format) {
  std::ostringstream out;
  out.precision(9);
  auto xyz = [&](const std::array<double, 3>& p) { out << p[0] << " " << p[1] << " " << p[2] << "\n"; };
  if (format == Format::kObj) {
    for (const auto& p : m.vertices) {
      out << "v ";
      xyz(p);
    }
    for (const auto& f : m.faces) {
      out << (f.size() == 1 ? "p" : f.size() == 2 ? "l" : "f");
      for (int i : f) out << " " << i + 1;
      out << "\n";
    }
  } else if (format == Format::kOff || format == Format::kPly) {
    if (format == Format::kOff)
      out << "OFF\n" << m.vertices.size() << " " << m.faces.size() << " 0\n";
    else
      out << "ply\nformat ascii 1.0\nelement vertex " << m.vertices.size()
          << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << m.faces.size()
          << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const auto& p : m.vertices) xyz(p);
    for (const auto& f : m.faces) {
      out << f.size();
      for (int i : f) out << " " << i;
      out << "\n";
    }
  } else {
    // STL: triangles only, a quad as two
    out << "solid fuzz\n";
    for (const auto& f : m.faces)
      for (std::size_t t = 0; t + 2 < f.size(); ++t) {
        out << "facet normal 0 0 0\nouter loop\n";
        for (int i : {f[0], f[t + 1], f[t + 2]}) {
          out << "vertex ";
          xyz(m.vertices[static_cast<std::size_t>(i)]);
        }
        out << "endloop\nendfacet\n";
      }
    out << "endsolid fuzz\n";
  }
  return out.str();
}

// abort (a libFuzzer finding) when an accepted body is malformed
void check_body(const clothbench::BodyFrame& frame) {
  try {
    clothbench::validate_body(frame, "rest pose");
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "load_body accepted a malformed body: %s\n", e.what());
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // a private temporary folder: assimp reads files, not memory, through load_body
  std::string pattern = (std::filesystem::temp_directory_path() / "body_fuzz.XXXXXX").string();
  if (!mkdtemp(pattern.data())) {
    std::perror("body_fuzz: mkdtemp");
    std::exit(2);
  }
  g_dir = pattern;
  std::atexit([] {
    std::error_code ignored;
    std::filesystem::remove_all(g_dir, ignored);
  });
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // format and options from the first byte, the mesh from the rest
  if (size < 3) return 0;
  const auto format = static_cast<Format>(data[0] % kExtensions.size());
  const std::size_t flags = data[0] / kExtensions.size();
  clothbench::BodyLoadOptions options;
  options.require_closed = (flags & 1) == 0;
  options.drop_open_parts = (flags & 2) == 0;
  options.normalise = (flags & 4) == 0;
  const std::string path = g_dir + "/body" + kExtensions[static_cast<std::size_t>(format)];
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << write(decode(data, size, format), format);
  }
  try {
    const clothbench::BodyModel body = clothbench::load_body(path, options);
    check_body(body.rest());
  } catch (const clothbench::InputError&) {
  }
  return 0;
}
