// load_body: any format assimp reads -> one welded, closed, normalised mesh + skin + animations.
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <unordered_map>

#include <sys/wait.h>
#include <unistd.h>

#include "body_model_impl.hpp"
#include "clothbench/io/data_root.hpp"
#include "clothbench/io/errors.hpp"

namespace clothbench {

namespace {

Mat4d to_eigen(const aiMatrix4x4& m) {
  Mat4d e;
  e << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4;
  return e;
}

// the vertex soup of every mesh instance, in scene space (rest), before welding
struct Soup {
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::vector<std::pair<int, float>>> influences;  // per vertex: (bone, weight)
  std::vector<std::array<int, 3>> triangles;
  long skipped_faces = 0;  // points and lines (and anything assimp could not triangulate)
};

void flatten_nodes(const aiNode* node, int parent, BodyModelImpl& m, std::unordered_map<const aiNode*, int>& ids) {
  const int id = static_cast<int>(m.nodes.size());
  m.nodes.push_back({node->mName.C_Str(), parent, to_eigen(node->mTransformation)});
  ids[node] = id;
  for (unsigned c = 0; c < node->mNumChildren; ++c) flatten_nodes(node->mChildren[c], id, m, ids);
}

int node_by_name(const BodyModelImpl& m, const std::string& name) {
  for (std::size_t n = 0; n < m.nodes.size(); ++n)
    if (m.nodes[n].name == name) return static_cast<int>(n);
  return -1;
}

// one mesh instance: vertices to scene space, bones (offset re-expressed on scene-space rest positions)
void add_mesh(const aiMesh& mesh, int node, const Mat4d& global, BodyModelImpl& m, Soup& soup,
              const std::string& path) {
  const int base = static_cast<int>(soup.positions.size());
  const Mat4d inv_global = global.inverse();
  for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
    const aiVector3D& p = mesh.mVertices[v];
    soup.positions.push_back((global * Eigen::Vector4d(p.x, p.y, p.z, 1)).head<3>());
  }
  soup.influences.resize(soup.positions.size());
  for (unsigned b = 0; b < mesh.mNumBones; ++b) {
    const aiBone& bone = *mesh.mBones[b];
    const int bn = node_by_name(m, bone.mName.C_Str());
    if (bn < 0) throw InputError(located(path, 0, std::string("bone '") + bone.mName.C_Str() + "' has no node"));
    const int id = static_cast<int>(m.bones.size());
    m.bones.push_back({bn, to_eigen(bone.mOffsetMatrix) * inv_global});
    for (unsigned w = 0; w < bone.mNumWeights; ++w)
      if (bone.mWeights[w].mWeight > 0)
        soup.influences[base + bone.mWeights[w].mVertexId].emplace_back(id, bone.mWeights[w].mWeight);
  }
  // vertices no bone weights follow the mesh's own node (a pseudo-bone); weights renormalised
  const int pseudo = static_cast<int>(m.bones.size());
  m.bones.push_back({node, inv_global, true});
  for (int v = base; v < static_cast<int>(soup.positions.size()); ++v) {
    auto& inf = soup.influences[v];
    float sum = 0;
    for (const auto& bw : inf) sum += bw.second;
    if (!(sum > 0)) {
      inf.assign(1, {pseudo, 1.f});
      continue;
    }
    for (auto& bw : inf) bw.second /= sum;
  }
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) {
      ++soup.skipped_faces;
      continue;
    }
    soup.triangles.push_back(
        {base + int(face.mIndices[0]), base + int(face.mIndices[1]), base + int(face.mIndices[2])});
  }
}

void collect_meshes(const aiScene& scene, BodyModelImpl& m, const std::unordered_map<const aiNode*, int>& ids,
                    Soup& soup, const std::string& path) {
  std::vector<Mat4d> globals;
  m.node_globals(-1, 0, globals);
  std::function<void(const aiNode*)> visit = [&](const aiNode* node) {
    const int id = ids.at(node);
    for (unsigned k = 0; k < node->mNumMeshes; ++k)
      add_mesh(*scene.mMeshes[node->mMeshes[k]], id, globals[id], m, soup, path);
    for (unsigned c = 0; c < node->mNumChildren; ++c) visit(node->mChildren[c]);
  };
  visit(scene.mRootNode);
}

