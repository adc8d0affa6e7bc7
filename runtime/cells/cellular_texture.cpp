// The state of one cellular texture: occupancy maps and placed cells
// (cellular_texture.h).
#include "runtime/cells/cellular_texture.h"

#include "runtime/cells/feature_param.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fgsg::rt::cells {

namespace {

Vec3 faceNormalAt(const FeatureFace& f, const Vec3& p) {
  if (f.kind == FaceKind::Cylindrical) return faceAt(f, projectOnFace(f, p)).normal;
  return f.normal;
}

// Signed distance of p above the face (along its outward normal).
double heightAbove(const FeatureFace& f, const Vec3& p) {
  if (f.kind == FaceKind::Cylindrical) {
    const Vec3 d = p - f.centre;
    const double r = (d - d.dot(f.axis) * f.axis).norm();
    return f.outward ? r - f.radius : f.radius - r;
  }
  return (p - f.origin).dot(f.normal);
}

uint64_t cellKey(int64_t x, int64_t y, int64_t z) {
  return (uint64_t(x) * 0x9E3779B97F4A7C15ull) ^ (uint64_t(y) * 0xC2B2AE3D27D4EB4Full) ^
         (uint64_t(z) * 0x165667B19E3779F9ull);
}

}  // namespace

namespace {

// What the separating-axis test needs of a convex cell: its corners, its faces' normals
// and its edges' directions. A prism's come from its outline; a mitred cell's from its
// solid's faces (cell.h Cell::solid).
struct CellSeparatingFeatures {
  std::vector<Vec3> vertices, normals, edges;
};
CellSeparatingFeatures cellSeparatingFeatures(const Cell& c) {
  CellSeparatingFeatures s;
  if (c.cuts.empty()) {
    s.vertices = c.vertices();
    const Polygon2 o = c.outline();
    s.normals.push_back(c.axes.col(2));
    s.edges.push_back(c.axes.col(2));
    for (size_t i = 0; i < o.size(); ++i) {
      const Vec2 d = o[(i + 1) % o.size()] - o[i];
      const Vec3 along = c.axes.col(0) * d.x() + c.axes.col(1) * d.y();
      s.edges.push_back(along);
      s.normals.push_back(along.cross(c.axes.col(2)));
    }
    return s;
  }
  for (const std::vector<Vec3>& f : c.solid()) {
    Vec3 newell = Vec3::Zero();
    for (size_t i = 0; i < f.size(); ++i) {
      const Vec3 &a = f[i], &b = f[(i + 1) % f.size()];
      newell += a.cross(b);
      s.edges.push_back(b - a);
      s.vertices.push_back(a);
    }
    s.normals.push_back(newell);
  }
  return s;
}

// Two convex cells (boxes, clipped or mitred cells): separated along some face normal of
// either or some cross product of their edge directions, or they overlap.
bool prismsOverlap(const Cell& a, const Cell& b, double slack) {
  const CellSeparatingFeatures fa = cellSeparatingFeatures(a), fb = cellSeparatingFeatures(b);
  const std::vector<Vec3>&va = fa.vertices, &vb = fb.vertices;
  auto separated = [&](const Vec3& axis) {
    const double n = axis.norm();
    if (n < 1e-12) return false;
    const Vec3 u = axis / n;
    double loA = INFINITY, hiA = -INFINITY, loB = INFINITY, hiB = -INFINITY;
    for (const Vec3& p : va) loA = std::min(loA, p.dot(u)), hiA = std::max(hiA, p.dot(u));
    for (const Vec3& p : vb) loB = std::min(loB, p.dot(u)), hiB = std::max(hiB, p.dot(u));
    return hiA <= loB + slack || hiB <= loA + slack;
  };
  for (const CellSeparatingFeatures* f : {&fa, &fb})
    for (const Vec3& n : f->normals)
      if (separated(n)) return false;
  for (const Vec3& ea : fa.edges)
    for (const Vec3& eb : fb.edges)
      if (separated(ea.cross(eb))) return false;
  return true;
}

}  // namespace

bool cellsOverlap(const Cell& a, const Cell& b, double slack) {
  if (!a.isBox() || !b.isBox()) return prismsOverlap(a, b, slack);
  // Separating axes of two boxes: their 3 + 3 face normals and the 9 edge cross products.
  const Vec3 ca = a.centre(), cb = b.centre();
  const Vec3 ha = 0.5 * a.size, hb = 0.5 * b.size;
  auto separated = [&](const Vec3& axis) {
    const double n = axis.norm();
    if (n < 1e-12) return false;
    const Vec3 u = axis / n;
    double ra = 0, rb = 0;
    for (int k = 0; k < 3; ++k) ra += ha[k] * std::abs(a.axes.col(k).dot(u)), rb += hb[k] * std::abs(b.axes.col(k).dot(u));
    return std::abs((cb - ca).dot(u)) >= ra + rb - slack;
  };
  for (int k = 0; k < 3; ++k)
    if (separated(a.axes.col(k)) || separated(b.axes.col(k))) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (separated(a.axes.col(i).cross(b.axes.col(j)))) return false;
  return true;
}

