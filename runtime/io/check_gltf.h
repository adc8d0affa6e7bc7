// glTF files (.gltf text, .glb binary; 1.0 and 2.0) are read by assimp, which expands the
// node hierarchy by copying: a node listed twice as a child is copied twice with all it
// holds, so 40 nodes that each list the next one twice become 2^40 nodes (a 2 KB file
// that exhausts any machine), and it allocates what an accessor or a buffer declares
// before looking at the bytes. This check reads the file's JSON first and refuses, at
// once and naming the offending entry, what assimp would expand without bound:
//  * a node hierarchy that is not a forest of trees (the glTF rule: each node has at most
//    one parent, no cycles; a scene lists only roots, each once);
//  * references to nodes, meshes, accessors, buffer views and buffers that do not exist;
//  * an accessor whose elements do not fit its buffer view, a view beyond its buffer, a
//    buffer larger than an input file may be (read_input.h) or than the .glb holds;
//  * more triangles placed by the nodes than a surface may have (kMaxGltfTriangles), and
//    an estimate of the memory the read takes above `memoryLimit`.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace fgsg::rt::io {

// Meshes instanced by many nodes multiply: more triangles than this, once every node's
// mesh is placed, is no surface anyone grows a grammar on.
constexpr uint64_t kMaxGltfTriangles = uint64_t(1) << 26;

// True when `bytes` (the whole file `path`) passes the checks above; otherwise one message
// "PATH: WHERE: what" (WHERE a JSON path such as nodes[0].children[1], or the parser's
// line and column). `memoryLimit`: bytes the reader may hold (memory_budget.h's
// readerMemoryLimit()).
bool checkGltfBounds(const std::string& path, std::string_view bytes, uint64_t memoryLimit, std::string& error);

}  // namespace fgsg::rt::io
