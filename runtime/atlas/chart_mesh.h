// One chart cut out of the surface as a mesh of its own: what parametrization flattens
// and what the disk test looks at. A vertex where the chart touches itself only at that
// vertex (two separate fans of the chart's faces around it) becomes one chart vertex per
// fan, so such a pinch is a boundary point like any other and not a reason to split.
#pragma once

#include "runtime/surface/surface_mesh.h"

#include <array>
#include <vector>

namespace fgsg::rt::atlas {

struct ChartMesh {
  std::vector<int> faces;                        // the mesh faces, ascending
  std::vector<int> meshVertex;                   // per chart vertex: the mesh vertex it is
  std::vector<std::array<int, 3>> triangles;     // per chart face: its chart vertices
  // Boundary edges as (from, to) chart vertices, running with their face (counter-
  // clockwise), so the chart lies to the left.
  std::vector<std::array<int, 2>> boundaryEdges;
  std::vector<int> boundaryFace;  // per boundary edge: its chart face
  std::vector<int> boundaryLoop;  // per boundary edge: its loop, 0 .. boundaryLoops-1
  int boundaryLoops = 0;
  bool connected = true;  // over shared edges

  int vertexCount() const { return int(meshVertex.size()); }
  // V - E + F: 1 for a disk, 2 - 2 genus - boundaries in general.
  int eulerCharacteristic() const {
    const int edges = (3 * int(triangles.size()) + int(boundaryEdges.size())) / 2;
    return vertexCount() - edges + int(triangles.size());
  }
  // One piece, one boundary loop, no handle: what a single flat chart can be.
  bool isDisk() const { return connected && boundaryLoops == 1 && eulerCharacteristic() == 1; }
};

// Scratch space reused across extractions (sized by the mesh, never cleared).
struct ChartMeshScratch {
  std::vector<int> positionInChart;  // per mesh face
};

// The chart made of `faces` (each with faceLabel == faceLabel[faces[0]]; any order), from
// a mesh whose topology is built. Deterministic: chart vertices are numbered in the order
// the sorted faces first use them.
ChartMesh extractChart(const surface::SurfaceMesh& mesh, std::vector<int> faces,
                       const std::vector<int>& faceLabel, ChartMeshScratch& scratch);

}  // namespace fgsg::rt::atlas
