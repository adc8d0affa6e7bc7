// Reads PNG (and the other formats stb_image knows) as 8-bit RGB, for labelled example
// images and mask images.
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

bool readRgbImage(const std::string& path, RgbImage& out, std::string& error);

}  // namespace fgsg::rt::synthesis
