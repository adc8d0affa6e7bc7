// An indexed triangle mesh with per-vertex normals, colours and texture coordinates, and
// line segments between its vertices (turtle segments "lines"): the form assets are
// loaded into and the form output geometry is assembled into before it is written.
#pragma once

#include "runtime/mesh_array.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt {

// Where a textured stretch of triangles starts (CGA's Texture): the triangles from
// `firstTriangle` up to the next run's first use the image `texture` (an index into
// Mesh::textures), or none when it is -1. A textured triangle's colour is the image at its
// texture coordinates times its vertex colours, as glTF's baseColorTexture x COLOR_0.
struct TextureRun {
  uint32_t firstTriangle = 0;
  int32_t texture = -1;
};

// One of CGA's uv sets 1..9 (CityEngine's texture layers: 1 bumpmap ... 5 normalmap ...)
// that a leaf's geometry carries besides set 0 (Mesh::texcoords): u v per vertex (v up).
// A set the leaf never had projected is absent, not zeros.
struct MeshUvSet {
  uint32_t set = 1;
  MeshArray<float> coords;
};

struct Mesh {
  // MeshArray (runtime/mesh_array.h): resize leaves new elements uninitialised.
  MeshArray<float> positions;    // x y z per vertex
  MeshArray<float> normals;      // x y z per vertex (unit length)
  MeshArray<float> colors;       // r g b per vertex in [0,1]; empty when none
  MeshArray<float> texcoords;    // u v per vertex (v up); empty when none
  MeshArray<uint32_t> indices;   // three per triangle, counter-clockwise = front
  MeshArray<uint32_t> lines;     // two per line segment; untextured
  // The image files textured triangles use (paths, PNG or JPEG) and the runs that say which
  // triangles use which, in triangle order, the first starting at triangle 0. No runs: no
  // triangle is textured. Assembled meshes list only images some run uses.
  std::vector<std::string> textures;
  std::vector<TextureRun> textureRuns;
  // CGA's uv sets 1..9 the mesh has, ascending by set; empty for all but such leaves (and
  // the meshes assembled from them). Only the glTF scene writer writes them (TEXCOORD_n).
  std::vector<MeshUvSet> uvSets;

  size_t vertexCount() const { return positions.size() / 3; }
  size_t triangleCount() const { return indices.size() / 3; }
  size_t lineCount() const { return lines.size() / 2; }
  bool empty() const { return indices.empty() && lines.empty(); }
  bool hasTexcoords() const { return !texcoords.empty() && texcoords.size() == 2 * vertexCount(); }
  bool textured() const { return !textureRuns.empty(); }
  // Set `set`'s coordinates (1..9), or null when the mesh does not have that set.
  const MeshArray<float>* uvSet(uint32_t set) const {
    for (const MeshUvSet& s : uvSets)
      if (s.set == set) return s.coords.size() == 2 * vertexCount() ? &s.coords : nullptr;
    return nullptr;
  }
  // Triangles from `firstTriangle` on draw `texture`: a new run, unless the last one draws it.
  void addTextureRun(size_t firstTriangle, int32_t texture) {
    if (textureRuns.empty() || textureRuns.back().texture != texture)
      textureRuns.push_back({uint32_t(firstTriangle), texture});
  }
  // The triangles [first, end) of run `r`.
  uint32_t runEnd(size_t r) const {
    return r + 1 < textureRuns.size() ? textureRuns[r + 1].firstTriangle : uint32_t(triangleCount());
  }

  std::array<float, 3> boundsMin() const;
  std::array<float, 3> boundsMax() const;
  // Fills `normals` with area-weighted vertex normals from the triangles.
  void computeNormals();
};

}  // namespace fgsg::rt
