// An indexed triangle mesh with per-vertex normals, colours and texture coordinates: the
// form assets are loaded into and the form output geometry is assembled into before it
// is written.
#pragma once

#include "runtime/mesh_array.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fgsg::rt {

struct Mesh {
  // MeshArray (runtime/mesh_array.h): resize leaves new elements uninitialised.
  MeshArray<float> positions;    // x y z per vertex
  MeshArray<float> normals;      // x y z per vertex (unit length)
  MeshArray<float> colors;       // r g b per vertex in [0,1]; empty when none
  MeshArray<float> texcoords;    // u v per vertex (v up); empty when none
  MeshArray<uint32_t> indices;   // three per triangle, counter-clockwise = front

  size_t vertexCount() const { return positions.size() / 3; }
  size_t triangleCount() const { return indices.size() / 3; }
  bool empty() const { return indices.empty(); }
  bool hasTexcoords() const { return !texcoords.empty() && texcoords.size() == 2 * vertexCount(); }

  std::array<float, 3> boundsMin() const;
  std::array<float, 3> boundsMax() const;
  // Fills `normals` with area-weighted vertex normals from the triangles.
  void computeNormals();
};

}  // namespace fgsg::rt
