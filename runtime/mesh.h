// An indexed triangle mesh with per-vertex normals, colours and texture coordinates: the
// form assets are loaded into and the form output geometry is assembled into before it
// is written.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fgsg::rt {

struct Mesh {
  std::vector<float> positions;  // x y z per vertex
  std::vector<float> normals;    // x y z per vertex (unit length)
  std::vector<float> colors;     // r g b per vertex in [0,1]; empty when none
  std::vector<float> texcoords;  // u v per vertex (v up); empty when none
  std::vector<uint32_t> indices; // three per triangle, counter-clockwise = front

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
