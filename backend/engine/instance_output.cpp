// The derivation's output: the instance list with its symbol, asset and colour tables,
// each instance placed (and checked to be finite), the surface appended, and the order of
// instances that direct code placed restored to the engine's own.
#include "backend/engine/derivation.h"

#include "runtime/cga/asset_geometry.h"
#include "runtime/cga/cga.h"
#include "runtime/cga/polygon_clip.h"
#include "runtime/cga/trim_mesh.h"
#include "runtime/cga/trim_planes.h"
#include "runtime/cga/uv_projection.h"
#include "runtime/float_range.h"
#include "runtime/insert_fit.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <functional>

namespace fgsg::backend {

uint32_t Derivation::addGeneratedAsset(const std::string& name, const rt::Mesh& world, rt::Scope* builtIn) {
  std::array<double, 16> placed{};
  assets_.addGenerated(name, world, placed);
  if (builtIn)
    for (int k = 0; k < 3; ++k) builtIn->P[k] = placed[12 + k], builtIn->S[k] = placed[5 * k];
  const auto asset = static_cast<uint32_t>(out_.assets.size());
  out_.assets.push_back(name);
  return asset;
}

void Derivation::initOutput() {
  out_.assets = m_.assets;
  origins_.setup(m_, opt_.recordOrigins);
  out_.strings = m_.strings;
  out_.textures = textures_.paths();
  for (const auto& s : m_.symbols) {
    out_.symbols.push_back(s.name);
    std::vector<rt::ParamKind> kinds;
    for (ir::Type t : s.paramTypes)
      kinds.push_back(t == ir::Type::Bool  ? rt::ParamKind::Boolean
                      : t == ir::Type::Str ? rt::ParamKind::String
                      : t == ir::Type::Vec3 ? rt::ParamKind::Vector
                                            : rt::ParamKind::Number);
    out_.paramKinds.push_back(std::move(kinds));
  }
  segmentAsset_ = static_cast<uint32_t>(out_.assets.size());
  // What `turtle segments` asks for: built-in assets that fill the segment's box.
  switch (m_.turtle.segments) {
    case ir::TurtleSegments::Cylinders: out_.assets.push_back("cylinder"); break;
    case ir::TurtleSegments::Tubes: out_.assets.push_back("tube" + std::to_string(m_.turtle.sides)); break;
    case ir::TurtleSegments::Ribbons: out_.assets.push_back("quad"); break;
    case ir::TurtleSegments::Lines: out_.assets.push_back("line"); break;
  }
  for (size_t i = 0; i < m_.assets.size(); ++i)
    if (m_.assets[i] == "none") noneAsset_ = static_cast<uint32_t>(i);
  leavesOutput_ = ir::leavesOutputGeometry(m_);
  const bool polygons = moduleUses([](const ir::Op& op) {
    return op.kind == ir::OpKind::Turtle && op.index == static_cast<uint32_t>(ir::TurtleOp::PolygonEnd);
  });
  const bool cylinders = moduleUses([](const ir::Op& op) {  // @Ge: generalized cylinders (turtle_commands.cpp)
    return op.kind == ir::OpKind::Turtle && op.index == static_cast<uint32_t>(ir::TurtleOp::CylinderEnd);
  });
  ownGeometryAsset_ = UINT32_MAX;  // else set by the first cut insert (placeTrimmedAsset)
  if (leavesOutput_ || polygons || cylinders) {
    ownGeometryAsset_ = static_cast<uint32_t>(out_.assets.size());
    out_.assets.push_back(rt::kOwnGeometryAsset);
  }
  if (leavesOutput_) {
    leafCubeAsset_ = static_cast<uint32_t>(out_.assets.size());
    out_.assets.push_back("cube");
    leafQuadAsset_ = static_cast<uint32_t>(out_.assets.size());
    out_.assets.push_back("quad");
  }
  segmentSymbol_ = static_cast<uint32_t>(out_.symbols.size());
  out_.symbols.push_back("F");
  for (const auto& s : m_.symbols) symbolColor_.push_back(colorFor(s.name));
  symbolColor_.push_back({0.45f, 0.33f, 0.2f});  // turtle segments: bark brown
  axiomSymbol_ = static_cast<uint32_t>(out_.symbols.size());
  out_.symbols.push_back("axiom");
  symbolColor_.push_back(colorFor("axiom"));
  if (polygons) {
    polygonSymbol_ = static_cast<uint32_t>(out_.symbols.size());
    out_.symbols.push_back("polygon");
    symbolColor_.push_back({0.3f, 0.6f, 0.2f});  // ABOP's polygons are mostly leaves
  }
  usesOcclusion_ = moduleUsesQuery(ir::Query::ScopeOcc);
  collide_.prepare(moduleUses([](const ir::Op& op) {
    return op.kind == ir::OpKind::Lock || (op.kind == ir::OpKind::Instance && op.mode != ir::InstanceMode::Plain);
  }));
  findEagerSymbols();
  makesTrimPlanes_ = moduleUses([this](const ir::Op& op) {
    if (op.kind != ir::OpKind::ShapeOperation) return false;
    const std::string& name = m_.strings[op.str];
    return name == "ApplyTrimPlanes" || name.rfind("Primitive", 0) == 0;
  }) || (moduleUses([](const ir::Op& op) { return op.kind == ir::OpKind::Comp; }) &&
         moduleUses([](const ir::Op& op) { return op.kind == ir::OpKind::Instance; }));
  noneId_ = stringId("none");
  partId_ = stringId("part");
  fullId_ = stringId("full");
}

std::array<float, 3> Derivation::colorFor(const std::string& name) {
  // A stable pastel hue per symbol, so parts of a pattern are told apart in previews.
  const double h = (rt::mix64(std::hash<std::string>{}(name)) % 360) / 60.0;
  const double x = 1 - std::abs(std::fmod(h, 2.0) - 1);
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(h)) {
    case 0: r = 1, g = x; break;
    case 1: r = x, g = 1; break;
    case 2: g = 1, b = x; break;
    case 3: g = x, b = 1; break;
    case 4: r = x, b = 1; break;
    default: r = 1, b = x; break;
  }
  auto pastel = [](double c) { return static_cast<float>(0.35 + 0.55 * c); };
  return {pastel(r), pastel(g), pastel(b)};
}

