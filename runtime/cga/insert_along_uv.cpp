// insertAlongUV (insert_along_uv.h): the shape's faces become cells of uv space, each a
// convex uv polygon with the affine map from its uvs to its points (a face whose uvs are an
// affine image of it stays whole; others, and all faces when heights follow the vertex
// normals, are cut into triangles). Every copy of the asset along u has each triangle
// clipped to every cell it crosses (Sutherland-Hodgman in uv, the height carried
// linearly), and each piece is mapped through its cell. A uniform grid over the cells' uv
// boxes gives each triangle (and each wall test, each overlap test) only the cells near
// it: a shape of many faces is not scanned whole for every piece of the asset.
#include "runtime/cga/insert_along_uv.h"

#include "runtime/cga/geometry_queries.h"
#include "runtime/cga/polygon_clip.h"
#include "runtime/cga/shape_operations.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <unordered_map>

namespace fgsg::rt::cga {
namespace {

using AlongUvPoint = Eigen::Vector2d;

double alongUvCross(const AlongUvPoint& a, const AlongUvPoint& b) { return a.x() * b.y() - a.y() * b.x(); }

double alongUvSignedArea(const std::vector<AlongUvPoint>& p) {
  double twice = 0.0;
  for (size_t i = 0; i < p.size(); ++i) twice += alongUvCross(p[i], p[(i + 1) % p.size()]);
  return 0.5 * twice;
}

// A convex region of uv space on one face of the shape, counter-clockwise, and the affine
// map from (u, v) to the face: origin + du u + dv v.
struct AlongUvCell {
  std::vector<AlongUvPoint> uv;
  Vec3 origin = Vec3::Zero(), du = Vec3::Zero(), dv = Vec3::Zero();
  size_t face = 0;
  Vec3 faceNormal = Vec3::UnitY();
  // Heights along the vertex normals: the cell is a triangle (uv) with its corners' normals.
  bool interpolates = false;
  std::array<Vec3, 3> normals;
  double lo[2] = {0, 0}, hi[2] = {0, 0};
  bool keepsWinding = true;  // the map keeps the asset's faces turned outward
  double scale = 1.0;        // its uv box's diagonal
};

// The affine map taking uv triangle (ta, tb, tc) onto points (pa, pb, pc); false when the
// triangle has no area in uv.
bool alongUvAffine(const AlongUvPoint& ta, const AlongUvPoint& tb, const AlongUvPoint& tc, const Vec3& pa,
                   const Vec3& pb, const Vec3& pc, AlongUvCell& cell) {
  Eigen::Matrix2d m;
  m.col(0) = tb - ta;
  m.col(1) = tc - ta;
  const double det = m.determinant();
  if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return false;
  Eigen::Matrix<double, 3, 2> e;
  e.col(0) = pb - pa;
  e.col(1) = pc - pa;
  const Eigen::Matrix<double, 3, 2> j = e * m.inverse();
  cell.du = j.col(0);
  cell.dv = j.col(1);
  cell.origin = pa - cell.du * ta.x() - cell.dv * ta.y();
  return true;
}

void alongUvBounds(AlongUvCell& cell) {
  cell.lo[0] = cell.lo[1] = std::numeric_limits<double>::infinity();
  cell.hi[0] = cell.hi[1] = -std::numeric_limits<double>::infinity();
  for (const AlongUvPoint& p : cell.uv)
    for (int k = 0; k < 2; ++k) cell.lo[k] = std::min(cell.lo[k], p[k]), cell.hi[k] = std::max(cell.hi[k], p[k]);
  cell.scale = std::hypot(cell.hi[0] - cell.lo[0], cell.hi[1] - cell.lo[1]);
}

bool alongUvInside(const AlongUvCell& cell, const AlongUvPoint& p) {
  if (p.x() < cell.lo[0] || p.x() > cell.hi[0] || p.y() < cell.lo[1] || p.y() > cell.hi[1]) return false;
  for (size_t i = 0; i < cell.uv.size(); ++i) {
    const AlongUvPoint& a = cell.uv[i];
    const AlongUvPoint& b = cell.uv[(i + 1) % cell.uv.size()];
    if (alongUvCross(b - a, p - a) < 0.0) return false;
  }
  return true;
}

// A point of the asset in uv space with its height, as the clipping carries it.
struct AlongUvVertex {
  AlongUvPoint uv;
  double h = 0.0;
};

// Sutherland-Hodgman: the part of `poly` inside the convex counter-clockwise `clip`.
std::vector<AlongUvVertex> alongUvClip(std::vector<AlongUvVertex> poly, const std::vector<AlongUvPoint>& clip) {
  for (size_t i = 0; i < clip.size() && !poly.empty(); ++i) {
    const AlongUvPoint& a = clip[i];
    const AlongUvPoint edge = clip[(i + 1) % clip.size()] - a;
    std::vector<AlongUvVertex> kept;
    for (size_t k = 0; k < poly.size(); ++k) {
      const AlongUvVertex& p = poly[k];
      const AlongUvVertex& q = poly[(k + 1) % poly.size()];
      const double dp = alongUvCross(edge, p.uv - a), dq = alongUvCross(edge, q.uv - a);
      if (dp >= 0.0) kept.push_back(p);
      if ((dp >= 0.0) != (dq >= 0.0)) {
        const double t = dp / (dp - dq);
        kept.push_back({p.uv + t * (q.uv - p.uv), p.h + t * (q.h - p.h)});
      }
    }
    poly = std::move(kept);
  }
  return poly;
}

double alongUvPolygonArea(const std::vector<AlongUvVertex>& p) {
  std::vector<AlongUvPoint> pts;
  for (const AlongUvVertex& v : p) pts.push_back(v.uv);
  return alongUvSignedArea(pts);
}

// The distinct corners so far, in buckets of side 2 tol: a corner within tol of another
// lies in its bucket or a neighbouring one. Corners without a bucket (not finite, or too
// far out for one) are asked every time, as a scan of all corners would.
class AlongUvCornerIndex {
 public:
  explicit AlongUvCornerIndex(double tol) : tol_(tol) {}

