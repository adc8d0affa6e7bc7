// Mesh files (OBJ, PLY, OFF, STL) read as they are, for surfaces and instanced assets alike.
// Nothing is allocated by a count the file declares until the file is known to be large
// enough to hold it, so a forged header fails at once with the file and line instead of
// exhausting memory. OFF is parsed here (OpenMesh's reader misreads comments after the
// header and trusts its counts); PLY is checked element by element before OpenMesh reads it;
// OBJ and STL carry no counts and go to OpenMesh directly. Texture coordinates come from
// OBJ (`vt`, per face corner) and PLY (vertex properties u v / s t, per vertex).
#pragma once

#include "runtime/deadline.h"

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace fgsg::rt::io {

struct MeshFileContent {
  std::vector<std::array<double, 3>> vertices;
  // Polygon p has the corners corners[polygonStart[p]] .. corners[polygonStart[p + 1] - 1];
  // every polygon has at least three, each a valid vertex index.
  std::vector<int> corners;
  std::vector<size_t> polygonStart = {0};
  // The texture coordinate (u, v; v up, as OBJ and PLY spell them) of every corner,
  // parallel to `corners`. Empty when the file has none, or has them for some faces only:
  // a partial set cannot texture the whole mesh consistently.
  std::vector<std::array<double, 2>> cornerUV;
  // OBJ materials with an image (`usemtl` of a `.mtl` material with `map_Kd`): per polygon
  // the index into `textureFiles` of its image, -1 for none; empty when no polygon has one.
  std::vector<int> polygonTexture;
  std::vector<std::string> textureFiles;  // as the .mtl names them

  size_t polygonCount() const { return polygonStart.size() - 1; }
  size_t cornerCount(size_t p) const { return polygonStart[p + 1] - polygonStart[p]; }
};

// Reads `path` (a regular file within kMaxInputBytes; the format by its extension, which
// the caller has checked is .obj, .ply, .off or .stl). False with one located message
// ("PATH:LINE: ..." where a line is known, else "PATH: ...") when the file cannot be read,
// declares more than it holds, spells a coordinate that is not finite, or has a face with
// fewer than three corners or an index out of range. With a `deadline` (a command's time
// limit, which counts the reading too), the checks and the parsing ask it line by line and
// stop once it has passed: false with readStoppedMessage().
bool readMeshFile(const std::string& path, MeshFileContent& out, std::string& error, Deadline* deadline = nullptr);

// "PATH: stopped by the time limit (2 s) while reading the file".
std::string readStoppedMessage(const std::string& path, const Deadline& deadline);

// Text readers (OpenMesh's, assimp's) cannot parse "nan" or "inf": they stop short or read
// garbage without saying so. So text files (`ext` .obj, .ply or .stl, lower case) are
// scanned for such vertex coordinates first, to name the line ("PATH:LINE: vertex
// coordinate 'nan' is not a finite number"). True for binary files, whose non-finite
// floats reach the caller's checks.
bool findNonFiniteText(const std::string& path, const std::string& ext, std::string_view bytes,
                       std::string& error, Deadline* deadline = nullptr);

}  // namespace fgsg::rt::io
