#include "backend/commands/cells_command.h"

#include "backend/engine/derivation.h"
#include "runtime/cells/feature_param.h"
#include "runtime/cells/generators.h"
#include "runtime/cells/mortar.h"
#include "runtime/cga/cga.h"
#include "runtime/cga/polygon_clip.h"
#include "runtime/io/find_file.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace fgsg::backend {
namespace {

using rt::cells::FeatureKind;
using rt::cells::FeatureRef;

[[noreturn]] void fail(ir::Loc at, const std::string& message) { throw DeriveError{at, "R026", message}; }

double nonNegative(double v, const char* what, ir::Loc at) {
  if (!(std::isfinite(v) && v >= 0)) fail(at, std::string("Cells: the ") + what + " must be a number >= 0");
  return v;
}

// The box of a scope as OBJ text (no bottom: a building stands on the ground), in world
// coordinates: the same reader, welding and checks as a base-mesh file.
std::string boxObj(const rt::Scope& s) {
  std::ostringstream o;
  o.precision(17);
  for (int k = 0; k < 8; ++k) {
    const rt::Vec3 p = s.P + s.axes.col(0) * ((k & 1) ? s.S.x() : 0.0) + s.axes.col(1) * ((k & 2) ? s.S.y() : 0.0) +
                       s.axes.col(2) * ((k & 4) ? s.S.z() : 0.0);
    o << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  // Y is up (CGA's convention): faces counter-clockwise from outside, no y = 0 face.
  o << "f 1 5 7 3\nf 2 4 8 6\nf 1 2 6 5\nf 3 7 8 4\nf 5 6 8 7\nf 3 4 2 1\n";
  return o.str();
}

bool has(const std::vector<std::string>& labels, const std::string& l) {
  return std::find(labels.begin(), labels.end(), l) != labels.end();
}

// A clipped cell's prism in its scope's unit box (the profile over its bounding
// rectangle, swept along Z), faces counter-clockwise from outside: a convex solid. A
// mitred cell's is its solid (the prism less its mitres) in the same box.
rt::cga::LocalGeometry prismGeometry(const rt::cells::Cell& c) {
  rt::cga::LocalGeometry g;
  g.kind = rt::GeomKind::Polyhedron;
  g.convex = true;
  if (!c.cuts.empty()) {
    const Eigen::Matrix3d toBox = c.axes.inverse();
    for (const std::vector<rt::Vec3>& face : c.solid()) {
      std::vector<rt::Vec3> local;
      for (const rt::Vec3& p : face) {
        const rt::Vec3 q = toBox * (p - c.origin);
        local.emplace_back(c.size.x() > 0 ? q.x() / c.size.x() : 0, c.size.y() > 0 ? q.y() / c.size.y() : 0,
                           c.size.z() > 0 ? q.z() / c.size.z() : 0);
      }
      g.faces.push_back(std::move(local));
    }
    return g;
  }
  std::vector<rt::Vec3> bottom, top;
  for (const rt::cells::Vec2& q : c.profile) {
    const double x = c.size.x() > 0 ? q.x() / c.size.x() : 0, y = c.size.y() > 0 ? q.y() / c.size.y() : 0;
    bottom.emplace_back(x, y, 0), top.emplace_back(x, y, 1);
  }
  g.faces.push_back(top);
  g.faces.emplace_back(bottom.rbegin(), bottom.rend());
  for (size_t i = 0; i < bottom.size(); ++i) {
    const size_t j = (i + 1) % bottom.size();
    g.faces.push_back({bottom[i], bottom[j], top[j], top[i]});
  }
  return g;
}

// Derives the bodies run while it lives on the spot (as a Lock does), with `recording`
// receiving the terminal shapes' pieces (null: none); both are undone when it ends.
class OnTheSpot {
 public:
  OnTheSpot(Derivation& d, std::vector<rt::cells::LabelledPolygon>* recording)
      : d_(d), outer_(d.recordTerminals(recording)) {
    d_.enterLock();
  }
  ~OnTheSpot() {
    d_.recordTerminals(outer_);
    d_.leaveLock();
  }
  OnTheSpot(const OnTheSpot&) = delete;
  OnTheSpot& operator=(const OnTheSpot&) = delete;

 private:
  Derivation& d_;
  std::vector<rt::cells::LabelledPolygon>* outer_;
};

}  // namespace

void CellsCommand::apply(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f) {
  if (op.kind == ir::OpKind::Cells) texture(op, a, n, st, ex, f);
  else pattern(op, a, n, st, ex, f);
}

rt::cells::LabelledMesh CellsCommand::baseMesh(const ir::Op& op, State& st, Exec& ex, Frame& f) {
  if (op.bodies.size() == 2) return basePart(op, st, ex, f);
  if (!op.index) {
    if (st.geom.kind != rt::GeomKind::Box || !(st.scope.S.minCoeff() > 0))
      fail(op.loc, "Cells: the shape's own geometry must be a box with a size in every axis (or give a base mesh "
                   "file: Cells(\"base.obj\", joint){ ... })");
    try {
      rt::cells::LabelledMesh m = rt::cells::parseBaseMeshObj(boxObj(st.scope), "the shape's box");
      return m;
    } catch (const std::exception& e) {
      fail(op.loc, std::string("Cells: ") + e.what());
    }
  }
  const std::string& name = d_.module().strings[op.str];
  auto it = files_.find(name);
  if (it == files_.end()) {
    try {
      auto m = std::make_shared<const rt::cells::LabelledMesh>(
          rt::cells::readBaseMeshObj(rt::io::findFile(name, d_.options().assetDirs)));
      it = files_.emplace(name, std::move(m)).first;
    } catch (const std::exception& e) {
      fail(op.loc, std::string("Cells: ") + e.what());
    }
  }
  // The file is Z-up (as modelling tools write architecture); fgsg's world is Y-up like
  // its CGA buildings: (x, y, z) -> (x, z, -y), a rotation, then moved to the shape.
  rt::cells::LabelledMesh m = *it->second;
  for (rt::Vec3& v : m.mesh.vertices) v = rt::Vec3(v.x(), v.z(), -v.y()) + st.scope.P;
  m.mesh.buildTopology();
  return m;
}

// { Base | Feature }: the base part is derived on the spot and its terminal shapes, the
// pieces its splits left, are recorded instead of dropped; they make the base mesh, each
// labelled with its symbol (a facade's `window` pieces are `window` features).
rt::cells::LabelledMesh CellsCommand::basePart(const ir::Op& op, State& st, Exec& ex, Frame& f) {
  std::vector<rt::cells::LabelledPolygon> pieces;
  {
    const OnTheSpot spot(d_, &pieces);
    d_.runBody(op, 0, st.scope, st.geom, st, ex, f);
  }
  try {
    return rt::cells::labelledMeshFromPolygons(pieces);
  } catch (const std::exception& e) {
    fail(op.loc, std::string("Cells: ") + e.what());
  }
}

rt::Scope CellsCommand::featureScope(const rt::cells::CellularTexture& tex, FeatureRef ref) const {
  const rt::cells::FeatureMesh& fm = tex.features();
  rt::Scope s;
  s.S = rt::Vec3::Zero();
  if (ref.kind == FeatureKind::Corner) {
    s.P = tex.mesh().vertices[fm.corners[ref.index].vertex];
  } else if (ref.kind == FeatureKind::Edge) {
    const auto& e = fm.edges[ref.index];
    const rt::cells::EdgeFrame fr = rt::cells::edgeAt(e, 0);
    s.P = fr.point;
    s.axes.col(0) = fr.tangent;
    s.axes.col(2) = fr.normal;
    s.axes.col(1) = fr.normal.cross(fr.tangent).normalized();
    s.S.x() = e.length;
  } else {
    const auto& face = fm.faces[ref.index];
    const auto& map = tex.faceMap(ref.index);
    if (face.kind == rt::cells::FaceKind::Planar) {
      s.P = face.origin + face.uAxis * map.lo().x() + face.vAxis * map.lo().y();
      s.axes.col(0) = face.uAxis, s.axes.col(1) = face.vAxis, s.axes.col(2) = face.normal;
      s.S = rt::Vec3(map.hi().x() - map.lo().x(), map.hi().y() - map.lo().y(), 0);
    } else {
      s.P = tex.mesh().vertices[tex.mesh().faces[face.triangles[0]][0]];
    }
  }
  return s;
}

void CellsCommand::texture(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f) {
  const double joint = nonNegative(a[0], "mortar joint", op.loc);
  const double mortar = n > 1 ? nonNegative(a[1], "mortar offset", op.loc) : 0.0;
  const rt::cells::LabelledMesh base = baseMesh(op, st, ex, f);
  const rt::Vec3 up = op.index ? rt::Vec3::UnitY() : rt::Vec3(st.scope.axes.col(1));
  const size_t tree = op.bodies.size() - 1;  // the feature tree is the last body part
  rt::cells::FeatureOptions options;
  options.up = up;
  rt::cells::FeatureMesh fm = rt::cells::buildLabelledFeatureMesh(base, options);
  if (std::none_of(fm.faces.begin(), fm.faces.end(),
                   [](const rt::cells::FeatureFace& face) { return face.kind != rt::cells::FaceKind::Freeform; }))
    fail(op.loc, "Cells: the base mesh has no usable features: no face is planar or cylindrical (faces are split "
                 "where the surface folds by more than 30 degrees)");
  rt::cells::CellularTexture tex(base.mesh, std::move(fm), up);
  rt::RandomStream rng{rt::childKey(ex.key, 0x5000000000000000ull | (uint64_t(op.loc.line) << 20) | op.loc.col), 0};
  // The feature tree's own terminal shapes are no base pieces of an outer Cells.
  const OnTheSpot spot(d_, nullptr);
  active_.push_back({&tex, {}, joint, &rng, {}});
  struct Pop {  // after the push: a push that throws leaves nothing to pop
    std::vector<Active>& active;
    ~Pop() { active.pop_back(); }
  } pop{active_};
  for (FeatureRef ref : tex.order()) {
    if (d_.deadline().expiredNow()) throw rt::TimeLimitReached{d_.deadline().seconds()};
    active_.back().feature = ref;
    d_.runBody(op, tree, featureScope(tex, ref), rt::GeomRef{}, st, ex, f);
  }
  // Coverage (docs/cells.md): over the faces a generator ran on.
  std::vector<int> laid = active_.back().facesLaid;
  std::sort(laid.begin(), laid.end());
  laid.erase(std::unique(laid.begin(), laid.end()), laid.end());
  for (int face : laid) {
    const rt::cells::FaceOccupancy& map = tex.faceMap(face);
    const double area = map.area();
    d_.stats().cellsFaceArea += area;
    d_.stats().cellsCoveredArea += area - map.freeArea();
  }
  if (mortar > 0) {
    const rt::Mesh mesh = rt::cells::mortarMesh(base.mesh, mortar);
    const std::string name = "<mortar " + std::to_string(++mortars_) + ">";
    rt::Scope box;
    const uint32_t asset = d_.addGeneratedAsset(name, mesh, &box);
    box.colored = st.scope.colored, box.color = st.scope.color;  // Color(...) before Cells tints the mortar
    d_.placeInstance(asset, box, d_.placingSymbol(ex), nullptr, 0, op.loc);
  }
}

uint32_t CellsCommand::cellAsset() {
  if (cellAsset_ != UINT32_MAX) return cellAsset_;
  rt::Mesh cube;  // the unit box, flat-shaded
  const int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {4, 5, 7, 6}, {0, 2, 3, 1}};
  const float normals[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}};
  cube.positions.resize(72), cube.normals.resize(72), cube.indices.resize(36);
  for (int q = 0; q < 6; ++q) {
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) {
        cube.positions[12 * q + 3 * k + c] = float((faces[q][k] >> c) & 1);
        cube.normals[12 * q + 3 * k + c] = normals[q][c];
      }
    const uint32_t b = uint32_t(4 * q);
    const uint32_t tri[6] = {b, b + 1, b + 2, b, b + 2, b + 3};
    for (int k = 0; k < 6; ++k) cube.indices[6 * q + k] = tri[k];
  }
  return cellAsset_ = d_.addGeneratedAsset("<cell>", cube);
}

