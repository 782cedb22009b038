#pragma once
// walking-t2's pictures: the frames of a walk kept for a picture sequence, its video and the every-frame chart.
// experiments/src only.
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "clothbench/bench/report.hpp"
#include "clothbench/render/picture.hpp"

namespace clothbench {

// one animation frame kept for the picture sequence: body and cloth vertex positions [m] (3 x n)
struct SequenceFrame {
  long frame;
  double t;
  Points3 body_positions, body_normals, cloth_positions;
};

// an H.264 video of a numbered PNG sequence at `fps`, when ffmpeg is on the PATH (skipped with a note otherwise);
// true when the video was written
bool make_video(const std::string& pattern, const std::string& mp4, double fps);

// PREFIX-frameNNN.png per kept frame (front view), drawn on the run's final body and mesh topology
void write_sequence(PictureRenderer& pictures, const std::vector<SequenceFrame>& sequence, const RunResult& r,
                    const std::string& prefix);

// inside and crossings against animation time, one series per collider (and the limits)
nlohmann::json frames_chart(const std::string& product, const std::vector<std::pair<std::string, RunResult>>& runs);

}  // namespace clothbench