CellularTexture::CellularTexture(const surface::SurfaceMesh& mesh, FeatureMesh features, const Vec3& up)
    : mesh_(mesh), fm_(std::move(features)), up_(up.normalized()) {
  courseBase_ = INFINITY;
  for (const Vec3& v : mesh.vertices) courseBase_ = std::min(courseBase_, v.dot(up_));
  tolerance_ = 1e-9 * std::max((mesh.boundsMax - mesh.boundsMin).norm(), 1e-12);
  edgeMaps_.resize(fm_.edges.size());
  faceMaps_.reserve(fm_.faces.size());
  for (const FeatureFace& f : fm_.faces) faceMaps_.emplace_back(f, mesh);
}

std::vector<FeatureRef> CellularTexture::order() const {
  std::vector<FeatureRef> out;
  for (int i = 0; i < int(fm_.corners.size()); ++i) out.push_back({FeatureKind::Corner, i});
  for (int i = 0; i < int(fm_.edges.size()); ++i) out.push_back({FeatureKind::Edge, i});
  for (int i = 0; i < int(fm_.faces.size()); ++i) out.push_back({FeatureKind::Face, i});
  return out;
}

EdgeSides CellularTexture::sidesAt(int edge, double s) const {
  const FeatureEdge& e = fm_.edges[edge];
  const EdgeFrame fr = edgeAt(e, s);
  EdgeSides sd;
  sd.point = fr.point;
  sd.tangent = fr.tangent;
  sd.twoSided = e.rightFace >= 0;
  sd.normal[0] = faceNormalAt(fm_.faces[e.leftFace], fr.point);
  sd.normal[1] = sd.twoSided ? faceNormalAt(fm_.faces[e.rightFace], fr.point) : sd.normal[0];
  if (sd.tangent.dot(up_) < -1e-9) {  // walk it upwards: left and right trade places
    sd.tangent = -sd.tangent;
    if (sd.twoSided) std::swap(sd.normal[0], sd.normal[1]), sd.swapped = true;
  }
  for (Vec3& n : sd.normal) n = (n - n.dot(sd.tangent) * sd.tangent).normalized();
  sd.away[0] = sd.normal[0].cross(sd.tangent).normalized();
  sd.away[1] = sd.tangent.cross(sd.normal[1]).normalized();
  return sd;
}

double CellularTexture::edgeParameter(int edge, const Vec3& p) const {
  const FeatureEdge& e = fm_.edges[edge];
  if (e.shape == EdgeShape::Line) return (p - e.points.front()).dot((e.points.back() - e.points.front()).normalized());
  if (e.shape == EdgeShape::Arc) {
    const Vec3 q = p - e.centre;
    double a = std::atan2(q.dot(e.axis.cross(e.ref)), q.dot(e.ref));
    if (a < 0) a += 2 * std::numbers::pi;
    const double sweep = e.length / e.radius;
    if (!e.closed && a > sweep && a - sweep > 2 * std::numbers::pi - a) a -= 2 * std::numbers::pi;
    return e.radius * a;
  }
  return projectOnEdge(e, p);
}

void CellularTexture::project(const Cell& c, FeatureRef onto) {
  if (onto.kind == FeatureKind::Edge) {
    const std::vector<Vec3> corners = c.vertices();
    const FeatureEdge& e = fm_.edges[onto.index];
    // A leaning vertical edge's courses are level, and so are its cells' tops and bottoms
    // in their face (generators.cpp verticalCourses): a cell claims the stretch of it
    // between the lowest and the highest point of its outline on the face (depth 0), not
    // its orthogonal projection, which a level-topped cell's far corners overshoot into
    // the courses above and below, nor its outer side's, which a leaning face's normal
    // tilts.
    const double rise = e.shape == EdgeShape::Line && e.direction == EdgeDirection::Vertical
                            ? (e.points.back() - e.points.front()).dot(up_) / e.length
                            : 1;
    const bool leaning = std::abs(rise) < 1 - 1e-12;
    double lo = INFINITY, hi = -INFINITY;
    for (size_t k = 0; k < (leaning ? corners.size() / 2 : corners.size()); ++k) {
      const Vec3& p = corners[k];  // vertices(): the outline at depth 0 first
      const double s = leaning ? (p - e.points.front()).dot(up_) / rise : edgeParameter(onto.index, p);
      lo = std::min(lo, s), hi = std::max(hi, s);
    }
    edgeMaps_[onto.index].add(std::max(lo, 0.0), std::min(hi, e.length));
  } else if (onto.kind == FeatureKind::Face) {
    const FeatureFace& f = fm_.faces[onto.index];
    if (f.kind == FaceKind::Freeform) return;
    double top = -INFINITY;
    std::vector<Vec2> uv;
    uv.reserve(2 * (c.isBox() ? 4 : c.profile.size()));
    auto visit = [&](const Vec3& p) {
      top = std::max(top, heightAbove(f, p));
      uv.push_back(projectOnFace(f, p));
    };
    if (c.cuts.empty() || f.kind != FaceKind::Planar) {
      c.forEachVertex(visit);
    } else {
      // A mitred cell (an outward mitre's, reaching round a corner into this face's
      // layer) claims the shadow of its part in front of the face: not its prism's,
      // which its mitre cuts off, nor that of its part behind the face's plane, which
      // lies over its own face past the edge.
      for (const std::vector<Vec3>& side : clipSolid(c.solid(), -f.normal, -f.normal.dot(f.origin), tolerance_))
        for (const Vec3& p : side) visit(p);
    }
    if (top <= tolerance_) return;  // behind the face: not in its layer of cells
    faceMaps_[onto.index].claim(std::move(uv));
  }
}

