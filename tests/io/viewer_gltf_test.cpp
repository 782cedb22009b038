// write_viewer_gltf: the report viewer's glTF (end state with _STRAIN / _DISTANCE; animated with morph targets).
#include "clothbench/io/viewer_gltf.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "clothbench/sim/body_frame.hpp"
#include "clothbench/sim/cloth.hpp"

namespace clothbench {
namespace {

using nlohmann::json;

struct Glb {
  json doc;
  std::string bin;
  // the accessor's values, dequantised (float, or int16 normalised)
  std::vector<float> values(int accessor) const {
    const json& a = doc["accessors"][accessor];
    const json& v = doc["bufferViews"][a["bufferView"].get<int>()];
    const int width = a["type"] == "VEC3" ? 3 : 1;
    const std::size_t count = a["count"], offset = v["byteOffset"];
    std::vector<float> out;
    for (std::size_t i = 0; i < count; ++i)
      for (int k = 0; k < width; ++k) {
        if (a["componentType"] == 5126) {
          float f;
          std::memcpy(&f, bin.data() + offset + 4 * (i * width + k), 4);
          out.push_back(f);
        } else {
          EXPECT_EQ(a["componentType"], 5122);
          EXPECT_TRUE(a.value("normalized", false));
          const std::size_t stride = v.value("byteStride", 2 * width);
          std::int16_t s;
          std::memcpy(&s, bin.data() + offset + stride * i + 2 * k, 2);
          out.push_back(float(s) / 32767.f);
        }
      }
    return out;
  }
};

Glb read_glb(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  const std::string data = s.str();
  Glb g;
  EXPECT_EQ(data.substr(0, 4), "glTF");
  std::uint32_t json_length = 0, bin_length = 0;
  std::memcpy(&json_length, data.data() + 12, 4);
  g.doc = json::parse(data.substr(20, json_length));
  std::memcpy(&bin_length, data.data() + 20 + json_length, 4);
  g.bin = data.substr(28 + json_length, bin_length);
  EXPECT_EQ(data.size(), 28 + json_length + bin_length);
  return g;
}

// the distance to the sphere of radius 0.3 m at the origin (exact, beside the tessellated body) and one colour a panel
ViewerStyle sphere_style() {
  ViewerStyle style;
  style.panel_colour = [](int) { return std::array<float, 3>{0.8f, 0.2f, 0.2f}; };
  style.signed_distance = [](const BodyFrame&, const Points3& points, std::vector<Real>& out) {
    out.resize(std::size_t(points.cols()));
    for (Eigen::Index i = 0; i < points.cols(); ++i) out[std::size_t(i)] = points.col(i).norm() - 0.3f;
  };
  return style;
}

// a strip of cloth through a sphere of radius 0.3 m: the middle inside, the ends outside
ClothMesh strip() {
  ClothMesh c = make_grid_cloth(11, 2, 0.1f, Vec3(-0.5f, -0.05f, 0.f), Vec3(1, 0, 0), Vec3(0, 1, 0));
  c.panel.assign(std::size_t(c.vertex_count()), 0);
  c.panel_names = {"strip"};
  return c;
}

TEST(ViewerGltf, KeptFramesSpreadEvenlyWithFirstAndLast) {
  EXPECT_EQ(kept_frames(0, 16), std::vector<std::size_t>{});
  EXPECT_EQ(kept_frames(1, 16), std::vector<std::size_t>{0});
  EXPECT_EQ(kept_frames(5, 16), (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  const std::vector<std::size_t> k = kept_frames(60, 16);
  ASSERT_EQ(k.size(), 16u);
  EXPECT_EQ(k.front(), 0u);
  EXPECT_EQ(k.back(), 59u);
  for (std::size_t i = 1; i < k.size(); ++i) EXPECT_GT(k[i], k[i - 1]);
}

TEST(ViewerGltf, EndStateCarriesStrainAndSignedDistance) {
  const BodyFrame body = make_sphere_body(Vec3::Zero(), 0.3f, 16, 32);
  ClothMesh cloth = strip();
  cloth.positions.row(0) *= 1.1f;  // every spring along x stretched by 10 %
  const std::string path = test::temp_path("viewer_static.glb");
  write_viewer_gltf(path, body, cloth, sphere_style());
  const Glb g = read_glb(path);
  ASSERT_EQ(g.doc["meshes"].size(), 2u);
  EXPECT_EQ(g.doc["meshes"][0]["name"], "body");
  EXPECT_EQ(g.doc["meshes"][1]["name"], "strip");
  EXPECT_FALSE(g.doc.contains("animations"));
  const json& attributes = g.doc["meshes"][1]["primitives"][0]["attributes"];
  const std::vector<float> x = g.values(attributes["POSITION"]), strain = g.values(attributes["_STRAIN"]),
                           distance = g.values(attributes["_DISTANCE"]);
  ASSERT_EQ(strain.size(), 22u);
  ASSERT_EQ(distance.size(), 22u);
  for (std::size_t v = 0; v < 22; ++v) {
    EXPECT_NEAR(strain[v], 0.1f, 1e-4f) << v;
    const float r = std::hypot(x[3 * v], x[3 * v + 1], x[3 * v + 2]);
    EXPECT_NEAR(distance[v], r - 0.3f, 0.01f) << v;  // the sphere is tessellated
  }
  EXPECT_LT(distance[5], 0.f);   // the middle: inside
  EXPECT_GT(distance[0], 0.f);   // the ends: outside
  // every cell as two triangles
  EXPECT_EQ(g.doc["accessors"][g.doc["meshes"][1]["primitives"][0]["indices"].get<int>()]["count"], 10 * 2 * 3);
}

TEST(ViewerGltf, AnimatedFileStepsThroughTheKeptFrames) {
  const BodyFrame body = make_sphere_body(Vec3::Zero(), 0.3f, 8, 16);
  const ClothMesh cloth = strip();
  std::vector<ViewerFrame> frames;
  for (int f = 0; f < 7; ++f) {
    ViewerFrame frame{1.0 + f / 30.0, body.positions, cloth.positions};
    frame.body.row(1).array() += 0.01f * float(f);   // the body rises 1 cm a frame
    frame.cloth.row(0).array() -= 0.02f * float(f);  // the cloth slides 2 cm a frame
    frames.push_back(frame);
  }
  const std::string path = test::temp_path("viewer_animated.glb");
  write_viewer_gltf(path, body, cloth, sphere_style(), frames, 4);  // frames 0, 2, 4, 6
  const Glb g = read_glb(path);
  EXPECT_EQ(g.doc["extensionsRequired"], json::array({"KHR_mesh_quantization"}));
  ASSERT_EQ(g.doc["animations"].size(), 1u);
  const json& anim = g.doc["animations"][0];
  EXPECT_EQ(anim["channels"].size(), 2u);
  const std::vector<float> times = g.values(anim["samplers"][0]["input"]);
  const std::vector<float> weights = g.values(anim["samplers"][0]["output"]);
  ASSERT_EQ(times.size(), 4u);
  EXPECT_NEAR(times[0], 0.f, 1e-6f);
  EXPECT_NEAR(times[3], 6 / 30.f, 1e-5f);
  ASSERT_EQ(weights.size(), 4u * 3u);  // 4 keys x 3 targets, one-hot after the base
  EXPECT_EQ(weights, (std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}));
  // the base is the first frame; target k is kept frame k + 1 less the base
  const json& body_primitive = g.doc["meshes"][0]["primitives"][0];
  const json& cloth_primitive = g.doc["meshes"][1]["primitives"][0];
  ASSERT_EQ(body_primitive["targets"].size(), 3u);
  ASSERT_EQ(cloth_primitive["targets"].size(), 3u);
  const std::vector<float> body_base = g.values(body_primitive["attributes"]["POSITION"]);
  EXPECT_NEAR(body_base[1], body.positions(1, 0), 1e-6f);
  const std::vector<float> rise = g.values(body_primitive["targets"][2]["POSITION"]);
  const std::vector<float> slide = g.values(cloth_primitive["targets"][0]["POSITION"]);
  for (std::size_t v = 0; v < rise.size() / 3; ++v) {
    EXPECT_NEAR(rise[3 * v], 0.f, 1e-4f);
    EXPECT_NEAR(rise[3 * v + 1], 0.06f, 1e-4f);
  }
  for (std::size_t v = 0; v < slide.size() / 3; ++v) EXPECT_NEAR(slide[3 * v], -0.04f, 1e-4f);
  EXPECT_EQ(g.doc["meshes"][0]["weights"].size(), 3u);
}

TEST(ViewerGltf, FramesOfAnotherTopologyAreRefused) {
  const BodyFrame body = make_sphere_body(Vec3::Zero(), 0.3f, 8, 16);
  const ClothMesh cloth = strip();
  std::vector<ViewerFrame> frames{{0.0, body.positions, cloth.positions}, {0.1, body.positions, Points3(3, 5)}};
  EXPECT_THROW(write_viewer_gltf(test::temp_path("viewer_bad.glb"), body, cloth, sphere_style(), frames),
               std::invalid_argument);
}

}  // namespace
}  // namespace clothbench
