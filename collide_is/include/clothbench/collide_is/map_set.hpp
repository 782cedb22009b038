#pragma once
/// Front and back depth, normal and velocity maps of a body (dressing paper section 5, walking
/// paper section 4), the cameras that produce them, and the two renderers that draw them:
/// OpenGL through OSMesa ("gl") and our CPU rasteriser ("cpu"), which give the same coverage.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "clothbench/sim/body_frame.hpp"
#include "clothbench/sim/collider.hpp"

namespace clothbench {

class DeviceMaps;

/// The two orthographic cameras of walking paper section 4, both looking at the centre of the
/// body's bounding box: the front camera sits on the box's +Z face and looks along -Z, the back
/// camera on the -Z face looks along +Z. Both see the same square of the x-y plane.
///
/// Window coordinates (pixels, origin at the map's lower-left corner, +y up) of a world point:
///   front: (u, v) = ((x - x0) / pixel, (y - y0) / pixel)            (dressing Eq. 8, X_front)
///   back:  (size - u, v)                                               (dressing Eq. 8, X_back)
/// Depth (z-buffer) runs 0 at the near plane to 1 at the far plane:
///   front: zbuf = (z_max - z) / (z_max - z_min),  back: zbuf = (z - z_min) / (z_max - z_min).
///
/// Beyond the papers, `views` = 4 adds a pair along X (view 2 on the box's +X face looking along
/// -X, view 3 on the -X face looking along +X; window (u, v) = ((z - z0) / pixel, (y - y0) / pixel))
/// and `views` = 6 a pair along Y (view 4 above looking down, view 5 below looking up; window
/// ((x - x0) / pixel, (z - z0) / pixel)): a cube of cameras, same pixel and size, neither mirrored.
/// View k looks along axis view_axis(k); even views sit on the + face (their map holds the largest
/// surface coordinate along that axis), odd views on the - face (the smallest).
struct MapFrame {
  int size = 0;    ///< pixels per side of each square map
  Real x0 = 0;     ///< world x of the map's left edge (front view) [m]
  Real y0 = 0;     ///< world y of the map's bottom edge [m]
  Real pixel = 0;  ///< side of one pixel [m] (dressing Eq. 11)
  Real z_min = 0;  ///< back camera's near plane = front camera's far plane [m]
  Real z_max = 0;  ///< front camera's near plane = back camera's far plane [m]
  int views = 2;   ///< 2 (front, back), 4 (+ along X) or 6 (+ along Y)
  Real z0 = 0;     ///< world z of the square's edge in the views along X and Y [m]
  Real x_min = 0, x_max = 0;  ///< near/far planes of the views along X [m]
  Real y_min = 0, y_max = 0;  ///< near/far planes of the views along Y [m]
  int layers = 1;             ///< surfaces kept per pixel by each even view (depth peeling; 1: the nearest only)

  /// Maps in a MapSet: the views, then layers 2..layers of every even view (peeled maps).
  int map_count() const { return views + views / 2 * (layers - 1); }
  /// Map holding `layer` (1 = the view itself) of even view `view`: layer by layer, views in order.
  int peel_map(int view, int layer) const { return layer == 1 ? view : views + (layer - 2) * (views / 2) + view / 2; }
  /// The view a map belongs to: itself for a view, its even view for a peeled map.
  int view_of(int map) const { return map < views ? map : 2 * ((map - views) % (views / 2)); }
  /// Layer of a map: 1 for a view, 2..layers for a peeled map.
  int layer_of(int map) const { return map < views ? 1 : (map - views) / (views / 2) + 2; }

