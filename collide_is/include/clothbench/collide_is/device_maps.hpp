#pragma once
/// Maps that stay on the device that draws them and answer the cloth's points there (is-egl: OpenGL 4.3 compute
/// shaders). Only the answers come back, a few bytes a point; the maps themselves are copied out only on request
/// (pictures, tests, `clothbench maps`).
#include <string>
#include <utility>
#include <vector>

#include "clothbench/collide_is/image_space_collider.hpp"
#include "clothbench/collide_is/map_set.hpp"

namespace clothbench {

class DeviceMaps {
 public:
  /// Map sets held on the device: the current maps and the next frame's (ImageSpaceCollider::prepare_body).
  static constexpr int kSlots = 2;

  DeviceMaps() = default;
  DeviceMaps(const DeviceMaps&) = delete;
  DeviceMaps& operator=(const DeviceMaps&) = delete;
  virtual ~DeviceMaps() = default;
  /// Draws `body` into map set `slot` as MapRenderer::render draws into `shape` (its frame, encoding and rows;
  /// its arrays are not touched), then the side layer of `rings` rings (add_side_layer; 0: none). Returns once
  /// the device has finished, so its time is the drawing's.
  virtual void draw(const BodyFrame& body, const MapSet& shape, int rings, int slot) = 0;
  /// Every point answered from map set `slot` as ImageSpaceCollider answers from a MapSet by `rules` (points that
  /// are not finite get an unspecified answer: the caller sets theirs).
  virtual void query(int slot, PointsView points, const AnswerRules& rules, Contact* out) = 0;
  /// A CPU copy of map set `slot`, every array sized and filled as the CPU path would fill it.
  virtual void copy(int slot, MapSet& maps) = 0;
  /// The device's own time per draw, by phase ("upload", "draw", "depth_copy", "resolve", "side_layer"), mean over
  /// every draw so far [ms] (its timestamp queries; empty before the first draw).
  virtual std::vector<std::pair<std::string, double>> draw_phases_ms() const = 0;
};

}  // namespace clothbench