// R005 when an instance's scope is not finite or reaches past a 32-bit float; called where
// the quick bound (unitBoxClearlyFitsFloat) cannot tell that it fits.
void Derivation::checkInstanceReach(const rt::Mat4& t, uint32_t symbol, ir::Loc loc) const {
  for (int k = 0; k < 16; ++k)
    if (!std::isfinite(t.data()[k]))
      throw DeriveError{loc, "R005",
                        "this instance's scope is not finite (a parameter became NaN or "
                        "infinite, e.g. sqrt of a negative number or a division by zero)"};
  if (const double reach = rt::unitBoxReach(t); !(reach <= double(FLT_MAX))) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", reach);
    throw DeriveError{loc, "R005",
                      "this instance of '" + out_.symbols[symbol] + "' reaches coordinate " + text +
                          ", beyond what mesh files store (32-bit floats, up to 3.4e+38): a scale, "
                          "extrusion or translation grew too large"};
  }
}

rt::Scope Derivation::insertFitted(const ir::Op& op, const rt::Scope& scope) const {
  if (op.insertFit == ir::InsertFit::AlignSizeAndPosition) return scope;
  const std::array<double, 6> box =
      op.index < assetSourceBox_.size() ? assetSourceBox_[op.index] : std::array<double, 6>{0, 0, 0, 1, 1, 1};
  // ir::InsertFit and rt::InsertFitMode list the modes in the same order.
  return rt::insertedScope(scope, rt::Vec3(box[0], box[1], box[2]), rt::Vec3(box[3], box[4], box[5]), op.zUp,
                           static_cast<rt::InsertFitMode>(op.insertFit));
}

