// write_viewer_gltf: a glTF 2.0 binary written by hand (JSON chunk + BIN chunk), morph-target animation.
#include "clothbench/io/viewer_gltf.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "clothbench/io/errors.hpp"
#include "clothbench/io/text_file.hpp"

namespace clothbench {

namespace {

using nlohmann::json;

constexpr int kFloat = 5126, kShort = 5122, kUInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;


// the panel of a cloth vertex (0 for a cloth without panels)
int cloth_vertex_panel(const ClothMesh& cloth, Eigen::Index v) {
  return cloth.panel.empty() ? 0 : cloth.panel[std::size_t(v)];
}

class Glb {
 public:
  json doc = {{"asset", {{"version", "2.0"}, {"generator", "clothbench export_viewer_gltf"}}},
              {"buffers", json::array()}, {"bufferViews", json::array()}, {"accessors", json::array()}};

  // a buffer view of `bytes` at a 4-byte aligned offset
  int view(const void* data, std::size_t bytes, int target, int stride = 0) {
    while (bin_.size() % 4) bin_.push_back('\0');
    json v = {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", bytes}};
    if (target) v["target"] = target;
    if (stride) v["byteStride"] = stride;
    bin_.append(static_cast<const char*>(data), bytes);
    doc["bufferViews"].push_back(v);
    return int(doc["bufferViews"].size()) - 1;
  }
  int accessor(int view, int component, std::size_t count, const char* type, json extra = json::object()) {
    json a = {{"bufferView", view}, {"componentType", component}, {"count", count}, {"type", type}};
    a.update(extra);
    doc["accessors"].push_back(a);
    return int(doc["accessors"].size()) - 1;
  }
  int floats(const std::vector<float>& v, const char* type, int target, bool bounds) {
    const int width = std::string(type) == "VEC3" ? 3 : 1;
    json extra = json::object();
    if (bounds) {
      std::vector<float> lo(width, std::numeric_limits<float>::max()), hi(width, std::numeric_limits<float>::lowest());
      for (std::size_t i = 0; i < v.size(); ++i) {
        lo[i % width] = std::min(lo[i % width], v[i]);
        hi[i % width] = std::max(hi[i % width], v[i]);
      }
      if (v.empty()) lo = hi = std::vector<float>(width, 0.f);
      extra = {{"min", lo}, {"max", hi}};
    }
    return accessor(view(v.data(), v.size() * sizeof(float), target), kFloat, v.size() / width, type, extra);
  }
  // offsets [m], all within 1 m: int16 normalised VEC3, each element padded to 8 bytes (4-byte aligned)
  int shorts(const std::vector<float>& v) {
    std::vector<std::int16_t> q(v.size() / 3 * 4, 0);
    std::vector<int> lo(3, 32767), hi(3, -32767);
    for (std::size_t i = 0; i < v.size(); ++i) {
      const int s = int(std::lround(double(v[i]) * 32767.0));
      q[i / 3 * 4 + i % 3] = std::int16_t(s);
      lo[i % 3] = std::min(lo[i % 3], s);
      hi[i % 3] = std::max(hi[i % 3], s);
    }
    if (v.empty()) lo = hi = {0, 0, 0};
    // min/max of a normalised accessor: its dequantised values
    std::vector<float> flo(3), fhi(3);
    for (int k = 0; k < 3; ++k) flo[k] = float(lo[k]) / 32767.f, fhi[k] = float(hi[k]) / 32767.f;
    return accessor(view(q.data(), q.size() * sizeof(std::int16_t), kArrayBuffer, 8), kShort, v.size() / 3, "VEC3",
                    {{"normalized", true}, {"min", flo}, {"max", fhi}});
  }
  int uints(const std::vector<std::uint32_t>& v) {
    return accessor(view(v.data(), v.size() * sizeof(std::uint32_t), kElementArrayBuffer), kUInt, v.size(), "SCALAR");
  }
  void write(const std::string& path) {
    while (bin_.size() % 4) bin_.push_back('\0');
    doc["buffers"].push_back({{"byteLength", bin_.size()}});
    std::string text = doc.dump();
    while (text.size() % 4) text.push_back(' ');
    const auto u32 = [](std::string& s, std::uint32_t x) {
      for (int k = 0; k < 4; ++k) s.push_back(char((x >> (8 * k)) & 0xff));
    };
    std::string out;
    u32(out, 0x46546C67);  // "glTF"
    u32(out, 2);
    u32(out, std::uint32_t(12 + 8 + text.size() + 8 + bin_.size()));
    u32(out, std::uint32_t(text.size()));
    u32(out, 0x4E4F534A);  // "JSON"
    out += text;
    u32(out, std::uint32_t(bin_.size()));
    u32(out, 0x004E4942);  // "BIN\0"
    out += bin_;
    write_text_file(path, out);
  }

 private:
  std::string bin_;
};

// one mesh of the file: its vertices (indices into the source positions) and triangles
struct Part {
  std::string name;
  std::vector<Eigen::Index> vertices;
  std::vector<std::uint32_t> triangles;  // in the part's numbering
  std::array<float, 3> colour;
  bool cloth;
};

std::vector<float> gather(const Points3& p, const std::vector<Eigen::Index>& vertices) {
  std::vector<float> out;
  out.reserve(3 * vertices.size());
  for (Eigen::Index v : vertices)
    for (int k = 0; k < 3; ++k) out.push_back(float(p(k, v)));
  return out;
}

}  // namespace

std::vector<std::size_t> kept_frames(std::size_t count, int max_frames) {
  std::vector<std::size_t> kept;
  if (count == 0) return kept;
  const std::size_t n = std::min<std::size_t>(count, std::size_t(std::max(2, max_frames)));
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t f = n == 1 ? 0 : (i * (count - 1) + (n - 1) / 2) / (n - 1);
    if (kept.empty() || kept.back() != f) kept.push_back(f);
  }
  return kept;
}

void write_viewer_gltf(const std::string& path, const BodyFrame& body, const ClothMesh& cloth, const ViewerStyle& style,
                        const std::vector<ViewerFrame>& frames, int max_frames) {
  const Eigen::Index nb = body.positions.cols(), nc = cloth.positions.cols();
  for (const auto& f : frames)
    if (f.body.cols() != nb || f.cloth.cols() != nc)
      throw std::invalid_argument(path + ": glTF export: a frame's vertex counts differ from the body's or the cloth's");
  if (body.triangles.size() > 0 && (body.triangles.minCoeff() < 0 || body.triangles.maxCoeff() >= nb))
    throw std::invalid_argument(path + ": glTF export: body triangle index out of range");
  if (cloth.quads.size() > 0 && (cloth.quads.minCoeff() < 0 || cloth.quads.maxCoeff() >= nc))
    throw std::invalid_argument(path + ": glTF export: cloth quad index out of range");
  const std::vector<std::size_t> kept = kept_frames(frames.size(), max_frames);
  // the base pose: the end state, or the first kept frame
  BodyFrame base_body = body;
  Points3 base_cloth = cloth.positions;
  if (!kept.empty()) {
    base_body.positions = frames[kept[0]].body;
    base_cloth = frames[kept[0]].cloth;
  }

  // the parts: the body, then one per panel (every vertex of the panel, also those in no quad)
  std::vector<Part> parts;
  {
    Part b{"body", {}, {}, {0.78f, 0.75f, 0.71f}, false};
    for (Eigen::Index v = 0; v < nb; ++v) b.vertices.push_back(v);
    for (Eigen::Index k = 0; k < body.triangles.size(); ++k) b.triangles.push_back(std::uint32_t(body.triangles.data()[k]));
    parts.push_back(std::move(b));
  }
  const int panels = std::max<int>(1, int(cloth.panel_names.size()));
  std::vector<int> index(std::size_t(nc), -1);
  const Tris triangles = cloth.surface_triangles();
  for (int p = 0; p < panels; ++p) {
    Part part{p < int(cloth.panel_names.size()) ? cloth.panel_names[std::size_t(p)] : "cloth", {}, {}, {}, true};
    part.colour = style.panel_colour(p);
    for (Eigen::Index v = 0; v < nc; ++v)
      if (cloth_vertex_panel(cloth, v) == p) {
        index[std::size_t(v)] = int(part.vertices.size());
        part.vertices.push_back(v);
      }
    for (Eigen::Index t = 0; t < triangles.cols(); ++t) {
      const auto c = triangles.col(t);
      if (cloth_vertex_panel(cloth, c(0)) != p) continue;
      if (index[std::size_t(c(0))] < 0 || index[std::size_t(c(1))] < 0 || index[std::size_t(c(2))] < 0) continue;
      for (int k = 0; k < 3; ++k) part.triangles.push_back(std::uint32_t(index[std::size_t(c(k))]));
    }
    parts.push_back(std::move(part));
  }

  // the fields on the base pose: strain of the structural springs, signed distance from the oracle
  std::vector<float> strain(std::size_t(nc), 0.f);
  std::vector<bool> has_spring(std::size_t(nc), false);
  for (Eigen::Index s = 0; s < cloth.springs.cols(); ++s) {
    if (std::size_t(s) < cloth.kind.size() && cloth.kind[std::size_t(s)] != SpringKind::kStructural) continue;
    const int a = cloth.springs(0, s), b = cloth.springs(1, s);
    const double l0 = cloth.rest_length(s);
    if (!(l0 > 0)) continue;
    const float e = float((base_cloth.col(a) - base_cloth.col(b)).norm() / l0 - 1.0);
    for (int v : {a, b}) {
      strain[std::size_t(v)] = has_spring[std::size_t(v)] ? std::max(strain[std::size_t(v)], e) : e;
      has_spring[std::size_t(v)] = true;
    }
  }
  std::vector<Real> distance;
  if (nc > 0 && body.triangles.cols() > 0) style.signed_distance(base_body, base_cloth, distance);
  distance.resize(std::size_t(nc), 0.f);
  for (auto& d : distance)
    if (!std::isfinite(d)) d = 0.f;

  Glb glb;
  json& doc = glb.doc;
  doc["meshes"] = json::array();
  doc["materials"] = json::array();
  doc["nodes"] = json::array();
  bool quantised = false;
  // the animation's keys: times from the first kept frame, key i weighs target i - 1 fully (key 0: the base)
  const std::size_t targets = kept.empty() ? 0 : kept.size() - 1;
  for (const Part& part : parts) {
    const Points3& base = part.cloth ? base_cloth : base_body.positions;
    const std::vector<float> positions = gather(base, part.vertices);
    json attributes = {{"POSITION", glb.floats(positions, "VEC3", kArrayBuffer, true)}};
    if (part.cloth) {
      std::vector<float> s, d;
      for (Eigen::Index v : part.vertices) {
        s.push_back(strain[std::size_t(v)]);
        d.push_back(float(distance[std::size_t(v)]));
      }
      attributes["_STRAIN"] = glb.floats(s, "SCALAR", kArrayBuffer, true);
      attributes["_DISTANCE"] = glb.floats(d, "SCALAR", kArrayBuffer, true);
    }
    json primitive = {{"attributes", attributes}, {"material", doc["materials"].size()}, {"mode", 4}};
    if (!part.triangles.empty()) primitive["indices"] = glb.uints(part.triangles);
    else primitive["mode"] = 0;  // points only
    json mesh = {{"name", part.name}, {"primitives", json::array()}};
    if (targets) {
      json list = json::array();
      for (std::size_t i = 1; i < kept.size(); ++i) {
        const ViewerFrame& f = frames[kept[i]];
        const std::vector<float> now = gather(part.cloth ? f.cloth : f.body, part.vertices);
        std::vector<float> offset(now.size());
        float largest = 0;
        for (std::size_t k = 0; k < now.size(); ++k) {
          offset[k] = now[k] - positions[k];
          largest = std::max(largest, std::fabs(offset[k]));
        }
        const bool fits = std::isfinite(largest) && largest < 0.999f;
        quantised = quantised || fits;
        list.push_back({{"POSITION", fits ? glb.shorts(offset) : glb.floats(offset, "VEC3", kArrayBuffer, true)}});
      }
      primitive["targets"] = list;
      mesh["weights"] = std::vector<float>(targets, 0.f);
    }
    mesh["primitives"].push_back(primitive);
    const float* c = part.colour.data();
    doc["materials"].push_back({{"name", part.name},
                                {"doubleSided", part.cloth},
                                {"pbrMetallicRoughness",
                                 {{"baseColorFactor", {c[0], c[1], c[2], 1.f}}, {"metallicFactor", 0.f}, {"roughnessFactor", 0.8f}}}});
    doc["nodes"].push_back({{"name", part.name}, {"mesh", doc["meshes"].size()}});
    doc["meshes"].push_back(mesh);
  }
  std::vector<int> roots;
  for (std::size_t i = 0; i < parts.size(); ++i) roots.push_back(int(i));
  doc["scenes"] = json::array({{{"name", "clothbench"}, {"nodes", roots}}});
  doc["scene"] = 0;
  if (targets) {
    std::vector<float> times, weights;
    for (std::size_t i = 0; i < kept.size(); ++i) {
      times.push_back(float(frames[kept[i]].t_s - frames[kept[0]].t_s));
      for (std::size_t t = 0; t < targets; ++t) weights.push_back(i > 0 && t == i - 1 ? 1.f : 0.f);
    }
    // keyframe times must increase strictly
    for (std::size_t i = 1; i < times.size(); ++i) times[i] = std::max(times[i], times[i - 1] + 1e-4f);
    const int input = glb.floats(times, "SCALAR", 0, true);
    const int output = glb.floats(weights, "SCALAR", 0, false);
    json channels = json::array();
    for (std::size_t i = 0; i < parts.size(); ++i)
      channels.push_back({{"sampler", 0}, {"target", {{"node", i}, {"path", "weights"}}}});
    doc["animations"] = json::array(
        {{{"name", "walk"}, {"samplers", json::array({{{"input", input}, {"output", output}, {"interpolation", "LINEAR"}}})},
          {"channels", channels}}});
  }
  if (quantised) doc["extensionsUsed"] = doc["extensionsRequired"] = json::array({"KHR_mesh_quantization"});
  doc["extras"] = {{"frames", kept.size()}, {"clip_frames", frames.size()},
                   {"fields", {{"_STRAIN", "largest structural strain at the vertex (fraction)"},
                               {"_DISTANCE", "signed distance to the body from the oracle [m], < 0 inside"}}}};
  glb.write(path);
}

}  // namespace clothbench
