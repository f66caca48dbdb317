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
  AtomicFile file(path);
  file.stream().write(reinterpret_cast<const char*>(png.data()),
                      static_cast<std::streamsize>(png.size()));
  // What reached the disk decodes to this picture, or the file is not published.
  file.commit([&](const std::filesystem::path& tmp) {
    std::vector<unsigned char> back;
    unsigned width = 0;
    unsigned height = 0;
    const unsigned decoded = lodepng::decode(back, width, height, tmp.string(), LCT_RGB);
    if (decoded != 0 || width != static_cast<unsigned>(image.width) ||
        height != static_cast<unsigned>(image.height) || back != image.rgb) {
      throw RuntimeFailure("'" + path.string() + "' does not read back as the picture written" +
                           (decoded != 0 ? std::string(": ") + lodepng_error_text(decoded) : ""));
    }
  });
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