  /// Continuous front-view column of world x [pixels].
  Real front_u(Real x) const { return (x - x0) / pixel; }
  /// Continuous row of world y [pixels].
  Real map_v(Real y) const { return (y - y0) / pixel; }
  /// Distance between the near and far planes [m] (bboxdepth of dressing Eq. 5).
  Real depth_range() const { return z_max - z_min; }
  /// World axis (0 x, 1 y, 2 z) view k looks along: 2 for views 0-1, 0 for 2-3, 1 for 4-5.
  static constexpr int view_axis(int view) { return view < 2 ? 2 : view < 4 ? 0 : 1; }
  /// World axes of view k's window columns and rows.
  static constexpr int column_axis(int view) { return view == 2 || view == 3 ? 2 : 0; }
  static constexpr int row_axis(int view) { return view >= 4 ? 2 : 1; }
  /// World coordinate of the squares' lower edge along `axis` [m].
  Real origin(int axis) const { return axis == 0 ? x0 : axis == 1 ? y0 : z0; }
  /// Near/far planes along `axis` [m].
  Real plane_min(int axis) const { return axis == 0 ? x_min : axis == 1 ? y_min : z_min; }
  Real plane_max(int axis) const { return axis == 0 ? x_max : axis == 1 ? y_max : z_max; }
};

/// Column-major clip-from-world matrix of one view (0 front, 1 back, 2-5 the extra views) for a
/// viewport of frame.size^2 pixels: the view's column and row axes to [-1, 1] over the map's square
/// (back view mirrored in x, dressing Eq. 8), its depth axis to -1 at its near plane and +1 at its
/// far plane. Both renderers use it, so both start from the same float window coordinates.
std::array<float, 16> clip_from_world(const MapFrame& frame, int view);

/// Cameras for a body's bounding box. The square is the papers' (side = box height, bottom on
/// the box's floor, centred on the box in x; dressing Eq. 8) or, with options.fit_extent, the
/// box's larger side plus two pixels each way, centred on the box. The near/far planes are the
/// box's z faces moved out by options.tol so no surface lies on a clipping plane. options.views
/// 4 and 6 add the cameras along X and Y: same pixel, the square centred on the box in z, planes on
/// the box's faces moved out by tol. Throws std::invalid_argument when options.map_size < 8, the
/// box is flat, or options.views / side_layer_mm are invalid (check_view_options).
MapFrame make_map_frame(const Box3& box, const ColliderOptions& options);

/// Throws std::invalid_argument unless options.views is 2, 4 or 6, options.layers is 1 to 8 and
/// options.side_layer_mm is a finite number >= 0 (messages name the allowed values).
void check_view_options(const ColliderOptions& options);

/// Depth peeling's gap: layer l of a view is the nearest surface more than this beyond layer l - 1 in
/// z-buffer units (1e-4 of the depth range: 0.03-0.2 mm), wider than the few micrometres by which a fragment's
/// depth in the shader may differ from the depth buffer's, narrower than any two surfaces worth telling apart.
inline constexpr float kPeelGap = 1e-4f;

/// Every view's maps (frame.views of them), front then back then the extra views, then the peeled
/// maps (frame.layers > 1: layer 2 of views 0, 2 and 4, then layer 3 of each, ...), each
/// `size x size` pixels, row-major, row 0 at the bottom, columns in the view's own window order
/// (so the back map is mirrored in x, dressing Eq. 8; a peeled map as its view). Pixel p of map k
/// (0 front, 1 back) is element k * size^2 + row * size + col. `z` holds each map's surface
/// coordinate along its view's axis. Peeling: layer l of a view is the nearest surface beyond
/// layer l - 1 (its z-buffer value larger by more than kPeelGap), so along the pixel's line the even view's layers
/// and the odd view's nearest surface list where the line enters and leaves the body.
struct MapSet {
  static constexpr int kFront = 0;
  static constexpr int kBack = 1;
  /// Mask values.
  static constexpr std::uint8_t kEmpty = 0;  ///< no body at this pixel
  static constexpr std::uint8_t kBody = 1;   ///< the body covers the pixel centre
  static constexpr std::uint8_t kSide = 2;   ///< the extra silhouette layer (dressing 5.4)

