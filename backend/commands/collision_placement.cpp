#include "backend/commands/collision_placement.h"

#include "runtime/marching/smooth_curves.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fgsg::backend {
namespace {

rt::CollisionTest testFor(const ir::CollisionSettings& s) {
  switch (s.metric) {
    case ir::CollisionMetric::Mesh: return rt::CollisionTest::Mesh;
    case ir::CollisionMetric::Distance: return rt::CollisionTest::Distance;
    // The geodesic test is the centre test with the geodesic distance having the last
    // word (CollisionWorld::collides' `confirm`; on the plane the two are the same).
    case ir::CollisionMetric::Centre:
    case ir::CollisionMetric::Geodesic: break;
  }
  return rt::CollisionTest::Centre;
}

rt::Mat4 transformOf(const rt::Instance& inst) {
  return Eigen::Map<const rt::Mat4>(inst.transform.data());
}

}  // namespace

CollisionPlacement::CollisionPlacement(rt::AssetLibrary& assets, rt::InstanceList& out,
                                       const ir::CollisionSettings& settings)
    : assets_(assets), out_(out), world_(assets, testFor(settings), settings.radius),
      radius_(settings.radius) {}

int CollisionPlacement::mesh(uint32_t asset) {
  if (asset >= meshOf_.size()) meshOf_.resize(asset + 1, -1);
  if (meshOf_[asset] < 0) {
    std::string error;
    meshOf_[asset] = assets_.resolve(out_.assets[asset], error);
    // Every asset is resolved before deriving; one that fails here is a bug.
    if (meshOf_[asset] < 0) throw std::logic_error("collision test of an unresolved asset: " + error);
  }
  return meshOf_[asset];
}

void CollisionPlacement::setTransform(rt::Instance& inst, const rt::Mat4& m) {
  for (int k = 0; k < 16; ++k) inst.transform[k] = m.data()[k];
}

bool CollisionPlacement::fits(uint32_t asset, const rt::Mat4& transform, const rt::Scope& scope) {
  if (!alongSurface_) return !world_.collides(mesh(asset), transform);
  return !world_.collides(mesh(asset), transform, [&](size_t obstacle) {
    return alongSurface_(scope, placedFrom_[obstacle], radius_) < radius_;
  });
}

void CollisionPlacement::placed(const rt::Scope& scope) {
  const rt::Instance& inst = out_.instances.back();
  if (out_.assets[inst.asset] == rt::kOwnGeometryAsset) {
    // A shape's own geometry (a CGA leaf, a turtle polygon) is an obstacle like any
    // asset: its mesh, out_.geometries.back() (Derivation::outputLeaf, placePolygon),
    // is one of a kind, registered in world coordinates.
    rt::Mesh world = out_.geometries.back();
    const rt::Mat4 t = transformOf(inst);
    for (size_t v = 0; v < world.vertexCount(); ++v) {
      float* p = &world.positions[3 * v];
      const rt::Vec3 q = (t * Eigen::Vector4d(p[0], p[1], p[2], 1.0)).head<3>();
      for (int d = 0; d < 3; ++d) p[d] = float(q[d]);
    }
    if (world.normals.size() != world.positions.size()) world.computeNormals();
    std::array<double, 16> unitBoxToWorld;
    const int id = assets_.addGenerated(std::string(rt::kOwnGeometryAsset) + " " + std::to_string(out_.instances.size()),
                                        world, unitBoxToWorld);
    world_.add(id, Eigen::Map<const rt::Mat4>(unitBoxToWorld.data()));
  } else {
    world_.add(mesh(inst.asset), transformOf(inst));
  }
  if (alongSurface_) placedFrom_.push_back(scope);  // only geodesic distances read it
}

bool CollisionPlacement::mergeInto(uint32_t asset, const rt::Mat4& transform, double maxDist,
                                   double maxAngle, const rt::Scope& scope) {
  rt::MergeIndex::Merge merge;
  rt::MergeIndex::Distance alongSurface;
  if (alongSurface_)
    alongSurface = [&](uint32_t slot, double) {
      // Asked to stop just past maxDist: a value at the limit means farther than maxDist.
      return alongSurface_(scope, mergeableFrom_[slot], std::nextafter(maxDist, HUGE_VAL));
    };
  if (!merges_.find(asset, transform, maxDist, maxAngle, merge, alongSurface)) return false;
  merges_.apply(merge);
  setTransform(out_.instances[merge.target], merge.transform);
  world_.move(merge.target, merge.transform);
  return true;
}

