#include "report/image.h"

#include <lodepng.h>

#include <string>

#include "common/atomic_file.h"
#include "common/errors.h"

namespace multicpg::report {

void write_png(const Image& image, const std::filesystem::path& path) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() !=
          3 * static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height)) {
    throw BadInput("cannot write '" + path.string() + "': image size does not match its pixels");
  }
  std::vector<unsigned char> png;
  const unsigned rc = lodepng::encode(png, image.rgb, static_cast<unsigned>(image.width),
                                      static_cast<unsigned>(image.height), LCT_RGB);
  if (rc != 0) {
    throw RuntimeFailure("PNG encoding of '" + path.string() +
                         "' failed: " + lodepng_error_text(rc));
  }
  write_file_atomic(path, std::string(png.begin(), png.end()));
}

Image read_png(const std::filesystem::path& path) {
  std::vector<unsigned char> rgb;
  unsigned width = 0;
  unsigned height = 0;
  const unsigned rc = lodepng::decode(rgb, width, height, path.string(), LCT_RGB);
  if (rc != 0) throw BadInput("cannot read PNG '" + path.string() + "': " + lodepng_error_text(rc));
  return Image{static_cast<int>(width), static_cast<int>(height), std::move(rgb)};
}

}  // namespace multicpg::report
