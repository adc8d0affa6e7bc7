#include "runtime/evolve/polycube_map.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace fgsg::rt::evolve {

namespace {

constexpr int kPadding = 2;          // empty cells around the mesh's bounding box
constexpr double kTouchSlack = 1e-4;  // cells: a surface this close to a cell touches it
constexpr int kMaxWalk = 16;          // triangles visited refining one hit

using Vec3i = Eigen::Vector3i;

// Does the triangle (a, b, c) overlap the closed axis-aligned cube of half-size h centred
// at the origin? Separating-axis test over the cube's axes, the triangle's normal and the
// nine edge-axis cross products.
bool triangleTouchesCube(const Vec3& a, const Vec3& b, const Vec3& c, double h) {
  const auto separated = [&](const Vec3& axis) {
    const double pa = axis.dot(a), pb = axis.dot(b), pc = axis.dot(c);
    const double r = h * axis.cwiseAbs().sum();
    return std::min({pa, pb, pc}) > r || std::max({pa, pb, pc}) < -r;
  };
  for (int k = 0; k < 3; ++k)
    if (separated(Vec3::Unit(k))) return false;
  const Vec3 e[3] = {b - a, c - b, a - c};
  if (separated(e[0].cross(e[1]))) return false;
  for (const Vec3& edge : e)
    for (int k = 0; k < 3; ++k)
      if (separated(edge.cross(Vec3::Unit(k)))) return false;
  return true;
}

// The point of triangle (a, b, c) nearest p, as barycentric coordinates (Voronoi regions of
// the corners, edges and interior).
Vec3 nearestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const double denom = 1 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {1 - v - w, v, w};
}

// Barycentric coordinates clamped to the triangle (negative ones dropped, renormalised).
Vec3 clampBary(Vec3 b) {
  b = b.cwiseMax(0.0);
  const double s = b.sum();
  return s > 0 ? Vec3(b / s) : Vec3(1.0 / 3, 1.0 / 3, 1.0 / 3);
}

}  // namespace

struct PolycubeMap::Impl {
  surface::SurfaceMesh mesh;
  std::vector<Vec3> texture;  // mesh vertices in texture space (cell units)
  double cellSize = 0;
  Vec3 origin = Vec3::Zero();
  Vec3i cells = Vec3i::Zero();
  std::vector<uint8_t> solid;    // per cell, x fastest
  std::vector<uint8_t> touched;  // per cell: the surface touches it
  // (cell index, face) for every face touching a cell, sorted: the faces near a cell.
  std::vector<std::pair<size_t, int>> cellFaces;
  size_t solidCount = 0;
  bool enclosing = false;  // the fallback rule was used (no cell centre inside)
  std::vector<Facelet> facelets;
  std::vector<Vec3i> faceletOrigin;                // texture-space corner (a, b) = (0, 0)
  std::vector<std::array<Vec3, 4>> cornerDirection;  // d at (0,0), (1,0), (0,1), (1,1)
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  mutable std::atomic<size_t> fallbacks{0};

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  size_t index(int x, int y, int z) const {
    return (size_t(z) * cells.y() + y) * cells.x() + x;
  }
  bool inside(const Vec3i& c) const {
    return (c.array() >= 0).all() && (c.array() < cells.array()).all();
  }
  bool isSolid(const Vec3i& c) const { return inside(c) && solid[index(c.x(), c.y(), c.z())]; }

  void chooseGrid(const PolycubeOptions& o);
  void markTouchedCells();
  void chooseSolid();
  bool centreInside(const Vec3i& c) const;
  void regularise();
  Vec3 vertexDirection(const Vec3i& v) const;
  bool regularAt(const Vec3i& v, Vec3i& lo, Vec3i& hi) const;
  void collectFacelets(size_t maxFacelets);
  void buildScene();
  bool refineHit(int face, const Vec3& p, const Vec3& d, int& outFace, Vec3& outBary) const;
  bool castLine(const Vec3& p, const Vec3& d, int& outFace, Vec3& outBary) const;
  void nearest(const Vec3& p, int& outFace, Vec3& outBary) const;
};