struct PosHash {
  std::size_t operator()(const std::array<float, 3>& p) const {
    std::uint32_t b[3];
    std::memcpy(b, p.data(), sizeof b);
    return (std::size_t(b[0]) * 73856093u) ^ (std::size_t(b[1]) * 19349663u) ^ (std::size_t(b[2]) * 83492791u);
  }
};

// Welds vertices with bit-identical float positions (assimp splits a vertex at UV/normal seams but
// keeps its coordinates), keeps the first copy's skin weights, drops triangles that collapse and
// vertices no triangle uses.
void weld(const Soup& soup, BodyModelImpl& m) {
  std::unordered_map<std::array<float, 3>, int, PosHash> index;
  std::vector<int> remap(soup.positions.size(), -1), first;  // soup -> welded; welded -> soup
  for (const auto& tri : soup.triangles)
    for (int c : tri) {
      if (remap[c] >= 0) continue;
      const auto& p = soup.positions[c];
      const std::array<float, 3> key{float(p.x()), float(p.y()), float(p.z())};
      const auto [it, added] = index.emplace(key, static_cast<int>(first.size()));
      if (added) first.push_back(c);
      remap[c] = it->second;
    }
  std::vector<std::array<int, 3>> tris;
  for (const auto& t : soup.triangles) {
    const std::array<int, 3> w{remap[t[0]], remap[t[1]], remap[t[2]]};
    if (w[0] != w[1] && w[1] != w[2] && w[0] != w[2]) tris.push_back(w);
  }
  m.rest.positions.resize(3, static_cast<Eigen::Index>(first.size()));
  m.influence_start.assign(1, 0);
  for (std::size_t v = 0; v < first.size(); ++v) {
    m.rest.positions.col(v) = soup.positions[first[v]].cast<Real>();
    for (const auto& [b, w] : soup.influences[first[v]]) {
      m.influence_bone.push_back(b);
      m.influence_weight.push_back(w);
    }
    m.influence_start.push_back(static_cast<int>(m.influence_bone.size()));
  }
  m.rest.triangles.resize(3, static_cast<Eigen::Index>(tris.size()));
  for (std::size_t t = 0; t < tris.size(); ++t) m.rest.triangles.col(t) << tris[t][0], tris[t][1], tris[t][2];
}

