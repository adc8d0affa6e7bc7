#include "runtime/output/base_color_opacity_image.h"

#include "runtime/output/packed_texture_image.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace fgsg::rt::output {

bool packBaseColorOpacity(const std::string* colorPath, const std::string& opacityPath, std::string& png,
                          std::string& error) {
  io::Image color, opacity;
  if ((colorPath && !decodeTextureLayer(*colorPath, color, error)) ||
      !decodeTextureLayer(opacityPath, opacity, error))
    return false;
  const int width = colorPath ? color.width : opacity.width, height = colorPath ? color.height : opacity.height;
  const size_t oc = size_t(opacity.channels), cc = size_t(color.channels);
  std::vector<uint8_t> rgba(size_t(width) * size_t(height) * 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      uint8_t* p = &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4];
      const size_t at = size_t(y) * size_t(width) + size_t(x);
      for (size_t c = 0; c < 3; ++c) p[c] = colorPath ? color.sample8(at * cc + (cc >= 3 ? c : 0)) : 255;
      const size_t ox = size_t(int64_t(x) * opacity.width / width), oy = size_t(int64_t(y) * opacity.height / height);
      const size_t o = (oy * size_t(opacity.width) + ox) * oc;
      if (oc == 2 || oc == 4) {
        p[3] = opacity.sample8(o + oc - 1);
      } else if (oc == 1) {
        p[3] = opacity.sample8(o);
      } else {
        const double luminance = 0.299 * opacity.sample8(o) + 0.587 * opacity.sample8(o + 1) + 0.114 * opacity.sample8(o + 2);
        p[3] = uint8_t(std::lround(luminance));
      }
    }
  return encodePackedTexture(width, height, 4, rgba.data(), "the base colour image with the opacity map", png, error);
}

}  // namespace fgsg::rt::output
