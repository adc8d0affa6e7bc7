#include "runtime/texture/texture_map.h"

#include "runtime/io/read_image.h"
#include "runtime/io/read_input.h"

#include <algorithm>
#include <cmath>

namespace fgsg::rt::texture {

namespace {

// One value per texel (see TextureMap) from the decoded samples.
std::vector<uint16_t> texelValues(const io::Image& image) {
  std::vector<uint16_t> out(size_t(image.width) * size_t(image.height));
  const size_t channels = size_t(image.channels);
  for (size_t i = 0; i < out.size(); ++i) {
    const size_t c = i * channels;
    out[i] = uint16_t(channels >= 3 ? std::max({image.sample(c), image.sample(c + 1), image.sample(c + 2)})
                                    : image.sample(c));
  }
  return out;
}

}  // namespace

bool TextureMap::load(const std::string& path, std::string& error) {
  std::string bytes;
  if (!io::readInputFile(path, "a texture image", bytes, error)) return false;
  io::Image image;
  const io::ImageLimits limits{kMaxTexels, kMaxTextureSide, "texels", "textures"};
  if (!io::decodeImage(path, bytes, limits, image, error)) return false;
  bytes = std::string();
  values_ = texelValues(image);
  width_ = image.width;
  height_ = image.height;
  bits_ = image.bits;
  full_ = image.fullScale;
  return true;
}

double TextureMap::sample(double u, double v) const {
  if (values_.empty() || std::isnan(u) || std::isnan(v)) return 0.0;
  // Continuous texel coordinates: x right from column 0's centre, y down from row 0's.
  const double x = std::clamp(u * width_ - 0.5, 0.0, double(width_ - 1));
  const double y = std::clamp((1.0 - v) * height_ - 0.5, 0.0, double(height_ - 1));
  const int i0 = std::min(int(x), std::max(width_ - 2, 0));
  const int j0 = std::min(int(y), std::max(height_ - 2, 0));
  const int i1 = std::min(i0 + 1, width_ - 1), j1 = std::min(j0 + 1, height_ - 1);
  const double fx = x - i0, fy = y - j0;
  const double top = (1 - fx) * texel(i0, j0) + fx * texel(i1, j0);
  const double bottom = (1 - fx) * texel(i0, j1) + fx * texel(i1, j1);
  return (1 - fy) * top + fy * bottom;
}

}  // namespace fgsg::rt::texture
