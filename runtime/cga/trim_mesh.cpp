#include "runtime/cga/trim_mesh.h"

#include "runtime/cga/polygon_clip.h"

#include <algorithm>
#include <cmath>

namespace fgsg::rt::cga {

namespace {

// A face corner: its point in the scope's normalised coordinates and where its attributes
// (normal x y z, then u v of set 0 if the asset has it, then u v of each uv set) start in
// the cut's attribute pool.
struct TrimMeshCorner {
  Vec3 u;
  size_t attrs = 0;
};

struct TrimMeshFace {
  std::vector<TrimMeshCorner> corners;
  int32_t image = -1;  // into the asset's textures, -1: none
};

// The world distance of a normalised point to a plane (positive: cut off), as trimGeometry
// measures it.
struct TrimMeshPlane {
  Vec3 along;
  double offset;
  double at(const Vec3& u) const { return along.dot(u) + offset; }
};

class TrimMeshCut {
 public:
  TrimMeshCut(const Scope& scope, size_t attrCount) : scope_(scope), n_(attrCount) {}

  size_t addAttrs(const double* values) {
    const size_t at = pool_.size();
    pool_.insert(pool_.end(), values, values + n_);
    return at;
  }
  const double* attrs(size_t at) const { return pool_.data() + at; }
  size_t attrCount() const { return n_; }

  // A corner on the edge a -> b where the plane crosses it: everything interpolated.
  TrimMeshCorner between(const TrimMeshCorner& a, const TrimMeshCorner& b, double t) {
    scratch_.resize(n_);
    for (size_t k = 0; k < n_; ++k) scratch_[k] = pool_[a.attrs + k] + (pool_[b.attrs + k] - pool_[a.attrs + k]) * t;
    return {a.u + (b.u - a.u) * t, addAttrs(scratch_.data())};
  }

  // A corner as it is, but with `normal` (a cap's).
  TrimMeshCorner withNormal(const TrimMeshCorner& c, const Vec3& normal) {
    scratch_.assign(pool_.begin() + std::ptrdiff_t(c.attrs), pool_.begin() + std::ptrdiff_t(c.attrs + n_));
    scratch_[0] = normal.x(), scratch_[1] = normal.y(), scratch_[2] = normal.z();
    return {c.u, addAttrs(scratch_.data())};
  }

  Vec3 world(const Vec3& u) const { return scope_.axes * scope_.S.cwiseProduct(u); }

  double worldArea(const TrimMeshFace& f) const {
    std::vector<Vec3> pts;
    for (const TrimMeshCorner& c : f.corners) pts.push_back(world(c.u));
    return 0.5 * newellNormal(pts.data(), pts.size()).norm();
  }

 private:
  const Scope& scope_;
  size_t n_;
  std::vector<double> pool_, scratch_;
};

// Sutherland-Hodgman: the part of `face` where d <= tol (points on the plane kept).
TrimMeshFace trimMeshClip(const TrimMeshFace& face, const TrimMeshPlane& plane, double tol, TrimMeshCut& cut) {
  TrimMeshFace out;
  out.image = face.image;
  const size_t n = face.corners.size();
  for (size_t i = 0; i < n; ++i) {
    const TrimMeshCorner& a = face.corners[i];
    const TrimMeshCorner& b = face.corners[(i + 1) % n];
    const double da = plane.at(a.u), db = plane.at(b.u);
    if (da <= tol) out.corners.push_back(a);
    if ((da < -tol && db > tol) || (da > tol && db < -tol)) out.corners.push_back(cut.between(a, b, da / (da - db)));
  }
  return out;
}

// The caps of a closed mesh cut by `plane`, as trimGeometry's: the kept faces' edges on the
// plane that no two faces share, reversed and chained into loops. False when they do not
// close (the mesh is left open there).
bool trimMeshCaps(const std::vector<TrimMeshFace>& kept, const TrimMeshPlane& plane, double tol, TrimMeshCut& cut,
                  std::vector<TrimMeshFace>& caps) {
  struct Segment {
    TrimMeshCorner a, b;  // a: the face's corner at the edge's end (the cap walks it back)
    int32_t image;
    bool used = false;
  };
  std::vector<Segment> segments;
  auto same = [&](const Vec3& p, const Vec3& q) { return (cut.world(p) - cut.world(q)).norm() <= tol; };
  for (const TrimMeshFace& face : kept)
    for (size_t i = 0; i < face.corners.size(); ++i) {
      const TrimMeshCorner& a = face.corners[i];
      const TrimMeshCorner& b = face.corners[(i + 1) % face.corners.size()];
      if (std::abs(plane.at(a.u)) > tol || std::abs(plane.at(b.u)) > tol || same(a.u, b.u)) continue;
      auto twin = std::find_if(segments.begin(), segments.end(),
                               [&](const Segment& s) { return !s.used && same(s.a.u, a.u) && same(s.b.u, b.u); });
      if (twin != segments.end()) {
        twin->used = true;
        continue;
      }
      segments.push_back({b, a, face.image});
    }
  segments.erase(std::remove_if(segments.begin(), segments.end(), [](const Segment& s) { return s.used; }),
                 segments.end());
  for (size_t start = 0; start < segments.size(); ++start) {
    if (segments[start].used) continue;
    TrimMeshFace loop;
    loop.image = segments[start].image;
    loop.corners.push_back(segments[start].a);
    segments[start].used = true;
    Vec3 end = segments[start].b.u;
    while (!same(end, loop.corners.front().u)) {
      auto next = std::find_if(segments.begin(), segments.end(),
                               [&](const Segment& s) { return !s.used && same(s.a.u, end); });
      if (next == segments.end()) return false;
      next->used = true;
      loop.corners.push_back(next->a);
      end = next->b.u;
    }
    if (loop.corners.size() < 3 || cut.worldArea(loop) <= kMinArea) continue;
    std::vector<Vec3> pts;
    for (const TrimMeshCorner& c : loop.corners) pts.push_back(c.u);
    const Vec3 normal = newellNormal(pts.data(), pts.size()).normalized();
    for (TrimMeshCorner& c : loop.corners) c = cut.withNormal(c, normal);
    caps.push_back(std::move(loop));
  }
  return true;
}

}  // namespace

Mesh trimAssetMesh(const Scope& scope, const Mesh& asset, bool zUp, const std::vector<TrimPlane>& planes) {
  // The attributes a corner carries: its normal, then the uv sets the asset has.
  const bool texcoords = asset.hasTexcoords();
  std::vector<const MeshArray<float>*> sets;
  std::vector<uint32_t> setNumbers;
  for (const MeshUvSet& s : asset.uvSets)
    if (const MeshArray<float>* coords = asset.uvSet(s.set)) sets.push_back(coords), setNumbers.push_back(s.set);
  const bool normals = asset.normals.size() == asset.positions.size();
  TrimMeshCut cut(scope, 3 + (texcoords ? 2 : 0) + 2 * sets.size());

  // Each triangle a face; a zUp asset turned (normals too) as insertTransform turns it.
  std::vector<TrimMeshFace> faces;
  faces.reserve(asset.triangleCount());
  std::vector<double> values(cut.attrCount());
  size_t run = 0;
  for (size_t t = 0; t < asset.triangleCount(); ++t) {
    while (run + 1 < asset.textureRuns.size() && asset.textureRuns[run + 1].firstTriangle <= t) ++run;
    TrimMeshFace face;
    face.image = asset.textureRuns.empty() ? -1 : asset.textureRuns[run].texture;
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = asset.indices[3 * t + size_t(k)];
      const Vec3 p(asset.positions[3 * v], asset.positions[3 * v + 1], asset.positions[3 * v + 2]);
      const Vec3 n = normals ? Vec3(asset.normals[3 * v], asset.normals[3 * v + 1], asset.normals[3 * v + 2])
                             : Vec3::Zero();
      const Vec3 tn = zUp ? Vec3(n.x(), n.z(), -n.y()) : n;
      values[0] = tn.x(), values[1] = tn.y(), values[2] = tn.z();
      size_t at = 3;
      if (texcoords) values[at++] = asset.texcoords[2 * v], values[at++] = asset.texcoords[2 * v + 1];
      for (const MeshArray<float>* s : sets) values[at++] = (*s)[2 * v], values[at++] = (*s)[2 * v + 1];
      face.corners.push_back({zUp ? Vec3(p.x(), p.z(), 1.0 - p.y()) : p, cut.addAttrs(values.data())});
    }
    faces.push_back(std::move(face));
  }

