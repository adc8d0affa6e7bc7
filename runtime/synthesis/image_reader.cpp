#include "runtime/synthesis/image_reader.h"

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

bool readRgbImage(const std::string& path, RgbImage& out, std::string& error) {
  int w = 0, h = 0, n = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 3);
  if (!data) {
    const char* why = stbi_failure_reason();
    error = std::string("cannot read image: ") + (why ? why : "unknown error");
    return false;
  }
  if (w <= 0 || h <= 0 || int64_t(w) * h > (int64_t(1) << 26)) {
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
