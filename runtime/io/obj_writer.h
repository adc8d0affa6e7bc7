// Wavefront OBJ: `v x y z` (with `r g b` when the mesh has colours, the common vertex
// colour extension of MeshLab, Blender and OpenMesh), then `vt u v` (v up, as the
// mesh's), `vn x y z`, and `f` lines counting from 1 (`f v//vn`, `f v/vt`, `f v/vt/vn`).
// Numbers are the shortest text that reads back as the same 32-bit float
// (std::to_chars), formatted straight into the sink's buffer.
#pragma once

#include "runtime/io/byte_sink.h"
#include "runtime/mesh.h"

namespace fgsg::rt::io {

// The whole file into `out`; the caller checks out.ok().
void writeObj(const Mesh& mesh, ByteSink& out);

}  // namespace fgsg::rt::io
