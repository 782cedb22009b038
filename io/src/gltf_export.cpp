// export_gltf: an aiScene built from our meshes, written by assimp's glb2 exporter.
#include "clothbench/io/gltf_export.hpp"

#include <assimp/material.h>
#include <assimp/scene.h>

#include <assimp/Exporter.hpp>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "clothbench/io/errors.hpp"

namespace clothbench {

namespace {

aiMesh* to_ai_mesh(const ExportMesh& m, unsigned material) {
  auto* mesh = new aiMesh;
  mesh->mName = m.name;
  mesh->mMaterialIndex = material;
  mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  mesh->mNumVertices = static_cast<unsigned>(m.positions.cols());
  mesh->mVertices = new aiVector3D[mesh->mNumVertices];
  for (unsigned v = 0; v < mesh->mNumVertices; ++v)
    mesh->mVertices[v] = aiVector3D(m.positions(0, v), m.positions(1, v), m.positions(2, v));
  mesh->mNumFaces = static_cast<unsigned>(m.triangles.cols());
  mesh->mFaces = new aiFace[mesh->mNumFaces];
  for (unsigned t = 0; t < mesh->mNumFaces; ++t) {
    aiFace& f = mesh->mFaces[t];
    f.mNumIndices = 3;
    f.mIndices = new unsigned[3];
    for (int k = 0; k < 3; ++k) f.mIndices[k] = static_cast<unsigned>(m.triangles(k, t));
  }
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
  // the scene owns every array below and frees them in its destructor
  auto scene = std::make_unique<aiScene>();
  scene->mRootNode = new aiNode("clothbench");
  const auto n = static_cast<unsigned>(meshes.size());
  scene->mNumMeshes = scene->mNumMaterials = n;
  scene->mMeshes = new aiMesh*[n];
  scene->mMaterials = new aiMaterial*[n];
  scene->mRootNode->mNumMeshes = n;
  scene->mRootNode->mMeshes = new unsigned[n];
  for (unsigned i = 0; i < n; ++i) {
    scene->mMeshes[i] = to_ai_mesh(meshes[i], i);
    scene->mMaterials[i] = to_ai_material(meshes[i]);
    scene->mRootNode->mMeshes[i] = i;
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