void CellsCommand::pattern(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f) {
  if (active_.empty())
    fail(op.loc, "'" + op.name + "' places cells on a feature: it can only run inside Cells(...){ ... }");
  Active& at = active_.back();
  rt::cells::CellularTexture& tex = *at.texture;
  const size_t first = tex.cells().size();
  try {
    switch (static_cast<ir::CellGenerator>(op.index)) {
      case ir::CellGenerator::BrickBond:
      case ir::CellGenerator::EnglishBond:
      case ir::CellGenerator::FlemishBond:
      case ir::CellGenerator::HeaderBond: {
        using G = ir::CellGenerator;
        const auto g = static_cast<G>(op.index);
        const rt::cells::Bond bond = g == G::EnglishBond   ? rt::cells::Bond::English
                                     : g == G::FlemishBond ? rt::cells::Bond::Flemish
                                     : g == G::HeaderBond  ? rt::cells::Bond::Header
                                                           : rt::cells::Bond::Running;
        rt::cells::layBricks(tex, at.feature, {a[0], a[1], a[2], n > 3 && a[3] != 0.0, bond});
        break;
      }
      case ir::CellGenerator::HeaderRow: rt::cells::layHeaders(tex, at.feature, {a[0], a[1], a[2]}); break;
      case ir::CellGenerator::ArchBricks: rt::cells::layArchBricks(tex, at.feature, {a[0], a[1], a[2]}); break;
      case ir::CellGenerator::Shingles: rt::cells::layShingles(tex, at.feature, {a[0], a[1], a[2]}); break;
      case ir::CellGenerator::RandomStones:
        rt::cells::layStones(tex, at.feature, {a[0], a[1], a[2], a[3]}, *at.rng);
        break;
    }
  } catch (const std::invalid_argument& e) {
    fail(op.loc, "'" + op.name + "': " + e.what());
  }
  if (static_cast<ir::CellGenerator>(op.index) == ir::CellGenerator::ArchBricks && tex.cells().size() == first &&
      at.feature.kind == FeatureKind::Edge) {
    // Never a silent empty ring (#46): each ArchBricks on an arc lays a ring outside the last.
    const rt::cells::FeatureEdge& arc = tex.features().edges[at.feature.index];
    if (arc.shape == rt::cells::EdgeShape::Arc && arc.rightFace >= 0)
      fail(op.loc, "'ArchBricks' placed no voussoir on this arc (radius " + std::to_string(arc.radius) +
                       "): cells placed before it (on the arc's corners, or by another generator on this edge) "
                       "take all the room its ring needs");
  }
  if (at.feature.kind == FeatureKind::Face) at.facesLaid.push_back(at.feature.index);
  for (size_t k = first; k < tex.cells().size(); ++k) placeCell(tex.cells()[k], op, st, ex, f);
}

