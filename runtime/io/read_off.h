// The OFF format (Geomview; CGAL's data is mostly OFF): a keyword such as OFF, COFF, NOFF or
// 4OFF, the vertex, face and edge counts, then one vertex and one face per line; `#` starts
// a comment anywhere; what follows the coordinates or the corner indices on a line (normals,
// colours, texture coordinates) is skipped.
#pragma once

#include "runtime/io/read_mesh_file.h"

#include <string>
#include <string_view>

namespace fgsg::rt::io {

// Parses text OFF (binary OFF is refused with a message). Counts are checked against the
// bytes that follow them before anything is allocated; every error names the line.
// With a `deadline`, stops once it has passed (readStoppedMessage()).
bool parseOff(const std::string& path, std::string_view text, MeshFileContent& out,
              std::string& error, Deadline* deadline = nullptr);

}  // namespace fgsg::rt::io
