#pragma once
/// @file
/// Writing PNG images (pictures of grasps, report charts) with libpng: OpenCV's image codecs
/// would bring GDAL and about a hundred other libraries into every process that draws (a
/// one-shot `antipode detect` took 0.78 s with them against 0.58 s without, together with
/// reading model files in one piece, measured side by side when they were replaced).

#include <cstddef>
#include <cstdint>
#include <string>

namespace antipode {

/// Writes the 8-bit colour image `pixels` to the PNG file `path`, all-or-nothing
/// (write_file_atomically). `pixels` holds `height` rows `row_bytes` apart, each of `width`
/// pixels of three bytes in blue, green, red order (OpenCV's CV_8UC3 layout). Throws
/// antipode::Error naming the file when it cannot be written or the sizes are not positive.
void write_png_bgr(const std::string& path, int width, int height, const std::uint8_t* pixels,
                   std::size_t row_bytes);

}  // namespace antipode