CellularTexture::Bounds CellularTexture::boundsOf(const Cell& c) {
  Bounds b{c.corner(0), c.corner(0)};
  c.forEachVertex([&](const Vec3& p) { b.lo = b.lo.cwiseMin(p), b.hi = b.hi.cwiseMax(p); });
  return b;
}

template <class Visit>
void CellularTexture::forBuckets(const Bounds& b, Visit&& visit) const {
  for (int64_t x = int64_t(std::floor(b.lo.x() / gridSize_)); x <= int64_t(std::floor(b.hi.x() / gridSize_)); ++x)
    for (int64_t y = int64_t(std::floor(b.lo.y() / gridSize_)); y <= int64_t(std::floor(b.hi.y() / gridSize_)); ++y)
      for (int64_t z = int64_t(std::floor(b.lo.z() / gridSize_)); z <= int64_t(std::floor(b.hi.z() / gridSize_)); ++z)
        visit(cellKey(x, y, z));
}

bool CellularTexture::overlapsPlaced(const Cell& c) const {
  if (grid_.empty()) return false;
  const Bounds b = boundsOf(c);
  const double slack = 1e3 * tolerance_;
  if (++visit_ == 0) std::fill(visited_.begin(), visited_.end(), 0), visit_ = 1;
  bool hit = false;
  forBuckets(b, [&](uint64_t key) {
    if (hit) return;
    auto it = grid_.find(key);
    if (it == grid_.end()) return;
    for (int other : it->second) {
      if (visited_[other] == visit_) continue;
      visited_[other] = visit_;
      // Boxes whose bounds overlap by no more than the slack on some world axis overlap by
      // no more than it anywhere: the separating-axis test would say so too.
      const Bounds& o = bounds_[other];
      if (((b.hi - o.lo).array() <= slack).any() || ((o.hi - b.lo).array() <= slack).any()) continue;
      if (cellsOverlap(c, cells_[other], slack)) {
        hit = true;
        return;
      }
    }
  });
  return hit;
}

void CellularTexture::index(int id) {
  const Cell& c = cells_[id];
  if (grid_.empty()) gridSize_ = std::max(2 * c.size.maxCoeff(), 1e3 * tolerance_);
  bounds_.push_back(boundsOf(c));
  visited_.push_back(0);
  forBuckets(bounds_.back(), [&](uint64_t key) { grid_[key].push_back(id); });
}

bool CellularTexture::add(Cell cell, FeatureRef on, double keep) {
  if (!(cell.size.minCoeff() > 1e3 * tolerance_) || !cell.origin.allFinite() || !cell.size.allFinite()) return false;
  if (overlapsPlaced(cell)) {
    // The cell cut at `length` along axis 0 (a clipped cell: its profile cut there too).
    auto cut = [&](double length) {
      Cell t = cell;
      t.size.x() = length;
      if (!t.isBox()) {
        t.profile = clipHalfPlane(cell.profile, Vec2(1, 0), length);
        if (t.profile.empty()) t.size.x() = 0;
        else fitToProfile(t);
      }
      return t;
    };
    if (!(keep > 0)) return false;
    Cell trial = cut(keep * cell.size.x());
    if (!(trial.size.x() > 0) || overlapsPlaced(trial)) return false;
    double good = keep * cell.size.x(), bad = cell.size.x();
    for (int k = 0; k < 24; ++k) {
      const double mid = 0.5 * (good + bad);
      (overlapsPlaced(cut(mid)) ? bad : good) = mid;
    }
    cell = cut(good);
  }
  cell.feature = on;
  cells_.push_back(std::move(cell));
  index(int(cells_.size()) - 1);
  const Cell& placed = cells_.back();
  project(placed, on);
  if (on.kind == FeatureKind::Corner) {
    const FeatureCorner& c = fm_.corners[on.index];
    for (int e : c.edges) project(placed, {FeatureKind::Edge, e});
    for (int f : c.faces) project(placed, {FeatureKind::Face, f});
  } else if (on.kind == FeatureKind::Edge) {
    const FeatureEdge& e = fm_.edges[on.index];
    for (int f : {e.leftFace, e.rightFace})
      if (f >= 0) project(placed, {FeatureKind::Face, f});
  }
  return true;
}

}  // namespace fgsg::rt::cells
