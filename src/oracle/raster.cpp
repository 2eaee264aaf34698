// raster.hpp: the canvas; the font is font.cpp's.
#include "oracle/raster.hpp"

#include <cmath>
#include <cstdlib>

#include "oracle/png.hpp"

namespace relpos::detail::oracle {

Canvas::Canvas(int width, int height, std::uint8_t background)
    : width_(width), height_(height), pixels_(static_cast<std::size_t>(width * height), background) {}

void Canvas::set(int x, int y, std::uint8_t colour) {
  if (x >= 0 && y >= 0 && x < width_ && y < height_) pixels_[static_cast<std::size_t>(y * width_ + x)] = colour;
}

void Canvas::fill(int x0, int y0, int x1, int y1, std::uint8_t colour) {
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) set(x, y, colour);
}

void Canvas::line(double fx0, double fy0, double fx1, double fy1, std::uint8_t colour, int thickness, int dash) {
  int x0 = static_cast<int>(std::lround(fx0)), y0 = static_cast<int>(std::lround(fy0));
  const int x1 = static_cast<int>(std::lround(fx1)), y1 = static_cast<int>(std::lround(fy1));
  const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0), sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
  const int lo = -(thickness - 1) / 2, hi = thickness / 2;
  int err = dx + dy;
  for (int step = 0;; ++step) {
    if (dash == 0 || (step / dash) % 2 == 0) fill(x0 + lo, y0 + lo, x0 + hi, y0 + hi, colour);
    if (x0 == x1 && y0 == y1) break;
    const int e2 = 2 * err;
    if (e2 >= dy) {
      err += dy;
      x0 += sx;
    }
    if (e2 <= dx) {
      err += dx;
      y0 += sy;
    }
  }
}

int Canvas::text(int x, int y, std::string_view s, std::uint8_t colour, int scale) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    const std::array<std::uint8_t, 7>& g = glyph(s[i]);
    const int left = x + static_cast<int>(i) * 6 * scale;
    for (int row = 0; row < 7; ++row)
      for (int col = 0; col < 5; ++col)
        if ((g[static_cast<std::size_t>(row)] >> (4 - col)) & 1)
          fill(left + col * scale, y + row * scale, left + col * scale + scale - 1, y + row * scale + scale - 1,
               colour);
  }
  return text_width(s, scale);
}

std::string Canvas::png(const std::vector<std::array<std::uint8_t, 3>>& palette) const {
  return png_indexed(static_cast<std::size_t>(width_), static_cast<std::size_t>(height_), palette, pixels_);
}

}  // namespace relpos::detail::oracle
