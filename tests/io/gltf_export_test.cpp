// glTF export through assimp's glb2 exporter: every vertex of every mesh survives a round trip.
#include "clothbench/io/gltf_export.hpp"

#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <assimp/Importer.hpp>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "clothbench/sim/body_frame.hpp"

namespace clothbench {
namespace {

namespace fs = std::filesystem;

// vertices per node name after re-import (a glTF mesh of several primitives comes back as several
// meshes of one node)
std::map<std::string, unsigned> reimported_vertices(const std::string& path) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, 0);
  EXPECT_NE(scene, nullptr) << importer.GetErrorString();
  std::map<std::string, unsigned> out;
  if (!scene) return out;
  std::vector<const aiNode*> nodes{scene->mRootNode};
  while (!nodes.empty()) {
    const aiNode* node = nodes.back();
    nodes.pop_back();
    for (unsigned i = 0; i < node->mNumMeshes; ++i)
      out[node->mName.C_Str()] += scene->mMeshes[node->mMeshes[i]]->mNumVertices;
    nodes.insert(nodes.end(), node->mChildren, node->mChildren + node->mNumChildren);
  }
  return out;
}

std::string temp_path(const std::string& name) { return (fs::temp_directory_path() / name).string(); }

// a 4 x 3 grid of two triangles per cell and one vertex beside it in no triangle
ExportMesh panel_with_lone_vertex() {
  ExportMesh m;
  m.name = "panel";
  m.positions.resize(3, 13);
  std::vector<int> tris;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) m.positions.col(j * 4 + i) = Vec3(0.1f * i, 0.1f * j, 0.2f);
  m.positions.col(12) = Vec3(0.45f, 0.25f, 0.2f);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const int a = j * 4 + i;
      tris.insert(tris.end(), {a, a + 1, a + 5, a, a + 5, a + 4});
    }
  m.triangles = Eigen::Map<const Tris>(tris.data(), 3, static_cast<Eigen::Index>(tris.size() / 3));
  return m;
}

TEST(GltfExport, RoundTripKeepsEveryVertex) {
  const BodyFrame sphere = make_sphere_body(Vec3::Zero(), 0.3f, 12, 24);
  const std::vector<ExportMesh> meshes{{"body", sphere.positions, sphere.triangles, {0.8f, 0.8f, 0.8f}},
                                       panel_with_lone_vertex()};
  const std::string path = temp_path("clothbench_gltf_round_trip.glb");
  export_gltf(path, meshes);
  const auto counts = reimported_vertices(path);
  std::string read;
  for (const auto& [name, n] : counts) read += " " + name + ": " + std::to_string(n);
  EXPECT_EQ(counts.count("body") ? counts.at("body") : 0u, static_cast<unsigned>(sphere.vertex_count())) << read;
  EXPECT_EQ(counts.count("panel") ? counts.at("panel") : 0u, 13u) << "the vertex in no triangle was dropped;" << read;
  EXPECT_FALSE(fs::exists(path + ".tmp"));
  fs::remove(path);
}

TEST(GltfExport, RejectsIndexOutOfRange) {
  ExportMesh m = panel_with_lone_vertex();
  m.triangles(1, 0) = 13;
  EXPECT_THROW(export_gltf(temp_path("clothbench_gltf_bad.glb"), {m}), std::invalid_argument);
}

}  // namespace
}  // namespace clothbench
