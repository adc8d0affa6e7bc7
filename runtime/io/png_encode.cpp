#include "runtime/io/png_encode.h"

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace fgsg::rt::io {
namespace {

void appendBytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
}

}  // namespace

bool encodePng(int width, int height, int channels, const uint8_t* pixels, std::string& out) {
  return stbi_write_png_to_func(appendBytes, &out, width, height, channels, pixels, width * channels) != 0;
}

}  // namespace fgsg::rt::io
