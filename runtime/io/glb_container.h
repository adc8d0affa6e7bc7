// What every .glb fgsg writes shares: glTF's numeric codes and the binary container
// around the JSON and BIN chunks (a 12-byte header, then each chunk's length and type).
// The flattened mesh (glb_writer.h) and the scene (runtime/output/gltf_writer.h) fill
// the chunks their own ways and frame them here.
#pragma once

#include <cstddef>
#include <string>

namespace fgsg::rt::io::gltf {

constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kLines = 1, kTriangles = 4;

// Chunks are 4-byte aligned.
inline size_t padded4(size_t bytes) { return (bytes + 3) & ~size_t(3); }

// Pads `json` with spaces to 4 bytes and gives what precedes the BIN chunk's bytes: the
// header, the JSON chunk and, for `binBytes` > 0 (a multiple of 4), the BIN chunk's
// header. False with a message past the format's 4 GiB.
bool glbPrefix(std::string& json, size_t binBytes, std::string& prefix, std::string& error);

}  // namespace fgsg::rt::io::gltf
