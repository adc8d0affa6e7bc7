#include "runtime/surface/surface_mesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace fgsg::rt::surface {

void SurfaceMesh::buildTopology() {
  const size_t nv = vertices.size(), nf = faces.size();
  neighbours.assign(nf, {-1, -1, -1});
  faceNormals.assign(nf, Vec3::Zero());
  faceAreas.assign(nf, 0.0);
  vertexNormals.assign(nv, Vec3::Zero());
  vertexFace.assign(nv, -1);
  boundaryVertex.assign(nv, 0);
  // Half-edge (a -> b) of face f, edge k: its twin is (b -> a) in the neighbour. The
  // half-edges leaving each vertex, as one compressed list sorted by where they go, find
  // it by a binary search (a hash map of millions of half-edges was most of the load time).
  struct Leaving {
    int to, face;
    bool operator<(const Leaving& o) const { return to != o.to ? to < o.to : face < o.face; }
  };
  std::vector<size_t> first(nv + 1, 0);
  for (const auto& t : faces)
    for (int v : t) ++first[size_t(v) + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<Leaving> leaving(3 * nf);
  {
    std::vector<size_t> fill(first.begin(), first.end() - 1);
    for (size_t f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k)
        leaving[fill[size_t(faces[f][k])]++] = {faces[f][(k + 1) % 3], int(f)};
  }
  for (size_t v = 0; v < nv; ++v) std::sort(leaving.begin() + first[v], leaving.begin() + first[v + 1]);
  double edgeSum = 0;
  size_t edgeCount = 0;
  for (size_t f = 0; f < nf; ++f) {
    const auto& t = faces[f];
    for (int k = 0; k < 3; ++k) {
      const size_t b = size_t(t[(k + 1) % 3]);
      const auto end = leaving.begin() + first[b + 1];
      const auto it = std::lower_bound(leaving.begin() + first[b], end, Leaving{t[k], -1});
      if (it != end && it->to == t[k]) neighbours[f][k] = it->face;
      edgeSum += (vertices[t[(k + 1) % 3]] - vertices[t[k]]).norm();
      ++edgeCount;
      if (vertexFace[t[k]] < 0) vertexFace[t[k]] = int(f);
    }
    const Vec3 n = (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]);
    faceAreas[f] = 0.5 * n.norm();
    faceNormals[f] = n.norm() > 0 ? Vec3(n.normalized()) : Vec3::UnitZ();
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = (vertices[t[(k + 1) % 3]] - vertices[t[k]]).normalized();
      const Vec3 b = (vertices[t[(k + 2) % 3]] - vertices[t[k]]).normalized();
      const double angle = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
      vertexNormals[t[k]] += angle * faceNormals[f];
    }
  }
  for (size_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k)
      if (neighbours[f][k] < 0) {
        boundaryVertex[faces[f][k]] = 1;
        boundaryVertex[faces[f][(k + 1) % 3]] = 1;
        // A boundary vertex's fan walk starts at its boundary face.
        vertexFace[faces[f][k]] = int(f);
      }
  for (auto& n : vertexNormals) n = n.norm() > 0 ? Vec3(n.normalized()) : Vec3::UnitZ();
  meanEdgeLength = edgeCount ? edgeSum / edgeCount : 0.0;
  boundsMin = Vec3::Constant(INFINITY);
  boundsMax = Vec3::Constant(-INFINITY);
  for (const Vec3& v : vertices) {
    boundsMin = boundsMin.cwiseMin(v);
    boundsMax = boundsMax.cwiseMax(v);
  }
  if (vertices.empty()) boundsMin = boundsMax = Vec3::Zero();
}

std::vector<int> SurfaceMesh::facesAround(int v) const {
  std::vector<int> ring;
  const int start = vertexFace[v];
  if (start < 0) return ring;
  // Walk one way to the boundary (or all the way round), then collect going the other way:
  // across each face's edge leaving v, which turns clockwise seen from outside.
  int f = start;
  if (boundaryVertex[v]) {
    for (size_t guard = 0; guard <= faces.size(); ++guard) {
      const int k = cornerOf(f, v);
      const int prev = neighbours[f][(k + 2) % 3];  // across the edge entering v
      if (prev < 0 || prev == start) break;
      f = prev;
    }
  }
  const int first = f;
  for (size_t guard = 0; guard <= faces.size(); ++guard) {
    ring.push_back(f);
    const int k = cornerOf(f, v);
    const int next = neighbours[f][k];  // across the edge leaving v
    if (next < 0 || next == first) break;
    f = next;
  }
  return ring;
}

void fitToSize(SurfaceMesh& m, double size) {
  const Vec3 centre = 0.5 * (m.boundsMin + m.boundsMax);
  const double extent = (m.boundsMax - m.boundsMin).maxCoeff();
  if (!(extent > 0)) return;
  for (Vec3& v : m.vertices) v = (v - centre) * (size / extent);
  m.buildTopology();
}

}  // namespace fgsg::rt::surface
