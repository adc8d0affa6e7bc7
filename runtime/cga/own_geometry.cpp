// A leaf shape's own geometry as a mesh (CGA outputs every shape no rule replaces).
#include "runtime/cga/cga.h"
#include "runtime/cga/polygon_clip.h"

namespace fgsg::rt::cga {
namespace {

// Appends one face, flat shaded: its own vertices, its Newell normal (in unit-box
// coordinates, which the instance's cofactor matrix maps onto the world face's normal).
void appendOwnFace(const Vec3* face, std::size_t count, Mesh& out, std::vector<uint32_t>& tris) {
  tris.clear();
  earClip(face, count, tris);
  if (tris.empty()) return;
  const Vec3 n = newellNormal(face, count).normalized();
  const auto base = static_cast<uint32_t>(out.positions.size() / 3);
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3& p = face[i];
    out.positions.insert(out.positions.end(), {float(p.x()), float(p.y()), float(p.z())});
    out.normals.insert(out.normals.end(), {float(n.x()), float(n.y()), float(n.z())});
  }
  for (uint32_t i : tris) out.indices.push_back(base + i);
}

// Calls visit(points, count) for each face of the shape's geometry, read in place (the
// arena's faces are not copied out): a box's six faces, or the one face a flat box is.
template <class Visit>
void forEachFace(const Scope& scope, const GeomRef& geom, const GeometryArena& arena, Visit&& visit) {
  if (geom.kind == GeomKind::Box) {
    int flatAxis = -1, flats = 0;
    for (int a = 0; a < 3; ++a)
      if (!(scope.S[a] > 0.0)) flatAxis = a, ++flats;
    if (flats > 1) return;  // a line or a point
    for (const Polygon3& f : unitBoxFaces()) {
      // A flat box (a footprint, a facade piece) is the one face looking along the
      // positive axis it has no size in; its opposite face would lie on top of it.
      if (flatAxis >= 0 && !(newellNormal(f)[flatAxis] > 0)) continue;
      visit(f.data(), f.size());
    }
  } else if (geom.kind == GeomKind::Polygon) {
    visit(arena.polygon(geom), std::size_t(geom.count));
  } else if (geom.kind == GeomKind::Polyhedron) {
    for (uint32_t i = 0; i < geom.count; ++i) {
      const GeometryArena::Face& f = arena.face(geom, i);
      visit(arena.facePoints(f), std::size_t(f.count));
    }
  }
}

}  // namespace

Mesh ownGeometryMesh(const Scope& scope, const GeomRef& geom, const GeometryArena& arena) {
  Mesh out;
  if (geom.kind == GeomKind::Edge) return out;
  // Room for every face at once: a leaf's mesh is built by the million in a city.
  size_t vertices = 0, triangles = 0;
  forEachFace(scope, geom, arena, [&](const Vec3*, std::size_t count) {
    vertices += count;
    triangles += count >= 3 ? count - 2 : 0;
  });
  out.positions.reserve(3 * vertices);
  out.normals.reserve(3 * vertices);
  out.indices.reserve(3 * triangles);
  thread_local std::vector<uint32_t> tris;  // a face's triangles, reused from leaf to leaf
  forEachFace(scope, geom, arena, [&](const Vec3* face, std::size_t count) { appendOwnFace(face, count, out, tris); });
  return out;
}

}  // namespace fgsg::rt::cga
