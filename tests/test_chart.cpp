// The judge's chart (src/oracle/png, raster, font, chart): CRC-32 and Adler-32 against their standard
// check values, a PNG decoded here independently (chunks, CRCs, stored deflate blocks, Adler-32,
// pixels), the font's glyphs, lines and text on a canvas, and the chart of a judged file as a PNG.
#include <catch2/catch.hpp>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "oracle/cases.hpp"
#include "oracle/chart.hpp"
#include "oracle/judge.hpp"
#include "oracle/png.hpp"
#include "oracle/raster.hpp"

using namespace relpos::detail::oracle;

namespace {

std::uint32_t be32(const std::string& s, std::size_t at) {
  std::uint32_t x = 0;
  for (std::size_t k = 0; k < 4; ++k) x = (x << 8) | static_cast<unsigned char>(s[at + k]);
  return x;
}

/// A decoded palette PNG of png_indexed's kind: width, height, palette, pixels. Fails the test on
/// anything not as the format requires.
struct Decoded {
  std::uint32_t width = 0, height = 0;
  std::vector<std::array<std::uint8_t, 3>> palette;
  std::vector<std::uint8_t> pixels;
};

Decoded decode(const std::string& png) {
  REQUIRE(png.substr(0, 8) == std::string("\x89PNG\r\n\x1a\n", 8));
  Decoded d;
  std::string idat;
  std::vector<std::string> types;
  for (std::size_t at = 8; at < png.size();) {
    const std::uint32_t n = be32(png, at);
    const std::string type = png.substr(at + 4, 4), data = png.substr(at + 8, n);
    const std::string covered = png.substr(at + 4, 4 + n);
    CHECK(be32(png, at + 8 + n) == crc32(reinterpret_cast<const unsigned char*>(covered.data()), covered.size()));
    types.push_back(type);
    if (type == "IHDR") {
      d.width = be32(data, 0);
      d.height = be32(data, 4);
      CHECK(data.substr(8) == std::string("\x08\x03\x00\x00\x00", 5));
    } else if (type == "PLTE") {
      for (std::size_t k = 0; k + 2 < data.size(); k += 3)
        d.palette.push_back({static_cast<std::uint8_t>(data[k]), static_cast<std::uint8_t>(data[k + 1]),
                             static_cast<std::uint8_t>(data[k + 2])});
    } else if (type == "IDAT") {
      idat += data;
    }
    at += 12 + n;
  }
  CHECK(types == std::vector<std::string>{"IHDR", "PLTE", "IDAT", "IEND"});
  // zlib: header, stored blocks, Adler-32 of the inflated data.
  REQUIRE(idat.size() >= 6);
  CHECK((static_cast<unsigned char>(idat[0]) * 256 + static_cast<unsigned char>(idat[1])) % 31 == 0);
  CHECK((idat[0] & 0x0F) == 8);  // deflate
  std::string raw;
  std::size_t at = 2;
  for (bool last = false; !last;) {
    const auto header = static_cast<unsigned char>(idat[at]);
    last = header & 1;
    CHECK((header >> 1) == 0);  // BTYPE 00: stored
    const std::size_t len = static_cast<unsigned char>(idat[at + 1]) | static_cast<unsigned char>(idat[at + 2]) << 8;
    const std::size_t nlen = static_cast<unsigned char>(idat[at + 3]) | static_cast<unsigned char>(idat[at + 4]) << 8;
    CHECK(len == (~nlen & 0xFFFF));
    raw += idat.substr(at + 5, len);
    at += 5 + len;
  }
  CHECK(be32(idat, at) == adler32(reinterpret_cast<const unsigned char*>(raw.data()), raw.size()));
  CHECK(at + 4 == idat.size());
  REQUIRE(raw.size() == d.height * (d.width + 1));
  for (std::uint32_t y = 0; y < d.height; ++y) {
    CHECK(raw[y * (d.width + 1)] == 0);  // filter: none
    for (std::uint32_t x = 0; x < d.width; ++x)
      d.pixels.push_back(static_cast<std::uint8_t>(raw[y * (d.width + 1) + 1 + x]));
  }
  return d;
}

}  // namespace

