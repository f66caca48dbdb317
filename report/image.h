// An RGB picture in memory and its PNG file form (lodepng, the encoder MuJoCo's own tools use).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace multicpg::report {

// 8-bit RGB, rows top to bottom, 3 bytes per pixel.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;

  const std::uint8_t* pixel(int x, int y) const {
    return rgb.data() + 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                             static_cast<std::size_t>(x));
  }
};

// Writes atomically (whole file or none) and checks the written file decodes to `image` before
// publishing it. Throws BadInput for an unwritable path, RuntimeFailure if encoding, writing or
// the check fails.
void write_png(const Image& image, const std::filesystem::path& path);

// Decodes any PNG to RGB. Throws BadInput when the file is missing or not a PNG.
Image read_png(const std::filesystem::path& path);

}  // namespace multicpg::report