void Derivation::placeInstance(uint32_t asset, const rt::Scope& scope, uint32_t symbol,
                               const double* params, uint32_t paramCount, ir::Loc loc, bool zUp,
                               std::optional<rt::GeomRef>* cut) {
  if (asset == noneAsset_) return;
  // Frame 0 has no trim planes: the one test every other instance pays.
  if (scope.pivot != 0 && asset < m_.assets.size() &&
      placeTrimmedAsset(asset, scope, symbol, params, paramCount, loc, zUp, cut))
    return;
  const rt::Mat4 t = rt::insertTransform(scope, zUp);
  if (!rt::unitBoxClearlyFitsFloat(t)) checkInstanceReach(t, symbol, loc);
  // Written in place: a million-segment L-system places an instance per segment.
  rt::Instance& inst = out_.instances.emplace_back();
  inst.asset = asset;
  inst.symbol = symbol;
  std::copy(t.data(), t.data() + 16, inst.transform.begin());
  inst.color = scope.colored ? scope.color : symbolColor_[symbol];
  if (asset < assetHasTexcoords_.size()) applyAssetLook(inst, asset, scope);
  if (scope.marchSegment >= 0) inst.curve = static_cast<uint32_t>(scope.marchSegment);
  if (origins_.on()) out_.origins.push_back(origins_.of(loc, placingDepth_));
  if (scope.finish) {  // Material(...): InstanceList::finishIndex, as long as the last instance with one
    out_.finishIndex.resize(out_.instances.size(), 0);
    out_.finishIndex.back() = scope.finish;
  }
  inst.firstParam = static_cast<uint32_t>(out_.params.size());
  inst.paramCount = paramCount;
  out_.params.insert(out_.params.end(), params, params + paramCount);
  if (recordShapesAtInstances_) shapesAtInstance_.push_back(stats_.shapesCreated);
  if (orderedDirect_) placedBy_.push_back(placingShape_);
  if (usesOcclusion_) occluders_.add(scope);
  collide_.placed(scope);
}

// A CGA leaf: the shape's own geometry (a split piece, a face, a solid) as an instance
// over its scope, so it is coloured, checked and counted like any other. Below a Texture
// it carries texture coordinates from the projection and draws the image, in white
// unless Color tinted it.
void Derivation::outputLeaf(uint32_t symbol, const State& st, const double* params, ir::Loc loc) {
  const uint32_t slots = m_.symbols[symbol].slotCount;
  if (!carriedAssets_.empty() && outputCarriedAsset(symbol, st, params, slots, loc)) return;
  // (A projection without an image yet, from setupProjection, or after deleteUV draws nothing.)
  const rt::cga::UvProjection* projection = textures_.projection(st.scope.projection);
  if (projection && !projection->draws()) projection = nullptr;
  // Uv sets 1..9 with coordinates (projected, not deleted) go out as they are, image or not.
  std::array<const rt::cga::UvProjection*, ir::kUvSets> otherSets{};
  bool hasOtherSets = false;
  for (uint32_t set = 1; set < ir::kUvSets; ++set) {
    const rt::cga::UvProjection* p = textures_.projection(st.scope.projection, set);
    if (p && p->coordinates) otherSets[set] = p, hasOtherSets = true;
  }
  // The commonest untextured leaves share a built-in mesh over their scope: a whole box is
  // the cube, a rectangle (a facade's split piece) the quad. Other shapes build their own.
  const bool plain = !projection && !hasOtherSets;
  if (plain && st.geom.kind == rt::GeomKind::Box && st.scope.S.minCoeff() > 0)
    return placeInstance(leafCubeAsset_, st.scope, symbol, params, slots, loc);
  if (plain && st.geom.kind == rt::GeomKind::Polygon &&
      rt::cga::isUnitSquare(arena_.polygon(st.geom), st.geom.count))
    return placeInstance(leafQuadAsset_, st.scope, symbol, params, slots, loc);
  rt::Mesh mesh = rt::cga::ownGeometryMesh(st.scope, st.geom, arena_);
  if (mesh.indices.empty()) return;  // an edge, a point
  if (projection) rt::cga::projectTexcoords(mesh, st.scope, *projection);
  for (uint32_t set = 1; set < ir::kUvSets; ++set)
    if (otherSets[set]) {
      mesh.uvSets.push_back({set, {}});
      rt::cga::projectTexcoordsInto(mesh, st.scope, *otherSets[set], mesh.uvSets.back().coords);
    }
  // The mesh goes first: a collision world reads it as it records the instance.
  out_.geometries.push_back(std::move(mesh));
  const size_t before = out_.instances.size();
  placeInstance(ownGeometryAsset_, st.scope, symbol, params, slots, loc);
  if (out_.instances.size() == before) return out_.geometries.pop_back();
  rt::Instance& inst = out_.instances.back();
  inst.geometry = static_cast<uint32_t>(out_.geometries.size() - 1);
  if (projection) {
    inst.texture = projection->texture;
    if (!st.scope.colored) inst.color = {1.0f, 1.0f, 1.0f};
  }
}

