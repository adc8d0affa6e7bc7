#include "runtime/texture/color_texture.h"

#include "runtime/io/read_input.h"

#include <cmath>

// Static linkage: other runtime files carry their own stb_image implementation
// (runtime/texture/texture_map.cpp, runtime/synthesis/image_reader.cpp). Only the two
// formats glTF embeds.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace fgsg::rt::texture {

namespace {

constexpr const char* kWhat = "a texture image";

std::string failureReason() {
  const char* why = stbi_failure_reason();
  return why ? why : "unknown error";
}

std::string sizeText(long w, long h) { return std::to_string(w) + " x " + std::to_string(h); }

const stbi_uc* data8(const std::string& bytes) { return reinterpret_cast<const stbi_uc*>(bytes.data()); }

// The checks probe and load share, from the file's bytes alone: the format by its magic,
// then the size its header declares, before anything is decoded (a small file can declare
// a huge picture).
bool checkHeader(const std::string& path, const std::string& bytes, int& w, int& h, std::string& error) {
  if (!ColorTexture::mimeType(bytes)) {
    error = path + ": is not a PNG or JPEG image (glTF embeds only those)";
    return false;
  }
  const int length = int(bytes.size());  // within the input cap, far below INT_MAX
  int channels = 0;
  if (!stbi_info_from_memory(data8(bytes), length, &w, &h, &channels)) {
    error = path + ": cannot read the image's header: " + failureReason();
    return false;
  }
  if (w <= 0 || h <= 0) {
    error = path + ": the image is empty (" + sizeText(w, h) + ")";
    return false;
  }
  if (int64_t(w) * h > kMaxColorTexturePixels) {
    error = path + ": the image is " + sizeText(w, h) + " pixels, more than the limit for textures (" +
            std::to_string(kMaxColorTexturePixels) + ")";
    return false;
  }
  return true;
}

// i mod n for any i, in [0, n).
int wrap(int64_t i, int n) {
  const int64_t r = i % n;
  return int(r < 0 ? r + n : r);
}

}  // namespace

const char* ColorTexture::mimeType(const std::string& bytes) {
  if (bytes.compare(0, 8, "\x89PNG\r\n\x1a\n", 8) == 0) return "image/png";
  if (bytes.compare(0, 3, "\xFF\xD8\xFF", 3) == 0) return "image/jpeg";
  return nullptr;
}

bool ColorTexture::probe(const std::string& path, std::string& error) {
  std::string bytes;
  if (!io::readInputFile(path, kWhat, bytes, error)) return false;
  int w = 0, h = 0;
  return checkHeader(path, bytes, w, h, error);
}

bool ColorTexture::load(const std::string& path, std::string& error) {
  std::string bytes;
  if (!io::readInputFile(path, kWhat, bytes, error)) return false;
  int w = 0, h = 0;
  if (!checkHeader(path, bytes, w, h, error)) return false;
  int dw = 0, dh = 0, channels = 0;
  stbi_uc* data = stbi_load_from_memory(data8(bytes), int(bytes.size()), &dw, &dh, &channels, 3);
  if (!data) {
    error = path + ": cannot decode the image: " + failureReason();
    return false;
  }
  // The decoder must agree with the header the size was checked by.
  if (dw != w || dh != h) {
    stbi_image_free(data);
    error = path + ": the decoded image (" + sizeText(dw, dh) + ") does not match its header (" +
            sizeText(w, h) + ")";
    return false;
  }
  rgb_.assign(data, data + size_t(w) * size_t(h) * 3);
  stbi_image_free(data);
  width_ = w;
  height_ = h;
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