  MapFrame frame;                     ///< the cameras
  bool float_maps = true;             ///< float normal/velocity (true) or 8-bit colours (dressing Eq. 6, walking Eq. 9)
  bool has_velocity = false;          ///< velocity maps were rendered (moving bodies only)
  Real max_speed = 3;                 ///< maxv of the 8-bit velocity encoding [m/s] (walking Eq. 9/10)
  std::vector<float> z;            ///< body surface z [m] (maps x size^2); -inf (even views) / +inf (odd) where empty
  std::vector<std::uint8_t> mask;  ///< kEmpty, kBody or kSide (maps x size^2)
  std::vector<float> normal;       ///< float maps: interpolated normal xyz + 1 (4 x maps x size^2)
  std::vector<float> velocity;     ///< float maps with velocity: xyz + 1 [m/s] (4 x maps x size^2)
  std::vector<std::uint8_t> normal8;  ///< 8-bit maps: RGBA, RGB = 0.5 n + 0.5 (dressing Eq. 6)
  std::vector<std::uint8_t> velocity8;  ///< 8-bit maps: RGBA, RGB = 0.5 v / maxv + 0.5 (walking Eq. 9)
  /// The rows each view (and its peeled layers) draws and reads back, first and last: every row after reset();
  /// limit_rows() narrows them to a region the queries come from. Rows outside are left empty.
  std::array<int, 6> row_first{}, row_last{};