void PolycubeMap::Impl::chooseGrid(const PolycubeOptions& o) {
  Vec3 lo = mesh.vertices[0], hi = mesh.vertices[0];
  for (const Vec3& p : mesh.vertices) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double extent = (hi - lo).maxCoeff();
  if (!std::isfinite(extent)) throw std::invalid_argument("polycube map: the mesh has non-finite coordinates");
  if (!(extent > 0)) throw std::invalid_argument("polycube map: the mesh has no extent (all vertices coincide)");
  if (o.cellSize == 0) {
    cellSize = extent / o.resolution;
  } else {
    if (!(o.cellSize > 0) || !std::isfinite(o.cellSize))
      throw std::invalid_argument("polycube map: cellSize must be finite and > 0 (or 0 to use the resolution), got " +
                                  std::to_string(o.cellSize));
    if (std::ceil(extent / o.cellSize) > kMaxPolycubeResolution)
      throw std::invalid_argument("polycube map: cellSize " + std::to_string(o.cellSize) + " makes " +
                                  std::to_string(std::ceil(extent / o.cellSize)) +
                                  " cells along the largest extent, at most " +
                                  std::to_string(kMaxPolycubeResolution) + " are allowed");
    cellSize = o.cellSize;
  }
  origin = lo - Vec3::Constant(kPadding * cellSize);
  for (int k = 0; k < 3; ++k)
    cells[k] = int(std::ceil((hi[k] - lo[k]) / cellSize)) + 2 * kPadding;
  texture.resize(mesh.vertices.size());
  for (size_t i = 0; i < texture.size(); ++i) texture[i] = (mesh.vertices[i] - origin) / cellSize;
  solid.assign(size_t(cells.x()) * cells.y() * cells.z(), 0);
  touched.assign(solid.size(), 0);
}

void PolycubeMap::Impl::markTouchedCells() {
  for (size_t fi = 0; fi < mesh.faces.size(); ++fi) {
    const auto& f = mesh.faces[fi];
    const Vec3 &a = texture[f[0]], &b = texture[f[1]], &c = texture[f[2]];
    const Vec3 lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
    Vec3i from, to;
    for (int k = 0; k < 3; ++k) {
      from[k] = std::max(0, int(std::floor(lo[k] - kTouchSlack)));
      to[k] = std::min(cells[k] - 1, int(std::floor(hi[k] + kTouchSlack)));
    }
    for (int z = from.z(); z <= to.z(); ++z)
      for (int y = from.y(); y <= to.y(); ++y)
        for (int x = from.x(); x <= to.x(); ++x) {
          const Vec3 centre(x + 0.5, y + 0.5, z + 0.5);
          if (!triangleTouchesCube(a - centre, b - centre, c - centre, 0.5 + kTouchSlack)) continue;
          touched[index(x, y, z)] = 1;
          cellFaces.push_back({index(x, y, z), int(fi)});
        }
  }
  std::sort(cellFaces.begin(), cellFaces.end());
}

// Is the centre of touched cell c on the inner side of the surface? The nearest surface
// point lies within half a cell diagonal, so among the faces touching the 3x3x3 cells
// around c; its side is the sign against the angle-weighted pseudo-normal of the feature
// it lies on (face, edge or vertex), which is exact for a closed mesh (Baerentzen and
// Aanaes 2005) and the nearest face's side for an open one.
bool PolycubeMap::Impl::centreInside(const Vec3i& c) const {
  const Vec3 centre = c.cast<double>() + Vec3::Constant(0.5);
  double best = std::numeric_limits<double>::infinity();
  int face = -1;
  Vec3 bary;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const Vec3i n = c + Vec3i(dx, dy, dz);
        if (!inside(n)) continue;
        const size_t i = index(n.x(), n.y(), n.z());
        auto it = std::lower_bound(cellFaces.begin(), cellFaces.end(), std::pair<size_t, int>{i, -1});
        for (; it != cellFaces.end() && it->first == i; ++it) {
          const auto& f = mesh.faces[it->second];
          const Vec3 b = nearestOnTriangle(centre, texture[f[0]], texture[f[1]], texture[f[2]]);
          const double d = (b[0] * texture[f[0]] + b[1] * texture[f[1]] + b[2] * texture[f[2]] - centre).squaredNorm();
          // Ties (a vertex or edge shared by several faces) go to the lowest face index.
          if (d < best || (d == best && it->second < face)) best = d, face = it->second, bary = b;
        }
      }
  if (face < 0) return false;
  const auto& f = mesh.faces[face];
  const Vec3 q = bary[0] * texture[f[0]] + bary[1] * texture[f[1]] + bary[2] * texture[f[2]];
  Vec3 pseudo = mesh.faceNormals[face];
  const int zeros = (bary[0] == 0) + (bary[1] == 0) + (bary[2] == 0);
  if (zeros == 2) {
    int k;
    bary.maxCoeff(&k);
    pseudo = mesh.vertexNormals[f[k]];
  } else if (zeros == 1) {
    int k;
    bary.minCoeff(&k);  // the edge opposite corner k: edge (k + 1) % 3
    const int other = mesh.neighbours[face][(k + 1) % 3];
    if (other >= 0) pseudo += mesh.faceNormals[other];
  }
  return (centre - q).dot(pseudo) <= 0;
}

