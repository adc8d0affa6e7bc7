// The collision world's implementation (collision_backend.h): FCL's BVH-against-BVH
// tests under rigid transforms with a dynamic AABB tree as broad phase, whole-volume
// containment, the clearance test (FCL's BVH distance), and the centre test. Built into lib/libfgsg_fcl.so (and linked into
// executables that do not open plugins).
#include "runtime/collision/collision_backend.h"

#include "runtime/point_grid.h"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <new>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace fgsg::rt {
namespace {

using Model = fcl::BVHModel<fcl::OBBRSSd>;

// Columns of an instance's linear part that are this close to orthogonal (relative) are
// treated as rotation x scale, so the scaled mesh can be shared between instances.
constexpr double kOrthogonalityTolerance = 1e-9;
// A scale below this (relative to the largest) flattens the instance: it has no volume
// and so can neither contain nor be contained.
constexpr double kFlatScale = 1e-9;
// The ray of the inside test points in a direction no modelled edge is likely to lie in,
// so it seldom grazes an edge or vertex (which would count a crossing twice).
const Vec3 kInsideRay = Vec3(0.5773, 0.5861, 0.5684).normalized();

// An asset's triangles with coincident vertices welded (flat-shaded primitives repeat
// corners per face), and whether the welded surface is closed: every edge has two faces.
struct WeldedAsset {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
  bool closed = false;
};

WeldedAsset weld(const Mesh& mesh) {
  WeldedAsset w;
  std::map<std::array<float, 3>, int> index;
  std::vector<int> remap(mesh.vertexCount());
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    const std::array<float, 3> p{mesh.positions[3 * v], mesh.positions[3 * v + 1],
                                 mesh.positions[3 * v + 2]};
    auto [it, inserted] = index.emplace(p, static_cast<int>(w.vertices.size()));
    if (inserted) w.vertices.emplace_back(p[0], p[1], p[2]);
    remap[v] = it->second;
  }
  std::map<std::pair<int, int>, int> edgeUse;
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    std::array<int, 3> tri{remap[mesh.indices[3 * t]], remap[mesh.indices[3 * t + 1]],
                           remap[mesh.indices[3 * t + 2]]};
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
    w.triangles.push_back(tri);
    for (int k = 0; k < 3; ++k) {
      int a = tri[k], b = tri[(k + 1) % 3];
      ++edgeUse[{std::min(a, b), std::max(a, b)}];
    }
  }
  w.closed = !edgeUse.empty();
  for (const auto& [edge, uses] : edgeUse)
    if (uses != 2) w.closed = false;
  return w;
}

// An instance's mesh in the frame its rigid transform moves: the asset scaled (and
// mirrored) by the instance, with its BVH. Shared by every instance of the same asset
// and scale.
struct ScaledShape {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
  bool solid = false;  // closed with volume: may contain another instance
  std::shared_ptr<Model> bvh;
};

// The rigid part and the scale of a unit-box-to-world transform.
struct Decomposed {
  bool rigid = false;  // false: the columns are not orthogonal (a shear)
  Mat3 R = Mat3::Identity();
  Vec3 t = Vec3::Zero();
  Vec3 scale = Vec3::Ones();
};

Decomposed decompose(const Mat4& M) {
  Decomposed d;
  const Mat3 A = M.block<3, 3>(0, 0);
  d.t = M.block<3, 1>(0, 3);
  const double largest = std::max({A.col(0).norm(), A.col(1).norm(), A.col(2).norm(), 1e-300});
  for (int k = 0; k < 3; ++k) d.scale[k] = A.col(k).norm();
  // Flattened axes have no direction of their own: complete them from the others.
  std::array<bool, 3> flat{};
  int flatCount = 0;
  for (int k = 0; k < 3; ++k) {
    flat[k] = d.scale[k] < kFlatScale * largest;
    flatCount += flat[k];
    if (!flat[k]) d.R.col(k) = A.col(k) / d.scale[k];
  }
  if (flatCount >= 2) return d;  // a segment or a point: keep the world-space fallback
  for (int k = 0; k < 3; ++k)
    if (flat[k]) {
      d.R.col(k) = d.R.col((k + 1) % 3).cross(d.R.col((k + 2) % 3)).normalized();
      d.scale[k] = 0.0;
    }
  const Mat3 gram = d.R.transpose() * d.R;
  if (!gram.isApprox(Mat3::Identity(), kOrthogonalityTolerance) &&
      (gram - Mat3::Identity()).cwiseAbs().maxCoeff() > kOrthogonalityTolerance)
    return d;
  if (d.R.determinant() < 0) {  // a mirror: fold it into the scale, keep R a rotation
    d.R.col(0) = -d.R.col(0);
    d.scale[0] = -d.scale[0];
  }
  d.rigid = true;
  return d;
}

