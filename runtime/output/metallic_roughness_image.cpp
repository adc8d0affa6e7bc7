#include "runtime/output/metallic_roughness_image.h"

#include "runtime/output/packed_texture_image.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace fgsg::rt::output {

namespace {

// One layer's image decoded, and the channel it is read by.
struct MetallicRoughnessSource {
  io::Image image;
  size_t channel = 0;  // green (1) or blue (2) of a colour image; a grey one's grey
  bool present = false;

  bool load(const std::string* path, size_t colorChannel, std::string& error) {
    if (!path) return true;
    if (!decodeTextureLayer(*path, image, error)) return false;
    channel = image.channels >= 3 ? colorChannel : 0;
    present = true;
    return true;
  }
  // The sample at pixel (x, y) of a width x height picture (nearest); 255 without an image.
  uint8_t at(int x, int y, int width, int height) const {
    if (!present) return 255;
    const size_t sx = size_t(int64_t(x) * image.width / width), sy = size_t(int64_t(y) * image.height / height);
    return image.sample8((sy * size_t(image.width) + sx) * size_t(image.channels) + channel);
  }
};

}  // namespace

bool packMetallicRoughness(const std::string* roughnessPath, const std::string* metallicPath, std::string& png,
                           std::string& error) {
  MetallicRoughnessSource roughness, metallic;
  if (!roughness.load(roughnessPath, 1, error) || !metallic.load(metallicPath, 2, error)) return false;
  const int width = std::max({roughness.present ? roughness.image.width : 1, metallic.present ? metallic.image.width : 1});
  const int height = std::max({roughness.present ? roughness.image.height : 1, metallic.present ? metallic.image.height : 1});
  std::vector<uint8_t> rgb(size_t(width) * size_t(height) * 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      uint8_t* p = &rgb[(size_t(y) * size_t(width) + size_t(x)) * 3];
      p[0] = 255;
      p[1] = roughness.at(x, y, width, height);
      p[2] = metallic.at(x, y, width, height);
    }
  return encodePackedTexture(width, height, 3, rgb.data(), "the packed metallic-roughness image", png, error);
}

}  // namespace fgsg::rt::output
