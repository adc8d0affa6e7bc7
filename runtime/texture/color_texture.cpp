#include "runtime/texture/color_texture.h"

#include "runtime/io/read_image.h"
#include "runtime/io/read_input.h"

#include <cmath>

namespace fgsg::rt::texture {

namespace {

constexpr const char* kWhat = "a texture image";
constexpr io::ImageLimits kLimits{kMaxColorTexturePixels, int64_t(1) << 31, "pixels", "textures"};

// The checks probe and load share, from the file's bytes alone: the format by its magic,
// the size its header declares and the whole file present (a truncated PNG must not be
// embedded), before anything is decoded.
bool checkHeader(const std::string& path, const std::string& bytes, io::Image& header, std::string& error) {
  if (!ColorTexture::mimeType(bytes)) {
    error = path + ": is not a PNG or JPEG image (glTF embeds only those)";
    return false;
  }
  return io::checkImage(path, bytes, kLimits, header, error);
}

// i mod n for any i, in [0, n).
int wrap(int64_t i, int n) {
  const int64_t r = i % n;
  return int(r < 0 ? r + n : r);
}

}  // namespace

const char* ColorTexture::mimeType(const std::string& bytes) { return io::imageMimeType(io::imageFormatOf(bytes)); }

bool ColorTexture::probe(const std::string& path, std::string& error) {
  std::string bytes;
  if (!io::readInputFile(path, kWhat, bytes, error)) return false;
  io::Image header;
  return checkHeader(path, bytes, header, error);
}

bool ColorTexture::load(const std::string& path, std::string& error) {
  std::string bytes;
  if (!io::readInputFile(path, kWhat, bytes, error)) return false;
  io::Image header, image;
  if (!checkHeader(path, bytes, header, error) || !io::decodeImage(path, bytes, kLimits, image, error)) return false;
  bytes = std::string();
  // RGB from any channel count: grey repeated, alpha dropped.
  const size_t pixels = size_t(image.width) * size_t(image.height), channels = size_t(image.channels);
  std::vector<uint8_t> rgb(pixels * 3);
  for (size_t p = 0; p < pixels; ++p)
    for (size_t c = 0; c < 3; ++c) rgb[p * 3 + c] = image.sample8(p * channels + (channels >= 3 ? c : 0));
  rgb_ = std::move(rgb);
  width_ = image.width;
  height_ = image.height;
  return true;
}

std::array<float, 3> ColorTexture::sample(double u, double v) const {
  if (rgb_.empty() || !std::isfinite(u) || !std::isfinite(v)) return {0.0f, 0.0f, 0.0f};
  // Continuous pixel coordinates (x right from column 0's centre, y down from row 0's) of
  // the coordinate's place within one repeat of the image, so huge u or v cannot overflow.
  const double x = (u - std::floor(u)) * width_ - 0.5;
  const double y = (1.0 - (v - std::floor(v))) * height_ - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y);
  const double fx = x - x0, fy = y - y0;
  const int i0 = wrap(int64_t(x0), width_), i1 = wrap(int64_t(x0) + 1, width_);
  const int j0 = wrap(int64_t(y0), height_), j1 = wrap(int64_t(y0) + 1, height_);
  const auto at = [&](int i, int j, int c) { return double(rgb_[3 * (size_t(j) * width_ + i) + c]); };
  std::array<float, 3> out;
  for (int c = 0; c < 3; ++c) {
    const double top = (1 - fx) * at(i0, j0, c) + fx * at(i1, j0, c);
    const double bottom = (1 - fx) * at(i0, j1, c) + fx * at(i1, j1, c);
    // Bytes are interpolated and divided last, so a pixel centre reads exactly byte / 255.
    out[c] = float((1 - fy) * top + fy * bottom) / 255.0f;
  }
  return out;
}

}  // namespace fgsg::rt::texture
