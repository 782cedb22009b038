#pragma once
// The maps of the OpenGL renderer kept on its device (OpenGL 4.3): compute shaders turn each pass's targets into
// map sets laid out as MapSet's arrays (shader storage buffers), grow the side layer there and answer query points
// there, as the CPU path does (depth_from_zbuffer, add_side_layer, ImageSpaceCollider's query).
#include <array>
#include <string>
#include <vector>

#include "clothbench/collide_is/device_maps.hpp"
#include "gl_api.hpp"

namespace clothbench {

class GlComputeMaps {
 public:
  // compiles the shaders; the context is current and offers OpenGL 4.3 (`gl` loaded with its compute functions);
  // `clock` (the drawing's, outliving this) is marked after each depth copy and resolve
  GlComputeMaps(const GlApi& gl, std::string who, GpuClock& clock);
  GlComputeMaps(const GlComputeMaps&) = delete;
  GlComputeMaps& operator=(const GlComputeMaps&) = delete;
  // deletes every GL object; the context is current
  void release();

  // map set `slot` takes `shape` (buffers sized for it); its maps are empty until resolved
  void begin(int slot, const MapSet& shape);
  // the targets of one pass (the bound FBO's z-buffer, colour textures `normal` and `velocity`; view k in rows
  // k size ..) into map `map` of view `view`; each pass's first call has view 0
  void resolve(int slot, int view, int map, GLuint normal, GLuint velocity);
  // dressing 5.4's side layer, `rings` rings, on every view of map set `slot`
  void side_layer(int slot, int rings);
  void query(int slot, PointsView points, const AnswerRules& rules, Contact* out);
  void copy(int slot, MapSet& maps);

 private:
  struct Slot {
    MapSet shape;                 // frame, encoding, rows (arrays empty)
    std::array<GLuint, 4> buf{};  // z, mask, normal, velocity
    std::size_t pixels = 0;       // elements the buffers hold
  };
  GLuint program(const char* source);
  void bind(const Slot& s);
  // the bound FBO's z-buffer values, as glReadPixels hands them out, into zbuffer_ on the device
  void read_zbuffer(const MapFrame& f);

  GlApi gl_;
  std::string who_;
  GpuClock& clock_;
  GLuint resolve_ = 0, side_ = 0, query_ = 0;
  std::array<Slot, DeviceMaps::kSlots> slots_;
  GLuint points_ = 0, contacts_ = 0;  // the query batch's buffers
  GLuint zbuffer_ = 0;                // a pass's z-buffer values
  GLsizeiptr zbuffer_bytes_ = 0;
  std::size_t points_capacity_ = 0;
  std::vector<float> answers_;   // read back: 8 floats a point
  std::vector<float> scratch_;   // copy(): one array read back
};

}  // namespace clothbench
