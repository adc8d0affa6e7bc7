// FGSG Fig. 17's genus-7 surface, "a union of three rotated tori": tori of the same radii
// about the Z, X and Y axes, centred at the origin. Each torus's circle crosses the other
// two twice, so the union is a thickened graph of 6 junctions and 12 arcs: genus
// 12 - 6 + 1 = 7. CGAL's corefinement computes the boolean union of the meshed tori where
// the tubes meet, and isotropic remeshing (isotropic_remesh.h) onto the smooth tori evens
// out the slivers along the seams, so fields and traces behave on it as on the other
// procedural surfaces. Every step is independent of memory layout and time: the same
// arguments give the same mesh in every run.
#include "runtime/surface/procedural.h"

#include "runtime/surface/isotropic_remesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace fgsg::rt::surface {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalMesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

CgalMesh toCgal(const SurfaceMesh& m, const Eigen::Matrix3d& rotation) {
  CgalMesh out;
  std::vector<CgalMesh::Vertex_index> index;
  index.reserve(m.vertices.size());
  for (const Vec3& p : m.vertices) {
    const Vec3 q = rotation * p;
    index.push_back(out.add_vertex(Kernel::Point_3(q.x(), q.y(), q.z())));
  }
  for (const auto& f : m.faces) out.add_face(index[f[0]], index[f[1]], index[f[2]]);
  return out;
}

// Face f's three vertices, each renumbered by `number` (indexed by vertex index).
std::array<int, 3> triangleOf(const CgalMesh& m, CgalMesh::Face_index f, const std::vector<int>& number) {
  std::array<int, 3> t{};
  int k = 0;
  for (auto v : m.vertices_around_face(m.halfedge(f))) {
    if (k == 3) throw std::logic_error("three tori: the union holds a face that is not a triangle");
    t[k++] = number[v.idx()];
  }
  return t;
}

// The mesh with its vertices in lexicographic order of their positions and its faces in
// order of their (rotated) vertex triples. CGAL's corefinement numbers the vertices it
// creates in an order that depends on where its nodes lie in memory; this order does
// not, so remeshing — which depends on the order — gives the same surface in every run.
CgalMesh canonical(const CgalMesh& m) {
  // A vertex's key: its position, then its neighbours' positions in order (the union
  // can hold two vertices at one position, on either side of a seam).
  using Position = std::array<double, 3>;
  auto position = [&](CgalMesh::Vertex_index v) {
    const auto& p = m.point(v);
    return Position{p.x(), p.y(), p.z()};
  };
  std::vector<std::vector<Position>> key(m.number_of_vertices() + m.number_of_removed_vertices());
  for (auto v : m.vertices()) {
    auto& k = key[v.idx()];
    for (auto n : m.vertices_around_target(m.halfedge(v))) k.push_back(position(n));
    std::sort(k.begin(), k.end());
    k.insert(k.begin(), position(v));
  }
  std::vector<CgalMesh::Vertex_index> order(m.vertices().begin(), m.vertices().end());
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return key[a.idx()] < key[b.idx()]; });
  std::vector<int> rank(m.number_of_vertices() + m.number_of_removed_vertices(), -1);
  for (size_t k = 0; k < order.size(); ++k) rank[order[k].idx()] = static_cast<int>(k);
  std::vector<std::array<int, 3>> tris;
  for (auto f : m.faces()) {
    std::array<int, 3> t = triangleOf(m, f, rank);
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    tris.push_back(t);
  }
  std::sort(tris.begin(), tris.end());
  CgalMesh out;
  std::vector<CgalMesh::Vertex_index> index;
  for (auto v : order) index.push_back(out.add_vertex(m.point(v)));
  for (const auto& t : tris) out.add_face(index[t[0]], index[t[1]], index[t[2]]);
  return out;
}

SurfaceMesh fromCgal(const CgalMesh& m) {
  SurfaceMesh out;
  std::vector<int> index(m.number_of_vertices() + m.number_of_removed_vertices(), -1);
  for (auto v : m.vertices()) {
    const auto& p = m.point(v);
    index[v.idx()] = static_cast<int>(out.vertices.size());
    out.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (auto f : m.faces()) out.faces.push_back(triangleOf(m, f, index));
  return out;
}

// The point of the torus about `axis` (radii R, r, centred at the origin) closest to p,
// and p's signed distance to it (negative inside the tube).
Vec3 closestOnTorus(const Vec3& p, const Vec3& axis, double R, double r, double& distance) {
  Vec3 radial = p - axis * axis.dot(p);
  if (radial.norm() < 1e-300) radial = axis.unitOrthogonal();
  const Vec3 ring = R * radial.normalized();
  Vec3 out = p - ring;
  if (out.norm() < 1e-300) out = radial;
  distance = (p - ring).norm() - r;
  return ring + r * out.normalized();
}

// The point of the union of the tori closest to p (p near it): the nearest of the tori's
// closest points that no other tube swallows; one that another tube swallows is carried
// onto the seam of the two by alternating projections.
Vec3 closestOnUnion(const Vec3& p, const std::array<Vec3, 3>& axes, double R, double r) {
  Vec3 best = p;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    double d = 0;
    Vec3 c = closestOnTorus(p, axes[i], R, r, d);
    for (int round = 0; round < 64; ++round) {
      int inside = -1;
      for (int j = 0; j < 3; ++j) {
        double dj = 0;
        closestOnTorus(c, axes[j], R, r, dj);
        if (j != i && dj < -1e-9 * r) inside = j;
      }
      if (inside < 0) break;
      c = closestOnTorus(closestOnTorus(c, axes[inside], R, r, d), axes[i], R, r, d);
    }
    const double distance = (c - p).norm();
    if (distance < bestDistance) best = c, bestDistance = distance;
  }
  return best;
}

}  // namespace

SurfaceMesh threeTori(double R, double r, int segments) {
  // CGAL draws from a thread-local generator seeded with the clock (box intersection's
  // approximate medians): seeded here, so nothing of the union depends on the time.
  CGAL::Random& shared = CGAL::get_default_random();
  const CGAL::Random saved = shared;
  shared = CGAL::Random(0x7041);
  struct Restore {
    CGAL::Random& to;
    const CGAL::Random& from;
    ~Restore() { to = from; }
  } restore{shared, saved};

  const SurfaceMesh tube = torus(R, r, segments);  // about Z
  const Eigen::Matrix3d aboutX = Eigen::AngleAxisd(M_PI / 2, Vec3::UnitY()).toRotationMatrix();   // Z to X
  const Eigen::Matrix3d aboutY = Eigen::AngleAxisd(-M_PI / 2, Vec3::UnitX()).toRotationMatrix();  // Z to Y
  CgalMesh z = toCgal(tube, Eigen::Matrix3d::Identity()), x = toCgal(tube, aboutX), y = toCgal(tube, aboutY);
  CgalMesh zx, zxy;
  if (!PMP::corefine_and_compute_union(z, x, zx) || !PMP::corefine_and_compute_union(zx = canonical(zx), y, zxy))
    throw std::runtime_error("tori3: the union of the tori could not be computed");
  // The seams' slivers evened out to the torus's own edge length, every vertex kept on
  // the union of the smooth tori.
  const double edge = 2 * M_PI * r / segments;
  const std::array<Vec3, 3> axes{Vec3::UnitZ(), Vec3::UnitX(), Vec3::UnitY()};
  return remeshIsotropic(fromCgal(canonical(zxy)), edge,
                         [&](const Vec3& p) { return closestOnUnion(p, axes, R, r); });
}

}  // namespace fgsg::rt::surface