// An asset with texture coordinates of its own draws the image of a Texture above it,
// and one with images of its own keeps them; either untinted unless Color says.
void Derivation::applyAssetLook(rt::Instance& inst, uint32_t asset, const rt::Scope& scope) const {
  const rt::cga::UvProjection* projection = textures_.projection(scope.projection);
  const bool textured = projection && assetHasTexcoords_[asset] && projection->draws();
  if (textured) inst.texture = projection->texture;
  if ((textured || assetHasImages_[asset]) && !scope.colored) inst.color = {1.0f, 1.0f, 1.0f};
}

rt::GeomRef Derivation::insertedGeometry(uint32_t asset, bool zUp) {
  if (assetGeometry_.size() < assetMesh_.size()) assetGeometry_.resize(assetMesh_.size());
  std::optional<rt::GeomRef>& made = assetGeometry_[asset][zUp ? 1 : 0];
  if (!made) made = rt::cga::storeGeometry(arena_, rt::cga::assetGeometry(assets_.mesh(assetMesh_[asset]), zUp));
  return *made;
}

std::vector<rt::cga::TrimPlane> Derivation::planesCuttingAsset(uint32_t asset, const rt::Scope& scope, bool zUp) const {
  std::vector<rt::cga::TrimPlane> planes = frames_.enabledTrimPlanes(scope.pivot, scope.trim);
  if (planes.empty()) return planes;
  // The asset's box wholly on the kept side of every plane: the instance as it is.
  const rt::Mat4 t = rt::insertTransform(scope, zUp);
  const double tol = 1e-9 * (1.0 + scope.S.norm());
  bool boxCrosses = false;
  for (int c = 0; c < 8 && !boxCrosses; ++c) {
    const rt::Vec3 corner = (t * Eigen::Vector4d(c & 1, (c >> 1) & 1, (c >> 2) & 1, 1.0)).head<3>();
    for (const rt::cga::TrimPlane& p : planes)
      if ((corner - p.point).dot(p.normal) > tol) boxCrosses = true;
  }
  if (!boxCrosses) return {};
  // The box crosses a plane, the asset itself may not (a round asset in a mitred corner):
  // its vertices (in its unit box, turned as trimAssetMesh turns a zUp one) decide.
  const rt::Mesh& mesh = assets_.mesh(assetMesh_[asset]);
  for (const rt::cga::TrimPlane& p : planes) {
    const rt::Vec3 n = scope.S.cwiseProduct(scope.axes.transpose() * p.normal);
    const double d = p.normal.dot(scope.P - p.point);
    for (size_t v = 0; v + 2 < mesh.positions.size(); v += 3) {
      const rt::Vec3 u = zUp ? rt::Vec3(mesh.positions[v], mesh.positions[v + 2], 1.0 - mesh.positions[v + 1])
                             : rt::Vec3(mesh.positions[v], mesh.positions[v + 1], mesh.positions[v + 2]);
      if (n.dot(u) + d > tol) return planes;
    }
  }
  return {};
}

rt::GeomRef Derivation::carryInsert(const ir::Op& op, const rt::Scope& scope) {
  CarriedAsset carried{op.index, op.zUp, -1};
  rt::GeomRef geom = insertedGeometry(op.index, op.zUp);
  if (scope.pivot != 0) {  // frame 0 has no trim planes
    const std::vector<rt::cga::TrimPlane> planes = planesCuttingAsset(op.index, scope, op.zUp);
    if (!planes.empty()) {
      rt::cga::Part part;
      rt::cga::trimGeometry(scope, geom, arena_, planes, part);
      // A plane through the asset's box but not its solid leaves the geometry as it was,
      // the key every uncut insert of the asset shares: no cut mesh for it.
      const bool cut = part.geom.kind != geom.kind || part.geom.first != geom.first;
      geom = part.geom;
      if (cut) {
        carried.cutMesh = static_cast<int32_t>(carriedCutMeshes_.size());
        carriedCutMeshes_.push_back(rt::cga::trimAssetMesh(scope, assets_.mesh(assetMesh_[op.index]), op.zUp, planes));
      }
    }
  }
  if (geom.count > 0) carriedAssets_[carriedKey(geom)] = carried;  // all cut away: the leaf outputs nothing
  return geom;
}