  // The first of `points` (all added here) closer than tol to c, or points.size().
  size_t find(const std::vector<Vec3>& points, const Vec3& c) const {
    std::array<int64_t, 3> key;
    if (!bucket(c, key)) {
      size_t k = 0;
      while (k < points.size() && (points[k] - c).norm() > tol_) ++k;
      return k;
    }
    size_t best = points.size();
    for (size_t k : loose_)
      if (k < best && !((points[k] - c).norm() > tol_)) best = k;
    for (int64_t dx = -1; dx <= 1; ++dx)
      for (int64_t dy = -1; dy <= 1; ++dy)
        for (int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = buckets_.find({key[0] + dx, key[1] + dy, key[2] + dz});
          if (it == buckets_.end()) continue;
          for (size_t k : it->second)
            if (k < best && !((points[k] - c).norm() > tol_)) best = k;
        }
    return best;
  }

  void add(size_t k, const Vec3& c) {
    std::array<int64_t, 3> key;
    if (bucket(c, key)) buckets_[key].push_back(k);
    else loose_.push_back(k);
  }

 private:
  struct KeyHash {
    size_t operator()(const std::array<int64_t, 3>& k) const {
      uint64_t h = 1469598103934665603ull;
      for (int64_t x : k) h = (h ^ uint64_t(x)) * 1099511628211ull;
      return size_t(h);
    }
  };

  bool bucket(const Vec3& c, std::array<int64_t, 3>& key) const {
    if (!(tol_ > 0.0)) return false;
    for (int a = 0; a < 3; ++a) {
      const double t = std::floor(c[a] / (2.0 * tol_));
      if (!(std::abs(t) < 1e15)) return false;  // not finite, or too far out for a bucket
      key[size_t(a)] = int64_t(t);
    }
    return true;
  }

