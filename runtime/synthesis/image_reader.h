// Labelled example images, mask images and image fields as 8-bit RGB, whatever the file
// holds (grey, alpha, 16 bits), decoded by the image reader (runtime/io/read_image.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt::synthesis {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // row-major, row 0 at the top
  uint32_t pixel(int x, int y) const {
    const uint8_t* p = &rgb[(size_t(y) * size_t(width) + size_t(x)) * 3];
    return (uint32_t(p[0]) << 16) | (uint32_t(p[1]) << 8) | p[2];
  }
};

// False and "PATH: ..." when the file cannot be read, is not a PNG, JPEG, BMP or PGM/PPM
// image, is truncated or damaged, or has more than io::ImageLimits' pixels.
bool readRgbImage(const std::string& path, RgbImage& out, std::string& error);

}  // namespace fgsg::rt::synthesis
