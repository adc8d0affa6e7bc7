// Writes an assembled mesh to a file whose extension picks the format: .glb (glTF 2.0
// binary), .obj (Wavefront, with normals) or .ply (binary little endian). Files are
// written atomically and their bytes depend only on the mesh (no timestamps).
#pragma once

#include "runtime/mesh.h"

#include <string>
#include <vector>

namespace fgsg::rt::io {

// The extensions writeMesh understands, with the dot, lower case.
const std::vector<std::string>& supportedMeshExtensions();

// Encodes the mesh in the format named by `extension` (".glb", ".obj", ".ply"; any case)
// into `bytes`. False and a message in `error` for an unknown extension.
bool encodeMesh(const Mesh& mesh, const std::string& extension, std::string& bytes,
                std::string& error);

// Encodes by the extension of `path` and replaces the file atomically. An empty mesh
// still gives a valid file (a glTF scene without meshes, an OBJ/PLY with no elements).
bool writeMesh(const Mesh& mesh, const std::string& path, std::string& error);

}  // namespace fgsg::rt::io
