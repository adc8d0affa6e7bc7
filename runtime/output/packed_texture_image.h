// What the glTF writer's packed texture images (base colour + opacity, metallic +
// roughness) share: reading a CityEngine texture layer's image within the colour
// texture's bounds, and encoding the packed picture as PNG.
#pragma once

#include "runtime/io/read_image.h"

#include <cstdint>
#include <string>

namespace fgsg::rt::output {

// Reads and decodes one layer's image (any format the image reader knows; the result is
// re-encoded as PNG), at most texture::kMaxColorTexturePixels pixels. False and
// "PATH: ..." when it cannot be read.
bool decodeTextureLayer(const std::string& path, io::Image& image, std::string& error);

// The 8-bit picture (`channels` 3 or 4, rows top down) as PNG bytes in `png`. False and a
// message naming `what` and the size when it cannot be encoded.
bool encodePackedTexture(int width, int height, int channels, const uint8_t* pixels, const std::string& what,
                         std::string& png, std::string& error);

}  // namespace fgsg::rt::output
