// glTF 2.0 binary (GLB) straight from the mesh's arrays: the 12-byte header, the JSON
// chunk (padded with spaces) and one BIN chunk holding positions, normals, colours
// (clamped to [0,1]), texture coordinates (v flipped: glTF's v runs down) and the
// uint32 indices, each tightly packed, in that order. The arrays stored verbatim go to
// the sink without a copy; the clamped colours and flipped coordinates pass through it
// in bounded chunks.
//
// The bytes equal what tinygltf 2.7 wrote for the same model (the JSON is built with the
// same nlohmann::json, whose keys are sorted): tinygltf is now only the tests' oracle.
#pragma once

#include "runtime/io/byte_sink.h"
#include "runtime/mesh.h"

#include <string>

namespace fgsg::rt::io {

// The JSON chunk's text, unpadded, for a mesh of finite vertices.
std::string glbJson(const Mesh& mesh);

// The whole file into `out` (the caller checks out.ok()). False, with nothing written,
// when the file would pass GLB's 4 GiB limit. May throw std::bad_alloc.
bool writeGlb(const Mesh& mesh, ByteSink& out, std::string& error);

}  // namespace fgsg::rt::io
