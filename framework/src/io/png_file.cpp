#include "antipode/io/png_file.hpp"

#include <png.h>

#include "antipode/core/atomic_file.hpp"
#include "antipode/core/error.hpp"

namespace antipode {

void write_png_bgr(const std::string& path, int width, int height, const std::uint8_t* pixels,
                   std::size_t row_bytes) {
  if (width <= 0 || height <= 0 || pixels == nullptr)
    throw Error(path + ": cannot write a PNG of " + std::to_string(width) + " x " +
                std::to_string(height) + " pixels");
  write_file_atomically(path, [&](const std::string& temporary) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(width);
    image.height = static_cast<png_uint_32>(height);
    image.format = PNG_FORMAT_BGR;
    if (png_image_write_to_file(&image, temporary.c_str(), 0, pixels,
                                static_cast<png_int_32>(row_bytes), nullptr) == 0) {
      const std::string message = image.message;
      png_image_free(&image);
      throw Error(path + ": cannot write the PNG: " + message);
    }
  });
}

}  // namespace antipode
