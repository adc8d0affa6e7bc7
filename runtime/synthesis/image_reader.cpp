#include "runtime/synthesis/image_reader.h"

#include "runtime/io/read_input.h"

// Static linkage: other runtime files may carry their own stb_image implementation.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_BMP
#define STBI_ONLY_TGA
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace fgsg::rt::synthesis {

namespace {
constexpr int64_t kMaxImagePixels = int64_t(1) << 26;
}  // namespace

bool readRgbImage(const std::string& path, RgbImage& out, std::string& error) {
  std::string bytes;
  if (!io::readInputFile(path, "an image file", bytes, error)) return false;
  const auto* data8 = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int length = int(bytes.size());  // within the input cap, far below INT_MAX
  int w = 0, h = 0, n = 0;
  // The size first: a small file can declare a huge picture.
  if (stbi_info_from_memory(data8, length, &w, &h, &n) &&
      (w <= 0 || h <= 0 || int64_t(w) * h > kMaxImagePixels)) {
    error = "image is empty or too large";
    return false;
  }
  unsigned char* data = stbi_load_from_memory(data8, length, &w, &h, &n, 3);
  if (!data) {
    const char* why = stbi_failure_reason();
    error = std::string("cannot read image: ") + (why ? why : "unknown error");
    return false;
  }
  if (w <= 0 || h <= 0 || int64_t(w) * h > kMaxImagePixels) {
    stbi_image_free(data);
    error = "image is empty or too large";
    return false;
  }
  out.width = w;
  out.height = h;
  out.rgb.assign(data, data + size_t(w) * size_t(h) * 3);
  stbi_image_free(data);
  return true;
}

}  // namespace fgsg::rt::synthesis
