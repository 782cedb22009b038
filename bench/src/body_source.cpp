// BodySource: the run's body loaded (mesh, collision proxy, clip window) or made (sphere), and posed at a time.
#include "body_source.hpp"

#include <cstdio>
#include <set>
#include <string>

#include "clothbench/io/errors.hpp"
#include "clothbench/sim/body_frame.hpp"

namespace clothbench::runner_detail {

namespace {

// what loading the body changed or warns about (body_loader.hpp), once per file and process
void print_notes(const BodyModel& model) {
  static std::set<std::string> printed;
  if (!printed.insert(model.path()).second) return;
  for (const std::string& n : model.notes())
    std::fprintf(stderr, "clothbench: %s: %s%s\n", model.path().c_str(), n.rfind("warning: ", 0) == 0 ? "" : "note: ",
                 n.c_str());
}

}  // namespace

BodySource::BodySource(const Scene& scene) : spec_(scene.body) {
  if (!(spec_.scale.minCoeff() >= 0.2f && spec_.scale.maxCoeff() <= 5))
    throw InputError(located(scene.path, 0, "body.scale: each factor must lie in [0.2, 5]"));
  if (spec_.shape == "sphere") {
    if (spec_.scale != Vec3::Ones())
      throw InputError(located(scene.path, 0, "body.scale needs a mesh body, not a sphere (set its radius)"));
    if (spec_.collision_triangles > 0)
      throw InputError(located(scene.path, 0, "body.collision_triangles needs a mesh body, not a sphere"));
    sphere_ = make_sphere_body(Vec3::Zero(), spec_.radius, 48, 96);
    t1_ = spec_.move_s;
    return;
  }
  model_.emplace(load_body(resolve_scene_path(scene, spec_.file)));
  print_notes(*model_);
  if (spec_.collision_triangles > 0) proxy_.emplace(model_->simplified(spec_.collision_triangles));
  if (spec_.animation.empty()) return;
  anim_ = model_->animation_index(spec_.animation);
  const double clip = model_->animations()[anim_].duration_s;
  dress_ = spec_.dress_at_s;
  t0_ = spec_.start_s;
  t1_ = spec_.end_s < 0 ? clip : spec_.end_s;
  if (!(dress_ <= t0_ && t0_ < t1_) || t1_ > clip + 1e-9)
    throw InputError(located(scene.path, 0, "body: need dress_at_s <= start_s < end_s inside the clip [0, " +
                                                 std::to_string(clip) + "] s, got " + std::to_string(dress_) +
                                                 ", " + std::to_string(t0_) + ", " + std::to_string(t1_)));
}

void BodySource::frame_into(const std::optional<BodyModel>& model, BodyFrame& out, double t) const {
  if (model) {
    if (anim_ < 0) {
      out = model->rest();
    } else {
      model->frame_into(out, anim_, t, spec_.walk_in_place);
    }
    if (spec_.scale != Vec3::Ones()) {
      out.positions = spec_.scale.asDiagonal() * out.positions;
      out.velocities = spec_.scale.asDiagonal() * out.velocities;
      angle_weighted_normals_into(out.positions, out.triangles, out.normals);
    }
    return;
  }
  // at rest while dressing (t = 0), moving at constant velocity during the animation
  out = sphere_;
  out.positions.colwise() += sphere_center(t);
  if (t > 0) {
    out.velocities.colwise() = spec_.velocity;
    out.moving = true;
  }
}

}  // namespace clothbench::runner_detail