// The solid: a flood fill from the grid's border (all padding) through untouched cells
// marks the outside; untouched cells it does not reach are enclosed by the surface and
// solid; touched cells are solid when their centre is inside. When that leaves nothing
// (a surface thinner than a cell everywhere), every touched or enclosed cell is solid.
void PolycubeMap::Impl::chooseSolid() {
  std::vector<uint8_t> outside(solid.size(), 0);
  std::vector<Vec3i> stack;
  const auto push = [&](const Vec3i& c) {
    if (!inside(c)) return;
    const size_t i = index(c.x(), c.y(), c.z());
    if (touched[i] || outside[i]) return;
    outside[i] = 1;
    stack.push_back(c);
  };
  push(Vec3i(0, 0, 0));  // a padding cell; the padding layer is connected, so this reaches all
  while (!stack.empty()) {
    const Vec3i c = stack.back();
    stack.pop_back();
    for (int k = 0; k < 3; ++k) {
      push(c + Vec3i::Unit(k));
      push(c - Vec3i::Unit(k));
    }
  }
  solidCount = 0;
  for (int z = 0; z < cells.z(); ++z)
    for (int y = 0; y < cells.y(); ++y)
      for (int x = 0; x < cells.x(); ++x) {
        const size_t i = index(x, y, z);
        solid[i] = touched[i] ? centreInside(Vec3i(x, y, z)) : !outside[i];
        solidCount += solid[i];
      }
  if (solidCount == 0) {
    enclosing = true;
    for (size_t i = 0; i < solid.size(); ++i) solid[i] = !outside[i], solidCount += solid[i];
  }
}

// d(v): the componentwise sign of the sum, over the solid cells around lattice vertex v, of
// the offset from v to the cell's centre (each component +-1/2, doubled to +-1 here).
Vec3 PolycubeMap::Impl::vertexDirection(const Vec3i& v) const {
  Vec3i sum = Vec3i::Zero();
  for (int o = 0; o < 8; ++o) {
    const Vec3i d((o & 1), (o >> 1) & 1, (o >> 2) & 1);
    if (isSolid(v - Vec3i::Ones() + d)) sum += 2 * d - Vec3i::Ones();
  }
  return Vec3(sum.x() > 0 ? 1 : sum.x() < 0 ? -1 : 0, sum.y() > 0 ? 1 : sum.y() < 0 ? -1 : 0,
              sum.z() > 0 ? 1 : sum.z() < 0 ? -1 : 0);
}

// Is d(v) pointing into the solid through every face-let at v (for each cell face at v
// between a solid and an empty cell, d's component along that face's axis has the solid
// side's sign)? When not, [lo, hi] receives the box (offsets 0..1 per axis) of v's solid
// cells.
bool PolycubeMap::Impl::regularAt(const Vec3i& v, Vec3i& lo, Vec3i& hi) const {
  bool any = false, all = true;
  uint8_t occ[8];
  lo = Vec3i::Constant(1), hi = Vec3i::Constant(0);
  for (int o = 0; o < 8; ++o) {
    const Vec3i d((o & 1), (o >> 1) & 1, (o >> 2) & 1);
    occ[o] = isSolid(v - Vec3i::Ones() + d);
    if (occ[o]) any = true, lo = lo.cwiseMin(d), hi = hi.cwiseMax(d);
    else all = false;
  }
  if (!any || all) return true;
  const Vec3 dir = vertexDirection(v);
  for (int o = 0; o < 8; ++o)
    for (int k = 0; k < 3; ++k) {
      const int other = o ^ (1 << k);
      if (!occ[o] || occ[other]) continue;  // not a face-let with o the solid side
      const int solidSide = (o >> k) & 1 ? 1 : -1;
      if (dir[k] != solidSide) return false;
    }
  return true;
}

