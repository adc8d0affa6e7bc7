// Writes an assembled mesh to a file whose extension picks the format: .glb (glTF 2.0
// binary), .obj (Wavefront, with normals) or .ply (binary little endian). Texture
// coordinates, when the mesh has them, go out as TEXCOORD_0 (v flipped: glTF's v runs
// down), `vt` with `f v/vt/vn`, and PLY `u v`; a mesh without them gives the same bytes as
// before they existed. A textured mesh (Mesh::textureRuns) written as .obj comes with a
// .mtl of the same name beside it (runtime/io/obj_writer.h). Files are written
// atomically and their bytes depend only on the mesh and where they go (no timestamps).
#pragma once

#include "runtime/io/output_transaction.h"
#include "runtime/mesh.h"

#include <string>
#include <vector>

namespace fgsg::rt::io {

// The extensions writeMesh understands, with the dot, lower case.
const std::vector<std::string>& supportedMeshExtensions();

// Encodes the mesh in the format named by `extension` (".glb", ".obj", ".ply"; any case)
// into `bytes`. False and a message in `error` for an unknown extension, a vertex that
// is not finite (files store 32-bit floats), a GLB past 4 GiB, or running out of memory.
// The same bytes writeMesh writes (tests compare them; the writers stream), except that a
// textured OBJ has no `mtllib` line: with no file beside it there are no materials to name
// (its faces still follow their `usemtl` lines).
bool encodeMesh(const Mesh& mesh, const std::string& extension, std::string& bytes,
                std::string& error);

// The same, streamed into `out` (false too when a write to it failed).
bool encodeMesh(const Mesh& mesh, const std::string& extension, ByteSink& out, std::string& error);

// Encodes by the extension of `path` straight into a temporary staged in `outputs`
// (renamed over `path` on commit): the format and the vertices are checked before the
// temporary is created, and a failed write removes it. A textured OBJ's materials are
// staged in `outputs` too, as `path` with the extension .mtl, their image paths relative
// to its folder, and the OBJ names them with `mtllib`.
bool stageMesh(const Mesh& mesh, const std::string& path, OutputTransaction& outputs, std::string& error);

// Encodes by the extension of `path` and replaces the file atomically. An empty mesh
// still gives a valid file (a glTF scene without meshes, an OBJ/PLY with no elements).
bool writeMesh(const Mesh& mesh, const std::string& path, std::string& error);

}  // namespace fgsg::rt::io