  const double tol = 1e-9 * (1.0 + scope.S.norm());
  for (const TrimPlane& p : planes) {
    const TrimMeshPlane plane{scope.S.cwiseProduct(scope.axes.transpose() * p.normal), p.normal.dot(scope.P - p.point)};
    double most = -INFINITY;
    for (const TrimMeshFace& face : faces)
      for (const TrimMeshCorner& c : face.corners) most = std::max(most, plane.at(c.u));
    if (most <= tol) continue;  // all of it on the kept side
    std::vector<TrimMeshFace> kept;
    for (const TrimMeshFace& face : faces) {
      TrimMeshFace clipped = trimMeshClip(face, plane, tol, cut);
      if (clipped.corners.size() >= 3 && cut.worldArea(clipped) > kMinArea) kept.push_back(std::move(clipped));
    }
    if (!kept.empty()) {
      std::vector<TrimMeshFace> caps;
      if (trimMeshCaps(kept, plane, 100 * tol, cut, caps)) kept.insert(kept.end(), caps.begin(), caps.end());
    }
    faces = std::move(kept);
    if (faces.empty()) break;
  }

  Mesh out;
  for (const uint32_t set : setNumbers) out.uvSets.push_back({set, {}});
  std::vector<Vec3> pts;
  std::vector<uint32_t> tris;
  for (const TrimMeshFace& face : faces) {
    pts.clear();
    for (const TrimMeshCorner& c : face.corners) pts.push_back(c.u);
    tris.clear();
    earClip(pts.data(), pts.size(), tris);
    if (tris.empty()) continue;
    const Vec3 flat = newellNormal(pts.data(), pts.size()).normalized();
    if (!asset.textureRuns.empty()) out.addTextureRun(out.triangleCount(), face.image);
    const auto base = static_cast<uint32_t>(out.vertexCount());
    for (const TrimMeshCorner& c : face.corners) {
      const double* a = cut.attrs(c.attrs);
      Vec3 n(a[0], a[1], a[2]);
      n = n.norm() > 1e-12 ? n.normalized() : flat;  // an asset without normals: the face's
      out.positions.insert(out.positions.end(), {float(c.u.x()), float(c.u.y()), float(c.u.z())});
      out.normals.insert(out.normals.end(), {float(n.x()), float(n.y()), float(n.z())});
      size_t at = 3;
      if (texcoords) out.texcoords.insert(out.texcoords.end(), {float(a[at]), float(a[at + 1])}), at += 2;
      for (MeshUvSet& s : out.uvSets) s.coords.insert(s.coords.end(), {float(a[at]), float(a[at + 1])}), at += 2;
    }
    for (uint32_t i : tris) out.indices.push_back(base + i);
  }
  if (out.indices.empty()) return Mesh{};
  out.textures = asset.textures;
  return out;
}

}  // namespace fgsg::rt::cga