int find_root(std::vector<int>& parent, int v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

// Drops small open parts (a body file's eyes, lashes, teeth: open shells under 10 % of the vertices)
// so that the body itself is the one closed mesh; the skin (CSR) follows the vertex renumbering.
void drop_open_parts(BodyModelImpl& m) {
  const Tris& tris = m.rest.triangles;
  const Eigen::Index nv = m.rest.positions.cols();
  // connected components over triangles
  std::vector<int> parent(nv);
  for (Eigen::Index v = 0; v < nv; ++v) parent[v] = static_cast<int>(v);
  for (Eigen::Index t = 0; t < tris.cols(); ++t)
    for (int k = 1; k < 3; ++k) parent[find_root(parent, tris(k, t))] = find_root(parent, tris(0, t));
  // components with a boundary edge (an undirected edge used once) are open
  std::unordered_map<std::int64_t, int> uses;
  for (Eigen::Index t = 0; t < tris.cols(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::int64_t a = tris(k, t), b = tris((k + 1) % 3, t);
      ++uses[std::min(a, b) * nv + std::max(a, b)];
    }
  std::unordered_map<int, int> size;
  std::unordered_map<int, bool> open;
  for (Eigen::Index v = 0; v < nv; ++v) ++size[find_root(parent, static_cast<int>(v))];
  for (const auto& [edge, n] : uses)
    if (n == 1) open[find_root(parent, static_cast<int>(edge / nv))] = true;
  std::vector<char> keep(nv, 1);
  for (Eigen::Index v = 0; v < nv; ++v) {
    const int r = find_root(parent, static_cast<int>(v));
    keep[v] = !(open.count(r) && size[r] * 10 < nv);
  }
  for (const auto& [root, is_open] : open)
    if (is_open && size[root] * 10 < nv) {
      ++m.dropped_parts;
      m.dropped_vertices += size[root];
    }
  if (m.dropped_parts == 0) return;
  std::vector<Eigen::Index> kept_tris;
  for (Eigen::Index t = 0; t < tris.cols(); ++t)
    if (keep[tris(0, t)]) kept_tris.push_back(t);
  Tris out(3, static_cast<Eigen::Index>(kept_tris.size()));
  for (std::size_t i = 0; i < kept_tris.size(); ++i) out.col(static_cast<Eigen::Index>(i)) = tris.col(kept_tris[i]);
  m.keep_vertices(keep, out);
}

// A body in the design frame faces +Z: it is wider (X, shoulders and arms) than deep (Z), and its feet reach further
// forward than its ankles. Where either fails the body probably faces another way, and the cloth placed in front of
// it would start inside it: warn (a note), do not guess a rotation.
void warn_facing(BodyModelImpl& m) {
  const Points3& x = m.rest.positions;
  const Box3 box = bounding_box(x);
  const Vec3 size = box.size();
  if (size.z() > size.x()) {
    m.notes.push_back("warning: it is deeper (Z) than wide (X): it may face +-X; the design frame's front is +Z");
    return;
  }
  // soles (the lowest 3 % of the height) against the ankles (3-8 %): the toes reach forward
  double feet = 0, ankles = 0;
  int nf = 0, na = 0;
  for (Eigen::Index v = 0; v < x.cols(); ++v) {
    const double h = (x(1, v) - box.min.y()) / size.y();
    if (h < 0.03) feet += x(2, v), ++nf;
    else if (h < 0.08) ankles += x(2, v), ++na;
  }
  if (nf && na && feet / nf < ankles / na - 0.02 * size.y())
    m.notes.push_back("warning: its feet reach further back (-Z) than its ankles: it may face -Z; the design "
                      "frame's front is +Z");
}

// Normalisation to the DESIGN frame. assimp already applies the units and up axis a file declares
// where its importer supports them (COLLADA <unit>/<up_axis>, glTF is metres +Y up by definition).
// What remains is a heuristic: a standing body is taller than it is deep, so when its Z extent
// exceeds its Y extent the file is Z-up (Blender/3ds Max convention, front along -Y) and is rotated
// -90 deg about X (Z -> Y, -Y -> Z); then a power of ten brings the height into [0.5, 5) m
// (MakeHuman decimetres, centimetres, millimetres); finally the lowest point moves to y = 0.
void normalise(BodyModelImpl& m) {
  const Box3 box = bounding_box(m.rest.positions);
  const Vec3 size = box.size();
  const bool z_up = size.z() > size.y();
  Mat4d rot = Mat4d::Identity();
  if (z_up) rot.topLeftCorner<3, 3>() = Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()).matrix();
  double height = std::max(size.y(), size.z()), scale = 1;
  while (height * scale >= 5) scale /= 10;
  while (height * scale > 0 && height * scale < 0.5) scale *= 10;
  Mat4d s = Mat4d::Identity();
  s.topLeftCorner<3, 3>() *= scale;
  Mat4d n = s * rot;
  double min_y = 1e300;
  for (Eigen::Index v = 0; v < m.rest.positions.cols(); ++v)
    min_y = std::min(min_y, (n * Eigen::Vector4d(m.rest.positions.col(v).cast<double>().homogeneous())).y());
  Mat4d lift = Mat4d::Identity();
  lift(1, 3) = -min_y;
  m.normalise = lift * n;
  m.denormalise = m.normalise.inverse();
  for (Eigen::Index v = 0; v < m.rest.positions.cols(); ++v)
    m.rest.positions.col(v) =
        (m.normalise * m.rest.positions.col(v).cast<double>().homogeneous()).head<3>().cast<Real>();
  if (z_up) m.notes.push_back("its Z extent exceeds its Y extent: read as Z-up and turned +Y up");
  if (scale != 1) {
    char text[96];
    std::snprintf(text, sizeof text, "scaled by %g to metres (height %.2f m)", scale, height * scale);
    m.notes.push_back(text);
  }
  warn_facing(m);
}

Channel read_channel(const aiNodeAnim& a, double tps) {
  Channel c;
  for (unsigned k = 0; k < a.mNumPositionKeys; ++k) {
    c.pos_t.push_back(a.mPositionKeys[k].mTime / tps);
    const auto& v = a.mPositionKeys[k].mValue;
    c.pos.emplace_back(v.x, v.y, v.z);
  }
  for (unsigned k = 0; k < a.mNumRotationKeys; ++k) {
    c.rot_t.push_back(a.mRotationKeys[k].mTime / tps);
    const auto& q = a.mRotationKeys[k].mValue;
    c.rot.emplace_back(q.w, q.x, q.y, q.z);
  }
  for (unsigned k = 0; k < a.mNumScalingKeys; ++k) {
    c.scale_t.push_back(a.mScalingKeys[k].mTime / tps);
    const auto& v = a.mScalingKeys[k].mValue;
    c.scale.emplace_back(v.x, v.y, v.z);
  }
  return c;
}

// every key time and value is a finite number
bool finite(const Channel& c) {
  auto times = [](const std::vector<double>& t) {
    return std::all_of(t.begin(), t.end(), [](double x) { return std::isfinite(x); });
  };
  auto vectors = [](const std::vector<Eigen::Vector3d>& v) {
    return std::all_of(v.begin(), v.end(), [](const Eigen::Vector3d& x) { return x.allFinite(); });
  };
  const bool rotations =
      std::all_of(c.rot.begin(), c.rot.end(), [](const Eigen::Quaterniond& q) { return q.coeffs().allFinite(); });
  return times(c.pos_t) && times(c.rot_t) && times(c.scale_t) && vectors(c.pos) && vectors(c.scale) && rotations;
}

// animations in seconds (assimp's default of 25 ticks/s when the file gives none)
void read_animations(const aiScene& scene, BodyModelImpl& m) {
  for (unsigned i = 0; i < scene.mNumAnimations; ++i) {
    const aiAnimation& a = *scene.mAnimations[i];
    Animation anim;
    const double tps = a.mTicksPerSecond > 0 ? a.mTicksPerSecond : 25.0;
    anim.info.name = a.mName.length > 0 ? a.mName.C_Str() : "animation_" + std::to_string(i);
    anim.info.ticks_per_second = tps;
    anim.info.duration_s = a.mDuration / tps;
    if (!std::isfinite(anim.info.duration_s) || !std::isfinite(tps))
      throw InputError(located(m.path, 0, "animation '" + anim.info.name + "': non-finite duration or tick rate"));
    anim.node_channel.assign(m.nodes.size(), -1);
    for (unsigned c = 0; c < a.mNumChannels; ++c) {
      const int node = node_by_name(m, a.mChannels[c]->mNodeName.C_Str());
      if (node < 0) continue;  // a channel for a node not in the hierarchy moves nothing
      anim.node_channel[node] = static_cast<int>(anim.channels.size());
      anim.channels.push_back(read_channel(*a.mChannels[c], tps));
      if (!finite(anim.channels.back()))
        throw InputError(located(m.path, 0,
                                 "animation '" + anim.info.name + "', node '" + a.mChannels[c]->mNodeName.C_Str() +
                                     "': non-finite key time or value"));
    }
    anim.info.channels = static_cast<int>(anim.channels.size());
    m.infos.push_back(anim.info);
    m.animations.push_back(std::move(anim));
  }
}

// the file's bones (pseudo-bones of static meshes are not counted),
// and the topmost bone node: the root whose horizontal travel walk-in-place removes
void find_bones_and_root(BodyModelImpl& m) {
  std::vector<char> is_bone(m.nodes.size(), 0);
  for (const auto& b : m.bones)
    if (!b.pseudo) is_bone[b.node] = 1;
  m.bone_count = static_cast<int>(std::count(is_bone.begin(), is_bone.end(), 1));
  for (std::size_t n = 0; n < m.nodes.size() && m.root_node < 0; ++n) {
    if (!is_bone[n]) continue;
    bool top = true;
    for (int p = m.nodes[n].parent; p >= 0; p = m.nodes[p].parent) top = top && !is_bone[p];
    if (top) m.root_node = static_cast<int>(n);
  }
}

constexpr unsigned kReadFlags =
    aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_ValidateDataStructure;

// a skeleton-only file (BVH, skeleton FBX) is no body: assimp would draw its bones as a mesh
void configure(Assimp::Importer& importer) { importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true); }

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", s);
  return buf;
}