std::shared_ptr<ScaledShape> buildShape(const WeldedAsset& asset, const Mat3& linear, bool solid) {
  auto s = std::make_shared<ScaledShape>();
  s->vertices.reserve(asset.vertices.size());
  for (const Vec3& v : asset.vertices) s->vertices.push_back(linear * v);
  s->triangles = asset.triangles;
  s->solid = solid;
  std::vector<fcl::Triangle> tris;
  tris.reserve(s->triangles.size());
  for (const auto& t : s->triangles) tris.emplace_back(t[0], t[1], t[2]);
  s->bvh = std::make_shared<Model>();
  // FCL reports a failed allocation by a return code (and a line on stderr), not an
  // exception; an unchecked one leaves a half-built tree that crashes the first query.
  const auto check = [](int status) {
    if (status == fcl::BVH_ERR_MODEL_OUT_OF_MEMORY) throw std::bad_alloc();
    if (status != fcl::BVH_OK) throw std::runtime_error("FCL could not build a collision tree (status " +
                                                        std::to_string(status) + ")");
  };
  check(s->bvh->beginModel(static_cast<int>(tris.size()), static_cast<int>(s->vertices.size())));
  check(s->bvh->addSubModel(s->vertices, tris));
  check(s->bvh->endModel());
  return s;
}

// Even-odd ray test: is `p` (in the shape's frame) inside the closed shape?
bool inside(const ScaledShape& s, const Vec3& p) {
  int crossings = 0;
  for (const auto& tri : s.triangles) {
    const Vec3& a = s.vertices[tri[0]];
    const Vec3 e1 = s.vertices[tri[1]] - a, e2 = s.vertices[tri[2]] - a;
    const Vec3 h = kInsideRay.cross(e2);
    const double det = e1.dot(h);
    if (std::abs(det) < 1e-300) continue;
    const Vec3 q = p - a;
    const double u = q.dot(h) / det;
    if (u < 0 || u > 1) continue;
    const Vec3 r = q.cross(e1);
    const double v = kInsideRay.dot(r) / det;
    if (v < 0 || u + v > 1) continue;
    if (e2.dot(r) / det > 0) ++crossings;
  }
  return crossings % 2 == 1;
}

struct Obstacle {
  int mesh = 0;
  std::shared_ptr<ScaledShape> shape;
  std::unique_ptr<fcl::CollisionObjectd> object;  // Mesh and Distance tests
  Vec3 centre;
};

class FclCollisionWorld final : public CollisionBackend {
 public:
  const AssetLibrary& assets;
  CollisionTest test;
  double radius;
  std::unordered_map<int, WeldedAsset> welded;
  // Scaled shapes by asset and exact scale bits: a pattern reuses a handful of sizes.
  std::map<std::tuple<int, uint64_t, uint64_t, uint64_t>, std::shared_ptr<ScaledShape>> shapes;
  std::vector<Obstacle> obstacles;
  fcl::DynamicAABBTreeCollisionManagerd broadPhase;
  PointGrid centres;  // Centre test only: ids as in `obstacles`
  mutable std::vector<uint32_t> nearby;
  uint64_t narrowTests = 0;

  FclCollisionWorld(const AssetLibrary& a, CollisionTest t, double r) : assets(a), test(t), radius(r) {
    if (test == CollisionTest::Centre) centres.reserveRadius(radius);
  }

  const WeldedAsset& weldedAsset(int mesh) {
    auto it = welded.find(mesh);
    if (it == welded.end()) it = welded.emplace(mesh, weld(assets.mesh(mesh))).first;
    return it->second;
  }

  static uint64_t bits(double x) {
    uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
  }

  // The instance as an FCL object (its shape possibly shared with earlier instances).
  Obstacle makeObstacle(int mesh, const Mat4& M) {
    Obstacle o;
    o.mesh = mesh;
    o.centre = instanceCentre(M);
    if (test == CollisionTest::Centre) return o;
    const WeldedAsset& asset = weldedAsset(mesh);
    const Decomposed d = decompose(M);
    fcl::Transform3d pose = fcl::Transform3d::Identity();
    if (d.rigid) {
      const bool solid = asset.closed && (d.scale.cwiseAbs().array() > 0).all();
      auto key = std::make_tuple(mesh, bits(d.scale[0]), bits(d.scale[1]), bits(d.scale[2]));
      auto& shared = shapes[key];
      if (!shared) shared = buildShape(asset, Mat3(d.scale.asDiagonal()), solid);
      o.shape = shared;
      pose.linear() = d.R;
      pose.translation() = d.t;
    } else {  // sheared: this instance gets its own mesh, in world space
      o.shape = buildShape(asset, M.block<3, 3>(0, 0), false);
      pose.translation() = M.block<3, 1>(0, 3);
    }
    o.object = std::make_unique<fcl::CollisionObjectd>(o.shape->bvh, pose);
    o.object->setUserData(o.shape.get());
    o.object->computeAABB();
    return o;
  }

