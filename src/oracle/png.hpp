// A minimal PNG writer (ISO/IEC 15948): an 8-bit palette image in one IDAT chunk whose zlib stream
// (RFC 1950) holds stored deflate blocks (RFC 1951, BTYPE 00): no compression, so no dependency and
// nothing to get wrong beyond the two checksums, CRC-32 (chunks) and Adler-32 (the zlib stream).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace relpos::detail::oracle {

/// CRC-32 of ISO 3309 / ITU-T V.42 (reflected polynomial 0xEDB88320), as PNG and zlib's crc32 define it.
std::uint32_t crc32(const unsigned char* data, std::size_t n);

/// Adler-32 of RFC 1950.
std::uint32_t adler32(const unsigned char* data, std::size_t n);

/// The PNG file of a width x height image, row by row, each pixel an index into `palette` (at most
/// 256 RGB colours). Throws std::invalid_argument on a size mismatch.
std::string png_indexed(std::size_t width, std::size_t height, const std::vector<std::array<std::uint8_t, 3>>& palette,
                        const std::vector<std::uint8_t>& pixels);

}  // namespace relpos::detail::oracle
