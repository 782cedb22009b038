#include "embree_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace clothbench::detail {

namespace {

// what the point-query callback reads and writes
struct QueryState {
  const float* vertices;
  const std::uint32_t* indices;
  Vec3 p;
  ClosestPoint best;
};

// exact closest point on one candidate triangle; shrinks the query radius on improvement
bool closest_callback(RTCPointQueryFunctionArguments* args) {
  auto* s = static_cast<QueryState*>(args->userPtr);
  const std::uint32_t* tri = s->indices + 3 * std::size_t(args->primID);
  const Eigen::Map<const Vec3> a(s->vertices + 3 * std::size_t(tri[0]));
  const Eigen::Map<const Vec3> b(s->vertices + 3 * std::size_t(tri[1]));
  const Eigen::Map<const Vec3> c(s->vertices + 3 * std::size_t(tri[2]));
  ClosestPoint cp = closest_point_on_triangle(s->p, a, b, c);
  if (!(cp.dist2 < s->best.dist2)) return false;
  cp.triangle = static_cast<int>(args->primID);
  s->best = cp;
  args->query->radius = std::sqrt(cp.dist2);
  return true;
}

void record_error(void* user, RTCError code, const char* message) {
  auto* error = static_cast<std::string*>(user);
  *error = "error " + std::to_string(int(code)) + (message ? std::string(": ") + message : std::string());
}

}  // namespace

EmbreeScene::EmbreeScene(int threads) {
  // one device per scene: no globals, two colliders can run side by side
  const std::string config = "threads=" + std::to_string(std::max(1, threads));
  device_ = rtcNewDevice(config.c_str());
  if (!device_)
    throw std::runtime_error("embree: rtcNewDevice(\"" + config + "\") failed, error " +
                             std::to_string(int(rtcGetDeviceError(nullptr))));
  rtcSetDeviceErrorFunction(device_, record_error, &error_);
}

EmbreeScene::~EmbreeScene() {
  release_scene();
  rtcReleaseDevice(device_);
}

void EmbreeScene::release_scene() {
  if (geometry_) rtcReleaseGeometry(geometry_);
  if (scene_) rtcReleaseScene(scene_);
  geometry_ = nullptr;
  scene_ = nullptr;
}

void EmbreeScene::check(const std::string& what) {
  const RTCError code = rtcGetDeviceError(device_);
  if (code == RTC_ERROR_NONE && error_.empty()) return;
  const std::string message = error_.empty() ? "error " + std::to_string(int(code)) : error_;
  error_.clear();
  throw std::runtime_error("embree: " + what + " failed: " + message);
}

void EmbreeScene::build(const BodyFrame& body, bool moving) {
  release_scene();
  // shared buffers: Embree reads 16 bytes per vertex, hence the spare float at the end
  const std::size_t nv = static_cast<std::size_t>(body.vertex_count());
  const std::size_t nt = static_cast<std::size_t>(body.triangle_count());
  vertices_.assign(body.positions.data(), body.positions.data() + 3 * nv);
  vertices_.push_back(0.0f);
  indices_.resize(3 * nt);
  std::transform(body.triangles.data(), body.triangles.data() + 3 * nt, indices_.begin(),
                 [](std::int32_t i) { return static_cast<std::uint32_t>(i); });

  // a moving body: dynamic scene, LOW build quality, REFIT geometry (vertex updates refit the
  // BVH); a static one: HIGH quality (spatial splits, tighter boxes); robust rays either way
  moving_ = moving;
  scene_ = rtcNewScene(device_);
  rtcSetSceneFlags(scene_, moving ? RTC_SCENE_FLAG_DYNAMIC | RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene_, moving ? RTC_BUILD_QUALITY_LOW : RTC_BUILD_QUALITY_HIGH);
  geometry_ = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetGeometryBuildQuality(geometry_, moving ? RTC_BUILD_QUALITY_REFIT : RTC_BUILD_QUALITY_HIGH);
  rtcSetSharedGeometryBuffer(geometry_, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices_.data(), 0,
                             3 * sizeof(float), nv);
  rtcSetSharedGeometryBuffer(geometry_, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, indices_.data(), 0,
                             3 * sizeof(std::uint32_t), nt);
  rtcCommitGeometry(geometry_);
  rtcAttachGeometry(scene_, geometry_);
  rtcCommitScene(scene_);
  check("building the body scene");
}

void EmbreeScene::refit(const BodyFrame& body) {
  // the first motion of a body built static rebuilds it for refitting
  if (!moving_) return build(body, true);
  // overwrite the shared buffer in place, then refit
  const Points3& positions = body.positions;
  std::copy(positions.data(), positions.data() + positions.size(), vertices_.begin());
  rtcUpdateGeometryBuffer(geometry_, RTC_BUFFER_TYPE_VERTEX, 0);
  rtcCommitGeometry(geometry_);
  rtcCommitScene(scene_);
  check("refitting the body scene");
}

ClosestPoint EmbreeScene::closest(const Vec3& p, Real radius) const {
  // only triangles strictly closer than radius count
  QueryState state{vertices_.data(), indices_.data(), p, ClosestPoint{}};
  state.best.dist2 = radius * radius;
  RTCPointQuery query;
  query.x = p.x();
  query.y = p.y();
  query.z = p.z();
  query.time = 0.0f;
  query.radius = radius;
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(scene_, &query, &context, closest_callback, &state);
  return state.best;
}

bool EmbreeScene::segment_hits(const Vec3& a, const Vec3& b) const {
  const Vec3 d = b - a;
  if (d.squaredNorm() == 0) return false;
  // one occlusion ray along the unnormalised direction b - a: t in [0, 1] spans the segment
  RTCRay ray;
  ray.org_x = a.x();
  ray.org_y = a.y();
  ray.org_z = a.z();
  ray.dir_x = d.x();
  ray.dir_y = d.y();
  ray.dir_z = d.z();
  ray.tnear = 0.0f;
  ray.tfar = 1.0f;
  ray.time = 0.0f;
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded1(scene_, &context, &ray);
  // rtcOccluded1 sets tfar to -infinity on a hit
  return ray.tfar < 0.0f;
}

}  // namespace clothbench::detail
