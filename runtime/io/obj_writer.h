// Wavefront OBJ: `v x y z` (with `r g b` when the mesh has colours, the common vertex
// colour extension of MeshLab, Blender and OpenMesh), then `vt u v` (v up, as the
// mesh's), `vn x y z`, and `f` lines counting from 1 (`f v//vn`, `f v/vt`, `f v/vt/vn`).
// Numbers are the shortest text that reads back as the same 32-bit float
// (std::to_chars), formatted straight into the sink's buffer.
//
// A textured mesh (Mesh::textureRuns) also gets materials, as Blender, MeshLab and most
// viewers read them: each run's faces follow `usemtl fgsg_plain` (untextured) or
// `usemtl fgsg_texture_K` (Mesh::textures[K]), and a companion .mtl file, named by a
// `mtllib` line after the header, defines those materials with the image as `map_Kd`.
// An untextured mesh gives the same bytes as before textures existed.
#pragma once

#include "runtime/io/byte_sink.h"
#include "runtime/mesh.h"

#include <string>

namespace fgsg::rt::io {

// The whole file into `out`; the caller checks out.ok(). No `mtllib` line: for bytes
// alone (encodeMesh), where there is no file for the materials to sit beside.
void writeObj(const Mesh& mesh, ByteSink& out);

// The same with `mtllib mtlFileName` after the header when the mesh is textured, naming
// the mtlText file written beside the OBJ (a bare file name: OBJ readers look for it in
// the OBJ's folder).
void writeObj(const Mesh& mesh, ByteSink& out, const std::string& mtlFileName);

// The .mtl file for a textured mesh: `fgsg_plain` and one `fgsg_texture_K` per texture,
// white (the OBJ's vertex colours tint them), each image as `map_Kd` with its path
// relative to `mtlFolder` (the folder the .mtl will be in), so that the pair can be moved
// with the images; absolute when no relative path exists. Paths are written as they are,
// spaces included (readers take the rest of the line).
std::string mtlText(const Mesh& mesh, const std::string& mtlFolder);

// `path` as seen from `folder` (a .mtl's `map_Kd`): relative, with symbolic links resolved
// so that it leads to the same file, or absolute when there is no relative path.
std::string pathFrom(const std::string& folder, const std::string& path);

}  // namespace fgsg::rt::io