void PolycubeMap::Impl::regularise() {
  for (bool changed = true; changed;) {
    changed = false;
    for (int z = 1; z < cells.z(); ++z)
      for (int y = 1; y < cells.y(); ++y)
        for (int x = 1; x < cells.x(); ++x) {
          const Vec3i v(x, y, z);
          Vec3i lo, hi;
          if (regularAt(v, lo, hi)) continue;
          for (int dz = lo.z(); dz <= hi.z(); ++dz)
            for (int dy = lo.y(); dy <= hi.y(); ++dy)
              for (int dx = lo.x(); dx <= hi.x(); ++dx) {
                uint8_t& s = solid[index(x - 1 + dx, y - 1 + dy, z - 1 + dz)];
                if (!s) s = 1, ++solidCount, changed = true;
              }
        }
  }
}

void PolycubeMap::Impl::collectFacelets(size_t maxFacelets) {
  for (int z = 0; z < cells.z(); ++z)
    for (int y = 0; y < cells.y(); ++y)
      for (int x = 0; x < cells.x(); ++x) {
        const Vec3i c(x, y, z);
        if (!solid[index(x, y, z)]) continue;
        for (int axis = 0; axis < 3; ++axis)
          for (int sign : {-1, 1}) {
            if (isSolid(c + sign * Vec3i::Unit(axis))) continue;
            if (facelets.size() == maxFacelets)
              throw std::invalid_argument("polycube map: more than " + std::to_string(maxFacelets) +
                                          " face-lets (maxFacelets); lower the resolution");
            const int ua = sign > 0 ? (axis + 1) % 3 : (axis + 2) % 3;
            const int va = sign > 0 ? (axis + 2) % 3 : (axis + 1) % 3;
            const Vec3i o = sign > 0 ? Vec3i(c + Vec3i::Unit(axis)) : c;
            Facelet f;
            f.cell = {x, y, z};
            f.axis = axis;
            f.sign = sign;
            f.origin = origin + cellSize * o.cast<double>();
            f.u = cellSize * Vec3::Unit(ua);
            f.v = cellSize * Vec3::Unit(va);
            f.normal = sign * Vec3::Unit(axis);
            facelets.push_back(f);
            faceletOrigin.push_back(o);
            const Vec3i U = Vec3i::Unit(ua), V = Vec3i::Unit(va);
            cornerDirection.push_back({vertexDirection(o), vertexDirection(o + U), vertexDirection(o + V),
                                       vertexDirection(o + U + V)});
          }
      }
}

void PolycubeMap::Impl::buildScene() {
  device = rtcNewDevice(nullptr);
  if (!device) throw std::runtime_error("polycube map: Embree device could not be created");
  scene = rtcNewScene(device);
  // Robust traversal: no ray slips through the shared edge of two triangles.
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                        3 * sizeof(float), texture.size()));
  for (size_t i = 0; i < texture.size(); ++i)
    for (int k = 0; k < 3; ++k) v[3 * i + k] = float(texture[i][k]);
  auto* idx = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                             3 * sizeof(uint32_t), mesh.faces.size()));
  for (size_t f = 0; f < mesh.faces.size(); ++f)
    for (int k = 0; k < 3; ++k) idx[3 * f + k] = uint32_t(mesh.faces[f][k]);
  rtcCommitGeometry(geom);
  rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(scene);
}

// The ray p + t d (t >= 0) against the plane of `face` in double precision; while the
// intersection lies outside the triangle, step across the edge it lies beyond. False when
// the ray is parallel to the plane or meets it behind p (keep Embree's face then).
bool PolycubeMap::Impl::refineHit(int face, const Vec3& p, const Vec3& d, int& outFace, Vec3& outBary) const {
  int previous = -1;
  for (int step = 0; step < kMaxWalk; ++step) {
    const auto& f = mesh.faces[face];
    const Vec3 &a = texture[f[0]], &b = texture[f[1]], &c = texture[f[2]];
    const Vec3 n = (b - a).cross(c - a);
    const double nd = n.dot(d);
    if (std::abs(nd) <= 1e-300) return false;
    const double t = n.dot(a - p) / nd;
    if (!(t >= 0)) return false;
    const Vec3 x = p + t * d;
    const double nn = n.squaredNorm();
    const Vec3 bary(n.dot((b - x).cross(c - x)) / nn, n.dot((c - x).cross(a - x)) / nn,
                    n.dot((a - x).cross(b - x)) / nn);
    outFace = face;
    outBary = clampBary(bary);
    int worst;
    if (bary.minCoeff(&worst) >= -1e-12) return true;
    // Beyond the edge opposite corner `worst`: edge (worst + 1) % 3 in neighbours' numbering.
    const int next = mesh.neighbours[face][(worst + 1) % 3];
    if (next < 0 || next == previous) return true;  // the clamped point on this face
    previous = face;
    face = next;
  }
  return true;
}