bool Derivation::outputCarriedAsset(uint32_t symbol, const State& st, const double* params, uint32_t slots,
                                    ir::Loc loc) {
  if (st.geom.count == 0) return false;
  const auto found = carriedAssets_.find(carriedKey(st.geom));
  if (found == carriedAssets_.end()) return false;  // a geometry operation made geometry of its own
  const CarriedAsset carried = found->second;
  // Texture coordinates the asset does not have (a projection on an asset without uvs, or
  // uv sets 1..9) are projected onto the shape's geometry: outputLeaf's own-geometry path.
  const rt::cga::UvProjection* projection = textures_.projection(st.scope.projection);
  if (projection && projection->draws() && !assetHasTexcoords_[carried.asset]) return false;
  for (uint32_t set = 1; set < ir::kUvSets; ++set) {
    const rt::cga::UvProjection* p = textures_.projection(st.scope.projection, set);
    if (p && p->coordinates) return false;
  }
  if (carried.cutMesh < 0) {
    placeInstance(carried.asset, st.scope, symbol, params, slots, loc, carried.zUp);
    return true;
  }
  out_.geometries.push_back(carriedCutMeshes_[carried.cutMesh]);  // first, as below
  const size_t before = out_.instances.size();
  placeInstance(ownGeometryAsset_, st.scope, symbol, params, slots, loc);
  if (out_.instances.size() == before) {
    out_.geometries.pop_back();
    return true;
  }
  rt::Instance& inst = out_.instances.back();
  inst.geometry = static_cast<uint32_t>(out_.geometries.size() - 1);
  applyAssetLook(inst, carried.asset, st.scope);
  return true;
}

bool Derivation::placeTrimmedAsset(uint32_t asset, const rt::Scope& scope, uint32_t symbol, const double* params,
                                   uint32_t paramCount, ir::Loc loc, bool zUp, std::optional<rt::GeomRef>* cut) {
  const std::vector<rt::cga::TrimPlane> planes = planesCuttingAsset(asset, scope, zUp);
  if (planes.empty()) return false;
  // The shape's geometry after the insert: the asset's solid, cut as trim() cuts one.
  if (cut) {
    rt::cga::Part part;
    rt::cga::trimGeometry(scope, insertedGeometry(asset, zUp), arena_, planes, part);
    *cut = part.geom;
  }
  // What goes out: the asset's mesh cut with its normals, texture coordinates and images.
  rt::Mesh own = rt::cga::trimAssetMesh(scope, assets_.mesh(assetMesh_[asset]), zUp, planes);
  if (own.indices.empty()) return true;  // all cut away
  if (ownGeometryAsset_ == UINT32_MAX) {  // the first cut asset of a grammar without leaves
    ownGeometryAsset_ = static_cast<uint32_t>(out_.assets.size());
    out_.assets.push_back(rt::kOwnGeometryAsset);
  }
  out_.geometries.push_back(std::move(own));  // first, as in outputLeaf
  const size_t before = out_.instances.size();
  placeInstance(ownGeometryAsset_, scope, symbol, params, paramCount, loc);
  if (out_.instances.size() == before) {
    out_.geometries.pop_back();
    return true;
  }
  rt::Instance& inst = out_.instances.back();
  inst.geometry = static_cast<uint32_t>(out_.geometries.size() - 1);
  applyAssetLook(inst, asset, scope);
  return true;
}

void Derivation::placePolygon(const std::vector<rt::Vec3>& vertices, const rt::Scope& turtle, ir::Loc loc) {
  if (vertices.size() < 3) return;  // nothing to fill
  rt::Mesh mesh;
  mesh.positions.resize(3 * vertices.size());
  for (size_t v = 0; v < vertices.size(); ++v)
    for (int d = 0; d < 3; ++d) mesh.positions[3 * v + d] = float(vertices[v][d]);
  mesh.indices.resize(3 * (vertices.size() - 2));
  for (uint32_t t = 0; t + 2 < vertices.size(); ++t)
    mesh.indices[3 * t] = 0, mesh.indices[3 * t + 1] = t + 1, mesh.indices[3 * t + 2] = t + 2;
  placeTurtleMesh(std::move(mesh), turtle, polygonSymbol_, loc);
}

