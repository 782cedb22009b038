// export_viewer_gltf: io's glTF writer with render's panel colours and the oracle's distances.
#include "clothbench/bench/viewer_export.hpp"

#include "clothbench/bench/oracle.hpp"
#include "clothbench/render/picture.hpp"

namespace clothbench {

void export_viewer_gltf(const std::string& path, const BodyFrame& body, const ClothMesh& cloth,
                        const std::vector<ViewerFrame>& frames, int max_frames) {
  ViewerStyle style;
  style.panel_colour = [](int panel) {
    const Rgb c = panel_colour(panel);
    return std::array<float, 3>{c.r / 255.f, c.g / 255.f, c.b / 255.f};
  };
  style.signed_distance = [](const BodyFrame& b, const Points3& points, std::vector<Real>& out) {
    Oracle(b).signed_distance(PointsView(points), out);
  };
  write_viewer_gltf(path, body, cloth, style, frames, max_frames);
}

}  // namespace clothbench