// The surface point nearest p on the line p + t d, either side (t of either sign): forward
// first, then backward no farther than the forward hit.
bool PolycubeMap::Impl::castLine(const Vec3& p, const Vec3& d, int& outFace, Vec3& outBary) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  int face = -1;
  Vec3 dir = d, bary;
  float tfar = std::numeric_limits<float>::infinity();
  for (const double sign : {1.0, -1.0}) {
    RTCRayHit rh{};
    rh.ray.org_x = float(p.x()), rh.ray.org_y = float(p.y()), rh.ray.org_z = float(p.z());
    rh.ray.dir_x = float(sign * d.x()), rh.ray.dir_y = float(sign * d.y()), rh.ray.dir_z = float(sign * d.z());
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = tfar;
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &ctx, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
    face = int(rh.hit.primID);
    bary = Vec3(1 - rh.hit.u - rh.hit.v, rh.hit.u, rh.hit.v);  // Embree's u, v weight corners 1, 2
    dir = sign * d;
    tfar = rh.ray.tfar;
  }
  if (face < 0) return false;
  if (!refineHit(face, p, dir, outFace, outBary)) outFace = face, outBary = clampBary(bary);
  return true;
}

namespace {

// Embree's point query visits the faces whose (float) bounds are within the radius; each
// is measured in double and the radius shrinks to the best so far, kept a little wider so
// that rounding in the bounds never hides a face as near. Ties go to the lower face index:
// the same face on every run and thread, whatever order the tree is walked in.
struct NearestQuery {
  const std::vector<Vec3>* texture;
  const std::vector<std::array<int, 3>>* faces;
  Vec3 p;
  int face = -1;
  Vec3 bary = Vec3::Zero();
  double best = std::numeric_limits<double>::infinity();  // squared distance
};

bool visitNearest(RTCPointQueryFunctionArguments* args) {
  auto* q = static_cast<NearestQuery*>(args->userPtr);
  const int i = int(args->primID);
  const auto& f = (*q->faces)[size_t(i)];
  const auto& t = *q->texture;
  const Vec3 b = nearestOnTriangle(q->p, t[f[0]], t[f[1]], t[f[2]]);
  const double dist = (b[0] * t[f[0]] + b[1] * t[f[1]] + b[2] * t[f[2]] - q->p).squaredNorm();
  if (dist > q->best || (dist == q->best && i > q->face)) return false;
  q->best = dist, q->face = i, q->bary = b;
  args->query->radius = float(std::sqrt(dist) * (1 + 1e-5) + 1e-6);
  return true;
}

}  // namespace

// The fallback: the surface point nearest p (texture space), through Embree's tree.
void PolycubeMap::Impl::nearest(const Vec3& p, int& outFace, Vec3& outBary) const {
  NearestQuery q{&texture, &mesh.faces, p};
  RTCPointQuery query;
  query.x = float(p.x()), query.y = float(p.y()), query.z = float(p.z());
  query.radius = std::numeric_limits<float>::infinity();
  query.time = 0;
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(scene, &query, &context, visitNearest, &q);
  outFace = q.face, outBary = q.bary;
}

PolycubeMap::PolycubeMap(const surface::SurfaceMesh& mesh, const PolycubeOptions& options)
    : impl_(std::make_unique<Impl>()) {
  if (mesh.faces.empty() || mesh.vertices.empty())
    throw std::invalid_argument("polycube map: the mesh is empty (no faces)");
  if (mesh.vertexNormals.size() != mesh.vertices.size() || mesh.neighbours.size() != mesh.faces.size() ||
      mesh.faceNormals.size() != mesh.faces.size())
    throw std::invalid_argument("polycube map: the mesh has no topology (call buildTopology() first)");
  if (options.resolution < 1 || options.resolution > kMaxPolycubeResolution)
    throw std::invalid_argument("polycube map: resolution must be in 1.." + std::to_string(kMaxPolycubeResolution) +
                                " (cells along the largest extent), got " + std::to_string(options.resolution));
  Impl& m = *impl_;
  m.mesh = mesh;
  m.chooseGrid(options);
  m.markTouchedCells();
  m.chooseSolid();
  m.regularise();
  m.collectFacelets(options.maxFacelets);
  m.buildScene();
}

