// export_gltf: an aiScene built from our meshes, written by assimp's glb2 exporter.
#include "clothbench/io/gltf_export.hpp"

#include <assimp/material.h>
#include <assimp/scene.h>

#include <assimp/Exporter.hpp>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <vector>

#include "clothbench/io/errors.hpp"

namespace clothbench {

namespace {

// triangles, then one point per vertex in no triangle: assimp's glb2 exporter always runs
// JoinIdenticalVertices, which keeps only vertices some face uses
aiMesh* to_ai_mesh(const ExportMesh& m, unsigned material) {
  auto* mesh = new aiMesh;
  mesh->mName = m.name;
  mesh->mMaterialIndex = material;
  mesh->mNumVertices = static_cast<unsigned>(m.positions.cols());
  mesh->mVertices = new aiVector3D[mesh->mNumVertices];
  for (unsigned v = 0; v < mesh->mNumVertices; ++v)
    mesh->mVertices[v] = aiVector3D(m.positions(0, v), m.positions(1, v), m.positions(2, v));
  // which vertices no triangle uses
  std::vector<unsigned> lone;
  std::vector<bool> used(mesh->mNumVertices, false);
  for (Eigen::Index k = 0; k < m.triangles.size(); ++k) used[static_cast<std::size_t>(m.triangles.data()[k])] = true;
  for (unsigned v = 0; v < mesh->mNumVertices; ++v)
    if (!used[v]) lone.push_back(v);
  // the faces
  const auto nt = static_cast<unsigned>(m.triangles.cols());
  mesh->mNumFaces = nt + static_cast<unsigned>(lone.size());
  mesh->mFaces = new aiFace[mesh->mNumFaces];
  for (unsigned t = 0; t < nt; ++t) {
    aiFace& f = mesh->mFaces[t];
    f.mNumIndices = 3;
    f.mIndices = new unsigned[3];
    for (int k = 0; k < 3; ++k) f.mIndices[k] = static_cast<unsigned>(m.triangles(k, t));
  }
  for (std::size_t i = 0; i < lone.size(); ++i) {
    aiFace& f = mesh->mFaces[nt + i];
    f.mNumIndices = 1;
    f.mIndices = new unsigned[1]{lone[i]};
  }
  mesh->mPrimitiveTypes = 0;
  if (nt > 0) mesh->mPrimitiveTypes |= aiPrimitiveType_TRIANGLE;
  if (!lone.empty()) mesh->mPrimitiveTypes |= aiPrimitiveType_POINT;
  return mesh;
}

aiMaterial* to_ai_material(const ExportMesh& m) {
  auto* material = new aiMaterial;
  const aiColor4D colour(m.colour[0], m.colour[1], m.colour[2], 1.f);
  material->AddProperty(&colour, 1, AI_MATKEY_COLOR_DIFFUSE);
  material->AddProperty(&colour, 1, AI_MATKEY_BASE_COLOR);
  const aiString name(m.name);
  material->AddProperty(&name, AI_MATKEY_NAME);
  return material;
}

}  // namespace

void export_gltf(const std::string& path, const std::vector<ExportMesh>& meshes) {
  // indices checked before any assimp array exists
  for (const auto& m : meshes)
    if (m.triangles.size() > 0 && (m.triangles.minCoeff() < 0 || m.triangles.maxCoeff() >= m.positions.cols()))
      throw std::invalid_argument(path + ": glTF export: mesh '" + m.name + "' has a vertex index out of range");
  // the scene owns every array below and frees them in its destructor
  auto scene = std::make_unique<aiScene>();
  scene->mRootNode = new aiNode("clothbench");
  const auto n = static_cast<unsigned>(meshes.size());
  scene->mNumMeshes = scene->mNumMaterials = n;
  scene->mMeshes = new aiMesh*[n];
  scene->mMaterials = new aiMaterial*[n];
  // one named child node per mesh (the exporter merges the meshes of one node into one glTF mesh)
  scene->mRootNode->mNumChildren = n;
  scene->mRootNode->mChildren = new aiNode*[n];
  for (unsigned i = 0; i < n; ++i) {
    scene->mMeshes[i] = to_ai_mesh(meshes[i], i);
    scene->mMaterials[i] = to_ai_material(meshes[i]);
    auto* node = new aiNode(meshes[i].name);
    node->mParent = scene->mRootNode;
    node->mNumMeshes = 1;
    node->mMeshes = new unsigned[1]{i};
    scene->mRootNode->mChildren[i] = node;
  }
  Assimp::Exporter exporter;
  const std::string tmp = path + ".tmp";
  if (exporter.Export(scene.get(), "glb2", tmp) != aiReturn_SUCCESS) {
    std::remove(tmp.c_str());
    throw InputError(path + ": glTF export failed: " + exporter.GetErrorString());
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw InputError(path + ": cannot write: " + ec.message());
  }
}

}  // namespace clothbench