void Derivation::placeTurtleMesh(rt::Mesh mesh, const rt::Scope& turtle, uint32_t symbol, ir::Loc loc) {
  mesh.computeNormals();
  // World coordinates: the instance's box is the unit box itself.
  rt::Scope box;
  box.colored = turtle.colored;
  box.color = turtle.color;
  out_.geometries.push_back(std::move(mesh));  // first, as in outputLeaf
  const size_t before = out_.instances.size();
  placeInstance(ownGeometryAsset_, box, symbol, nullptr, 0, loc);
  if (out_.instances.size() == before) return out_.geometries.pop_back();
  out_.instances.back().geometry = static_cast<uint32_t>(out_.geometries.size() - 1);
}

// Smooth terminals are bent along their march segment's curve (Buron et al. §6), known
// only now that every march has ended. (After seed plants the curves are theirs, merged.)
void Derivation::appendCurves() {
  std::vector<rt::CurveSegment> curves = marching_.curves();
  out_.curves.insert(out_.curves.end(), curves.begin(), curves.end());
}

// The surface the pattern grew on is part of the output, in a neutral grey.
void Derivation::appendSurface() {
  if (!surface_) return;
  out_.symbols.push_back("surface");
  rt::placeGenerated(assets_, out_, "<surface>", surface_->surfaceMesh(),
                     static_cast<uint32_t>(out_.symbols.size() - 1), {0.72f, 0.72f, 0.7f});
}

// Puts the instances placed while direct shapes were derived into the interpreter's
// order: by the placing shape's depth, then preorder (breadth-first), or by preorder
// alone (depth-first); a stable sort keeps each successor's own order.
void Derivation::orderDirectInstances() {
  if (!orderedDirect_ || placedBy_.size() != out_.instances.size()) return;
  const bool breadthFirst = m_.mode == ir::DeriveMode::BreadthFirst;
  auto before = [breadthFirst](const PlacingShape& x, const PlacingShape& y) {
    if (breadthFirst && x.depth != y.depth) return x.depth < y.depth;
    return x.preorder < y.preorder;
  };
  // Each start shape (a lot) is derived to its end before the next begins: the order is
  // restored within each one's instances (InstanceList::startBounds), which stay apart.
  const std::vector<uint32_t>& bounds = out_.startBounds;
  const auto sortedWithin = [&](uint32_t begin, uint32_t end) {
    return std::is_sorted(placedBy_.begin() + begin, placedBy_.begin() + end, before);
  };
  bool sorted = true;
  for (size_t k = 0; k + 1 < bounds.size(); ++k) sorted = sorted && sortedWithin(bounds[k], bounds[k + 1]);
  if (bounds.size() < 2) sorted = sortedWithin(0, uint32_t(placedBy_.size()));
  // Often already so (depth-first, or every instance placed at one depth).
  if (sorted) {
    placedBy_.clear();
    return;
  }
  std::vector<uint32_t> order(out_.instances.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  if (bounds.size() < 2) {
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return before(placedBy_[a], placedBy_[b]); });
  } else {
    for (size_t k = 0; k + 1 < bounds.size(); ++k)
      std::stable_sort(order.begin() + bounds[k], order.begin() + bounds[k + 1],
                       [&](uint32_t a, uint32_t b) { return before(placedBy_[a], placedBy_[b]); });
  }
  rt::MeshArray<rt::Instance> instances;
  std::vector<double> params;
  std::vector<rt::InstanceOrigin> origins;
  std::vector<uint32_t> finishIndex;
  instances.reserve(order.size());
  params.reserve(out_.params.size());
  for (uint32_t i : order) {
    rt::Instance inst = out_.instances[i];
    const uint32_t first = inst.firstParam;
    inst.firstParam = static_cast<uint32_t>(params.size());
    params.insert(params.end(), out_.params.begin() + first, out_.params.begin() + first + inst.paramCount);
    instances.push_back(inst);
    if (i < out_.origins.size()) origins.push_back(out_.origins[i]);
    if (!out_.finishIndex.empty()) finishIndex.push_back(i < out_.finishIndex.size() ? out_.finishIndex[i] : 0);
  }
  out_.instances = std::move(instances);
  out_.params = std::move(params);
  out_.origins = std::move(origins);
  out_.finishIndex = std::move(finishIndex);
  placedBy_.clear();
}

}  // namespace fgsg::backend