PolycubeMap::~PolycubeMap() = default;
PolycubeMap::PolycubeMap(PolycubeMap&&) noexcept = default;
PolycubeMap& PolycubeMap::operator=(PolycubeMap&&) noexcept = default;

const std::vector<Facelet>& PolycubeMap::facelets() const { return impl_->facelets; }
double PolycubeMap::cellSize() const { return impl_->cellSize; }
Vec3 PolycubeMap::gridOrigin() const { return impl_->origin; }
std::array<int, 3> PolycubeMap::gridCells() const { return {impl_->cells.x(), impl_->cells.y(), impl_->cells.z()}; }
size_t PolycubeMap::solidCells() const { return impl_->solidCount; }
size_t PolycubeMap::fallbackCount() const { return impl_->fallbacks.load(); }

namespace {

void checkPoint(size_t facelet, size_t count, double a, double b) {
  if (facelet >= count)
    throw std::out_of_range("polycube map: face-let " + std::to_string(facelet) + " of " + std::to_string(count));
  if (!(a >= 0 && a <= 1 && b >= 0 && b <= 1))
    throw std::out_of_range("polycube map: face-let point (" + std::to_string(a) + ", " + std::to_string(b) +
                            ") outside [0,1]^2");
}

}  // namespace

Vec3 PolycubeMap::projectionDirection(size_t facelet, double a, double b) const {
  checkPoint(facelet, impl_->facelets.size(), a, b);
  const auto& d = impl_->cornerDirection[facelet];
  return ((1 - a) * (1 - b) * d[0] + a * (1 - b) * d[1] + (1 - a) * b * d[2] + a * b * d[3]).normalized();
}

MappedPoint PolycubeMap::map(size_t facelet, double a, double b) const {
  const Impl& m = *impl_;
  checkPoint(facelet, m.facelets.size(), a, b);
  const Facelet& fl = m.facelets[facelet];
  const int ua = fl.sign > 0 ? (fl.axis + 1) % 3 : (fl.axis + 2) % 3;
  const int va = fl.sign > 0 ? (fl.axis + 2) % 3 : (fl.axis + 1) % 3;
  // Texture-space point and direction, computed so that a point shared by two face-lets
  // comes out bit-identical from both (integer corner + parameter, products with 0 or 1).
  Vec3 p = m.faceletOrigin[facelet].cast<double>();
  p[ua] += a;
  p[va] += b;
  const auto& cd = m.cornerDirection[facelet];
  const Vec3 d = (1 - a) * (1 - b) * cd[0] + a * (1 - b) * cd[1] + (1 - a) * b * cd[2] + a * b * cd[3];

  MappedPoint out;
  out.hit = m.castLine(p, d, out.face, out.bary);
  if (!out.hit) {
    m.fallbacks.fetch_add(1, std::memory_order_relaxed);
    m.nearest(p, out.face, out.bary);
  }

  const surface::SurfacePoint sp{out.face, out.bary};
  out.position = sp.position(m.mesh);
  const auto& f = m.mesh.faces[out.face];
  const Vec3 n = out.bary[0] * m.mesh.vertexNormals[f[0]] + out.bary[1] * m.mesh.vertexNormals[f[1]] +
                 out.bary[2] * m.mesh.vertexNormals[f[2]];
  out.normal = n.norm() > 1e-12 ? Vec3(n.normalized()) : m.mesh.faceNormals[out.face];
  // Face-let axes projected onto the tangent plane; where one is (nearly) parallel to the
  // normal the other, crossed with the normal, stands in (u and v are orthogonal, so at
  // most one of them can be).
  const Vec3 U = Vec3::Unit(ua), V = Vec3::Unit(va);
  Vec3 tu = U - U.dot(out.normal) * out.normal, tv = V - V.dot(out.normal) * out.normal;
  if (tu.norm() >= tv.norm()) {
    tu.normalize();
    tv = tv.norm() > 1e-6 ? Vec3(tv.normalized()) : Vec3(out.normal.cross(tu));
  } else {
    tv.normalize();
    tu = tu.norm() > 1e-6 ? Vec3(tu.normalized()) : Vec3(tv.cross(out.normal));
  }
  out.tangentU = tu;
  out.tangentV = tv;
  return out;
}

}  // namespace fgsg::rt::evolve