  double tol_;
  std::unordered_map<std::array<int64_t, 3>, std::vector<size_t>, KeyHash> buckets_;
  std::vector<size_t> loose_;
};

// Each corner's normal: the area-weighted normals of the faces meeting there (corners
// closer than `tol` are one), as CityEngine computes vertex normals from merged vertices.
std::vector<std::vector<Vec3>> alongUvVertexNormals(const std::vector<AlongUvFace>& faces, double tol,
                                                    Deadline* deadline) {
  std::vector<Vec3> points, sums;
  AlongUvCornerIndex distinct(tol);
  std::vector<std::vector<size_t>> index(faces.size());
  for (size_t f = 0; f < faces.size(); ++f) {
    const Vec3 n = newellNormal(faces[f].corners);  // length: twice the area
    for (const Vec3& c : faces[f].corners) {
      if (deadline) deadline->check();
      const size_t k = distinct.find(points, c);
      if (k == points.size()) distinct.add(k, c), points.push_back(c), sums.push_back(Vec3::Zero());
      sums[k] += n;
      index[f].push_back(k);
    }
  }
  std::vector<std::vector<Vec3>> out(faces.size());
  for (size_t f = 0; f < faces.size(); ++f)
    for (size_t k : index[f]) out[f].push_back(sums[k].norm() > 0 ? Vec3(sums[k].normalized()) : Vec3::Zero());
  return out;
}

// The cells of one face (none when its uvs have no area: the projection sees it edge-on).
void alongUvCells(const AlongUvFace& face, size_t index, const std::vector<Vec3>& normals, bool interpolate,
                  double extent, std::vector<AlongUvCell>& cells) {
  const size_t n = face.corners.size();
  if (n < 3 || face.uvs.size() != n) return;
  std::vector<AlongUvPoint> uv;
  for (const auto& t : face.uvs) uv.emplace_back(t[0], t[1]);
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const AlongUvPoint& p : uv)
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  const double uvScale = std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
  const double area = alongUvSignedArea(uv);
  if (!(uvScale > 0.0) || !(std::abs(area) > 1e-12 * uvScale * uvScale)) return;
  const Vec3 normal = newellNormal(face.corners);
  if (!(normal.norm() > 0.0)) return;
  AlongUvCell base;
  base.face = index;
  base.faceNormal = normal.normalized();
  if (!interpolate) {
    // Whole, when its uvs are a convex polygon and an affine image of its corners.
    bool convex = true;
    for (size_t i = 0; i < n && convex; ++i) {
      const AlongUvPoint e0 = uv[(i + 1) % n] - uv[i], e1 = uv[(i + 2) % n] - uv[(i + 1) % n];
      if (!(e0.norm() > 1e-12 * uvScale)) convex = false;
      else if (alongUvCross(e0, e1) * (area > 0 ? 1.0 : -1.0) < -1e-12 * uvScale * uvScale) convex = false;
    }
    size_t b = 1, c = 2;
    double best = 0.0;
    for (size_t i = 1; i < n; ++i)
      for (size_t k = i + 1; k < n; ++k)
        if (const double a = std::abs(alongUvCross(uv[i] - uv[0], uv[k] - uv[0])); a > best) best = a, b = i, c = k;
    AlongUvCell cell = base;
    if (convex && alongUvAffine(uv[0], uv[b], uv[c], face.corners[0], face.corners[b], face.corners[c], cell)) {
      bool affine = true;
      for (size_t i = 0; i < n && affine; ++i)
        affine = (cell.origin + cell.du * uv[i].x() + cell.dv * uv[i].y() - face.corners[i]).norm() <= 1e-9 * extent;
      if (affine) {
        cell.uv = uv;
        if (area < 0) std::reverse(cell.uv.begin(), cell.uv.end());
        alongUvBounds(cell);
        cells.push_back(std::move(cell));
        return;
      }
    }
  }
  std::vector<uint32_t> tris;
  earClip(face.corners, tris);
  for (size_t t = 0; t + 2 < tris.size(); t += 3) {
    std::array<size_t, 3> k{tris[t], tris[t + 1], tris[t + 2]};
    AlongUvCell cell = base;
    const double triArea = 0.5 * alongUvCross(uv[k[1]] - uv[k[0]], uv[k[2]] - uv[k[0]]);
    if (!(std::abs(triArea) > 1e-12 * uvScale * uvScale)) continue;
    if (triArea < 0) std::swap(k[1], k[2]);  // counter-clockwise in uv
    if (!alongUvAffine(uv[k[0]], uv[k[1]], uv[k[2]], face.corners[k[0]], face.corners[k[1]], face.corners[k[2]], cell))
      continue;
    cell.uv = {uv[k[0]], uv[k[1]], uv[k[2]]};
    cell.interpolates = interpolate;
    for (int i = 0; i < 3; ++i) cell.normals[size_t(i)] = normals.empty() ? base.faceNormal : normals[k[size_t(i)]];
    alongUvBounds(cell);
    cells.push_back(std::move(cell));
  }
}

// The two cells' overlap in uv (convex polygons).
double alongUvOverlap(const AlongUvCell& a, const AlongUvCell& b) {
  if (a.hi[0] <= b.lo[0] || b.hi[0] <= a.lo[0] || a.hi[1] <= b.lo[1] || b.hi[1] <= a.lo[1]) return 0.0;
  std::vector<AlongUvVertex> poly;
  for (const AlongUvPoint& p : a.uv) poly.push_back({p, 0.0});
  return std::abs(alongUvPolygonArea(alongUvClip(std::move(poly), b.uv)));
}

// A uniform grid over the cells' uv boxes: each bucket lists the cells whose boxes reach
// into it. Buckets come from one monotonic map of u and of v (clamped at the grid's ends),
// so a box that overlaps another box, or holds a point, shares a bucket with it.
class AlongUvGrid {
 public:
  explicit AlongUvGrid(const std::vector<AlongUvCell>& cells) {
    for (int k = 0; k < 2; ++k) lo_[k] = INFINITY;
    double hi[2] = {-INFINITY, -INFINITY};
    for (const AlongUvCell& c : cells)
      for (int k = 0; k < 2; ++k) lo_[k] = std::min(lo_[k], c.lo[k]), hi[k] = std::max(hi[k], c.hi[k]);
    // About one bucket per cell, shaped like the uv box; coarser while long cells would
    // be listed in too many buckets (memory stays linear in the cells).
    const double span[2] = {hi[0] - lo_[0], hi[1] - lo_[1]};
    const double count = double(cells.size());
    const double aspect = span[0] > 0 && span[1] > 0 && std::isfinite(span[0] / span[1]) ? span[0] / span[1] : 1.0;
    n_[0] = int(std::clamp(std::round(std::sqrt(count * aspect)), 1.0, count));
    n_[1] = int(std::clamp(std::round(count / n_[0]), 1.0, count));
    for (;;) {
      for (int k = 0; k < 2; ++k) scale_[k] = span[k] > 0 && std::isfinite(span[k]) ? n_[k] / span[k] : 0.0;
      double listed = 0.0;
      for (const AlongUvCell& c : cells)
        listed += double(bucket(0, c.hi[0]) - bucket(0, c.lo[0]) + 1) * double(bucket(1, c.hi[1]) - bucket(1, c.lo[1]) + 1);
      if (listed <= 16.0 * count + 64.0 || (n_[0] == 1 && n_[1] == 1)) break;
      n_[0] = std::max(1, n_[0] / 2), n_[1] = std::max(1, n_[1] / 2);
    }
    buckets_.resize(size_t(n_[0]) * size_t(n_[1]));
    for (size_t i = 0; i < cells.size(); ++i)
      for (int y = bucket(1, cells[i].lo[1]); y <= bucket(1, cells[i].hi[1]); ++y)
        for (int x = bucket(0, cells[i].lo[0]); x <= bucket(0, cells[i].hi[0]); ++x)
          buckets_[size_t(y) * size_t(n_[0]) + size_t(x)].push_back(i);
    seen_.assign(cells.size(), 0);
  }

