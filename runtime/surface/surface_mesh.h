// The surface a grammar grows on (FGSG §4): a triangle mesh with the adjacency that
// tracing and field design walk over. Built once (from a file or a procedural
// generator), validated, then read-only during derivation.
#pragma once

#include "runtime/scope.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt::surface {

struct SurfaceMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> faces;  // counter-clockwise seen from outside
  // The file's texture coordinates per face corner (u right, v up), when it has them:
  // what a painted texture context is sampled with. Empty: none (an atlas is generated).
  std::vector<std::array<Eigen::Vector2d, 3>> textureUV;

  // ---- filled by buildTopology() ----
  // Across edge k of face f (from faces[f][k] to faces[f][(k + 1) % 3]): the neighbouring
  // face, or -1 on the boundary.
  std::vector<std::array<int, 3>> neighbours;
  std::vector<Vec3> faceNormals;      // unit
  std::vector<double> faceAreas;
  std::vector<Vec3> vertexNormals;    // unit, angle-weighted
  std::vector<int> vertexFace;        // one face around each vertex (-1: isolated)
  std::vector<uint8_t> boundaryVertex;
  double meanEdgeLength = 0;
  Vec3 boundsMin = Vec3::Zero(), boundsMax = Vec3::Zero();

  // Computes everything above from `vertices` and `faces`. Assumes a manifold mesh with
  // consistent orientation (validation checks that before).
  void buildTopology();

  size_t vertexCount() const { return vertices.size(); }
  size_t faceCount() const { return faces.size(); }
  // The faces around vertex v in clockwise order seen from outside (starting at a
  // boundary face when v is on the boundary).
  std::vector<int> facesAround(int v) const;
  // Index (0..2) of vertex v in face f, or -1.
  int cornerOf(int f, int v) const {
    for (int k = 0; k < 3; ++k)
      if (faces[f][k] == v) return k;
    return -1;
  }
};

// --surface-size: centres the mesh at the origin and scales it uniformly so that its
// largest bounding-box extent is `size`, topology rebuilt (a mesh of no extent stays).
void fitToSize(SurfaceMesh& mesh, double size);

// A point on the surface: a face and barycentric coordinates (b0 + b1 + b2 = 1, all
// >= 0) with respect to its corners. A vertex or an edge point is a face point with one
// or two zero coordinates.
struct SurfacePoint {
  int face = -1;
  Vec3 bary = Vec3(1.0 / 3, 1.0 / 3, 1.0 / 3);

  bool valid() const { return face >= 0; }
  Vec3 position(const SurfaceMesh& m) const {
    const auto& f = m.faces[face];
    return bary[0] * m.vertices[f[0]] + bary[1] * m.vertices[f[1]] + bary[2] * m.vertices[f[2]];
  }
  // The smooth (interpolated vertex) normal here, unit length.
  Vec3 normal(const SurfaceMesh& m) const {
    const auto& f = m.faces[face];
    return (bary[0] * m.vertexNormals[f[0]] + bary[1] * m.vertexNormals[f[1]] +
            bary[2] * m.vertexNormals[f[2]]).normalized();
  }
};

}  // namespace fgsg::rt::surface