// Reads the file with assimp in a child process (killed after timeout_s) and throws when assimp
// crashed or hung there; returns when the child finished, whatever assimp made of the file (the
// real read then reports that). When fork fails nothing is checked.
void read_in_child(const std::string& path, double timeout_s) {
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) return;
  if (pid == 0) {
    // die by the signal itself (a sanitizer's handler would print a report and exit instead)
    for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(sig, SIG_DFL);
    alarm(static_cast<unsigned>(std::ceil(timeout_s)));
    Assimp::Importer importer;
    configure(importer);
    importer.ReadFile(path, kReadFlags);  // a file assimp rejects cleanly is reported by the real read
    _exit(0);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
  if (WIFEXITED(status))  // a sanitizer turns a crash into an exit code
    throw InputError(located(path, 0,
                             "assimp crashed reading it (exit code " + std::to_string(WEXITSTATUS(status)) +
                                 "): the file is malformed or uses something assimp mishandles"));
  const int sig = WTERMSIG(status);
  if (sig == SIGALRM)
    throw InputError(located(
        path, 0,
        "assimp did not finish reading it within " + seconds(timeout_s) + " s (a malformed file can make it loop)"));
  throw InputError(located(path, 0,
                           std::string("assimp crashed reading it (") + strsignal(sig) +
                               "): the file is malformed or uses something assimp mishandles"));
}

