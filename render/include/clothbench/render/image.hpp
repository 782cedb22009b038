#pragma once
/// The one image type of every picture: an 8-bit RGB raster with a few drawing primitives, written as
/// PNG (libpng).
#include <cstdint>
#include <string>
#include <vector>

namespace clothbench {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
};

class Image {
 public:
  Image(int width, int height, Rgb fill = {255, 255, 255});
  int width() const { return w_; }
  int height() const { return h_; }
  /// Sets a pixel; (0, 0) is the top-left corner; outside the raster it does nothing.
  void set(int x, int y, Rgb c);
  Rgb get(int x, int y) const;
  /// The pixels: row-major, top row first, 3 bytes per pixel (3 x width x height).
  std::uint8_t* data() { return rgb_.data(); }
  const std::uint8_t* data() const { return rgb_.data(); }
  /// A 1-pixel line from (x0, y0) to (x1, y1) (Bresenham).
  void line(int x0, int y0, int x1, int y1, Rgb c);
  /// A filled axis-aligned square of side 2r+1 centred at (x, y).
  void dot(int x, int y, int r, Rgb c);
  /// Writes the image as an 8-bit RGB PNG; throws std::runtime_error naming the path on failure.
  /// Written to PATH.tmp first and renamed, so no half-written file is ever left.
  void write_png(const std::string& path) const;

 private:
  int w_, h_;
  std::vector<std::uint8_t> rgb_;  // row-major, top row first (3 x w x h)
};

/// A colour of a perceptually ordered map (viridis-like) for t in [0, 1]; NaN gives grey.
Rgb colormap(double t);

}  // namespace clothbench