TEST_CASE("CRC-32 and Adler-32 give their standard check values", "[chart]") {
  const std::string nine = "123456789", wiki = "Wikipedia";
  CHECK(crc32(reinterpret_cast<const unsigned char*>(nine.data()), nine.size()) == 0xCBF43926u);
  CHECK(adler32(reinterpret_cast<const unsigned char*>(wiki.data()), wiki.size()) == 0x11E60398u);
  CHECK(crc32(nullptr, 0) == 0);
  CHECK(adler32(nullptr, 0) == 1);
  // IEND's CRC, the constant every PNG ends with.
  CHECK(crc32(reinterpret_cast<const unsigned char*>("IEND"), 4) == 0xAE426082u);
}

TEST_CASE("png_indexed writes what an independent decoder reads back, across several stored blocks", "[chart]") {
  const std::size_t w = 301, h = 257;  // more than 65535 bytes of filtered data: two blocks
  std::vector<std::uint8_t> pixels(w * h);
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<std::uint8_t>((i * 7 + i / w) % 5);
  const std::vector<std::array<std::uint8_t, 3>> palette = {
      {0, 0, 0}, {255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {9, 9, 9}};
  const Decoded d = decode(png_indexed(w, h, palette, pixels));
  CHECK(d.width == w);
  CHECK(d.height == h);
  CHECK(d.palette == palette);
  CHECK(d.pixels == pixels);
  CHECK_THROWS(png_indexed(2, 2, palette, std::vector<std::uint8_t>(3)));
}

TEST_CASE("the font and the canvas: distinct glyphs, lines to their ends, text where asked", "[chart]") {
  std::set<std::array<std::uint8_t, 7>> seen;
  for (char c = 33; c < 127; ++c) seen.insert(glyph(c));
  CHECK(seen.size() == 94);  // every visible character drawn differently
  CHECK(glyph(' ') == std::array<std::uint8_t, 7>{});
  CHECK(glyph('\x01') == glyph('?'));
  CHECK(glyph('I') == std::array<std::uint8_t, 7>{0x0e, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0e});
  Canvas c(40, 30, 0);
  c.line(2, 3, 30, 20, 1);
  CHECK(c.at(2, 3) == 1);
  CHECK(c.at(30, 20) == 1);
  CHECK(c.at(30, 3) == 0);
  c.line(0, 29, 39, 29, 2, 1, 4);  // dashed: 4 on, 4 off
  CHECK(c.at(1, 29) == 2);
  CHECK(c.at(5, 29) == 0);
  Canvas t(20, 20, 0);
  CHECK(t.text(5, 5, "I", 3, 2) == Canvas::text_width("I", 2));
  CHECK(t.at(7, 5) == 3);  // the top bar of I, doubled
  CHECK(t.at(5, 5) == 0);  // its first column is blank
  CHECK(t.at(9, 8) == 3);  // the stem
  c.set(-1, 100, 3);       // clipped, no effect
  CHECK(decode(c.png({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}})).pixels.size() == 40 * 30);
}

TEST_CASE("the chart of a judged file is a PNG with the curves' colours", "[chart]") {
  CaseOptions o;
  o.families = {"offaxis", "tiny"};
  o.n = 4;
  o.eps = {"1e-4", "1e-10", "0"};
  std::string cases, answers;
  for (const Case& c : make_cases(o)) {
    cases += case_line(c, Form::Exact) + "\n";
    answers += "{\"id\":\"" + c.id + "\",\"position\":\"C\"}\n";
  }
  const JudgeReport r = judge(cases, answers, JudgeOptions{});
  const Decoded d = decode(chart_png(r));
  CHECK(d.width == 1000);
  CHECK(d.height == 620);
  std::set<std::uint8_t> used(d.pixels.begin(), d.pixels.end());
  CHECK(used.count(0));     // white
  CHECK(used.count(1));     // black: text and the curve of all families
  CHECK(used.size() >= 6);  // grid, baselines, two families
  JudgeReport empty = judge(
      "{\"id\":1,\"ellipsoid\":{\"sphere\":{\"center\":[0,0,1],\"radius\":\"1/4\"}},"
      "\"paraboloid\":{\"vertex\":[0,0,0],\"a\":1,\"b\":1}}",
      "", JudgeOptions{});
  CHECK(decode(chart_png(empty)).width == 1000);  // no eps: the frame and a note
}
