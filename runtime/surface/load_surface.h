// Surfaces from mesh files (OBJ, PLY, OFF, STL read through OpenMesh; glTF, FBX, COLLADA
// and OBJ or PLY with texture coordinates through assimp) and the validation
// every surface passes before a grammar grows on it: tracing and field design walk
// adjacency, so a non-manifold edge or a flipped face would send them astray far from the
// cause. Problems are reported with element indices; the sound repairs (dropping what
// carries no area, reorienting) happen only when asked for.
#pragma once

#include "runtime/surface/surface_mesh.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt::surface {

// A face is degenerate (zero area) when twice its area is at most this fraction of its
// longest edge squared, i.e. its height is below 1e-10 of its length: scale-free, and far
// below the float rounding of stored coordinates on any sound mesh.
constexpr double kDegenerateFaceTolerance = 1e-10;
// At most this many problems are spelled out; the rest are counted by kind.
constexpr size_t kMaxListedProblems = 10;

struct SurfaceLoadOptions {
  // Opt-in repair (the CLI's --repair-surface): drop degenerate and duplicate faces and
  // isolated vertices, and orient every connected component consistently (outwards for a
  // closed one). Non-manifold geometry is never repaired: it stays an error.
  bool repair = false;
  // --max-memory: the glTF reader refuses a file whose nodes would place more than this
  // holds (memory_budget.h's readerMemoryLimit(); 0: the default budget).
  uint64_t maxMemoryBytes = 0;
};

// What repairSurface() changed.
struct SurfaceRepairReport {
  size_t degenerateFaces = 0;   // dropped
  size_t duplicateFaces = 0;    // dropped (the first of each set stays)
  size_t isolatedVertices = 0;  // dropped (the others renumbered)
  size_t flippedFaces = 0;      // reversed
  bool any() const { return degenerateFaces || duplicateFaces || isolatedVertices || flippedFaces; }
  // "dropped 2 degenerate faces, flipped 5 faces", or "" when nothing changed.
  std::string summary() const;
};

// Reads a triangle mesh (polygons are fan-triangulated; coincident STL corners are welded
// by OpenMesh's reader, corners assimp splits at texture seams by read_textured_mesh.h)
// with the file's texture coordinates in `textureUV` when it has them, repairs it when
// asked, validates it and builds its topology. On failure `out` is left empty and `error`
// holds one problem per line, each starting with `path`, and a hint when --repair-surface
// would fix them. `repaired`, when given, receives what the repair changed.
bool loadSurface(const std::string& path, SurfaceMesh& out, std::string& error,
                 const SurfaceLoadOptions& options = {}, SurfaceRepairReport* repaired = nullptr);

// Checks vertices and faces (topology is not needed): finite coordinates, valid indices,
// at least one face, no degenerate or duplicate faces, manifold edges (at most two faces)
// and vertices (one fan of faces), no isolated vertices, consistent orientation. True
// when all hold; otherwise `problems` receives one line per problem (at most
// kMaxListedProblems, then one "and N more" line counting the rest by kind).
bool validateSurface(const SurfaceMesh& mesh, std::vector<std::string>& problems);

// The sound repairs of SurfaceLoadOptions::repair on vertices and faces (topology is
// cleared; call buildTopology() after validating). Leaves non-manifold and non-finite
// geometry alone, and a component that cannot be oriented (a Moebius strip) as it was.
// Texture coordinates stay with their faces (dropped with them, turned with them).
SurfaceRepairReport repairSurface(SurfaceMesh& mesh);

}  // namespace fgsg::rt::surface
