// glTF 2.0 from a Scene (runtime/output/scene.h): .glb (binary) or .gltf (JSON, its one
// buffer a base64 data URI). Instanced parts are one node each with the shared mesh and
// EXT_mesh_gpu_instancing (TRANSLATION, ROTATION, SCALE and the instances' colours as
// _COLOR_0, float accessors; SCALE left out where all instances have one scale, which the
// mesh is then written scaled by); mirrored instances a node each with a negative scale;
// baked parts the group node's mesh, a primitive per material. Vertex
// attributes share a buffer view per element size (byteStride set), indices one, the
// instances one. The bytes depend only on the scene.
#pragma once

#include "runtime/io/byte_sink.h"
#include "runtime/io/output_transaction.h"
#include "runtime/output/scene.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt::output {

// A node of the file that places a shared mesh, and the instances it places (indices
// into the instance list): an instanced node all of its part's, in the order of its
// EXT_mesh_gpu_instancing attributes; a mirrored instance's node (or, under
// Instancing::Nodes, each instance's) one. fgsg view maps a picked object back to the
// instance that placed it with these.
struct PlacedNode {
  int node = 0;                       // index into the file's "nodes"
  const uint32_t* instances = nullptr;  // into the Scene's InstancedPart::instances
  size_t count = 0;
};

// How vertex data is encoded. `quantize` (fgsg run --quantize): KHR_mesh_quantization,
// lossy, required by the file (readers without it cannot open it): baked meshes' positions
// as 16-bit integers on a uniform grid of the node's box (their node's translation and
// scale map them back: at most half a step of box size / 65535 off per axis), normals
// and tangents as normalized 16-bit, TEXCOORD_0 as 16-bit integers in 1/2^k tile steps
// (k as large as the coordinates' span allows, whole tiles taken off; the materials'
// KHR_texture_transform scales them back; floats where that step would be coarser than
// 1/4096 of a tile: a span past 16 tiles, or a value that is not finite; normals and
// tangents that are not finite stay floats too),
// instance rotations as normalized 16-bit. Shared meshes' positions, colours and other
// uv sets stay floats.
struct GltfEncoding {
  bool quantize = false;
};

// The whole file, binary (.glb) or not (.gltf), into `bytes`. False and a message when an
// image cannot be embedded or a vertex is not finite, or the GLB would pass 4 GiB.
// `placed`, when given, receives the nodes that place shared meshes, in the file's order.
bool encodeGltf(const Scene& scene, bool binary, std::string& bytes, std::string& error,
                std::vector<PlacedNode>* placed = nullptr, const GltfEncoding& encoding = {});

// Encodes by the extension of `path` (.glb or .gltf, any case) into a temporary staged in
// `outputs`.
bool stageGltf(const Scene& scene, const std::string& path, io::OutputTransaction& outputs, std::string& error,
               const GltfEncoding& encoding = {});

}  // namespace fgsg::rt::output
