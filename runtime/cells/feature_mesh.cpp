// Finding the parent mesh's faces, edges and corners (feature_mesh.h).
#include "runtime/cells/feature_mesh.h"

#include "runtime/cells/feature_param.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>

namespace fgsg::rt::cells {

namespace {

constexpr double kDegree = std::numbers::pi / 180;

// One feature edge of the child mesh, directed as it runs in `leftTri` (counter-
// clockwise seen from outside, so leftTri lies on its left).
struct MeshEdge {
  int a, b, leftTri, rightTri;  // rightTri -1: boundary
  EdgeFold fold;
  double angle;  // dihedral, radians (0 on the boundary)
  int other(int v) const { return v == a ? b : a; }
};

void validate(const surface::SurfaceMesh& m, const FeatureOptions& o) {
  if (m.faces.empty()) throw std::invalid_argument("buildFeatureMesh: the mesh has no faces");
  if (m.neighbours.size() != m.faces.size() || m.faceNormals.size() != m.faces.size())
    throw std::invalid_argument("buildFeatureMesh: the mesh's topology is not built (call buildTopology())");
  for (const auto& t : m.faces)
    for (int v : t)
      if (v < 0 || size_t(v) >= m.vertices.size())
        throw std::invalid_argument("buildFeatureMesh: a face refers to vertex " + std::to_string(v) +
                                    " of " + std::to_string(m.vertices.size()));
  auto in = [](double x, double lo, double hi) { return std::isfinite(x) && x > lo && x < hi; };
  if (!in(o.creaseDegrees, 0, 180))
    throw std::invalid_argument("FeatureOptions: creaseDegrees must be in (0, 180)");
  if (!(std::isfinite(o.planarDegrees) && o.planarDegrees >= 0 && o.planarDegrees <= o.creaseDegrees))
    throw std::invalid_argument("FeatureOptions: planarDegrees must be in [0, creaseDegrees]");
  if (!in(o.cornerDegrees, 0, 180.0000001))
    throw std::invalid_argument("FeatureOptions: cornerDegrees must be in (0, 180]");
  if (!(std::isfinite(o.directionDegrees) && o.directionDegrees >= 0 && o.directionDegrees < 45))
    throw std::invalid_argument("FeatureOptions: directionDegrees must be in [0, 45)");
  if (!in(o.fitTolerance, 0, 1)) throw std::invalid_argument("FeatureOptions: fitTolerance must be in (0, 1)");
  if (!o.up.allFinite() || o.up.norm() == 0)
    throw std::invalid_argument("FeatureOptions: up must be a finite non-zero vector");
}

int opposite(const std::array<int, 3>& t, int a, int b) {
  for (int v : t)
    if (v != a && v != b) return v;
  return t[0];
}

// The connected components of the chains `ids`, joined at their end vertices.
int countLoops(const std::vector<FeatureEdge>& edges, const std::vector<int>& ids) {
  std::map<int, int> node;  // end vertex -> union-find node
  std::vector<int> parent;
  auto nodeOf = [&](int v) {
    const auto [it, fresh] = node.emplace(v, int(parent.size()));
    if (fresh) parent.push_back(it->second);
    return it->second;
  };
  auto root = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  int loops = 0;
  for (int e : ids) {
    const int a = root(nodeOf(edges[e].vertices.front())), b = root(nodeOf(edges[e].vertices.back()));
    parent[a] = b;
  }
  for (int i = 0; i < int(parent.size()); ++i) loops += root(i) == i;
  return loops;
}

}  // namespace

FeatureMesh buildFeatureMesh(const surface::SurfaceMesh& m, const FeatureOptions& options,
                             const std::vector<int>* triangleGroup) {
  validate(m, options);
  if (triangleGroup && triangleGroup->size() != m.faces.size())
    throw std::invalid_argument("buildFeatureMesh: " + std::to_string(triangleGroup->size()) +
                                " triangle groups for " + std::to_string(m.faces.size()) + " triangles");
  FeatureOptions o = options;
  o.up.normalize();
  const int nf = int(m.faces.size()), nv = int(m.vertices.size());
  FeatureMesh fm;

  // Feature edges of the child mesh, each once.
  std::vector<MeshEdge> medges;
  std::vector<std::array<uint8_t, 3>> isFeature(size_t(nf), {0, 0, 0});
  const double crease = std::cos(o.creaseDegrees * kDegree);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int g = m.neighbours[f][k];
      if (g >= 0 && g < f) continue;  // seen from g
      const int a = m.faces[f][k], b = m.faces[f][(k + 1) % 3];
      if (g < 0) {
        medges.push_back({a, b, f, -1, EdgeFold::Boundary, 0});
        isFeature[f][k] = 1;
        continue;
      }
      const double c = m.faceNormals[f].dot(m.faceNormals[g]);
      const bool grouped = triangleGroup && (*triangleGroup)[f] != (*triangleGroup)[g];
      if (c >= crease && !grouped) continue;
      // Convex when the neighbour's far vertex lies below f's plane (on it: a flat edge
      // between groups, where rounding must not pick the fold).
      const Vec3 far = m.vertices[opposite(m.faces[g], a, b)] - m.vertices[a];
      const double below = far.dot(m.faceNormals[f]);
      const bool flat = grouped && std::abs(below) <= 1e-9 * far.norm();
      const EdgeFold fold = below < 0 || flat ? EdgeFold::Convex : EdgeFold::Concave;
      medges.push_back({a, b, f, g, fold, std::acos(std::clamp(c, -1.0, 1.0))});
      isFeature[f][k] = 1;
      for (int j = 0; j < 3; ++j)
        if (m.neighbours[g][j] == f && m.faces[g][j] == b) isFeature[g][j] = 1;
    }

