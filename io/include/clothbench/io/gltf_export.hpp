#pragma once
/// Export of a dressed body (body and cloth meshes) as binary glTF through assimp's exporter, for
/// Blender or a web viewer.
#include <array>
#include <string>
#include <vector>

#include "clothbench/sim/types.hpp"

namespace clothbench {

/// One mesh to export: positions [m] (3 x nv), triangles (3 x nt), an RGB colour in [0, 1].
struct ExportMesh {
  std::string name;
  Points3 positions;
  Tris triangles;
  std::array<float, 3> colour{0.8f, 0.8f, 0.8f};
};

/// Writes the meshes into one .glb file (written to PATH.tmp first, then renamed). Every vertex
/// reaches the file: those in no triangle are written as points (a second primitive of the mesh).
/// Throws std::invalid_argument on a vertex index out of range, InputError naming the path when
/// assimp cannot export or the file cannot be written.
void export_gltf(const std::string& path, const std::vector<ExportMesh>& meshes);

}  // namespace clothbench