  /// Pixels per view.
  std::size_t view_pixels() const { return static_cast<std::size_t>(frame.size) * frame.size; }
  /// Element index of (map, col, row); a view's map is the view's index.
  std::size_t index(int map, int col, int row) const {
    return map * view_pixels() + static_cast<std::size_t>(row) * frame.size + col;
  }
  /// Unit normal at element i (dressing Eq. 7 for 8-bit maps); zero where the map is empty.
  Vec3 normal_at(std::size_t i) const;
  /// The interpolated normal as stored at element i, not normalised (decoded by Eq. 7).
  Vec3 raw_normal_at(std::size_t i) const;
  /// Body velocity at element i [m/s] (walking Eq. 10 for 8-bit maps); zero without velocity maps.
  Vec3 velocity_at(std::size_t i) const;
  /// Copies depth, normal and velocity (not the mask) of element `from` to element `to`.
  void copy_element(std::size_t from, std::size_t to) {
    z[to] = z[from];
    if (float_maps) {
      std::copy_n(&normal[4 * from], 4, &normal[4 * to]);
      if (has_velocity) std::copy_n(&velocity[4 * from], 4, &velocity[4 * to]);
    } else {
      std::copy_n(&normal8[4 * from], 4, &normal8[4 * to]);
      if (has_velocity) std::copy_n(&velocity8[4 * from], 4, &velocity8[4 * to]);
    }
  }
  /// Sizes every array for `frame` and the encoding, clearing z to +-inf and the mask to kEmpty; every row drawn.
  void reset(const MapFrame& new_frame, bool floats, bool with_velocity, Real maxv);
  /// Frame, encoding and rows as reset() sets them, the arrays untouched: the shape of maps drawn elsewhere
  /// (DeviceMaps).
  void set_shape(const MapFrame& new_frame, bool floats, bool with_velocity, Real maxv);
  /// Draws only the rows of each view that `region` spans (each view's row axis, a pixel more each way): the
  /// maps are then the full maps in those rows and empty in the others (a region that misses a view leaves it
  /// empty). For a caller whose queries all come from within `region` (ImageSpaceCollider::set_query_region).
  void limit_rows(const Box3& region);
  /// The elements [first, second) of map `map`'s rows that are drawn (first == second: none).
  std::pair<std::size_t, std::size_t> drawn(int map) const;
};

/// Adds the silhouette layer of dressing 5.4: every empty pixel with a body pixel among its 8
/// neighbours takes the depth, normal and velocity of the neighbour nearest to the camera and
/// becomes kSide. Applied to every view (not to the peeled maps). `rings` > 1 repeats it outwards from the last ring
/// (a layer `rings` pixels wide, Chebyshev distance), each ring taking its values from the previous.
void add_side_layer(MapSet& maps, int rings = 1);

/// Rings of the side layer for `options` at `pixel` [m]: 0 without options.side_layer, 1 for
/// side_layer_mm = 0 (the papers' one pixel), else ceil(side_layer_mm / pixel), at least 1.
int side_layer_rings(const ColliderOptions& options, Real pixel);

/// Turns maps.z from z-buffer values (0 at the view's near plane, 1 at its far plane; 1 where
/// nothing was drawn) into the body surface coordinate along each map's view axis [m] (dressing Eq. 5,
/// tol applied at the query) and sets the mask to kBody where something was drawn, kEmpty
/// (z = -inf for even views, +inf for odd) elsewhere.
void depth_from_zbuffer(MapSet& maps);

/// Draws every view of a body into a MapSet whose frame and encoding are already set (reset()).
class MapRenderer {
 public:
  MapRenderer() = default;
  MapRenderer(const MapRenderer&) = delete;
  MapRenderer& operator=(const MapRenderer&) = delete;
  virtual ~MapRenderer() = default;
  /// "gl", "egl" or "cpu".
  virtual std::string_view name() const = 0;
  /// What draws the maps: "OSMesa: Mesa llvmpipe (LLVM 15.0.6, 256 bits)", "EGL device 0 ...: NVIDIA
  /// Corporation NVIDIA H100", "our CPU rasteriser".
  virtual std::string device() const = 0;
  /// Renders depth and normal maps (and velocity maps when maps.has_velocity) of `body`, every
  /// view and peeled layer, mask kBody or kEmpty. Does not add the side layer. Never throws once set up, but for
  /// an OpenGL context that another thread holds (std::runtime_error).
  /// Any thread may call it, one at a time.
  virtual void render(const BodyFrame& body, MapSet& maps) = 0;
  /// The renderer's maps kept on its device, answering points there; null where the maps live on the CPU.
  virtual DeviceMaps* device_maps() { return nullptr; }
};

/// Whether a MapRenderer::device() names a renderer on the CPU (Mesa's llvmpipe, our rasteriser), not a GPU.
bool cpu_device(std::string_view device);

/// OpenGL via OSMesa (llvmpipe): one off-screen context with its own small client buffer, drawing as
/// make_gl_map_renderer(context) (gl_context.hpp). Throws std::runtime_error when no context can be created or a
/// shader does not compile, and in builds without CLOTHBENCH_WITH_GL (message naming the option).
std::unique_ptr<MapRenderer> make_gl_map_renderer();

/// The CPU rasteriser: every view in one pass over the triangles, reproducing llvmpipe (Mesa 22.3):
/// window coordinates through clip_from_world and the viewport of one size x (views x size) target
/// (back view above the front, the extra views above that), vertices snapped to 1/256 pixel, pixel centres sampled with the
/// top-left fill rule, and the z-buffer value from llvmpipe's depth plane: set up in float from
/// the unsnapped vertices in its vertex order, anchored at the window origin, evaluated with fused
/// multiply-adds where the host has them (as llvmpipe's JIT does). Float attributes, anchored at
/// the triangle's first vertex.
std::unique_ptr<MapRenderer> make_cpu_map_renderer();

/// One-shot maps of a body: frame from its bounding box and `options` (map_size, fit_extent,
/// float_maps, max_speed, side_layer, side_layer_mm, views), velocity maps when body.moving. `renderer` is "gl" or
/// "cpu". Throws std::invalid_argument for another name or a malformed body, std::runtime_error
/// when GL is asked for and no context can be created or the build lacks CLOTHBENCH_WITH_GL.
MapSet render_maps(const BodyFrame& body, std::string_view renderer, const ColliderOptions& options);
/// The same with a renderer of the caller's (is-egl's, make_egl_map_renderer()).
MapSet render_maps(const BodyFrame& body, MapRenderer& renderer, const ColliderOptions& options);
/// Draws `body` into `maps` (reused): cameras on its bounding box, velocity maps for a moving body, only the rows
/// `rows` spans when given (MapSet::limit_rows), then the side layer. The body is not validated here.
void render_maps_into(const BodyFrame& body, MapRenderer& renderer, const ColliderOptions& options, MapSet& maps,
                      const std::optional<Box3>& rows = std::nullopt);
/// The shape render_maps_into gives `maps` (frame, encoding, rows; MapSet::set_shape), the arrays untouched.
void shape_maps(const BodyFrame& body, const ColliderOptions& options, MapSet& maps,
                const std::optional<Box3>& rows = std::nullopt);

}  // namespace clothbench