  // Faces: components of triangles joined across non-feature edges, found in order of
  // their smallest triangle.
  fm.faceOfTriangle.assign(size_t(nf), -1);
  for (int seed = 0; seed < nf; ++seed) {
    if (fm.faceOfTriangle[seed] >= 0) continue;
    const int id = int(fm.faces.size());
    FeatureFace face;
    std::vector<int> stack{seed};
    fm.faceOfTriangle[seed] = id;
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      face.triangles.push_back(f);
      for (int k = 0; k < 3; ++k) {
        const int g = m.neighbours[f][k];
        if (g < 0 || isFeature[f][k] || fm.faceOfTriangle[g] >= 0) continue;
        fm.faceOfTriangle[g] = id;
        stack.push_back(g);
      }
    }
    std::sort(face.triangles.begin(), face.triangles.end());
    fm.faces.push_back(std::move(face));
  }
  auto faceOf = [&](int tri) { return tri < 0 ? -1 : fm.faceOfTriangle[tri]; };

  // Corners: where other than two feature edges meet, or two that do not continue
  // each other (a sharp turn, a change of fold, different faces either side).
  std::vector<std::vector<int>> incident(static_cast<size_t>(nv));
  for (int e = 0; e < int(medges.size()); ++e) {
    incident[medges[e].a].push_back(e);
    incident[medges[e].b].push_back(e);
  }
  const double turn = std::cos(o.cornerDegrees * kDegree);
  auto sides = [&](const MeshEdge& e) {
    std::array<int, 2> s{faceOf(e.leftTri), faceOf(e.rightTri)};
    std::sort(s.begin(), s.end());
    return s;
  };
  fm.cornerOfVertex.assign(size_t(nv), -1);
  for (int v = 0; v < nv; ++v) {
    auto& inc = incident[v];
    std::sort(inc.begin(), inc.end(), [&](int x, int y) { return medges[x].other(v) < medges[y].other(v); });
    if (inc.empty()) continue;
    bool corner = inc.size() != 2;
    if (!corner) {
      const MeshEdge &e1 = medges[inc[0]], &e2 = medges[inc[1]];
      const Vec3 d1 = (m.vertices[v] - m.vertices[e1.other(v)]).normalized();
      const Vec3 d2 = (m.vertices[e2.other(v)] - m.vertices[v]).normalized();
      corner = d1.dot(d2) < turn || e1.fold != e2.fold || sides(e1) != sides(e2);
    }
    if (!corner) continue;
    fm.cornerOfVertex[v] = int(fm.corners.size());
    FeatureCorner c;
    c.vertex = v;
    fm.corners.push_back(c);
  }

  // Edges: walk the chains from the corners, then the closed loops that have none.
  std::vector<uint8_t> used(medges.size(), 0);
  auto walk = [&](int start, int first) {
    std::vector<int> verts{start}, segs;
    int v = start, e = first;
    while (e >= 0 && !used[e]) {
      used[e] = 1;
      segs.push_back(e);
      v = medges[e].other(v);
      verts.push_back(v);
      if (fm.cornerOfVertex[v] >= 0) break;
      int next = -1;
      for (int x : incident[v])
        if (!used[x]) next = x;
      e = next;
    }
    // Orient so that the first mesh edge runs as in its left triangle.
    if (medges[segs[0]].a != verts[0]) {
      std::reverse(verts.begin(), verts.end());
      std::reverse(segs.begin(), segs.end());
    }
    FeatureEdge edge;
    edge.vertices = verts;
    edge.closed = verts.front() == verts.back();
    const MeshEdge& e0 = medges[segs[0]];
    edge.leftFace = faceOf(e0.leftTri);
    edge.rightFace = faceOf(e0.rightTri);
    edge.fold = e0.fold;
    for (int s : segs) {
      const MeshEdge& me = medges[s];
      edge.dihedralDegrees += me.angle / kDegree / double(segs.size());
      Vec3 n = m.faceNormals[me.leftTri];
      if (me.rightTri >= 0) n += m.faceNormals[me.rightTri];
      edge.segmentNormals.push_back(n.norm() > 0 ? Vec3(n.normalized()) : m.faceNormals[me.leftTri]);
    }
    for (int x : verts) edge.points.push_back(m.vertices[x]);
    edge.startCorner = fm.cornerOfVertex[verts.front()];
    edge.endCorner = fm.cornerOfVertex[verts.back()];
    fitEdge(edge, o);
    fm.edges.push_back(std::move(edge));
  };
  for (const auto& c : fm.corners)
    for (int e : incident[c.vertex])
      if (!used[e]) walk(c.vertex, e);
  for (int v = 0; v < nv; ++v)
    for (int e : incident[v])
      if (!used[e]) walk(v, e);

  for (int e = 0; e < int(fm.edges.size()); ++e) {
    const FeatureEdge& edge = fm.edges[e];
    for (int f : {edge.leftFace, edge.rightFace})
      if (f >= 0) fm.faces[f].edges.push_back(e);
    for (int c : {edge.startCorner, edge.endCorner})
      if (c >= 0) fm.corners[c].edges.push_back(e);
  }
  for (auto& face : fm.faces) {
    std::sort(face.edges.begin(), face.edges.end());
    face.edges.erase(std::unique(face.edges.begin(), face.edges.end()), face.edges.end());
    face.loops = countLoops(fm.edges, face.edges);
    fitFace(face, m, o);
  }
  for (auto& c : fm.corners) {
    std::sort(c.edges.begin(), c.edges.end());
    c.valence = int(c.edges.size());
    for (int f : m.facesAround(c.vertex)) c.faces.push_back(fm.faceOfTriangle[f]);
    std::sort(c.faces.begin(), c.faces.end());
    c.faces.erase(std::unique(c.faces.begin(), c.faces.end()), c.faces.end());
    int convex = 0, concave = 0, boundary = 0;
    for (int e : c.edges) {
      const EdgeFold f = fm.edges[e].fold;
      (f == EdgeFold::Convex ? convex : f == EdgeFold::Concave ? concave : boundary)++;
    }
    c.kind = boundary ? CornerKind::Boundary
             : concave == 0 ? CornerKind::Convex
             : convex == 0  ? CornerKind::Concave
                            : CornerKind::Mixed;
  }
  return fm;
}

