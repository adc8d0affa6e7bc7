#include "runtime/surface/isotropic_remesh.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <cmath>
#include <cstdlib>
#include <vector>

namespace fgsg::rt::surface {

namespace {

struct Traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using Mesh = OpenMesh::TriMesh_ArrayKernelT<Traits>;

// A collapse or flip may turn a face's normal by at most this much (cosine).
constexpr double kMinNormalCosine = 0.5;

Vec3 toEigen(const OpenMesh::Vec3d& p) { return {p[0], p[1], p[2]}; }
OpenMesh::Vec3d toOpenMesh(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

double edgeLength(const Mesh& m, Mesh::EdgeHandle e) {
  const auto h = m.halfedge_handle(e, 0);
  return (m.point(m.to_vertex_handle(h)) - m.point(m.from_vertex_handle(h))).norm();
}

Vec3 triangleNormal(const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a); }

// Whether moving `moved` to `to` keeps every face around it (but those in `skip`) turned
// by less than the limit and not degenerate.
bool facesStayUpright(const Mesh& m, Mesh::VertexHandle moved, const Vec3& to, Mesh::FaceHandle skipA,
                      Mesh::FaceHandle skipB) {
  for (auto f : m.vf_range(moved)) {
    if (f == skipA || f == skipB) continue;
    Vec3 p[3], q[3];
    int k = 0;
    for (auto v : m.fv_range(f)) {
      p[k] = toEigen(m.point(v));
      q[k] = v == moved ? to : p[k];
      ++k;
    }
    const Vec3 before = triangleNormal(p[0], p[1], p[2]), after = triangleNormal(q[0], q[1], q[2]);
    const double lb = before.norm(), la = after.norm();
    if (!(la > 1e-12 * std::max(lb, 1e-300)) || before.dot(after) < kMinNormalCosine * lb * la) return false;
  }
  return true;
}

void splitLongEdges(Mesh& m, double high, const SurfaceProjection& project) {
  // Every split halves an edge longer than `high`: the passes end once all are shorter.
  for (bool again = true; again;) {
    again = false;
    const size_t edges = m.n_edges();
    for (size_t i = 0; i < edges; ++i) {
      const Mesh::EdgeHandle e(static_cast<int>(i));
      if (edgeLength(m, e) <= high) continue;
      const auto h = m.halfedge_handle(e, 0);
      const Vec3 mid = 0.5 * (toEigen(m.point(m.from_vertex_handle(h))) + toEigen(m.point(m.to_vertex_handle(h))));
      m.split(e, m.add_vertex(toOpenMesh(project(mid))));
      again = true;
    }
  }
}

void collapseShortEdges(Mesh& m, double low, double high, const SurfaceProjection& project) {
  for (size_t i = 0; i < m.n_edges(); ++i) {
    const Mesh::EdgeHandle e(static_cast<int>(i));
    if (m.status(e).deleted() || edgeLength(m, e) >= low) continue;
    const auto h = m.halfedge_handle(e, 0);
    const auto from = m.from_vertex_handle(h), to = m.to_vertex_handle(h);
    if (!m.is_collapse_ok(h)) continue;
    const Vec3 mid = project(0.5 * (toEigen(m.point(from)) + toEigen(m.point(to))));
    bool fits = true;
    for (auto v : {from, to})
      for (auto n : m.vv_range(v))
        if (n != from && n != to && (toEigen(m.point(n)) - mid).norm() > high) fits = false;
    const auto fa = m.face_handle(h), fb = m.face_handle(m.opposite_halfedge_handle(h));
    if (!fits || !facesStayUpright(m, from, mid, fa, fb) || !facesStayUpright(m, to, mid, fa, fb)) continue;
    m.set_point(to, toOpenMesh(mid));
    m.collapse(h);
  }
  m.garbage_collection();
}

// Angle at c in triangle (a, b, c).
double angleAt(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = a - c, v = b - c;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

// Flips every edge between two coplanar triangles that is not locally Delaunay, until
// none is left: each planar region (an input face cut by seams, say) then holds its
// constrained Delaunay triangulation, whatever triangulation it came in.
void flipCoplanarToDelaunay(Mesh& m) {
  // Each flip makes the region more Delaunay, so passes end; the bound only guards
  // against rounding making two configurations flip back and forth.
  for (int pass = 0, again = 1; again && pass < 100; ++pass) {
    again = 0;
    for (size_t i = 0; i < m.n_edges(); ++i) {
      const Mesh::EdgeHandle e(static_cast<int>(i));
      if (!m.is_flip_ok(e)) continue;
      const auto h = m.halfedge_handle(e, 0), o = m.opposite_halfedge_handle(h);
      const Vec3 a = toEigen(m.point(m.from_vertex_handle(h))), b = toEigen(m.point(m.to_vertex_handle(h)));
      const Vec3 c = toEigen(m.point(m.to_vertex_handle(m.next_halfedge_handle(h))));
      const Vec3 d = toEigen(m.point(m.to_vertex_handle(m.next_halfedge_handle(o))));
      const Vec3 n1 = triangleNormal(a, b, c).normalized(), n2 = triangleNormal(b, a, d).normalized();
      if (n1.dot(n2) < 1 - 1e-12) continue;  // a crease: keep it
      if (angleAt(a, b, c) + angleAt(a, b, d) <= M_PI + 1e-9) continue;
      // The flipped pair must be a convex quad's diagonal (both new triangles upright).
      if (triangleNormal(a, d, c).dot(n1) <= 0 || triangleNormal(b, c, d).dot(n1) <= 0) continue;
      m.flip(e);
      again = 1;
    }
  }
}

int valenceDeviation(int a, int b, int c, int d) { return std::abs(a - 6) + std::abs(b - 6) + std::abs(c - 6) + std::abs(d - 6); }

void flipTowardsValenceSix(Mesh& m) {
  for (size_t i = 0; i < m.n_edges(); ++i) {
    const Mesh::EdgeHandle e(static_cast<int>(i));
    if (!m.is_flip_ok(e)) continue;
    const auto h = m.halfedge_handle(e, 0), o = m.opposite_halfedge_handle(h);
    const auto a = m.from_vertex_handle(h), b = m.to_vertex_handle(h);
    const auto c = m.to_vertex_handle(m.next_halfedge_handle(h)), d = m.to_vertex_handle(m.next_halfedge_handle(o));
    const int va = int(m.valence(a)), vb = int(m.valence(b)), vc = int(m.valence(c)), vd = int(m.valence(d));
    if (valenceDeviation(va - 1, vb - 1, vc + 1, vd + 1) >= valenceDeviation(va, vb, vc, vd)) continue;
    // The two new triangles (a, d, c) and (b, c, d) must face as the old ones did.
    const Vec3 pa = toEigen(m.point(a)), pb = toEigen(m.point(b)), pc = toEigen(m.point(c)), pd = toEigen(m.point(d));
    const Vec3 old = triangleNormal(pa, pb, pc) + triangleNormal(pb, pa, pd);
    const Vec3 n1 = triangleNormal(pa, pd, pc), n2 = triangleNormal(pb, pc, pd);
    if (n1.dot(old) < kMinNormalCosine * n1.norm() * old.norm() || n2.dot(old) < kMinNormalCosine * n2.norm() * old.norm())
      continue;
    m.flip(e);
  }
}

void relaxTangentially(Mesh& m, const SurfaceProjection& project) {
  std::vector<Vec3> moved(m.n_vertices());
  for (auto v : m.vertices()) {
    const Vec3 p = toEigen(m.point(v));
    Vec3 centroid = Vec3::Zero(), normal = Vec3::Zero();
    int n = 0;
    for (auto w : m.vv_range(v)) centroid += toEigen(m.point(w)), ++n;
    for (auto f : m.vf_range(v)) {
      Vec3 q[3];
      int k = 0;
      for (auto u : m.fv_range(f)) q[k++] = toEigen(m.point(u));
      normal += triangleNormal(q[0], q[1], q[2]);
    }
    if (n == 0 || normal.norm() == 0) {
      moved[v.idx()] = p;
      continue;
    }
    normal.normalize();
    const Vec3 step = centroid / n - p;
    moved[v.idx()] = project(p + step - normal * normal.dot(step));
  }
  for (auto v : m.vertices()) m.set_point(v, toOpenMesh(moved[v.idx()]));
}

}  // namespace

SurfaceMesh remeshIsotropic(const SurfaceMesh& in, double target, const SurfaceProjection& project, int iterations) {
  Mesh m;
  m.request_vertex_status();
  m.request_edge_status();
  m.request_halfedge_status();
  m.request_face_status();
  std::vector<Mesh::VertexHandle> handle;
  handle.reserve(in.vertices.size());
  for (const Vec3& p : in.vertices) handle.push_back(m.add_vertex(toOpenMesh(p)));
  for (const auto& f : in.faces) m.add_face(handle[f[0]], handle[f[1]], handle[f[2]]);
  flipCoplanarToDelaunay(m);
  const double low = 0.8 * target, high = 4.0 / 3.0 * target;
  for (int i = 0; i < iterations; ++i) {
    splitLongEdges(m, high, project);
    collapseShortEdges(m, low, high, project);
    flipTowardsValenceSix(m);
    relaxTangentially(m, project);
  }
  SurfaceMesh out;
  out.vertices.reserve(m.n_vertices());
  for (auto v : m.vertices()) out.vertices.push_back(toEigen(m.point(v)));
  for (auto f : m.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (auto v : m.fv_range(f)) t[k++] = v.idx();
    out.faces.push_back(t);
  }
  out.buildTopology();
  return out;
}

}  // namespace fgsg::rt::surface
