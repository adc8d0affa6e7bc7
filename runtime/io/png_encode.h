// PNG encoding for every picture fgsg writes (previews, atlas previews, painted masks):
// one private copy of stb_image_write, whose static functions cannot clash with the stb
// symbols Debian's libtinygltf exports.
#pragma once

#include <cstdint>
#include <string>

namespace fgsg::rt::io {

// `pixels`: rows top to bottom, `channels` (1 grey, 3 RGB, 4 RGBA) bytes per pixel.
// Appends the PNG file's bytes to `out`; false when stb cannot encode it.
bool encodePng(int width, int height, int channels, const uint8_t* pixels, std::string& out);

}  // namespace fgsg::rt::io