const aiScene* read_scene(Assimp::Importer& importer, const std::string& path, double isolate_timeout_s) {
  configure(importer);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(located(path, 0, "file not found"));
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(located(path, 0, "not a regular file"));
  if (isolate_timeout_s > 0) read_in_child(path, isolate_timeout_s);
  const aiScene* scene = importer.ReadFile(path, kReadFlags);
  const std::string why = scene ? "" : importer.GetErrorString();
  // assimp's validation refuses a scene without meshes (a skeleton or motion file) before we see it
  if ((scene && (!scene->mRootNode || scene->mNumMeshes == 0)) || why.find("mNumMeshes is 0") != std::string::npos)
    throw InputError(located(path, 0, "contains no meshes (a skeleton or motion-only file is not a body)"));
  if (!scene) throw InputError(located(path, 0, "cannot be read as a mesh: " + why));
  return scene;
}

}  // namespace

BodyModel load_body(const std::string& reference, const BodyLoadOptions& options) {
  const std::string path = resolve_data_reference(reference);
  Assimp::Importer importer;
  const aiScene* scene = read_scene(importer, path, options.isolate_timeout_s);
  auto m = std::make_unique<BodyModelImpl>();
  m->path = path;
  std::unordered_map<const aiNode*, int> ids;
  flatten_nodes(scene->mRootNode, -1, *m, ids);
  Soup soup;
  collect_meshes(*scene, *m, ids, soup, path);
  if (soup.triangles.empty())
    throw InputError(located(path, 0,
                             "has no triangles (" + std::to_string(soup.skipped_faces) +
                                 " point/line faces; nothing assimp could triangulate)"));
  weld(soup, *m);
  if (m->rest.triangles.cols() == 0) throw InputError(located(path, 0, "has only degenerate triangles"));
  if (!m->rest.positions.allFinite()) throw InputError(located(path, 0, "has non-finite vertex coordinates"));
  // no unit makes a body span more than 1e6 (1000 km in metres, 1 km in millimetres); squares of
  // such numbers overflow float geometry
  if (m->rest.positions.cwiseAbs().maxCoeff() > 1e6f)
    throw InputError(located(path, 0, "has enormous vertex coordinates (|x| > 1e6 in the file's units)"));
  if (options.drop_open_parts) drop_open_parts(*m);
  find_bones_and_root(*m);
  read_animations(*scene, *m);
  if (options.normalise) normalise(*m);
  finish_static_body(m->rest);
  const EdgeCheck edges = check_edges(m->rest.triangles);
  if (options.require_closed && !edges.closed())
    throw InputError(located(path, 0,
                             "is not closed: " + std::to_string(edges.boundary_edges) + " boundary edges, " +
                                 std::to_string(edges.non_manifold_edges) + " non-manifold edges"));
  return BodyModel(std::move(m));
}

}  // namespace clothbench