void CollisionPlacement::placedMergeable(uint32_t asset, const rt::Mat4& transform, const rt::Scope& scope) {
  merges_.add(asset, out_.instances.size() - 1, transform);
  if (alongSurface_) mergeableFrom_.push_back(scope);
}

CollisionPlacement::Transaction CollisionPlacement::begin(const rt::LineNetwork& lines) const {
  return {out_.instances.size(), out_.params.size(), world_.mark(), merges_.mark(), lines.mark()};
}

void CollisionPlacement::rollback(const Transaction& t, rt::LineNetwork& lines) {
  // Merges first: they may have moved instances older than the transaction back.
  for (const auto& [target, before] : merges_.rollback(t.merges)) {
    if (target >= t.instances) continue;  // removed below anyway
    setTransform(out_.instances[target], before);
    world_.move(target, before);
  }
  world_.rollback(t.obstacles);
  if (alongSurface_) placedFrom_.resize(t.obstacles), mergeableFrom_.resize(merges_.size());
  out_.instances.resize(t.instances);
  if (out_.origins.size() > t.instances) out_.origins.resize(t.instances);
  if (out_.finishIndex.size() > t.instances) out_.finishIndex.resize(t.instances);
  out_.params.resize(t.params);
  lines.rollback(t.lines);
}

namespace {

// A line drawn with an asset: one instance per segment, its unit box's X along the
// segment's chord, Y and Z across it `width` wide (Z along the normal), bent along the
// segment's smooth curve (Instance::curve).
void placeAlongLine(const std::vector<rt::Vec3>& points, const rt::LineStyle& style, uint32_t symbol,
                    const std::array<float, 3>& colour, rt::InstanceList& out,
                    const std::function<rt::Vec3(const rt::Vec3&)>& normalAt) {
  std::vector<rt::marching::MarchNode> nodes;
  std::vector<rt::marching::MarchSegment> segments;
  for (uint32_t k = 0; k < points.size(); ++k) {
    nodes.push_back({points[k], normalAt(points[k])});
    if (k > 0) segments.push_back({k - 1, k});
  }
  const uint32_t first = static_cast<uint32_t>(out.curves.size());
  const std::vector<rt::CurveSegment> curves = rt::marching::smoothSegments(nodes, segments);
  out.curves.insert(out.curves.end(), curves.begin(), curves.end());
  const double w = style.width;
  for (uint32_t k = 0; k < segments.size(); ++k) {
    const rt::Vec3 chord = points[k + 1] - points[k];
    const double length = chord.norm();
    if (!(length > 0)) continue;
    const rt::Vec3 x = chord / length;
    rt::Vec3 z = nodes[k].normal - nodes[k].normal.dot(x) * x;
    if (!(z.norm() > 1e-9)) z = x.unitOrthogonal();
    z.normalize();
    const rt::Vec3 y = z.cross(x);
    rt::Scope scope;
    scope.axes << x, y, z;
    scope.S = rt::Vec3(length, w, w);
    scope.P = points[k] - 0.5 * w * (y + z);
    const rt::Mat4 m = scope.unitBoxToWorld();
    rt::Instance& inst = out.instances.emplace_back();
    inst.asset = style.asset;
    inst.symbol = symbol;
    std::copy(m.data(), m.data() + 16, inst.transform.begin());
    inst.color = colour;
    inst.firstParam = static_cast<uint32_t>(out.params.size());
    inst.curve = first + k;
  }
}

}  // namespace

void appendLineTubes(const rt::LineNetwork& lines, rt::AssetLibrary& assets, rt::InstanceList& out,
                     const std::vector<std::array<float, 3>>& symbolColor,
                     const std::function<rt::Vec3(const rt::Vec3&)>& normalAt) {
  for (uint32_t c = 0; c < lines.chainCount(); ++c) {
    if (lines.points(c).size() < 2) continue;
    rt::LinePath& path = out.lines.emplace_back();
    for (const rt::Vec3& p : lines.points(c)) path.points.push_back({p.x(), p.y(), p.z()});
    path.width = lines.style(c).width;
    path.merge = lines.style(c).merge;
    path.symbol = lines.owner(c);
    if (lines.style(c).asset != UINT32_MAX) {
      placeAlongLine(lines.points(c), lines.style(c), lines.owner(c), symbolColor[lines.owner(c)], out, normalAt);
      continue;
    }
    const rt::Mesh tube = lines.sweep(c);
    if (tube.empty()) continue;
    rt::placeGenerated(assets, out, "<line " + std::to_string(c) + ">", tube, lines.owner(c),
                       symbolColor[lines.owner(c)]);
  }
}

}  // namespace fgsg::backend