void applyGroupLabels(FeatureMesh& fm, const std::vector<std::string>& groups,
                      const std::vector<int>& triangleGroup) {
  if (triangleGroup.size() != fm.faceOfTriangle.size())
    throw std::invalid_argument("applyGroupLabels: " + std::to_string(triangleGroup.size()) +
                                " triangle groups for " + std::to_string(fm.faceOfTriangle.size()) + " triangles");
  auto tidy = [](std::vector<std::string>& l) {
    std::sort(l.begin(), l.end());
    l.erase(std::unique(l.begin(), l.end()), l.end());
  };
  auto add = [&](std::vector<std::string>& to, const std::vector<std::string>& from) {
    to.insert(to.end(), from.begin(), from.end());
    tidy(to);
  };
  for (size_t t = 0; t < triangleGroup.size(); ++t)
    if (triangleGroup[t] < 0 || size_t(triangleGroup[t]) >= groups.size())
      throw std::invalid_argument("applyGroupLabels: triangle " + std::to_string(t) + " has group " +
                                  std::to_string(triangleGroup[t]) + " of " + std::to_string(groups.size()));
  for (auto& face : fm.faces) {
    std::vector<int> ids;  // its triangles' groups: one, unless built without them
    for (int t : face.triangles) ids.push_back(triangleGroup[t]);
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    for (int g : ids)
      if (!groups[g].empty()) face.labels.push_back(groups[g]);
    tidy(face.labels);
  }
  for (auto& edge : fm.edges)
    for (int f : {edge.leftFace, edge.rightFace})
      if (f >= 0) add(edge.labels, fm.faces[f].labels);
  for (auto& corner : fm.corners)
    for (int e : corner.edges) add(corner.labels, fm.edges[e].labels);
}

const char* toString(EdgeFold f) {
  switch (f) {
    case EdgeFold::Convex: return "convex";
    case EdgeFold::Concave: return "concave";
    case EdgeFold::Boundary: return "boundary";
  }
  return "?";
}
const char* toString(EdgeShape s) {
  switch (s) {
    case EdgeShape::Line: return "line";
    case EdgeShape::Arc: return "arc";
    case EdgeShape::Polyline: return "polyline";
  }
  return "?";
}
const char* toString(EdgeDirection d) {
  switch (d) {
    case EdgeDirection::Horizontal: return "horizontal";
    case EdgeDirection::Vertical: return "vertical";
    case EdgeDirection::Slanted: return "slanted";
    case EdgeDirection::Curved: return "curved";
  }
  return "?";
}
const char* toString(CornerKind k) {
  switch (k) {
    case CornerKind::Convex: return "convex";
    case CornerKind::Concave: return "concave";
    case CornerKind::Mixed: return "mixed";
    case CornerKind::Boundary: return "boundary";
  }
  return "?";
}
const char* toString(FaceKind k) {
  switch (k) {
    case FaceKind::Planar: return "planar";
    case FaceKind::Cylindrical: return "cylindrical";
    case FaceKind::Freeform: return "freeform";
  }
  return "?";
}

}  // namespace fgsg::rt::cells