void CellsCommand::placeCell(const rt::cells::Cell& cell, const ir::Op& op, State& st, Exec& ex, Frame& f) {
  rt::cells::Cell c = rt::cells::shrunk(cell, active_.back().joint);
  if (c.axes.determinant() < 0) {  // a right-handed scope: axis 0 turned round, the profile mirrored
    c.origin += c.axes.col(0) * c.size.x(), c.axes.col(0) = -c.axes.col(0);
    for (rt::cells::Vec2& q : c.profile) q.x() = c.size.x() - q.x();
    std::reverse(c.profile.begin(), c.profile.end());
  }
  rt::Scope s = st.scope;
  s.P = c.origin, s.axes = c.axes, s.S = c.size;
  // A clipped cell's shape has its prism as geometry (a CGA leaf outputs it).
  const rt::GeomRef geom = c.isBox() ? rt::GeomRef{} : rt::cga::storeGeometry(d_.arena(), prismGeometry(c));
  rt::InstanceList& out = d_.output();
  const size_t before = out.instances.size();
  if (op.bodies.empty()) d_.placeInstance(cellAsset(), s, d_.placingSymbol(ex), nullptr, 0, op.loc);
  else d_.runBody(op, 0, s, geom, st, ex, f);
  if (c.isBox()) return;
  // The cube that draws a clipped cell (the cell's box with no body, or I("cube") in its
  // rules) is drawn as the cell's prism, stretched into the cube's box as any asset is.
  uint32_t prism = UINT32_MAX;
  for (size_t k = before; k < out.instances.size(); ++k) {
    rt::Instance& inst = out.instances[k];
    if (inst.geometry != UINT32_MAX || (inst.asset != cellAsset_ && out.assets[inst.asset] != "cube")) continue;
    if (prism == UINT32_MAX) {
      out.geometries.push_back(rt::cga::ownGeometryMesh(s, geom, d_.arena()));
      prism = static_cast<uint32_t>(out.geometries.size() - 1);
    }
    inst.geometry = prism;
  }
}

