// A leaf shape's own geometry as a mesh (CGA outputs every shape no rule replaces).
#include "runtime/cga/cga.h"
#include "runtime/cga/polygon_clip.h"

namespace fgsg::rt::cga {
namespace {

// Appends one face, flat shaded: its own vertices, its Newell normal (in unit-box
// coordinates, which the instance's cofactor matrix maps onto the world face's normal).
void appendFace(const Polygon3& face, Mesh& out, std::vector<uint32_t>& tris) {
  tris.clear();
  earClip(face, tris);
  if (tris.empty()) return;
  const Vec3 n = newellNormal(face).normalized();
  const auto base = static_cast<uint32_t>(out.positions.size() / 3);
  for (const Vec3& p : face) {
    out.positions.insert(out.positions.end(), {float(p.x()), float(p.y()), float(p.z())});
    out.normals.insert(out.normals.end(), {float(n.x()), float(n.y()), float(n.z())});
  }
  for (uint32_t i : tris) out.indices.push_back(base + i);
}

}  // namespace

Mesh ownGeometryMesh(const Scope& scope, const GeomRef& geom, const GeometryArena& arena) {
  Mesh out;
  if (geom.kind == GeomKind::Edge) return out;
  std::vector<Polygon3> faces;
  if (geom.kind == GeomKind::Box) {
    int flatAxis = -1, flats = 0;
    for (int a = 0; a < 3; ++a)
      if (!(scope.S[a] > 0.0)) flatAxis = a, ++flats;
    if (flats > 1) return out;  // a line or a point
    for (const Polygon3& f : unitBoxFaces()) {
      // A flat box (a footprint, a facade piece) is the one face looking along the
      // positive axis it has no size in; its opposite face would lie on top of it.
      if (flatAxis >= 0 && !(newellNormal(f)[flatAxis] > 0)) continue;
      faces.push_back(f);
    }
  } else {
    faces = loadGeometry(arena, geom).faces;
  }
  std::vector<uint32_t> tris;
  for (const Polygon3& f : faces) appendFace(f, out, tris);
  return out;
}

}  // namespace fgsg::rt::cga
