#include "runtime/texture/texture_map.h"

#include "runtime/io/read_input.h"
#include "runtime/texture/pnm_reader.h"

#include <algorithm>
#include <cmath>

// Static linkage: other runtime files carry their own stb_image implementation
// (runtime/synthesis/image_reader.cpp). No TGA: stb_image decodes a truncated one into
// uninitialised memory. No PNM either: pnm_reader.h says why.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_BMP
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace fgsg::rt::texture {

namespace {

// A picture as loaded, before it becomes the map.
struct Decoded {
  int width = 0, height = 0, bits = 0, full = 0;
  std::vector<uint16_t> values;  // one per texel, 0..full
};

std::string failureReason() {
  const char* why = stbi_failure_reason();
  return why ? why : "unknown error";
}

std::string sizeText(long w, long h) { return std::to_string(w) + " x " + std::to_string(h); }

// The size limits, checked from the header before anything is decoded: a small file can
// declare a huge picture.
bool checkSize(const std::string& path, long w, long h, std::string& error) {
  if (w <= 0 || h <= 0) {
    error = path + ": the image is empty (" + sizeText(w, h) + ")";
    return false;
  }
  if (w > kMaxTextureSide || h > kMaxTextureSide || w * h > kMaxTexels) {
    error = path + ": the image is " + sizeText(w, h) + " texels, larger than the limit for textures (" +
            std::to_string(kMaxTextureSide) + " per side, " + std::to_string(kMaxTexels) + " in all)";
    return false;
  }
  return true;
}

// One value per texel from `channels` interleaved channels (see TextureMap).
template <typename Channel>
std::vector<uint16_t> texelValues(const Channel* data, int w, int h, int channels) {
  std::vector<uint16_t> out(size_t(w) * size_t(h));
  for (size_t i = 0; i < out.size(); ++i) {
    const Channel* c = data + i * size_t(channels);
    out[i] = channels >= 3 ? std::max({c[0], c[1], c[2]}) : c[0];
  }
  return out;
}

bool decodePnm(const std::string& path, const std::string& bytes, Decoded& out, std::string& error) {
  PnmHeader header;
  std::string why;
  if (!readPnmHeader(bytes, header, why)) {
    error = path + ": " + why;
    return false;
  }
  if (!checkSize(path, header.width, header.height, error)) return false;
  std::vector<uint16_t> samples;
  if (!readPnmSamples(bytes, header, samples, why)) {
    error = path + ": " + why;
    return false;
  }
  out.width = header.width;
  out.height = header.height;
  out.bits = header.maxValue > 255 ? 16 : 8;
  out.full = header.maxValue;
  out.values = texelValues(samples.data(), header.width, header.height, header.channels);
  return true;
}

bool decodeWithStb(const std::string& path, const std::string& bytes, Decoded& out, std::string& error) {
  const auto* data8 = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int length = int(bytes.size());  // within the input cap, far below INT_MAX
  int w = 0, h = 0, n = 0;
  if (!stbi_info_from_memory(data8, length, &w, &h, &n)) {
    error = path + ": not an image fgsg reads (PNG, JPEG, BMP, PGM/PPM): " + failureReason();
    return false;
  }
  if (!checkSize(path, w, h, error)) return false;
  const bool sixteen = stbi_is_16_bit_from_memory(data8, length) != 0;
  int dw = 0, dh = 0, dn = 0;
  if (sixteen) {
    stbi_us* data = stbi_load_16_from_memory(data8, length, &dw, &dh, &dn, 0);
    if (!data) {
      error = path + ": cannot decode the 16-bit image: " + failureReason();
      return false;
    }
    if (dw == w && dh == h && dn >= 1 && dn <= 4) out.values = texelValues(data, w, h, dn);
    stbi_image_free(data);
  } else {
    stbi_uc* data = stbi_load_from_memory(data8, length, &dw, &dh, &dn, 0);
    if (!data) {
      error = path + ": cannot decode the image: " + failureReason();
      return false;
    }
    if (dw == w && dh == h && dn >= 1 && dn <= 4) out.values = texelValues(data, w, h, dn);
    stbi_image_free(data);
  }
  // The decoder must agree with the header the size was checked by.
  if (out.values.empty()) {
    error = path + ": the decoded image (" + sizeText(dw, dh) + ", " + std::to_string(dn) +
            " channels) does not match its header (" + sizeText(w, h) + ")";
    return false;
  }
  out.width = w;
  out.height = h;
  out.bits = sixteen ? 16 : 8;
  out.full = sixteen ? 65535 : 255;
  return true;
}

}  // namespace

bool TextureMap::load(const std::string& path, std::string& error) {
  std::string bytes;
  if (!io::readInputFile(path, "a texture image", bytes, error)) return false;
  Decoded d;
  if (!(looksLikePnm(bytes) ? decodePnm(path, bytes, d, error) : decodeWithStb(path, bytes, d, error)))
    return false;
  width_ = d.width;
  height_ = d.height;
  bits_ = d.bits;
  full_ = d.full;
  values_ = std::move(d.values);
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
