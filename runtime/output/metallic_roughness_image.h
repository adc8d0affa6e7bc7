// glTF's metallicRoughnessTexture made from CityEngine's two texture layers: glTF reads
// roughness from one image's green channel and metallic from its blue, CityEngine's
// material.roughnessmap "only uses the green channel" and material.metallicmap "only the
// blue" of two images of their own. The glTF writer embeds the packed PNG once per pair.
#pragma once

#include <string>

namespace fgsg::rt::output {

// The PNG (RGB, 8 bits) whose green is the roughness image's green and whose blue is the
// metallic image's blue (a grey image's grey), red 255 (glTF ignores it). A layer without
// an image (nullptr) is 255, so its factor alone applies. The picture is as wide and as high
// as the larger of the two; a smaller one is read at the nearest of its pixels (pixel
// (x, y) of a W-wide picture from its column floor(x * w / W)). False and "PATH: ..." when
// an image cannot be read.
bool packMetallicRoughness(const std::string* roughnessPath, const std::string* metallicPath, std::string& png,
                           std::string& error);

}  // namespace fgsg::rt::output