  // The cells listed in the buckets that the box lo..hi reaches, each once, ascending.
  const std::vector<size_t>& near(const double lo[2], const double hi[2]) {
    ++stamp_;
    found_.clear();
    for (int y = bucket(1, lo[1]); y <= bucket(1, hi[1]); ++y)
      for (int x = bucket(0, lo[0]); x <= bucket(0, hi[0]); ++x)
        for (size_t i : buckets_[size_t(y) * size_t(n_[0]) + size_t(x)])
          if (seen_[i] != stamp_) seen_[i] = stamp_, found_.push_back(i);
    std::sort(found_.begin(), found_.end());
    return found_;
  }

  // The cells whose boxes may hold the point p.
  const std::vector<size_t>& at(const AlongUvPoint& p) const {
    return buckets_[size_t(bucket(1, p.y())) * size_t(n_[0]) + size_t(bucket(0, p.x()))];
  }

 private:
  int bucket(int axis, double x) const {
    const double t = (x - lo_[axis]) * scale_[axis];
    if (!(t >= 0.0)) return 0;  // below the grid, or not a number
    return t >= double(n_[axis]) ? n_[axis] - 1 : int(t);
  }

  double lo_[2] = {0, 0}, scale_[2] = {0, 0};
  int n_[2] = {1, 1};
  std::vector<std::vector<size_t>> buckets_;
  std::vector<uint64_t> seen_;
  uint64_t stamp_ = 0;
  std::vector<size_t> found_;
};

// The height direction at uv point p of the cell.
Vec3 alongUvDirection(const AlongUvCell& cell, const AlongUvPoint& p, const Vec3& up) {
  if (!cell.interpolates) return up;
  const AlongUvPoint& a = cell.uv[0];
  const double total = alongUvCross(cell.uv[1] - a, cell.uv[2] - a);
  const double l1 = alongUvCross(p - a, cell.uv[2] - a) / total, l2 = alongUvCross(cell.uv[1] - a, p - a) / total;
  const Vec3 n = (1.0 - l1 - l2) * cell.normals[0] + l1 * cell.normals[1] + l2 * cell.normals[2];
  return n.norm() > 0.0 ? Vec3(n.normalized()) : cell.faceNormal;
}

std::string alongUvNumber(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

}  // namespace

bool insertAlongUvFaces(const std::vector<AlongUvFace>& faces, const Mesh& asset,
                        const std::array<double, 6>& sourceBox, const AlongUvOptions& options,
                        std::vector<std::vector<Vec3>>& out, std::string& error) {
  out.clear();
  if (!std::isfinite(options.height)) {
    error = "insertAlongUV: the height is not a number";
    return false;
  }
  double extent = 0.0;
  Vec3 lo3 = Vec3::Constant(INFINITY), hi3 = -lo3;
  for (const AlongUvFace& f : faces)
    for (const Vec3& c : f.corners) lo3 = lo3.cwiseMin(c), hi3 = hi3.cwiseMax(c);
  if (lo3.x() <= hi3.x()) extent = 1.0 + (hi3 - lo3).norm();
  const std::vector<std::vector<Vec3>> normals =
      options.vertexNormals ? alongUvVertexNormals(faces, 1e-9 * extent, options.deadline) : std::vector<std::vector<Vec3>>();
  std::vector<AlongUvCell> cells;
  for (size_t f = 0; f < faces.size(); ++f) {
    if (options.deadline) options.deadline->check();
    alongUvCells(faces[f], f, options.vertexNormals ? normals[f] : std::vector<Vec3>(), options.vertexNormals,
                 extent, cells);
  }
  if (cells.empty()) {
    error = "insertAlongUV: the shape has no face with uvs of any area (no faces, or every face seen edge-on by the "
            "uv set's projection)";
    return false;
  }
  // Two faces whose uvs cover the same place would both get the asset there: refused.
  std::vector<size_t> order(cells.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return cells[a].lo[0] < cells[b].lo[0]; });
  std::vector<size_t> rank(cells.size());
  for (size_t i = 0; i < order.size(); ++i) rank[order[i]] = i;
  AlongUvGrid grid(cells);
  std::vector<size_t> later;  // the cells after one in `order` that its box may overlap
  for (size_t i = 0; i < order.size(); ++i) {
    const AlongUvCell& a = cells[order[i]];
    later.clear();
    for (size_t j : grid.near(a.lo, a.hi))
      if (rank[j] > i && cells[j].lo[0] < a.hi[0]) later.push_back(rank[j]);
    std::sort(later.begin(), later.end());  // the pairs in the order of a sweep along u
    for (size_t j : later) {
      if (options.deadline) options.deadline->check();
      const AlongUvCell& b = cells[order[j]];
      if (a.face == b.face) continue;
      const double areaA = std::abs(alongUvSignedArea(a.uv)), areaB = std::abs(alongUvSignedArea(b.uv));
      if (alongUvOverlap(a, b) > 1e-9 * std::min(areaA, areaB)) {
        error = "insertAlongUV: the uvs of faces " + std::to_string(std::min(a.face, b.face)) + " and " +
                std::to_string(std::max(a.face, b.face)) +
                " overlap, so the asset would be inserted on both there: give the faces uvs that do not overlap, "
                "or select one face first (comp(f))";
        return false;
      }
    }
  }
  double uMin = INFINITY, uMax = -INFINITY, vMin = INFINITY, vMax = -INFINITY;
  for (AlongUvCell& c : cells) {
    uMin = std::min(uMin, c.lo[0]), uMax = std::max(uMax, c.hi[0]);
    vMin = std::min(vMin, c.lo[1]), vMax = std::max(vMax, c.hi[1]);
    // The asset's (x, y, z) goes to (du, height dir, -dv): its faces keep facing out when
    // that frame is right-handed, height * dir . (du x dv) > 0.
    const Vec3 dir = c.interpolates ? c.faceNormal : options.up;
    const double turn = dir.dot(c.du.cross(c.dv)) * (options.height < 0 ? -1.0 : 1.0);
    c.keepsWinding = turn >= 0.0;
  }
  if (!(vMax > 0.0 && vMin < 1.0)) {
    error = "insertAlongUV: the shape's v runs from " + alongUvNumber(vMin) + " to " + alongUvNumber(vMax) +
            ", outside 0 to 1 where the asset's depth (z) is laid: nothing would be inserted";
    return false;
  }
  // The asset in tile coordinates: (x, 1 - z) in uv, its height.
  const double ySpan = sourceBox[4] - sourceBox[1];
  const size_t nv = asset.vertexCount();
  std::vector<AlongUvVertex> verts(nv);
  for (size_t i = 0; i < nv; ++i) {
    const double x = asset.positions[3 * i], y = asset.positions[3 * i + 1], z = asset.positions[3 * i + 2];
    double h = y * options.height;
    if (options.keepPosition) h = ySpan > 0.0 ? (sourceBox[1] / ySpan + y) * options.height : 0.0;
    else if (!(ySpan > 0.0)) h = 0.0;
    verts[i] = {AlongUvPoint(x, 1.0 - z), h};
  }
  const double firstTile = std::floor(uMin), lastTile = std::ceil(uMax) - 1.0;
  const double tiles = std::max(1.0, lastTile - firstTile + 1.0);
  const double work = tiles * double(asset.triangleCount());
  if (!(work <= double(options.maxFaces))) {
    error = "insertAlongUV: the shape's u runs from " + alongUvNumber(uMin) + " to " + alongUvNumber(uMax) + ", " +
            alongUvNumber(tiles) + " copies of the asset's " + std::to_string(asset.triangleCount()) +
            " triangles: more than " + std::to_string(options.maxFaces) + " faces";
    return false;
  }
  const double minArea3 = 1e-18 * extent * extent;
  for (double tile = firstTile; tile <= lastTile; tile += 1.0)
    for (size_t t = 0; t + 2 < asset.indices.size(); t += 3) {
      std::vector<AlongUvVertex> tri;
      for (int k = 0; k < 3; ++k) {
        AlongUvVertex v = verts[asset.indices[t + size_t(k)]];
        v.uv.x() += tile;
        tri.push_back(v);
      }
      const AlongUvPoint e1 = tri[1].uv - tri[0].uv, e2 = tri[2].uv - tri[0].uv;
      const double triScale = std::max({e1.norm(), e2.norm(), (tri[2].uv - tri[1].uv).norm()});
      // A wall of the asset (its uv image a segment) lies wholly on a cell's edge when the
      // asset's side meets a face's edge: it goes to the one cell beside it, not to both.
      const bool wall = !(std::abs(alongUvCross(e1, e2)) > 1e-12 * triScale * triScale);
      if (wall && !(triScale > 0.0)) continue;
      AlongUvPoint across = AlongUvPoint::Zero();
      if (wall) {
        AlongUvPoint along = e1.norm() >= e2.norm() ? e1 : e2;
        if ((tri[2].uv - tri[1].uv).norm() > along.norm()) along = tri[2].uv - tri[1].uv;
        across = AlongUvPoint(-along.y(), along.x()).normalized();
        if (across.x() < 0 || (across.x() == 0 && across.y() < 0)) across = -across;
      }
      double tlo[2] = {INFINITY, INFINITY}, thi[2] = {-INFINITY, -INFINITY};
      for (const AlongUvVertex& v : tri)
        for (int k = 0; k < 2; ++k) tlo[k] = std::min(tlo[k], v.uv[k]), thi[k] = std::max(thi[k], v.uv[k]);
      const double triArea = std::abs(alongUvPolygonArea(tri));
      for (size_t c : grid.near(tlo, thi)) {
        if (options.deadline) options.deadline->check();
        const AlongUvCell& cell = cells[c];
        if (thi[0] < cell.lo[0] || tlo[0] > cell.hi[0] || thi[1] < cell.lo[1] || tlo[1] > cell.hi[1]) continue;
        std::vector<AlongUvVertex> piece = alongUvClip(tri, cell.uv);
        if (piece.size() < 3) continue;
        if (wall) {
          AlongUvPoint centre = AlongUvPoint::Zero();
          for (const AlongUvVertex& v : piece) centre += v.uv;
          centre /= double(piece.size());
          const double eps = 1e-7 * cell.scale;
          const AlongUvPoint ahead = centre + eps * across;
          bool mine = alongUvInside(cell, ahead);
          if (!mine) {
            bool elsewhere = false;
            for (size_t other : grid.at(ahead)) elsewhere = elsewhere || alongUvInside(cells[other], ahead);
            mine = !elsewhere && alongUvInside(cell, centre - eps * across);
          }
          if (!mine) continue;
        } else if (!(std::abs(alongUvPolygonArea(piece)) > 1e-9 * triArea)) {
          continue;  // a sliver along a shared edge
        }
        std::vector<Vec3> face;
        for (const AlongUvVertex& v : piece) {
          const Vec3 p = cell.origin + cell.du * v.uv.x() + cell.dv * v.uv.y() +
                         v.h * alongUvDirection(cell, v.uv, options.up);
          if (face.empty() || (face.back() - p).norm() > 1e-12 * extent) face.push_back(p);
        }
        while (face.size() > 1 && (face.front() - face.back()).norm() <= 1e-12 * extent) face.pop_back();
        if (face.size() < 3 || !(0.5 * newellNormal(face).norm() > minArea3)) continue;
        if (!cell.keepsWinding) std::reverse(face.begin(), face.end());
        if (cell.interpolates && face.size() > 3) {  // bent along the normals: not planar
          for (size_t k = 1; k + 1 < face.size(); ++k) {
            std::vector<Vec3> fan{face[0], face[k], face[k + 1]};
            if (0.5 * newellNormal(fan).norm() > minArea3) out.push_back(std::move(fan));
          }
        } else {
          out.push_back(std::move(face));
        }
        if (out.size() > options.maxFaces) {
          error = "insertAlongUV: more than " + std::to_string(options.maxFaces) + " faces";
          return false;
        }
      }
    }
  if (out.empty()) {
    error = "insertAlongUV: nothing of the asset lands on the shape (its uvs run u " + alongUvNumber(uMin) + " to " +
            alongUvNumber(uMax) + ", v " + alongUvNumber(vMin) + " to " + alongUvNumber(vMax) +
            "; the asset fills v 0 to 1 and repeats along u)";
    return false;
  }
  return true;
}

bool insertAlongUv(const Scope& scope, const GeomRef& geom, GeometryArena& arena, const UvProjection& projection,
                   const Mesh& asset, const std::array<double, 6>& sourceBox, const AlongUvOptions& options,
                   Part& out, std::string& error) {
  if (geom.kind == GeomKind::Edge) {
    error = "insertAlongUV: an edge has no faces to insert along";
    return false;
  }
  std::vector<AlongUvFace> faces;
  for (const std::vector<Vec3>& corners : geometryWorldFaces(scope, geom, arena)) {
    AlongUvFace f;
    f.corners = corners;
    const Vec3 facing = newellNormal(corners);
    for (const Vec3& c : corners) f.uvs.push_back(projectPoint(projection, c, facing));
    faces.push_back(std::move(f));
  }
  std::vector<std::vector<Vec3>> world;
  if (!insertAlongUvFaces(faces, asset, sourceBox, options, world, error)) return false;
  // A solid of those faces in the shape's axes, its scope fitted around it.
  out = Part{};
  const std::vector<Polygon3> local = fitScopeAroundWorldFaces(scope, scope.axes, world, out.scope);
  out.geom = arena.addPolyhedron(local);
  return true;
}

}  // namespace fgsg::rt::cga
