// png.hpp.
#include "oracle/png.hpp"

#include <algorithm>
#include <stdexcept>

namespace relpos::detail::oracle {

namespace {

void put32(std::string& out, std::uint32_t x) {
  for (int shift = 24; shift >= 0; shift -= 8) out += static_cast<char>((x >> shift) & 0xFF);
}

void chunk(std::string& out, const char type[4], const std::string& data) {
  put32(out, static_cast<std::uint32_t>(data.size()));
  const std::string body = std::string(type, 4) + data;  // the CRC covers the type and the data
  out += body;
  put32(out, crc32(reinterpret_cast<const unsigned char*>(body.data()), body.size()));
}

}  // namespace

std::uint32_t crc32(const unsigned char* data, std::size_t n) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < n; ++i) c = table[(c ^ data[i]) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

std::uint32_t adler32(const unsigned char* data, std::size_t n) {
  std::uint32_t a = 1, b = 0;
  for (std::size_t i = 0; i < n; ++i) {
    a = (a + data[i]) % 65521;
    b = (b + a) % 65521;
  }
  return (b << 16) | a;
}

std::string png_indexed(std::size_t width, std::size_t height, const std::vector<std::array<std::uint8_t, 3>>& palette,
                        const std::vector<std::uint8_t>& pixels) {
  if (width == 0 || height == 0 || pixels.size() != width * height || palette.empty() || palette.size() > 256)
    throw std::invalid_argument("png_indexed: the image does not match its size or palette");
  std::string out("\x89PNG\r\n\x1a\n", 8);
  std::string header;
  put32(header, static_cast<std::uint32_t>(width));
  put32(header, static_cast<std::uint32_t>(height));
  header += std::string("\x08\x03\x00\x00\x00", 5);  // 8 bits, palette, deflate, filters, no interlace
  chunk(out, "IHDR", header);
  std::string plte;
  for (const auto& c : palette) plte.append(reinterpret_cast<const char*>(c.data()), 3);
  chunk(out, "PLTE", plte);
  // The filtered image: each row preceded by its filter type 0 (none).
  std::string raw;
  raw.reserve(height * (width + 1));
  for (std::size_t y = 0; y < height; ++y) {
    raw += '\0';
    raw.append(reinterpret_cast<const char*>(pixels.data() + y * width), width);
  }
  std::string z("\x78\x01", 2);  // deflate, 32K window, no dictionary, fastest (FCHECK: 0x7801 % 31 == 0)
  constexpr std::size_t kBlock = 65535;
  for (std::size_t at = 0; at < raw.size() || at == 0; at += kBlock) {
    const std::size_t n = std::min(kBlock, raw.size() - at);
    const bool last = at + n >= raw.size();
    z += static_cast<char>(last ? 1 : 0);  // BFINAL, BTYPE 00; the block then starts on a byte
    z += static_cast<char>(n & 0xFF);
    z += static_cast<char>(n >> 8);
    z += static_cast<char>(~n & 0xFF);
    z += static_cast<char>((~n >> 8) & 0xFF);
    z.append(raw, at, n);
    if (last) break;
  }
  put32(z, adler32(reinterpret_cast<const unsigned char*>(raw.data()), raw.size()));
  chunk(out, "IDAT", z);
  chunk(out, "IEND", "");
  return out;
}

}  // namespace relpos::detail::oracle
