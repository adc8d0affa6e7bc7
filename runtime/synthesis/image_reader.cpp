#include "runtime/synthesis/image_reader.h"

#include "runtime/io/read_image.h"
#include "runtime/io/read_input.h"

namespace fgsg::rt::synthesis {

bool readRgbImage(const std::string& path, RgbImage& out, std::string& error) {
  std::string bytes;
  if (!io::readInputFile(path, "an image file", bytes, error)) return false;
  io::Image image;
  if (!io::decodeImage(path, bytes, io::ImageLimits{}, image, error)) return false;
  bytes = std::string();
  // RGB from any channel count: grey repeated, alpha dropped; 16-bit samples rounded.
  const size_t pixels = size_t(image.width) * size_t(image.height), channels = size_t(image.channels);
  out.rgb.assign(pixels * 3, 0);
  for (size_t p = 0; p < pixels; ++p)
    for (size_t c = 0; c < 3; ++c) out.rgb[p * 3 + c] = image.sample8(p * channels + (channels >= 3 ? c : 0));
  out.width = image.width;
  out.height = image.height;
  return true;
}

}  // namespace fgsg::rt::synthesis