  bool centreCollides(const Vec3& c, const std::function<bool(size_t)>& confirm) const {
    centres.near(c, radius, nearby);
    for (uint32_t id : nearby)
      if ((obstacles[id].centre - c).norm() < radius && (!confirm || confirm(id))) return true;
    return false;
  }

  // Whether one of two instances whose surfaces do not cross encloses the other.
  static bool enclosed(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b) {
    auto encloses = [](fcl::CollisionObjectd* outer, fcl::CollisionObjectd* inner) {
      const auto* o = static_cast<const ScaledShape*>(outer->getUserData());
      const auto* i = static_cast<const ScaledShape*>(inner->getUserData());
      if (!o->solid || i->vertices.empty()) return false;
      const Vec3 world = inner->getTransform() * i->vertices.front();
      return inside(*o, outer->getTransform().inverse() * world);
    };
    return encloses(a, b) || encloses(b, a);
  }

  // Exact test of one candidate pair whose bounding boxes overlap.
  bool meshesCollide(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b) {
    ++narrowTests;
    fcl::CollisionRequestd request(1, false);
    fcl::CollisionResultd result;
    fcl::collide(a, b, request, result);
    return result.isCollision() || enclosed(a, b);
  }

  // The clearance test of one candidate pair whose boxes are closer than `radius`: the
  // least distance between the two triangle meshes (0, or below, where they cross).
  bool meshesCloser(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b) {
    ++narrowTests;
    fcl::DistanceRequestd request;
    request.enable_nearest_points = false;
    fcl::DistanceResultd result;
    fcl::distance(a, b, request, result);
    return result.min_distance < radius || enclosed(a, b);
  }

  // The broad phase calls this for every obstacle whose box overlaps the query's.
  struct Query {
    FclCollisionWorld* world;
    bool hit = false;
  };
  static bool onCandidate(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b, void* data) {
    auto* q = static_cast<Query*>(data);
    q->hit = q->world->meshesCollide(a, b);
    return q->hit;  // true stops the broad phase
  }
  // The broad phase's distance walk visits obstacles whose boxes are closer to the
  // query's than `dist`; holding it at the clearance visits exactly the candidates.
  static bool onDistanceCandidate(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b, void* data, double& dist) {
    auto* q = static_cast<Query*>(data);
    q->hit = q->world->meshesCloser(a, b);
    dist = q->world->radius;
    return q->hit;
  }

  bool collides(int mesh, const Mat4& unitBoxToWorld, const std::function<bool(size_t)>& confirm) override {
    if (obstacles.empty()) return false;
    Obstacle query = makeObstacle(mesh, unitBoxToWorld);
    if (test == CollisionTest::Centre) return centreCollides(query.centre, confirm);
    Query state{this};
    if (test == CollisionTest::Distance)
      broadPhase.distance(query.object.get(), &state, onDistanceCandidate);
    else
      broadPhase.collide(query.object.get(), &state, onCandidate);
    return state.hit;
  }

  size_t add(int mesh, const Mat4& unitBoxToWorld) override {
    Obstacle o = makeObstacle(mesh, unitBoxToWorld);
    const size_t id = obstacles.size();
    if (test == CollisionTest::Centre) {
      centres.add(o.centre);
    } else {
      broadPhase.registerObject(o.object.get());
    }
    obstacles.push_back(std::move(o));
    return id;
  }

  void move(size_t id, const Mat4& unitBoxToWorld) override {
    Obstacle& old = obstacles[id];
    Obstacle moved = makeObstacle(old.mesh, unitBoxToWorld);
    if (test == CollisionTest::Centre) {
      centres.move(static_cast<uint32_t>(id), moved.centre);
    } else {
      broadPhase.unregisterObject(old.object.get());
      broadPhase.registerObject(moved.object.get());
    }
    old = std::move(moved);
  }

  void rollback(size_t mark) override {
    while (obstacles.size() > mark) {
      Obstacle& o = obstacles.back();
      if (test == CollisionTest::Centre) {
        centres.removeLast();
      } else {
        broadPhase.unregisterObject(o.object.get());
      }
      obstacles.pop_back();
    }
  }

  size_t size() const override { return obstacles.size(); }
  uint64_t narrowPhaseTests() const override { return narrowTests; }
};

const CollisionPlugin kPlugin{
    kCollisionPluginVersion,
    [](const AssetLibrary& assets, CollisionTest test, double radius) -> std::unique_ptr<CollisionBackend> {
      return std::make_unique<FclCollisionWorld>(assets, test, radius);
    },
};

}  // namespace
}  // namespace fgsg::rt

extern "C" __attribute__((visibility("default"))) const fgsg::rt::CollisionPlugin* fgsg_fcl_plugin() {
  return &fgsg::rt::kPlugin;
}
