// glTF's base colour texture with CityEngine's opacity map in its alpha: glTF 2.0 has no
// opacity texture of its own, the base colour texture's alpha is its opacity (alphaMode
// BLEND). The glTF writer embeds the combined PNG once per (colour map, opacity map) pair.
#pragma once

#include <string>

namespace fgsg::rt::output {

// The PNG (RGBA, 8 bits) whose colour is the colour map's (white without one: nullptr) and
// whose alpha is the opacity image's alpha where it has one, else its grey (a colour image's
// luminance, CCIR 601: 0.299 r + 0.587 g + 0.114 b, rounded). As large as the colour map
// (without one, the opacity image); the opacity image is read at its nearest pixel (pixel
// (x, y) of a W-wide picture from its column floor(x * w / W)). False and "PATH: ..." when an
// image cannot be read.
bool packBaseColorOpacity(const std::string* colorPath, const std::string& opacityPath, std::string& png,
                          std::string& error);

}  // namespace fgsg::rt::output
