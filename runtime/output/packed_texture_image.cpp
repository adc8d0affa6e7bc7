#include "runtime/output/packed_texture_image.h"

#include "runtime/io/png_encode.h"
#include "runtime/io/read_input.h"
#include "runtime/texture/color_texture.h"

namespace fgsg::rt::output {

bool decodeTextureLayer(const std::string& path, io::Image& image, std::string& error) {
  std::string bytes;
  const io::ImageLimits limits{texture::kMaxColorTexturePixels, int64_t(1) << 31, "pixels", "textures"};
  return io::readInputFile(path, "a texture image", bytes, error) && io::decodeImage(path, bytes, limits, image, error);
}

bool encodePackedTexture(int width, int height, int channels, const uint8_t* pixels, const std::string& what,
                         std::string& png, std::string& error) {
  png.clear();
  if (io::encodePng(width, height, channels, pixels, png)) return true;
  error = what + " (" + std::to_string(width) + " x " + std::to_string(height) + ") could not be encoded as a PNG";
  return false;
}

}  // namespace fgsg::rt::output
