// A palette canvas for the judge's chart: rectangles, thick and dashed lines, and text in a 5x7
// bitmap font (font.cpp, printable ASCII), scaled by whole pixels. Written out as PNG (png.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace relpos::detail::oracle {

/// The 5x7 glyph of a printable ASCII character (others draw as '?'): row r (top 0) is bits 4..0
/// of glyph(c)[r], bit 4 the leftmost column.
const std::array<std::uint8_t, 7>& glyph(char c);

class Canvas {
 public:
  Canvas(int width, int height, std::uint8_t background);
  int width() const { return width_; }
  int height() const { return height_; }
  std::uint8_t at(int x, int y) const { return pixels_[static_cast<std::size_t>(y * width_ + x)]; }
  /// Set a pixel (clipped to the canvas).
  void set(int x, int y, std::uint8_t colour);
  void fill(int x0, int y0, int x1, int y1, std::uint8_t colour);  ///< [x0, x1] x [y0, y1], clipped
  /// A line of the given thickness (a square brush along Bresenham's line); dashed: `dash` pixels on,
  /// `dash` off (0: solid).
  void line(double x0, double y0, double x1, double y1, std::uint8_t colour, int thickness = 1, int dash = 0);
  /// Text with its top-left corner at (x, y), each font pixel a scale x scale square, 6 x scale per
  /// character; returns the width drawn.
  int text(int x, int y, std::string_view s, std::uint8_t colour, int scale = 1);
  static int text_width(std::string_view s, int scale) { return static_cast<int>(s.size()) * 6 * scale - scale; }
  /// The PNG of the canvas with the palette's colours.
  std::string png(const std::vector<std::array<std::uint8_t, 3>>& palette) const;

 private:
  int width_, height_;
  std::vector<std::uint8_t> pixels_;
};

}  // namespace relpos::detail::oracle
