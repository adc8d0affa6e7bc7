// glTF 2.0 binary (GLB) straight from the mesh's arrays: the 12-byte header, the JSON
// chunk (padded with spaces) and one BIN chunk holding positions, normals, colours
// (clamped to [0,1]), texture coordinates (v flipped: glTF's v runs down) and the
// uint32 indices, each tightly packed, in that order. A textured mesh (Mesh::textureRuns)
// has one primitive per image, its indices grouped by image, and the images (PNG/JPEG
// files as they are) after the indices, each a material's baseColorTexture. The arrays stored verbatim go to
// the sink without a copy; the clamped colours and flipped coordinates pass through it
// in bounded chunks.
//
// The bytes equal what tinygltf 2.7 wrote for the same model (the JSON is built with the
// same nlohmann::json, whose keys are sorted): tinygltf is now only the tests' oracle.
#pragma once

#include "runtime/io/byte_sink.h"
#include "runtime/mesh.h"

#include <string>
#include <vector>

namespace fgsg::rt::io {

// A texture image as the file embeds it: the file's bytes and their glTF mime type.
struct EmbeddedImage {
  std::string bytes;
  const char* mimeType = nullptr;
};

// Reads the images of a textured mesh (none for an untextured one). False and a message
// naming the file when one cannot be read or is not a PNG or JPEG.
bool readImages(const Mesh& mesh, std::vector<EmbeddedImage>& images, std::string& error);

// The JSON chunk's text, unpadded, for a mesh of finite vertices (and its images, read).
std::string glbJson(const Mesh& mesh, const std::vector<EmbeddedImage>& images = {});

// The whole file into `out` (the caller checks out.ok()). False, with nothing written,
// when the file would pass GLB's 4 GiB limit. May throw std::bad_alloc.
bool writeGlb(const Mesh& mesh, ByteSink& out, std::string& error);

}  // namespace fgsg::rt::io