double CellsCommand::feature(const std::string& m, const std::string& arg, ir::Loc at) const {
  if (active_.empty()) fail(at, "Feature." + m + " asks about the feature being textured: only inside Cells(...){ ... }");
  const Active& a = active_.back();
  const rt::cells::FeatureMesh& fm = a.texture->features();
  const rt::Vec3 up = a.texture->up();
  const FeatureRef r = a.feature;
  const rt::cells::FeatureCorner* corner = r.kind == FeatureKind::Corner ? &fm.corners[r.index] : nullptr;
  const rt::cells::FeatureEdge* edge = r.kind == FeatureKind::Edge ? &fm.edges[r.index] : nullptr;
  const rt::cells::FeatureFace* face = r.kind == FeatureKind::Face ? &fm.faces[r.index] : nullptr;
  // Which way the faces at the feature look: up (a sill, a roof), down (a lintel's
  // underside), or neither.
  auto faces = [&] {
    std::vector<int> fs;
    if (face) fs.push_back(r.index);
    if (edge) fs = {edge->leftFace, edge->rightFace};
    if (corner) fs = corner->faces;
    return fs;
  };
  auto looks = [&](double sign) {
    for (int fi : faces())
      if (fi >= 0 && sign * fm.faces[fi].normal.dot(up) > 0.7) return true;
    return false;
  };
  const std::vector<std::string>& labels = corner ? corner->labels : edge ? edge->labels : face->labels;
  using rt::cells::EdgeDirection;
  if (m == "corner") return corner != nullptr;
  if (m == "edge") return edge != nullptr;
  if (m == "face") return face != nullptr;
  if (m == "label") return has(labels, arg);
  if (m == "horizontal" || m == "vertical") {
    // The paper's orientation test: an edge by its direction, a face by whether its
    // normal's largest component is up; corners are neither.
    bool horizontal = false, vertical = false;
    if (edge) horizontal = edge->direction == EdgeDirection::Horizontal, vertical = edge->direction == EdgeDirection::Vertical;
    if (face) {
      const double u = std::abs(face->normal.dot(up));
      horizontal = u >= std::sqrt(0.5) - 1e-12;  // up is at least as large as the rest together
      vertical = !horizontal;
    }
    return m == "horizontal" ? horizontal : vertical;
  }
  if (m == "curved") return edge ? edge->direction == EdgeDirection::Curved : face && face->kind == rt::cells::FaceKind::Cylindrical;
  if (m == "arc") return edge && edge->shape == rt::cells::EdgeShape::Arc;
  if (m == "convex")
    return edge ? edge->fold == rt::cells::EdgeFold::Convex : corner && corner->kind == rt::cells::CornerKind::Convex;
  if (m == "concave")
    return edge ? edge->fold == rt::cells::EdgeFold::Concave : corner && corner->kind == rt::cells::CornerKind::Concave;
  if (m == "boundary")
    return edge ? edge->fold == rt::cells::EdgeFold::Boundary : corner && corner->kind == rt::cells::CornerKind::Boundary;
  if (m == "bottom") return looks(1);
  if (m == "top") return looks(-1);
  if (m == "side") return !looks(1) && !looks(-1);
  if (m == "index") return r.index;
  if (m == "valence") return corner ? corner->valence : edge ? (edge->rightFace >= 0 ? 2 : 1) : double(face->edges.size());
  if (m == "length") return edge ? edge->length : 0.0;
  if (m == "area") return face ? face->area : 0.0;
  fail(at, "internal: unknown feature query Feature." + m);
}

}  // namespace fgsg::backend
