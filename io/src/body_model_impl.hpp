#pragma once
// Internal state of a BodyModel: rest mesh, skin (CSR influences), node hierarchy and animation
// channels copied out of assimp so the aiScene can be released after loading.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "clothbench/io/body_loader.hpp"

namespace clothbench {

using Mat4d = Eigen::Matrix4d;
using Mat34f = Eigen::Matrix<float, 3, 4>;

/// One node of the scene graph; parents come before children in BodyModelImpl::nodes.
struct SkelNode {
  std::string name;
  int parent = -1;
  Mat4d local = Mat4d::Identity();  ///< the file's rest transform relative to the parent
};

/// Keys of one animated node, times in seconds. Empty key lists keep the rest component.
struct Channel {
  std::vector<double> pos_t, rot_t, scale_t;
  std::vector<Eigen::Vector3d> pos, scale;
  std::vector<Eigen::Quaterniond> rot;
};

struct Animation {
  AnimationInfo info;
  std::vector<int> node_channel;  ///< per node: index into channels, -1 when not animated
  std::vector<Channel> channels;
};

/// A skinning matrix source: node `node` with `offset` mapping rest (file frame, scene space) to
/// node space, i.e. skinned = global(node, t) * offset * rest.
struct SkinBone {
  int node = -1;
  Mat4d offset = Mat4d::Identity();
  bool pseudo = false;  ///< stands for a static mesh's own node, not a bone of the file
};

class BodyModelImpl {
 public:
  std::string path;
  BodyFrame rest;                       ///< normalised rest mesh
  int dropped_parts = 0;                ///< small open parts removed (eyes, ...)
  int dropped_vertices = 0;
  std::vector<std::string> notes;      ///< what normalisation changed, and warnings about the pose (notes())
  int bone_count = 0;                   ///< the file's skin bones (pseudo-bones of static meshes excluded)
  std::vector<AnimationInfo> infos;
  std::vector<SkelNode> nodes;
  std::vector<Animation> animations;
  std::vector<SkinBone> bones;          ///< file bones, then one pseudo-bone per static mesh node
  std::vector<int> influence_start;     ///< CSR: vertex v uses [start[v], start[v+1])
  std::vector<int> influence_bone;
  std::vector<float> influence_weight;
  int root_node = -1;                   ///< topmost skin bone node (walk in place), -1 when none
  Mat4d normalise = Mat4d::Identity();  ///< file frame -> DESIGN frame (scale, rotation, translation)
  Mat4d denormalise = Mat4d::Identity();

  /// Global transforms of every node at time t [s] of animation a (a < 0: rest), into `out`.
  void node_globals(int a, double t, std::vector<Mat4d>& out) const;
  void frame_into(BodyFrame& out, int a, double t, bool in_place) const;
  /// Keeps the vertices with keep[v] (in order, with their skin) and makes `triangles` (old vertex numbers, every
  /// one kept) the rest mesh's.
  void keep_vertices(const std::vector<char>& keep, const Tris& triangles);
};


}  // namespace clothbench
