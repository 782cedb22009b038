// walking-t2's pictures: frame sequences, their video, the every-frame chart (walking_t2_media.hpp).
#include "walking_t2_media.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>

namespace clothbench {

bool make_video(const std::string& pattern, const std::string& mp4, double fps) {
  if (std::system("command -v ffmpeg > /dev/null 2>&1") != 0) {
    std::cerr << "  note: ffmpeg not installed, no video " << mp4 << " (apt-get install ffmpeg)\n";
    return false;
  }
  const std::string cmd = "ffmpeg -loglevel error -y -framerate " + num(fps, 0) + " -i '" + pattern +
                          "' -pix_fmt yuv420p -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' '" + mp4 + "'";
  if (std::system(cmd.c_str()) == 0) return true;
  std::cerr << "  warning: ffmpeg failed for " << mp4 << "\n";
  return false;
}

void write_sequence(PictureRenderer& pictures, const std::vector<SequenceFrame>& sequence, const RunResult& r,
                    const std::string& prefix) {
  BodyFrame body = r.final_body;
  ClothMesh mesh = r.mesh;
  for (const auto& f : sequence) {
    body.positions = f.body_positions;
    body.normals = f.body_normals;
    mesh.positions = f.cloth_positions;
    char name[32];
    std::snprintf(name, sizeof name, "-frame%03ld.png", f.frame);
    pictures.render(body, mesh, 200, View::kFront).write_png(prefix + name);
  }
}

nlohmann::json frames_chart(const std::string& product, const std::vector<std::pair<std::string, RunResult>>& runs) {
  nlohmann::json series = nlohmann::json::array();
  double t0 = 1e9, t1 = -1e9;
  for (const auto& [collider, r] : runs) {
    if (r.frame_samples.empty()) continue;
    std::vector<double> t, inside, crossings;
    for (const FrameSample& f : r.frame_samples)
      t.push_back(f.t_s), inside.push_back(f.inside_pct), crossings.push_back(f.crossings_pct);
    t0 = std::min(t0, t.front()), t1 = std::max(t1, t.back());
    series.push_back({{"label", collider + " crossings"}, {"x", t}, {"y", crossings}, {"style", "-"}});
    series.push_back({{"label", collider + " inside"}, {"x", t}, {"y", inside}, {"style", "--"}});
  }
  if (t1 > t0) {
    series.push_back({{"label", "limit: crossings 1 %"},
                      {"x", {t0, t1}},
                      {"y", {kAccuracyLimits.crossings_pct, kAccuracyLimits.crossings_pct}},
                      {"style", "k:"}});
    series.push_back({{"label", "limit: inside 0.5 %"},
                      {"x", {t0, t1}},
                      {"y", {kAccuracyLimits.inside_pct, kAccuracyLimits.inside_pct}},
                      {"style", "k-."}});
  }
  return {{"title", "walking-t2: " + product + ", walk_07_01, stable regime, every frame"},
          {"xlabel", "animation time [s]"},
          {"ylabel", "share of the cloth [%]"},
          {"series", series}};
}

}  // namespace clothbench
