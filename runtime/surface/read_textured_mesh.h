// Meshes with texture coordinates (OBJ `vt`, PLY per-vertex u v / s t / texture_u
// texture_v, glTF TEXCOORD_0, FBX, COLLADA), read through assimp. Painted texture contexts
// are sampled with these coordinates (Buron et al. §4), so they are kept per face corner
// in SurfaceMesh::textureUV. assimp splits vertices where coordinates differ on the two
// sides of a seam; the surface needs them shared again (tracing and marching walk across
// seams), so corners are welded back by exact position.
#pragma once

#include "runtime/surface/surface_mesh.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace fgsg::rt::surface {

// Whether `path` (extension `ext`, lower case, with the dot) goes through assimp: formats
// only assimp reads, and OBJ and PLY files that carry texture coordinates (`bytes` is the
// file's content; the others stay with the readers of read_mesh_file.h).
bool readsThroughAssimp(const std::string& ext, std::string_view bytes);

// Reads the whole scene: every mesh of every node, placed by its node's transform (faces
// of a mirroring transform are turned back to counter-clockwise), polygons fan-
// triangulated, faces numbered in node order (depth first), then in each mesh's order (an
// OBJ with several materials becomes one mesh per material, so its faces may be numbered
// out of file order); points and lines are ignored. `textureUV` is filled when the meshes
// have coordinates in their first channel (all of them, or it is an error), and left empty
// when none has; they are v-up as everywhere in fgsg (glTF's v runs down the image,
// assimp turns it: 1 - v). `bytes` is the file's content as io::readInputFile read it
// (assimp reads the file itself; the text formats are checked in `bytes` first). False
// with a message starting with `path` when the file cannot be read or holds non-finite
// numbers. `polygonal`: some polygon had more than three corners. glTF files are checked
// by io/check_gltf.h before assimp sees them (node trees, counts, and the memory the read
// would take against `maxMemoryBytes`, 0 for the default: memory_budget.h's
// readerMemoryLimit()), COLLADA files by io/check_collada.h (<instance_node> expansion), FBX
// files by io/check_fbx.h (model connections: copies, cycles, depth).
bool readTexturedMesh(const std::string& path, std::string_view bytes, SurfaceMesh& mesh, bool& polygonal,
                      std::string& error, uint64_t maxMemoryBytes = 0);

}  // namespace fgsg::rt::surface
