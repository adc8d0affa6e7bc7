// The output solid's surface: the faces of the plane arrangement with inside on one side
// and outside on the other, read from the labels of their vertices, as a closed triangle
// mesh (shared vertices; a face with more than three corners is fanned around its centre
// so that corners lying on a straight side keep the mesh watertight).
#pragma once

#include "runtime/mesh.h"
#include "runtime/synthesis/continuous/arrangement.h"
#include "runtime/synthesis/continuous/labels.h"

#include <cstdint>
#include <vector>

namespace fgsg::rt::synthesis::continuous {

struct BoundarySurface {
  Mesh mesh;
  size_t polygons = 0;  // arrangement faces
  // The same surface as whole faces: the arrangement faces of one plane and side that
  // touch, merged, points on straight sides dropped (counter-clockwise from outside,
  // world units). A region with a hole stays in its arrangement faces. Per face, the
  // connected part of the solid it bounds.
  std::vector<std::vector<DVec3>> faces;
  std::vector<uint32_t> facePart;
  std::vector<uint32_t> vertexPart;  // per vertex of `mesh`
  uint32_t parts = 0;
};

// `labelOf[v]` indexes `labels`; positions are lattice units times `spacing`.
BoundarySurface boundarySurface(const Arrangement& A, const std::vector<Label>& labels,
                                const std::vector<int32_t>& labelOf, double spacing);

}  // namespace fgsg::rt::synthesis::continuous
